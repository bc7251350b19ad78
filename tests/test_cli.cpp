// The `stepwise` command as other tools drive it: trace, run, check, list, bench forms, and bad
// input (one line naming the problem, exit 2, no output file).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include "bench_harness.hpp"
#include "bench_text.hpp"
#include "cli_harness.hpp"
#include "input.hpp"

using namespace sw;
using sw::testing::run_stepwise;
using sw::testing::sh_quote;

namespace {

std::vector<Json> json_lines(const std::string& text) {
  std::vector<Json> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty()) out.push_back(Json::parse(line));
  return out;
}

int count_lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST_CASE("cli: list names every algorithm once", "[cli]") {
  const auto r = run_stepwise("list");
  REQUIRE(r.status == 0);
  for (const char* id : {"dda-line", "dda-grid-walk", "bresenham-line"}) CHECK(r.out.find(std::string(id) + " ") != std::string::npos);
}

TEST_CASE("cli: trace writes header, steps and result", "[cli]") {
  const auto dir = sw::testing::scratch("trace");
  const auto out = (dir / "t.jsonl").string();
  const auto r = run_stepwise("trace dda-line --input '{\"p0\":[0,0],\"p1\":[4,2]}' --numeric exact --out " + sh_quote(out));
  REQUIRE(r.status == 0);
  const auto text = sw::testing::slurp(out);
  CHECK(text.rfind("{\"format\":\"stepwise-trace\",\"version\":2,\"algorithm\":\"dda-line\",\"numeric\":\"exact\",\"input\":", 0) == 0);
  const auto lines = json_lines(text);
  REQUIRE(lines.size() > 3);
  CHECK(lines.back()["result"]["pixels"] == Json::parse("[[0,0],[1,1],[2,1],[3,2]]"));
  for (std::size_t i = 1; i + 1 < lines.size(); ++i) {
    CHECK(lines[i]["step"] == i - 1);
    CHECK(lines[i].contains("line"));
    CHECK(lines[i].contains("kind"));
  }
  // Exact values are lossless strings: the slope of (0,0)->(4,2) is 1/2.
  CHECK(text.find("\"dpy\":\"1/2\"") != std::string::npos);
  // The trace agrees with the oracle.
  const auto c = run_stepwise("check " + sh_quote(out));
  CHECK(c.status == 0);
}

TEST_CASE("cli: check names the first divergent step of a tampered trace", "[cli]") {
  const auto dir = sw::testing::scratch("tamper");
  const auto good = (dir / "good.jsonl").string(), bad = (dir / "bad.jsonl").string();
  REQUIRE(run_stepwise("trace dda-grid-walk --input '{\"p0\":[0.25,0.5],\"p1\":[6.5,3.75]}' --numeric exact --out " + sh_quote(good)).status == 0);
  auto lines = json_lines(sw::testing::slurp(good));
  // Move the third visited cell one row up, as a student's off-by-one would.
  int visits = 0;
  std::size_t tampered = 0;
  for (std::size_t i = 1; i + 1 < lines.size(); ++i)
    if (lines[i]["kind"] == "visit" && ++visits == 3) {
      lines[i]["geo"][0]["pixel"][1] = lines[i]["geo"][0]["pixel"][1].get<int>() + 1;
      tampered = lines[i]["step"].get<std::size_t>();
    }
  REQUIRE(tampered > 0);
  std::ofstream(bad) << [&] { std::string s; for (auto& l : lines) s += l.dump() + "\n"; return s; }();
  const auto c = run_stepwise("check " + sh_quote(bad));
  CHECK(c.status == 1);
  CHECK(c.err.find("step " + std::to_string(tampered) + " diverges") != std::string::npos);
  // A wrong result with correct steps is caught too.
  lines = json_lines(sw::testing::slurp(good));
  lines.back()["result"]["cells"].erase(0);
  std::ofstream(bad, std::ios::trunc) << [&] { std::string s; for (auto& l : lines) s += l.dump() + "\n"; return s; }();
  const auto c2 = run_stepwise("check " + sh_quote(bad));
  CHECK(c2.status == 1);
  CHECK(c2.err.find("result diverges") != std::string::npos);
  CHECK(c2.err.find("result.cells") != std::string::npos);
}

TEST_CASE("cli: float and double traces pass check when decisions agree and numbers are within tolerance", "[cli]") {
  const auto dir = sw::testing::scratch("float");
  const auto t = (dir / "f.jsonl").string();
  REQUIRE(run_stepwise("trace dda-line --input '{\"p0\":[0,0],\"p1\":[9,3]}' --numeric float --out " + sh_quote(t)).status == 0);
  const auto ok = run_stepwise("check " + sh_quote(t));  // 1/3 is not a float, but within 2^-10
  CHECK(ok.status == 0);
  CHECK_THAT(ok.out, Catch::Contains("within"));
  CHECK(run_stepwise("check --decisions-only " + sh_quote(t)).status == 0);
  // A number far off (a wrong variable recorded) fails at its step, naming the variable.
  auto lines = json_lines(sw::testing::slurp(t));
  lines[5]["vars"]["qy"] = lines[5]["vars"]["qy"].get<double>() + 0.25;
  std::ofstream(t, std::ios::trunc) << [&] { std::string s; for (auto& l : lines) s += l.dump() + "\n"; return s; }();
  const auto bad = run_stepwise("check " + sh_quote(t));
  CHECK(bad.status == 1);
  CHECK_THAT(bad.err, Catch::Contains("step 4 diverges") && Catch::Contains("variable qy") && Catch::Contains("--decisions-only"));
  CHECK(run_stepwise("check --decisions-only " + sh_quote(t)).status == 0);
  // Filtered traces certify their decisions.
  REQUIRE(run_stepwise("trace dda-grid-walk --input '{\"p0\":[0.5,0.5],\"p1\":[6.5,3.5]}' --numeric filtered --out " + sh_quote(t)).status == 0);
  CHECK(run_stepwise("check " + sh_quote(t)).status == 0);
}

TEST_CASE("cli: a hand-written double DDA trace passes check and a wrong pixel fails at its step", "[cli]") {
  // A student's DDA in double with another operation order: q at column k is computed afresh as
  // p0 + (k - p0_x) dp, not by repeated addition. Same steps, same names; values differ by ulps.
  const double p0x = 0.25, p0y = 1.0 / 3.0, p1x = 20.5, p1y = 9.0 / 7.0;
  const double dx = p1x - p0x, dy = p1y - p0y, dpy = dy / dx;
  std::vector<Json> steps;
  auto step = [&](int line, const char* kind, Json vars, Json geo) {
    steps.push_back({{"step", steps.size()}, {"line", line}, {"kind", kind}, {"vars", std::move(vars)}, {"geo", std::move(geo)}});
  };
  step(1, "init", {{"dx", dx}, {"dy", dy}}, Json::array({{{"segment", {p0x, p0y, p1x, p1y}}}}));
  step(2, "decide", {{"a", 0}}, Json::array());
  step(3, "decide", {{"swapped", 0}, {"dx", dx}, {"dy", dy}}, Json::array());
  step(5, "init", {{"dpx", 1.0}, {"dpy", dpy}}, Json::array());
  const double off = 1 - p0x;
  Json pixels = Json::array();
  auto qy_at = [&](int k) { return p0y + (k - p0x) * dpy; };
  step(6, "init", {{"dp0x", off}, {"dp0y", off * dpy}, {"qx", 1.0}, {"qy", qy_at(1)}}, Json::array({{{"point", {1.0, qy_at(1)}}}}));
  for (int k = 1; k < 21; ++k) {
    const long j = static_cast<long>(std::floor(qy_at(k) + 0.5));
    pixels.push_back({k, j});
    step(8, "plot", {{"qx", double(k)}, {"qy", qy_at(k)}, {"i", k}, {"j", j}}, Json::array({{{"pixel", {k, j}}}, {{"point", {double(k), qy_at(k)}}}}));
    step(9, "advance", {{"qx", double(k + 1)}, {"qy", qy_at(k + 1)}}, Json::array({{{"point", {double(k + 1), qy_at(k + 1)}}}}));
  }
  step(10, "done", {{"qx", 21.0}, {"qy", qy_at(21)}}, Json::array({{{"point", {21.0, qy_at(21)}}}}));
  const Json header = {{"format", "stepwise-trace"}, {"version", 1}, {"algorithm", "dda-line"}, {"numeric", "double"},
                       {"input", {{"p0", {p0x, p0y}}, {"p1", {p1x, p1y}}}}};
  const auto dir = sw::testing::scratch("student");
  const auto t = (dir / "student.jsonl").string();
  auto write = [&] {
    std::ofstream f(t, std::ios::trunc);
    f << header.dump() << '\n';
    for (const Json& s : steps) f << s.dump() << '\n';
    f << Json{{"result", {{"pixels", pixels}}}}.dump() << '\n';
  };
  write();
  const auto ok = run_stepwise("check " + sh_quote(t));
  CHECK(ok.status == 0);
  INFO(ok.err);
  // One wrong pixel: exit 1 at that step, naming the geometry item.
  steps[15]["geo"][0]["pixel"][1] = steps[15]["geo"][0]["pixel"][1].get<int>() + 1;
  write();
  const auto bad = run_stepwise("check " + sh_quote(t));
  CHECK(bad.status == 1);
  CHECK_THAT(bad.err, Catch::Contains("step 15 diverges") && Catch::Contains("geo[0].pixel"));
}

TEST_CASE("cli: run answers one line per input, equal to the trace results", "[cli]") {
  const auto dir = sw::testing::scratch("run");
  const auto inputs = dir / "in.jsonl";
  std::ofstream(inputs) << "{\"p0\":[0,0],\"p1\":[5,2]}\n\n{\"p0\":[3,3],\"p1\":[-4,1]}\n{\"p0\":[1,1],\"p1\":[1,1]}\n";
  const auto r = run_stepwise("run bresenham-line --numeric int --inputs " + sh_quote(inputs.string()));
  REQUIRE(r.status == 0);
  const auto results = json_lines(r.out);
  REQUIRE(results.size() == 3);
  CHECK(results[0]["pixels"] == Json::parse("[[0,0],[1,0],[2,1],[3,1],[4,2]]"));
  CHECK(results[2]["pixels"].empty());
  const auto t = run_stepwise("trace bresenham-line --numeric int --input '{\"p0\":[3,3],\"p1\":[-4,1]}'");
  REQUIRE(t.status == 0);
  CHECK(json_lines(t.out).back()["result"] == results[1]);
}

TEST_CASE("cli: bench --json prints one object per mode and set", "[cli]") {
  const auto r = run_stepwise("bench bresenham-line --json --numeric int --numeric double --repeats 1 --set random");
  REQUIRE(r.status == 0);
  const auto rows = json_lines(r.out);
  REQUIRE(rows.size() == 2);  // 2 modes x the random set
  for (const auto& row : rows) {
    CHECK(row["ns_per_op"].get<double>() > 0);
    CHECK(row["cases"].get<int>() > 0);
    CHECK(row.contains("mismatches"));
    if (row["numeric"] == "int") CHECK(row["mismatches"] == 0);
  }
}

TEST_CASE("cli: bench --full runs every case, the default at most kQuickCases a set", "[cli][bench]") {
  const std::string args = "bench bresenham-line --json --numeric int --repeats 1 --set random";
  const auto quick = run_stepwise(args), full = run_stepwise(args + " --full");
  REQUIRE(quick.status == 0);
  REQUIRE(full.status == 0);
  const auto q = json_lines(quick.out), f = json_lines(full.out);
  REQUIRE(q.size() == 1);
  REQUIRE(f.size() == 1);
  const auto quick_cases = q[0]["cases"].get<std::size_t>(), full_cases = f[0]["cases"].get<std::size_t>();
  CHECK(quick_cases == BenchOptions::kQuickCases);
  CHECK(full_cases > quick_cases);
  CHECK(q[0]["full_cases"] == full_cases);  // the default says what it left out
  CHECK(f[0]["full_cases"] == full_cases);
  CHECK(q[0]["compared_with"] == "exact");
}

TEST_CASE("cli: bench names its units and the judge it compared with, exact or reference", "[cli][bench]") {
  struct Case {
    const char *alg, *judge, *not_judge, *unit;
  };
  // ray-sphere-stable has exact rationals; camera-ray has no exact mode: its judge is the 300-bit reference.
  for (const Case& c : {Case{"ray-sphere-stable", "exact", "reference", "ulps of t"}, Case{"camera-ray", "reference", "exact", "ulps"}}) {
    INFO(c.alg);
    const auto text = run_stepwise(std::string("bench ") + c.alg + " --repeats 1 --numeric float --numeric double --set random");
    REQUIRE(text.status == 0);
    CHECK_THAT(text.out, Catch::Contains("time per output unit (ns)") && Catch::Contains("ns/op (ns)"));
    CHECK_THAT(text.out, Catch::Contains(std::string("differs from ") + c.judge + " (cases)"));
    CHECK_THAT(text.out, Catch::Contains(std::string("max error (") + c.unit + ")"));
    CHECK_THAT(text.out, !Catch::Contains(std::string("from ") + c.not_judge));
    const auto json = run_stepwise(std::string("bench ") + c.alg + " --json --repeats 1 --numeric float --set random");
    REQUIRE(json.status == 0);
    const auto rows = json_lines(json.out);
    REQUIRE(rows.size() == 1);
    CHECK(rows[0]["compared_with"] == c.judge);
    CHECK(rows[0]["max_error_unit"] == c.unit);
    CHECK(rows[0].contains("max_error"));  // the keys of before stay
  }
}

TEST_CASE("cli: bench writes no progress off a terminal", "[cli][bench]") {
  const auto r = run_stepwise("bench bresenham-line --repeats 1 --set random");  // stderr is a file here
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  CHECK_THAT(r.out, Catch::StartsWith("bresenham-line: "));
}

TEST_CASE("cli: bench draws its progress line on a terminal and clears it", "[cli][bench]") {
  // script(1) (bsdutils, essential in Debian) gives the command a terminal and copies what it shows.
  const auto dir = sw::testing::scratch("tty");
  const std::string inner = sh_quote(SW_STEPWISE_EXE) + " bench bresenham-line --repeats 1 --set random >/dev/null";
  const std::string cmd = "script -qec " + sh_quote(inner) + " /dev/null >" + sh_quote((dir / "tty").string()) + " 2>&1 </dev/null";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const std::string shown = sw::testing::slurp(dir / "tty");
  CHECK_THAT(shown, Catch::StartsWith("\rbench bresenham-line: set random, "));  // the first report is always drawn
  CHECK_THAT(shown, Catch::EndsWith("\r\x1b[K"));                               // and the line is cleared at the end
  CHECK(shown.find('\n') == std::string::npos);
}

TEST_CASE("cli: the bench progress line names algorithm, mode, set and cases", "[cli][bench]") {
  const std::string timing = bench_progress_text("dda-line", {"long", Numeric::f32, false, 128, 192});
  CHECK(timing == "bench dda-line: set long, float: 128/192 case runs");
  const std::string judging = bench_progress_text("camera-ray", {"random", Numeric::reference, true, 3, 64});
  CHECK(judging == "bench camera-ray: set random, reference outputs to compare with: 3/64 cases");
  CHECK(judging.find('\n') == std::string::npos);
}

TEST_CASE("cli: bench_cases keeps at most the cap, evenly spaced and in order", "[cli][bench]") {
  std::vector<int> all(1000);
  for (int i = 0; i < 1000; ++i) all[std::size_t(i)] = i;
  const std::vector<int> cut = bench_cases(std::vector<int>(all), 64);
  REQUIRE(cut.size() == 64);
  CHECK(cut.front() == 0);
  CHECK(cut.back() >= 1000 - 1000 / 64 - 1);  // reaches the end of the set (its hard cases too)
  CHECK(std::is_sorted(cut.begin(), cut.end()));
  CHECK(std::adjacent_find(cut.begin(), cut.end()) == cut.end());
  CHECK(bench_cases(std::vector<int>(all), 0).size() == 1000);  // 0: every case
  CHECK(bench_cases(std::vector<int>(all.begin(), all.begin() + 10), 64).size() == 10);
}

TEST_CASE("cli: bad input is one line, exit 2, and no output file", "[cli][errors]") {
  const auto dir = sw::testing::scratch("bad");
  const auto out = dir / "never.jsonl";
  const std::string ok_seg = "'{\"p0\":[0,0],\"p1\":[3,1]}'";
  struct Case {
    const char* what;
    std::string args;
    const char* says;
  };
  const std::vector<Case> cases = {
      {"malformed JSON", "trace dda-line --input '{\"p0\":[0,0],' ", "malformed JSON"},
      {"NaN as a string", "trace dda-line --input '{\"p0\":[\"nan\",0],\"p1\":[1,1]}'", "not a finite number"},
      {"overflow to infinity", "trace dda-line --input '{\"p0\":[1e999,0],\"p1\":[1,1]}'", "overflow"},
      {"missing field", "trace dda-line --input '{\"p0\":[0,0]}'", "missing field \"p1\""},
      {"unknown field", "trace dda-line --input '{\"p0\":[0,0],\"p1\":[1,1],\"p2\":[2,2]}'", "unknown field \"p2\""},
      {"wrong arity", "trace dda-line --input '{\"p0\":[0,0,0],\"p1\":[1,1]}'", "array of 2"},
      {"not a number", "trace dda-line --input '{\"p0\":[\"abc\",0],\"p1\":[1,1]}'", "not a number"},
      {"zero denominator", "trace dda-line --input '{\"p0\":[\"1/0\",0],\"p1\":[1,1]}'", "zero denominator"},
      {"unknown algorithm", "trace dda-lines --input " + ok_seg, "unknown algorithm 'dda-lines'"},
      {"unknown numeric mode", "trace dda-line --numeric quad --input " + ok_seg, "unknown numeric mode 'quad'"},
      {"mode the algorithm lacks", "trace dda-line --numeric int --input " + ok_seg, "does not run on 'int'"},
      {"beyond the bound", "trace dda-line --input '{\"p0\":[0,0],\"p1\":[16777217,1]}'", "beyond the bound"},
      {"int mode, fractional", "trace bresenham-line --numeric int --input '{\"p0\":[0,0.5],\"p1\":[3,1]}'", "not an integer"},
      {"bresenham, fractional", "trace bresenham-line --numeric exact --input '{\"p0\":[\"1/3\",0],\"p1\":[3,1]}'", "not an integer"},
      {"missing input file", "trace dda-line --input /nonexistent/in.json", "cannot read input file"},
      {"unknown option", "trace dda-line --input " + ok_seg + " --bogus 1", "--bogus"},
      {"no bench set", "bench dda-line --set nosuch", "no bench set named 'nosuch'"},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    const bool writes = c.args.rfind("trace", 0) == 0;
    const auto r = run_stepwise(c.args + (writes ? " --out " + sh_quote(out.string()) : ""));
    CHECK(r.status == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.find(c.says) != std::string::npos);
    CHECK(r.out.empty());
    CHECK(!std::filesystem::exists(out));
    CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 0);
  }
  // run: a bad line anywhere means no output at all, and the line is named.
  const auto inputs = dir / "in.jsonl";
  std::ofstream(inputs) << "{\"p0\":[0,0],\"p1\":[5,2]}\n{\"p0\":[0,0],\"p1\":[5]}\n";
  const auto r = run_stepwise("run dda-line --inputs " + sh_quote(inputs.string()) + " --out " + sh_quote(out.string()));
  CHECK(r.status == 2);
  CHECK(r.err.find("line 2") != std::string::npos);
  CHECK(!std::filesystem::exists(out));
  // check: malformed or truncated traces are exit 2.
  std::ofstream(dir / "t.jsonl") << "{\"format\":\"stepwise-trace\",\"version\":1,\"algorithm\":\"dda-line\",\"numeric\":\"exact\",\"input\":{\"p0\":[0,0],\"p1\":[2,1]}}\n{\"step\":0,";
  CHECK(run_stepwise("check " + sh_quote((dir / "t.jsonl").string())).status == 2);
  std::ofstream(dir / "t.jsonl", std::ios::trunc) << "{\"format\":\"stepwise-trace\",\"version\":1,\"algorithm\":\"dda-line\",\"numeric\":\"exact\",\"input\":{\"p0\":[0,0],\"p1\":[2,1]}}\n";
  const auto trunc = run_stepwise("check " + sh_quote((dir / "t.jsonl").string()));
  CHECK(trunc.status == 2);
  CHECK(trunc.err.find("no result line") != std::string::npos);
  CHECK(run_stepwise("check /nonexistent.jsonl").status == 2);
}

TEST_CASE("cli: check refuses a trace nested 10^5 levels deep with exit 2 and one line", "[cli]") {
  const auto dir = sw::testing::scratch("deep");
  const auto t = (dir / "deep.jsonl").string();
  REQUIRE(run_stepwise("trace dda-line --input '{\"p0\":[0,0],\"p1\":[3,1]}' --numeric exact --out " + sh_quote(t)).status == 0);
  auto text = sw::testing::slurp(t);
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  // Replace the first step's vars with a deeply nested value, and separately the result.
  for (const std::string& where : {std::string("\"vars\":{"), std::string("{\"result\":")}) {
    std::string bad = text;
    const auto at = where[1] == 'v' ? bad.find(where) : bad.rfind(where);
    REQUIRE(at != std::string::npos);
    bad.insert(at + where.size(), where[1] == 'v' ? "\"x\":" + deep + "," : "{\"deep\":" + deep + "},\"r\":");
    std::ofstream(t, std::ios::trunc) << bad;
    const auto r = run_stepwise("check " + sh_quote(t));
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("nested more than 64"));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
}
