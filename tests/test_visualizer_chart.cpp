// The accuracy chart: `stepwise bench --plot` as SVG (well-formed, one marker per mode, exact and
// filtered at 0%) and PNG (the size asked, not blank), its refusals, and the app's Accuracy window
// (a bench on a background thread, then the same chart on screen).
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <stb_image.h>
#include <chrono>
#include <regex>
#include <thread>
#include "bench_text.hpp"
#include "cli_harness.hpp"
#include "headless/headless.hpp"

using namespace sw;
using namespace sw::vis;
using sw::testing::run_stepwise;
using sw::testing::scratch;
using sw::testing::sh_quote;
using sw::testing::slurp;

namespace {

// Every <tag ...> is closed by /> or a matching </tag>, in nesting order; returns the open tags
// left (empty when balanced) or "error" on a stray closing tag.
std::string unbalanced_tags(const std::string& xml) {
  std::vector<std::string> stack;
  std::size_t at = 0;
  for (int guard = 0; guard < 1000000; ++guard) {
    at = xml.find('<', at);
    if (at == std::string::npos) break;
    const std::size_t end = xml.find('>', at);
    if (end == std::string::npos) return "error: unterminated tag";
    const std::string tag = xml.substr(at + 1, end - at - 1);
    at = end + 1;
    if (tag.empty() || tag[0] == '?' || tag[0] == '!') continue;
    if (tag[0] == '/') {
      if (stack.empty() || stack.back() != tag.substr(1)) return "error: stray </" + tag.substr(1) + ">";
      stack.pop_back();
    } else if (tag.back() != '/') {
      stack.push_back(tag.substr(0, tag.find(' ')));
    }
  }
  std::string left;
  for (const auto& t : stack) left += t + " ";
  return left;
}

int count(const std::string& s, const std::string& what) {
  int n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

// The y of a marker: its group's translate(x,y).
double marker_y(const std::string& svg, const std::string& cls) {
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, std::regex("<g class=\"" + cls + "\" transform=\"translate\\(([-0-9.e]+),([-0-9.e]+)\\)\"")));
  return std::stod(m[2]);
}

// `stepwise bench ARGS --plot x.svg` (in a scratch folder named `name`): the SVG it wrote.
std::string bench_svg(const std::string& name, const std::string& args) {
  const auto out = scratch(name) / "chart.svg";
  const auto r = run_stepwise("bench " + args + " --plot " + sh_quote(out.string()));
  INFO(r.err);
  REQUIRE(r.status == 0);
  return slurp(out);
}

}  // namespace

TEST_CASE("visualizer chart: bench --plot writes an SVG with one marker per mode and labelled axes", "[visualizer][chart]") {
  const std::string svg = bench_svg("plot-svg", "dda-line --repeats 1 --set random");
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(unbalanced_tags(svg).empty());
  CHECK(count(svg, "<svg ") == 1);
  const Algorithm& alg = find_algorithm("dda-line");
  for (Numeric n : alg.numerics) {
    INFO(numeric_name(n));
    CHECK(count(svg, "class=\"marker " + std::string(numeric_name(n)) + " random\"") == 1);
    CHECK(count(svg, "class=\"legend " + std::string(numeric_name(n)) + "\"") == 1);
  }
  CHECK(count(svg, "class=\"marker ") == int(alg.numerics.size()));
  CHECK_THAT(svg, Catch::Contains("class=\"axis-label x\"") && Catch::Contains("time per output unit (ns), log scale"));
  CHECK_THAT(svg, Catch::Contains("class=\"axis-label y\"") && Catch::Contains("cases differing from exact (%)"));
  CHECK_THAT(svg, Catch::Contains("y: cases whose output differs from exact rationals"));
  CHECK(count(svg, "class=\"tick x\"") >= 2);
  CHECK(count(svg, "class=\"tick y\"") >= 2);
  CHECK_THAT(svg, Catch::Contains("dda-line, set random"));
  // Exact and filtered equal exact by definition: no marker sits lower (larger y) than theirs.
  const double y_exact = marker_y(svg, "marker exact random"), y_filtered = marker_y(svg, "marker filtered random");
  CHECK(std::fabs(y_exact - y_filtered) < 0.01);
  for (Numeric n : alg.numerics) CHECK(marker_y(svg, "marker " + std::string(numeric_name(n)) + " random") <= y_exact + 0.01);
}

namespace {

const ChartItem* item_with_role(const Chart& c, const std::string& role) {
  const auto it = std::find_if(c.items.begin(), c.items.end(), [&](const ChartItem& x) { return x.role == role; });
  return it == c.items.end() ? nullptr : &*it;
}

BenchRow made_row(Numeric n, Numeric judge, std::string_view unit, std::size_t mismatches, double max_error) {
  BenchRow r;
  r.set = "random", r.numeric = n, r.cases = 64, r.full_cases = 5000, r.ops = 64, r.ns_per_op = n == Numeric::f32 ? 3 : 40;
  r.mismatches = mismatches, r.max_error = max_error, r.error_unit = unit, r.judge = judge;
  return r;
}

}  // namespace

TEST_CASE("visualizer chart: every axis and label names its unit, and the judge the rows were compared with", "[visualizer][chart]") {
  for (const Numeric judge : {Numeric::exact, Numeric::reference}) {
    const std::string judged = std::string(judge_name(judge)), other = judge == Numeric::exact ? "reference" : "exact";
    INFO(judged);
    const std::vector<BenchRow> rows = {made_row(Numeric::f32, judge, "ulps", 7, 3.5), made_row(judge, judge, "ulps", 0, 0)};
    const Chart c = bench_chart("sphere-uv", rows, 900, 500);
    const ChartItem* y = item_with_role(c, "axis-label y");
    const ChartItem* x = item_with_role(c, "axis-label x");
    REQUIRE(y);
    REQUIRE(x);
    CHECK(y->text == "cases differing from " + judged + " (%)");
    CHECK_THAT(x->text, Catch::Contains("(ns)"));
    // The float marker's label: its percentage and its max error with the unit.
    const ChartItem* label = item_with_role(c, "marker-label float");
    REQUIRE(label);
    CHECK_THAT(label->text, Catch::Contains("%") && Catch::Contains("max error 3.5 ulps"));
    // The set's title says how many cases of how many ran; the note names judge and unit.
    const ChartItem* title = item_with_role(c, "title set random");
    REQUIRE(title);
    CHECK_THAT(title->text, Catch::Contains("64 of 5000 cases"));
    const ChartItem* note = item_with_role(c, "note");
    REQUIRE(note);
    CHECK_THAT(note->text, Catch::Contains("differs from " + std::string(judge_text(judge))) && Catch::Contains("max error in ulps"));
    for (const ChartItem& it : c.items) CHECK_THAT(it.text, !Catch::Contains(other));  // never the judge not used
  }
}

TEST_CASE("visualizer chart: bench --plot of a reference-only algorithm says reference, with the error's unit", "[visualizer][chart]") {
  const std::string svg = bench_svg("plot-ref", "sphere-uv --repeats 1 --set random");
  CHECK_THAT(svg, Catch::Contains("cases differing from reference (%)") && Catch::Contains("the 300-bit MPFR reference"));
  CHECK_THAT(svg, !Catch::Contains("from exact"));
  CHECK(std::regex_search(svg, std::regex("max error [0-9.e+-]+ ulps<")));  // float's label, at least
}

TEST_CASE("visualizer chart: bench --plot writes a PNG of the requested size that is not blank", "[visualizer][chart]") {
  const auto dir = scratch("plot-png");
  const auto out = dir / "dda.png";
  const auto r = run_stepwise("bench dda-line --repeats 1 --set random --numeric float --numeric exact --plot-size 800x500 --plot " + sh_quote(out.string()));
  INFO(r.err);
  REQUIRE(r.status == 0);
  int w = 0, h = 0, n = 0;
  unsigned char* img = stbi_load(out.c_str(), &w, &h, &n, 4);
  REQUIRE(img);
  CHECK(w == 800);
  CHECK(h == 500);
  // Not blank: the float marker's orange and the exact marker's near-white are both painted.
  const std::uint32_t orange = mode_colour(Numeric::f32), white = mode_colour(Numeric::exact);
  int orange_px = 0, white_px = 0;
  for (int i = 0; i < w * h; ++i) {
    const std::uint32_t c = std::uint32_t(img[4 * i]) | std::uint32_t(img[4 * i + 1]) << 8 | std::uint32_t(img[4 * i + 2]) << 16;
    orange_px += c == (orange & 0xffffffu);
    white_px += c == (white & 0xffffffu);
  }
  stbi_image_free(img);
  CHECK(orange_px >= 40);  // a 6 px marker and the legend's
  CHECK(white_px >= 40);
}

TEST_CASE("visualizer chart: bench --plot refuses a bad name, an unwritable place or a bad size with one line and no file", "[visualizer][chart]") {
  const auto dir = scratch("plot-bad");
  struct Bad {
    std::string args, expect;
  };
  const std::vector<Bad> bad = {
      {"--plot " + sh_quote((dir / "chart.txt").string()), "must end in .png or .svg"},
      {"--plot " + sh_quote((dir / "missing" / "chart.png").string()), "cannot write"},
      {"--plot " + sh_quote((dir / "chart.svg").string()) + " --plot-size 10x10", "--plot-size"},
      {"--plot " + sh_quote(dir.string() + "/"), ""},
  };
  for (const Bad& b : bad) {
    INFO(b.args);
    const auto r = run_stepwise("bench dda-line --repeats 1 --set random " + b.args);
    CHECK(r.status == 2);
    CHECK(count(r.err, "\n") == 1);
    CHECK_THAT(r.err, Catch::StartsWith("stepwise: error: ") && Catch::Contains(b.expect));
    CHECK(r.out.empty());  // refused before the bench ran
    CHECK(std::filesystem::is_empty(dir));
  }
}

TEST_CASE("visualizer chart: the Accuracy window benches on a thread and shows the chart", "[visualizer][chart]") {
  HeadlessHost host(1100, 700);
  App& app = host.app();
  REQUIRE(app.session().open_algorithm(find_algorithm("dda-line"), parse_json_text(R"({"p0":[0,0],"p1":[9,4]})", "t"), Numeric::exact));
  app.set_accuracy_open(true);
  host.render(1);
  REQUIRE(app.accuracy().run());
  // The frames go on while the thread works (bounded wait: the bench takes about a second).
  int frames = 0;
  for (; frames < 3000 && !app.accuracy().run()->finished(); ++frames) {
    host.render(1);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  REQUIRE(app.accuracy().run()->finished());
  CHECK(app.accuracy().run()->error().empty());
  CHECK(app.accuracy().run()->set() == "random");  // the first of the family's sets
  host.render(2);
  const Chart& chart = app.accuracy().chart();
  const Algorithm& alg = find_algorithm("dda-line");
  for (Numeric n : alg.numerics) {
    const std::string role = "marker " + std::string(numeric_name(n)) + " random";
    const auto it = std::find_if(chart.items.begin(), chart.items.end(), [&](const ChartItem& c) { return c.role == role; });
    INFO(role);
    REQUIRE(it != chart.items.end());
    // The marker is on screen in its colour at its centre.
    const ImVec2 o = app.accuracy().chart_origin();
    const std::uint32_t px = host.pixel(int(o.x + it->x0), int(o.y + it->y0));
    CHECK((px & 0xffffffu) == (mode_colour(n) & 0xffffffu));
  }
  app.set_accuracy_open(false);
  host.render(1);
  CHECK_FALSE(app.accuracy().run());
}
#endif  // SW_HAVE_VISUALIZER
