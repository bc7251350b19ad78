// How strict `check` is: every kind of field tampered with, one at a time, fails at the right step
// and names the field; legitimate variation (key order, number spelling, rounding within the
// trace's tolerance) passes.
#include <catch2/catch.hpp>
#include <algorithm>
#include <sstream>
#include "catalog.hpp"
#include "trace_io.hpp"

using namespace sw;

namespace {

std::vector<Json> trace_lines(const char* alg, const char* input, Numeric n) {
  std::stringstream s;
  write_trace(find_algorithm(alg).open(Json::parse(input), n), s);
  std::vector<Json> out;
  std::string line;
  while (std::getline(s, line)) out.push_back(Json::parse(line));
  return out;
}

CheckReport check(const std::vector<Json>& lines, bool decisions_only = false) {
  std::stringstream s;
  for (const Json& l : lines) s << l.dump() << '\n';
  return check_trace(s, decisions_only ? CheckScope::decisions : CheckScope::everything);
}

// The index (in `lines`) of the first step with this kind that records `var`.
std::size_t find_step(const std::vector<Json>& lines, const char* kind, const char* var) {
  for (std::size_t i = 1; i + 1 < lines.size(); ++i)
    if (lines[i]["kind"] == kind && lines[i]["vars"].contains(var)) return i;
  FAIL("no " << kind << " step with " << var);
  return 0;
}

void require_diverges(const std::vector<Json>& lines, std::size_t step, const std::string& field, bool decisions_only = false) {
  const CheckReport r = check(lines, decisions_only);
  INFO(r.message);
  CHECK(r.status == 1);
  CHECK_THAT(r.message, Catch::StartsWith("step " + std::to_string(step) + " diverges"));
  if (!field.empty()) CHECK_THAT(r.message, Catch::Contains(field));
}

const char* kDda = R"({"p0":["1/3",1],"p1":[9,"7/2"]})";

// The trace with its result line written as `result` (text: as another program may space and order it).
CheckReport check_with_result(const std::vector<Json>& lines, const std::string& result, CheckScope scope = CheckScope::everything) {
  std::stringstream s;
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) s << lines[i].dump() << '\n';
  s << result << '\n';
  return check_trace(s, scope);
}

// JSON text as Python's json.dumps spaces it, for values without strings (", " and ": ").
std::string spaced(const Json& j) {
  std::string t;
  for (char c : j.dump()) t += c == ',' ? ", " : c == ':' ? ": " : std::string(1, c);
  return t;
}

}  // namespace

TEST_CASE("check: the untampered exact trace agrees", "[check]") {
  for (const char* alg : {"dda-line", "circle-midpoint", "poly-forward-diff", "bezier-forward-diff"}) {
    INFO(alg);
    const Algorithm& a = find_algorithm(alg);
    const auto lines = trace_lines(alg, alg == std::string("dda-line") ? kDda : a.example.c_str(), Numeric::exact);
    CHECK(check(lines).status == 0);
  }
}

TEST_CASE("check: a numeric variable tampered fails and only with values compared", "[check]") {
  auto lines = trace_lines("dda-line", kDda, Numeric::exact);
  const std::size_t i = find_step(lines, "plot", "qy");
  lines[i]["vars"]["qy"] = Rational(parse_rational(lines[i]["vars"]["qy"], "") + Rational(1, 1000)).get_str();
  require_diverges(lines, i - 1, "variable qy");
  CHECK(check(lines, true).status == 0);  // --decisions-only ignores numbers
}

TEST_CASE("check: an integer variable tampered fails even with --decisions-only", "[check]") {
  auto lines = trace_lines("dda-line", kDda, Numeric::exact);
  const std::size_t i = find_step(lines, "plot", "j");
  lines[i]["vars"]["j"] = lines[i]["vars"]["j"].get<int>() + 1;
  require_diverges(lines, i - 1, "variable j");
  require_diverges(lines, i - 1, "variable j", true);
}

TEST_CASE("check: each geometry kind tampered fails at its step", "[check]") {
  struct Case {
    const char *alg, *kind;
    bool decision;
  };
  for (const Case& c : {Case{"dda-line", "pixel", true}, Case{"dda-line", "point", false}, Case{"dda-line", "segment", false},
                        Case{"circle-midpoint", "circle", false}, Case{"poly-forward-diff", "polyline", false},
                        Case{"bezier-forward-diff", "segment", false}}) {
    INFO(c.alg << " " << c.kind);
    const Algorithm& a = find_algorithm(c.alg);
    auto lines = trace_lines(c.alg, c.alg == std::string("dda-line") ? kDda : a.example.c_str(), Numeric::exact);
    std::size_t at = 0;
    for (std::size_t i = 1; i + 1 < lines.size() && !at; ++i)
      for (Json& g : lines[i]["geo"])
        if (g.contains(c.kind) && !at) {
          Json& v = g[c.kind][0];
          v = v.is_number_integer() ? Json(v.get<int>() + 1) : Json(Rational(parse_rational(v, "") + 1).get_str());
          at = i;
        }
    REQUIRE(at > 0);
    require_diverges(lines, at - 1, std::string(".") + c.kind);
    CHECK(check(lines, true).status == (c.decision ? 1 : 0));
  }
}

TEST_CASE("check: a step added, removed or swapped fails at that step", "[check]") {
  const auto good = trace_lines("dda-line", kDda, Numeric::exact);
  const std::size_t i = find_step(good, "plot", "qy");
  auto added = good;
  added.insert(added.begin() + static_cast<long>(i), good[i]);
  require_diverges(added, i, "");
  auto removed = good;
  removed.erase(removed.begin() + static_cast<long>(i));
  require_diverges(removed, i - 1, "");
  auto swapped = good;
  std::swap(swapped[i], swapped[i + 1]);
  require_diverges(swapped, i - 1, "");
  auto truncated = good;
  truncated.erase(truncated.end() - 2);  // the last step
  CHECK(check(truncated).status == 1);
}

TEST_CASE("check: a tampered result fails and names it", "[check]") {
  auto lines = trace_lines("dda-line", kDda, Numeric::exact);
  lines.back()["result"]["pixels"][2][1] = lines.back()["result"]["pixels"][2][1].get<int>() + 1;
  const CheckReport r = check(lines);
  CHECK(r.status == 1);
  CHECK_THAT(r.message, Catch::StartsWith("result diverges") && Catch::Contains("result.pixels[2][1]"));
  CHECK(check(lines, true).status == 1);  // pixels are decisions
}

TEST_CASE("check: key order and number spelling are legitimate variation", "[check]") {
  auto lines = trace_lines("dda-line", kDda, Numeric::exact);
  std::size_t respelled = 0;
  for (std::size_t i = 1; i + 1 < lines.size(); ++i) {
    // Rebuild vars in reverse key order, numbers as decimals where exact ("1/2" -> 0.5).
    Json vars = Json::object();
    std::vector<std::string> keys;
    for (auto it = lines[i]["vars"].begin(); it != lines[i]["vars"].end(); ++it) keys.push_back(it.key());
    for (auto k = keys.rbegin(); k != keys.rend(); ++k) {
      const Json& v = lines[i]["vars"][*k];
      const bool dyadic = v.is_string() && mpz_popcount(parse_rational(v, "").get_den_mpz_t()) == 1;
      vars[*k] = dyadic ? Json(parse_rational(v, "").get_d()) : v;
      respelled += dyadic;
    }
    Json step = Json::object();  // also a different member order
    step["geo"] = lines[i]["geo"];
    step["vars"] = vars;
    step["kind"] = lines[i]["kind"];
    step["line"] = lines[i]["line"];
    step["step"] = lines[i]["step"];
    lines[i] = step;
  }
  CHECK(respelled > 10);
  const CheckReport r = check(lines);
  INFO(r.message);
  CHECK(r.status == 0);
}

TEST_CASE("check: a vector variable's component tampered fails and names it", "[check]") {
  const Algorithm& a = find_algorithm("bezier-forward-diff");
  auto lines = trace_lines("bezier-forward-diff", a.example.c_str(), Numeric::exact);
  const std::size_t i = find_step(lines, "init", "d1");
  REQUIRE(lines[i]["vars"]["d1"].is_array());
  lines[i]["vars"]["d1"][1] = Rational(parse_rational(lines[i]["vars"]["d1"][1], "") + 1).get_str();
  require_diverges(lines, i - 1, "variable d1[1]");
  CHECK(check(lines, true).status == 0);
  lines[i]["vars"]["d1"] = Json::array({1, 2, 3, 4});  // a list of 4 is well formed, but not this variable
  require_diverges(lines, i - 1, "variable d1");
  lines[i]["vars"]["d1"] = Json(std::vector<int>(kMaxListLength + 1, 0));
  CHECK(check(lines).status == 2);  // longer than any list variable: malformed
}

TEST_CASE("check: a geometry item's label, lifetime or value tampered fails and naming none passes", "[check]") {
  // ray-box's running interval: {"segment3":[...],"label":"[t_near, t_far]","value":...,"life":"replace"}.
  const char* box = R"({"ray":{"o":[-3,0.5,0.5],"d":[1,0.125,0.0625]},"box":{"min":[0,0,0],"max":[1,1,1]}})";
  const auto lines = trace_lines("ray-box", box, Numeric::exact);
  const std::size_t i = find_step(lines, "advance", "t_near");
  REQUIRE(lines[i]["geo"].size() == 2);
  REQUIRE(lines[i]["geo"][1].contains("value"));
  for (const char* key : {"label", "life", "value"}) {
    INFO(key);
    auto t = lines;
    Json& item = t[i]["geo"][1];
    item[key] = std::string(key) == "value" ? Json(Rational(parse_rational(item[key], "") + 1).get_str()) : Json(std::string(key) == "life" ? "keep" : "[t0, t1]");
    require_diverges(t, i - 1, std::string("geo[1].") + key);
    CHECK(check(t, true).status == (std::string(key) == "value" ? 0 : 1));  // a value is a number; label and life are not
    // A trace need not state them at all (a hand-written one), but what it states must be known.
    t = lines;
    t[i]["geo"][1].erase(key);
    CHECK(check(t).status == 0);
  }
  auto t = lines;
  t[i]["geo"][0]["life"] = "forever";
  CHECK(check(t).status == 2);
  t = lines;
  t[i]["geo"][0]["colour"] = "red";  // a second kind key: not an item
  CHECK(check(t).status == 2);
}

TEST_CASE("check: a float trace's numbers are held to 2^-10 (1 + |exact|): within passes, beyond fails, near 0 too", "[check]") {
  // The tolerance the kit defines for float: |got - exact| <= 2^-10 (1 + |exact|), so a value that
  // is 0 exactly may be off by 2^-10 and no more.
  auto shifted = [](std::vector<Json> lines, std::size_t i, const char* var, int exponent) {
    const Rational w = parse_rational(lines[i]["vars"][var], "");
    const Rational step = Rational(1 + abs(w)) / Rational(mpz_class(1) << exponent);
    lines[i]["vars"][var] = Rational(w + step).get_str();
    return lines;
  };
  const auto lines = trace_lines("dda-line", kDda, Numeric::f32);
  REQUIRE(check(lines).status == 0);
  const std::size_t i = find_step(lines, "plot", "qy");
  CHECK(check(shifted(lines, i, "qy", 12)).status == 0);
  require_diverges(shifted(lines, i, "qy", 8), i - 1, "variable qy");
  const auto flat = trace_lines("dda-line", R"({"p0":[0,0],"p1":[10,0]})", Numeric::f32);
  const std::size_t d = find_step(flat, "init", "dy");
  REQUIRE(parse_rational(flat[d]["vars"]["dy"], "") == 0);
  CHECK(check(shifted(flat, d, "dy", 12)).status == 0);
  require_diverges(shifted(flat, d, "dy", 8), d - 1, "variable dy");
  // Just beyond: 1.5 x 2^-10 off a 0 fails too (a tolerance of 2^-10 (2 + |exact|) would pass it).
  std::vector<Json> just = flat;
  just[d]["vars"]["dy"] = Rational(3, 2048).get_str();
  require_diverges(just, d - 1, "variable dy");
}

TEST_CASE("check: a step numbered out of sequence fails, content after the result is malformed", "[check]") {
  const char* input = R"({"p0":[0.25,0.5],"p1":[30.75,9.5]})";
  std::vector<Json> lines = trace_lines("dda-line", input, Numeric::f64);
  REQUIRE(lines.size() > 22);
  REQUIRE(check(lines).status == 0);
  // Line 0 is the header: step 12 is line 13. Renumbered to 19, it is otherwise the right step.
  std::vector<Json> renumbered = lines;
  REQUIRE(renumbered[13]["step"] == 12);
  renumbered[13]["step"] = 19;
  const CheckReport r = check(renumbered);
  INFO(r.message);
  CHECK(r.status == 1);
  CHECK_THAT(r.message, Catch::StartsWith("step 12 diverges") && Catch::Contains("numbered from 0, in order"));
  // Anything after the result line: a second result, or a step.
  for (const Json& extra : {lines.back(), lines[5]}) {
    std::vector<Json> trailing = lines;
    trailing.push_back(extra);
    const CheckReport t = check(trailing);
    INFO(t.message);
    CHECK(t.status == 2);
    CHECK_THAT(t.message, Catch::Contains("content after the result line"));
  }
}

TEST_CASE("check: --decisions-only takes steps without geometry, --results-only reads past the steps", "[check]") {
  std::vector<Json> lines = trace_lines("dda-line", kDda, Numeric::f64);
  auto scoped = [](const std::vector<Json>& t, CheckScope scope) {
    std::stringstream s;
    for (const Json& l : t) s << l.dump() << '\n';
    return check_trace(s, scope);
  };
  // A student's trace that records no geometry: malformed in full, fine when only decisions count.
  std::vector<Json> bare = lines;
  for (std::size_t i = 1; i + 1 < bare.size(); ++i) bare[i].erase("geo");
  CHECK(scoped(bare, CheckScope::everything).status == 2);
  const CheckReport ok = scoped(bare, CheckScope::decisions);
  INFO(ok.message);
  CHECK(ok.status == 0);
  CHECK_THAT(ok.message, Catch::Contains("decisions only"));
  // Still held: an integer (a plotted pixel's row) changed in a step, or a wrong result.
  const std::size_t plot = find_step(bare, "plot", "j");
  std::vector<Json> wrong = bare;
  wrong[plot]["vars"]["j"] = wrong[plot]["vars"]["j"].get<int>() + 1;
  CHECK(scoped(wrong, CheckScope::decisions).status == 1);
  wrong = bare;
  wrong.back()["result"]["pixels"][0][0] = 99;
  CHECK(scoped(wrong, CheckScope::decisions).status == 1);
  // The result alone: steps thrown away, or garbage in their place, pass; a wrong result fails.
  const std::vector<Json> result_only = {lines.front(), lines.back()};
  const CheckReport r = scoped(result_only, CheckScope::result);
  INFO(r.message);
  CHECK(r.status == 0);
  CHECK_THAT(r.message, Catch::Contains("--results-only"));
  CHECK(scoped({lines.front(), Json{{"anything", 1}}, lines.back()}, CheckScope::result).status == 0);
  CHECK(scoped(result_only, CheckScope::everything).status == 1);
  wrong = result_only;
  wrong.back()["result"]["pixels"][0][0] = 99;
  CHECK(scoped(wrong, CheckScope::result).status == 1);
  CHECK(scoped({lines.front()}, CheckScope::result).status == 2);  // still needs its result
}

TEST_CASE("check: a divergence names the listing line a student looks at: number, name and text", "[check]") {
  std::vector<Json> lines = trace_lines("dda-line", kDda, Numeric::exact);
  const std::size_t plot = find_step(lines, "plot", "j");
  lines[plot]["vars"]["j"] = lines[plot]["vars"]["j"].get<int>() + 1;
  const CheckReport r = check(lines);
  INFO(r.message);
  const Listing& l = find_algorithm("dda-line").listing;
  const auto id = lines[plot]["line"].get<std::size_t>();
  REQUIRE(id >= 1);
  REQUIRE(id <= l.lines.size());
  CHECK_THAT(r.message, Catch::StartsWith("step " + std::to_string(plot - 1) + " diverges at line " + std::to_string(id) + " (" +
                                          std::string(l.lines[id - 1].name) + ": "));
  const std::string text(l.lines[id - 1].text);
  CHECK_THAT(r.message, Catch::Contains(text.substr(text.find_first_not_of(' '), 12)));  // its indentation collapsed
}

TEST_CASE("check: a long result is read as its text says and its first wrong pixel named, however it is written", "[check]") {
  // 4,096 pixels; the result's list is held as plain integers, not as Json (check_result.hpp).
  const auto lines = trace_lines("dda-line", R"({"p0":[0,0],"p1":[4096,1000]})", Numeric::f64);
  const Json pixels = lines.back()["result"]["pixels"];
  REQUIRE(pixels.size() == 4096);
  auto written = [&](const Json& px) { return "{\"result\": {\"pixels\": " + spaced(px) + "}}"; };
  const CheckReport ok = check_with_result(lines, written(pixels));
  INFO(ok.message);
  CHECK(ok.status == 0);
  // A number may be written either way: 3000.0 is the pixel 3000, and 2.5 no pixel.
  Json px = pixels;
  px[3000] = {px[3000][0].get<double>(), px[3000][1].get<double>()};
  CHECK(check_with_result(lines, written(px)).status == 0);
  px[3000][1] = px[3000][1].get<double>() + 0.5;
  CHECK_THAT(check_with_result(lines, written(px)).message, Catch::StartsWith("result diverges") && Catch::Contains("result.pixels[3000][1]: expected"));
  // One pixel off deep in the list, a pixel of three numbers, a pixel too few.
  px = pixels;
  px[3000][1] = px[3000][1].get<int>() + 1;
  CHECK_THAT(check_with_result(lines, written(px)).message, Catch::Contains("result.pixels[3000][1]: expected " + pixels[3000][1].dump() + ", got " + px[3000][1].dump()));
  CHECK(check_with_result(lines, written(px), CheckScope::decisions).status == 1);
  px = pixels;
  px[3000].push_back(0);
  CHECK_THAT(check_with_result(lines, written(px)).message, Catch::Contains("result.pixels[3000]: expected 2 entries, got 3"));
  px = pixels;
  px.erase(4000);
  CHECK_THAT(check_with_result(lines, written(px)).message, Catch::Contains("result.pixels: expected 4096 entries, got 4095"));
  // A key stated twice is malformed, a list or not.
  const CheckReport dup = check_with_result(lines, R"({"result":{"pixels":[[0,0]],"pixels":)" + pixels.dump() + "}}");
  CHECK(dup.status == 2);
  CHECK_THAT(dup.message, Catch::Contains("duplicate key \"pixels\""));
}

TEST_CASE("check: a result stated as a set passes in any order, and a result's first differing field is the first in key order", "[check]") {
  // The circles' pixels are compared sorted: a trace may list them in any order.
  const auto circle = trace_lines("circle-midpoint", R"({"c":[3,-2],"r":40})", Numeric::exact);
  Json px = circle.back()["result"]["pixels"];
  REQUIRE(px.size() > 200);
  std::reverse(px.begin(), px.end());
  std::swap(px[10], px[100]);
  const CheckReport ok = check_with_result(circle, "{\"result\":{\"pixels\":" + px.dump() + "}}");
  INFO(ok.message);
  CHECK(ok.status == 0);
  px[50] = {1000, 1000};  // off the circle: named where the sorted lists first differ
  Json want = circle.back()["result"]["pixels"], got = px;
  std::sort(want.begin(), want.end());
  std::sort(got.begin(), got.end());
  std::size_t k = 0;
  while (want[k] == got[k]) ++k;
  CHECK_THAT(check_with_result(circle, "{\"result\":{\"pixels\":" + px.dump() + "}}").message,
             Catch::StartsWith("result diverges") && Catch::Contains("result.pixels[" + std::to_string(k) + "]"));
  // perspective-interp's result holds pixels and values: with both wrong, the pixels are named,
  // whichever the trace writes first.
  const auto fill = trace_lines("perspective-interp", find_algorithm("perspective-interp").example.c_str(), Numeric::exact);
  Json pixels = fill.back()["result"]["pixels"], values = fill.back()["result"]["values"];
  REQUIRE(pixels.size() > 20);
  REQUIRE(values.size() == pixels.size());
  const CheckReport reordered = check_with_result(fill, "{\"result\": {\"values\": " + spaced(values) + ", \"pixels\": " + spaced(pixels) + "}}");
  INFO(reordered.message);
  CHECK(reordered.status == 0);
  values[5][0] = values[5][0].get<double>() + 1;
  pixels[7][0] = pixels[7][0].get<int>() + 1;
  CHECK_THAT(check_with_result(fill, "{\"result\": {\"values\": " + values.dump() + ", \"pixels\": " + pixels.dump() + "}}").message,
             Catch::Contains("result.pixels[7][0]"));
  pixels[7][0] = pixels[7][0].get<int>() - 1;
  CHECK_THAT(check_with_result(fill, "{\"result\": {\"values\": " + values.dump() + ", \"pixels\": " + pixels.dump() + "}}").message,
             Catch::Contains("result.values[5][0]"));
}
