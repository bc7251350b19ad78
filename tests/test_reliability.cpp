// The reproducers of the reliability issue, through the real binary: inputs that used to be
// accepted or crash are one line and exit 2; a result with NaN or an infinity is valid JSON that
// says the mode failed and that `check` reads; --out follows symbolic links, writes through FIFOs
// and devices, refuses directories; SIGTERM leaves no temporary behind.
#include <catch2/catch.hpp>
#include <csignal>
#include <fstream>
#include <set>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include "catalog.hpp"
#include "lighting/model_table.hpp"
#include "cli_harness.hpp"
#include "input.hpp"

using namespace sw::testing;

namespace {

std::size_t lines_in(const std::string& s) { return std::size_t(std::count(s.begin(), s.end(), '\n')); }

std::size_t entries(const std::filesystem::path& dir) {
  return std::size_t(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()));
}

}  // namespace

TEST_CASE("reliability: inputs that were accepted or echoed raw are one line and exit 2", "[cli][errors][reliability]") {
  const auto dir = scratch("reliable");
  const auto out = dir / "never.jsonl";
  std::ofstream(dir / "nul.json", std::ios::binary) << std::string("{\"p0\":[0,0],\"p1\":[3,1]}\0garbage", 32);
  std::ofstream(dir / "deep.json") << std::string(100000, '[') << std::string(100000, ']');
  std::filesystem::create_directory(dir / "adir");
  const std::string long_name(1 << 20, 'x');
  std::ofstream(dir / "long.json") << "{\"" << long_name << "\":1}";
  struct Case {
    const char* what;
    std::string args;
    const char* says;
  };
  const std::vector<Case> cases = {
      {"a directory of inputs", "run dda-line --inputs " + sh_quote((dir / "adir").string()), "is a directory"},
      {"a directory as input", "trace dda-line --input " + sh_quote((dir / "adir").string()), "is a directory"},
      {"a NUL byte, then garbage", "trace dda-line --input " + sh_quote((dir / "nul.json").string()), "NUL byte at offset 23"},
      {"nested 10^5 deep", "trace dda-line --input " + sh_quote((dir / "deep.json").string()), "nested more than 64 levels"},
      {"a duplicate key", "trace dda-line --input '{\"p0\":[0,0],\"p0\":[1,1],\"p1\":[3,1]}'", "duplicate key \"p0\""},
      {"1e400", "trace dda-line --input '{\"p0\":[0,0],\"p1\":[1e400,1]}'", "overflows double"},
      {"a newline in a name", "trace 'dda\nline' --input '{}'", "unknown algorithm 'dda\\nline'"},
      {"a megabyte key", "trace dda-line --input " + sh_quote((dir / "long.json").string()), "unknown field \"xxxx"},
      {"a directory as --out", "trace dda-line --input '{\"p0\":[0,0],\"p1\":[3,1]}' --out " + sh_quote((dir / "adir").string()), "is a directory"},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    const bool writes = c.args.find("--out") == std::string::npos && (c.args.rfind("trace", 0) == 0 || c.args.rfind("run", 0) == 0);
    const auto r = run_stepwise(c.args + (writes ? " --out " + sh_quote(out.string()) : ""));
    CHECK(r.status == 2);
    CHECK(lines_in(r.err) == 1);
    CHECK(r.err.size() < 1200);  // a megabyte of echoed input is cut
    CHECK(r.err.find(c.says) != std::string::npos);
    CHECK(r.out.empty());
    CHECK(!std::filesystem::exists(out));
  }
  CHECK(entries(dir) == 4);  // the inputs above, nothing else
}

TEST_CASE("reliability: NaN and infinities are strings in valid JSON, the mode reports its failure, and check reads it", "[cli][reliability]") {
  const auto dir = scratch("nonfinite");
  const auto trace = dir / "t.jsonl";
  // A direction of 1e-300 in double: d.d underflows to 0 and t comes out infinite.
  const auto r = run_stepwise("trace ray-sphere-quadratic --numeric double --input '{\"ray\":{\"o\":[0,0,0],\"d\":[1e-300,0,0]},\"sphere\":{\"c\":[5,0,0],\"r\":1}}' --out " +
                              sh_quote(trace.string()));
  REQUIRE(r.status == 0);
  std::ifstream in(trace);
  std::string line, last;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    INFO("line " << n << ": " << line);
    CHECK_NOTHROW(sw::Json::parse(line));  // strict JSON: no bare nan or inf
    CHECK(line.find("nan") == std::string::npos);
    last = line, ++n;
  }
  const sw::Json result = sw::Json::parse(last)["result"];
  CHECK(result["hit"] == true);
  CHECK(result["t"] == "Infinity");
  CHECK(result["failure"] == "t-not-finite-positive");
  const auto c = run_stepwise("check " + sh_quote(trace.string()));
  CHECK(c.status == 1);  // read, replayed, and found to diverge from exact: never "malformed"
  CHECK(lines_in(c.err) == 2);  // the divergence, then the step before it
  CHECK(c.err.find("\n  after step ") != std::string::npos);
  // A mapping that underflows in float: NaN values, and the generic failure.
  std::ofstream(dir / "in.jsonl") << "{\"sphere\":{\"c\":[0,0,0],\"r\":1e-300},\"point\":[1e-300,0,0]}\n";
  const auto m = run_stepwise("run sphere-uv --numeric float --inputs " + sh_quote((dir / "in.jsonl").string()));
  REQUIRE(m.status == 0);
  const sw::Json uv = sw::Json::parse(m.out);
  CHECK(uv["u"] == "NaN");
  CHECK(uv["failure"] == "nan-or-inf");
}

TEST_CASE("reliability: --out follows a symbolic link, writes through a FIFO and a device", "[cli][reliability][out]") {
  const auto dir = scratch("outs");
  const std::string seg = " --input '{\"p0\":[0,0],\"p1\":[3,1]}'";
  std::ofstream(dir / "real.jsonl") << "old\n";
  std::filesystem::create_symlink("real.jsonl", dir / "link.jsonl");
  REQUIRE(run_stepwise("trace dda-line" + seg + " --out " + sh_quote((dir / "link.jsonl").string())).status == 0);
  CHECK(std::filesystem::is_symlink(dir / "link.jsonl"));  // the link stays a link
  CHECK(slurp(dir / "real.jsonl").rfind("{\"format\":\"stepwise-trace\"", 0) == 0);
  // A FIFO: written through, still a FIFO afterwards.
  const auto fifo = dir / "fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string got;
  std::thread reader([&] {
    std::ifstream f(fifo);
    got.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  });
  const auto r = run_stepwise("trace dda-line" + seg + " --out " + sh_quote(fifo.string()));
  reader.join();
  CHECK(r.status == 0);
  CHECK(lines_in(got) == 14);  // header, 12 steps, result
  CHECK(std::filesystem::is_fifo(fifo));
  CHECK(run_stepwise("trace dda-line" + seg + " --out /dev/null").status == 0);
  CHECK(entries(dir) == 3);  // real, link, fifo: no temporaries
}

TEST_CASE("reliability: SIGTERM during a long write leaves no temporary file", "[cli][reliability][out]") {
  const auto dir = scratch("sigterm");
  const auto out = dir / "long.jsonl";
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    ::execl(SW_STEPWISE_EXE, SW_STEPWISE_EXE, "trace", "dda-grid-walk", "--input", "{\"p0\":[0,0],\"p1\":[16000000,7000001]}", "--max-steps", "100000000", "--out", out.c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Wait until the temporary exists, then stop the process.
  bool seen = false;
  for (int k = 0; k < 400 && !seen; ++k) {
    for (const auto& e : std::filesystem::directory_iterator(dir)) seen = seen || e.path().string().find(".tmp-") != std::string::npos;
    if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  CHECK(seen);
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  CHECK(entries(dir) == 0);
}

TEST_CASE("reliability: the work budget refuses what it estimates too large, and the output budget leaves no file", "[cli][reliability][budget]") {
  const auto dir = scratch("budget");
  const auto out = dir / "never.jsonl";
  const std::string longest = "'{\"p0\":[-16777216,-16777215.75],\"p1\":[16777216,16777215.5]}'";
  const auto t = run_stepwise("trace dda-grid-walk --numeric float --input " + longest + " --out " + sh_quote(out.string()));
  CHECK(t.status == 2);
  CHECK(lines_in(t.err) == 1);
  CHECK(t.err.find("201326608 steps, more than the budget of 4000000 (--max-steps raises it)") != std::string::npos);
  std::ofstream(dir / "in.jsonl") << "{\"p0\":[0,0],\"p1\":[3,1]}\n" << longest.substr(1, longest.size() - 2) << "\n";
  const auto r = run_stepwise("run dda-grid-walk --inputs " + sh_quote((dir / "in.jsonl").string()) + " --out " + sh_quote(out.string()));
  CHECK(r.status == 2);
  CHECK(r.err.find("line 2: this input implies") != std::string::npos);
  // Raised, the same kind of input runs.
  CHECK(run_stepwise("trace dda-grid-walk --input '{\"p0\":[0,0],\"p1\":[3000000,2000000]}' --max-steps 20000000 --max-output 1000 --out " + sh_quote(out.string())).err.find(
            "the output passes the budget of 1000 bytes (--max-output raises it)") != std::string::npos);
  CHECK(entries(dir) == 1);  // in.jsonl only: no output, no temporary
  CHECK(run_stepwise("trace dda-grid-walk --input '{\"p0\":[0,0],\"p1\":[30,20]}' --out " + sh_quote(out.string())).status == 0);
}

TEST_CASE("reliability: long exact numbers weigh every step, in run, trace and check", "[cli][reliability][budget]") {
  const auto dir = scratch("digits");
  // Exact strings of up to 4008 characters over one 2001-digit denominator, p1 about 330000 cells away.
  const std::string den = "1" + std::string(1999, '0') + "7";
  auto coord = [&](const std::string& whole) { return "\"" + whole + std::string(2000, '0') + "/" + den + "\""; };
  const std::string input = "{\"p0\":[" + coord("1") + "," + coord("2") + "],\"p1\":[" + coord("200000") + "," + coord("130000") + "]}";
  std::ofstream(dir / "in.json") << input;
  const std::string in = sh_quote((dir / "in.json").string());
  const auto exact = run_stepwise("run dda-grid-walk --numeric exact --inputs " + in);
  CHECK(exact.status == 2);
  CHECK(lines_in(exact.err) == 1);
  CHECK(exact.err.find("steps x 11 for exact numbers of 4008 characters, more than the budget of 4000000") != std::string::npos);
  // Rounded modes convert the numbers once: the same input is within the budget.
  CHECK(run_stepwise("run dda-grid-walk --numeric double --inputs " + in).status == 0);
  // check replays in exact: a trace whose header holds the input is refused before the replay.
  std::ofstream(dir / "t.jsonl") << "{\"format\":\"stepwise-trace\",\"version\":2,\"algorithm\":\"dda-grid-walk\",\"numeric\":\"double\",\"input\":" << input
                                 << "}\n{\"result\":{}}\n";
  const auto c = run_stepwise("check " + sh_quote((dir / "t.jsonl").string()));
  CHECK(c.status == 2);
  CHECK(c.err.find("more than the budget of 4000000") != std::string::npos);
}

TEST_CASE("reliability: a dear mode's steps count for more against the budget", "[cli][reliability][budget]") {
  // gouraud-vs-phong's widest triangle: about 10^5 steps, each 256 units in reference (docs/cli.md).
  sw::Json in = sw::parse_json_text(sw::find_algorithm("gouraud-vs-phong").example, "example");
  in["vertices"][1]["xy"] = sw::Json::array({64, 1});
  in["vertices"][2]["xy"] = sw::Json::array({5, 64});
  const std::string arg = sh_quote(in.dump());
  const auto ref = run_stepwise("trace gouraud-vs-phong --numeric reference --input " + arg + " --out /dev/null");
  CHECK(ref.status == 2);
  CHECK(lines_in(ref.err) == 1);
  CHECK(ref.err.find("steps x 256 for gouraud-vs-phong's steps in reference, more than the budget of 4000000") != std::string::npos);
  CHECK(run_stepwise("trace gouraud-vs-phong --numeric double --input " + arg + " --out /dev/null").status == 0);
  CHECK(run_stepwise("trace gouraud-vs-phong --numeric reference --max-steps 40000000 --max-output 100 --input " + arg + " --out /dev/null")
            .err.find("the output passes the budget of 100 bytes") != std::string::npos);
}

TEST_CASE("reliability: an algorithm without a step estimate runs a few steps, whatever its input", "[reliability][budget]") {
  // The budget can only refuse what an algorithm estimates (docs/cli.md). Those without an estimate
  // are the ones whose step count is constant (one ray, one reflection model) or bounded when parsed
  // (bsp: 4096 segments and a fragment bound; shade: 8 lights): a new algorithm with a loop over
  // its input must declare estimate_steps, and this list must not grow by accident.
  std::set<std::string> constant = {"ray-plane", "ray-sphere-geometric", "ray-sphere-quadratic", "ray-sphere-stable", "ray-box",
                                    "ray-triangle-barycentric", "ray-triangle-mt", "ray-triangle-watertight", "camera-ray", "sphere-uv"};
  for (const sw::lighting_io::ModelRow& r : sw::lighting_io::model_table()) constant.insert(std::string(r.id));  // one light, one term
  const std::set<std::string> parse_bounded = {"bsp-build", "bsp-painter", "shade"};
  for (const sw::Algorithm& a : sw::catalog()) {
    const std::string id(a.id);
    INFO(id);
    if (a.open(sw::parse_json_text(a.example, "example")).estimate_steps()) {
      CHECK(constant.count(id) + parse_bounded.count(id) == 0);
      continue;
    }
    REQUIRE(constant.count(id) + parse_bounded.count(id) == 1);
    if (!constant.count(id)) continue;
    const sw::Json input = sw::parse_json_text(a.example, "example");
    for (sw::Numeric n : a.numerics) CHECK(a.open(input, n).record().trace->size() <= 40);
  }
}

TEST_CASE("reliability: lines are read with a bound, as getline reads them below it", "[reliability]") {
  const std::string text = "a\n\n" + std::string(200000, 'b') + "\nlast";
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> got;
  while (sw::read_line(in, line, 300000, "t")) got.push_back(line);
  REQUIRE(got.size() == 4);
  CHECK(got[0] == "a");
  CHECK(got[1].empty());
  CHECK(got[2] == std::string(200000, 'b'));
  CHECK(got[3] == "last");
  std::istringstream in2(text);
  CHECK(sw::read_line(in2, line, 100, "t"));
  CHECK(sw::read_line(in2, line, 100, "t"));
  CHECK_THROWS_WITH(sw::read_line(in2, line, 100000, "trace line 3"), "trace line 3: a line of more than 100000 bytes");
}
