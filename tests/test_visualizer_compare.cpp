// The compare view on lesson 04 (a DDA line on float beside exact): the mismatched pixels are
// listed and outlined on both canvases, the divergent steps are listed for the timeline's ticks,
// the |difference| series of a variable matches the state panel's values, F fits both canvases,
// and exact fractions keep their decimal.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <set>
#include "panels/compare_plot.hpp"
#include "headless/headless.hpp"
#include "host_pixels.hpp"
#include "panels/theme.hpp"

using namespace sw;
using namespace sw::vis;
using sw::testing::channel_distance;

namespace {

const std::filesystem::path kLesson04 = std::filesystem::path(SW_SOURCE_DIR) / "lessons" / "04-float-drift.md";

// How many of the cell's four edges show `col` within 2 px across the edge at its midpoint.
int edges_with(const HeadlessHost& host, const std::array<float, 4>& r, std::uint32_t col) {
  const float mx = (r[0] + r[2]) / 2, my = (r[1] + r[3]) / 2;
  const std::array<std::array<float, 3>, 4> edges{{{mx, r[1], 0}, {mx, r[3], 0}, {r[0], my, 1}, {r[2], my, 1}}};  // x, y, vertical?
  int found = 0;
  for (const auto& e : edges) {
    bool hit = false;
    for (int d = -2; d <= 2 && !hit; ++d) {
      const int x = int(std::lround(e[0] + (e[2] ? float(d) : 0.f))), y = int(std::lround(e[1] + (e[2] ? 0.f : float(d))));
      hit = x >= 0 && y >= 0 && x < host.width() && y < host.height() && channel_distance(host.pixel(x, y), col) <= 30;
    }
    found += hit;
  }
  return found;
}

}  // namespace

TEST_CASE("visualizer compare: lesson 04's mismatched cells and divergent steps", "[visualizer][compare]") {
  HeadlessHost host(1280, 800);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_lesson(kLesson04));
  const TraceModel &a = *session.model(0), &b = *session.model(1);
  REQUIRE(session.compare_stats());
  const CompareStats& st = *session.compare_stats();
  // The cells one run plotted and the other never did, from the models' own cell lookups.
  std::set<Pixel> expected;
  for (const TraceModel* m : {&a, &b})
    for (const PlotEvent& e : m->plots())
      if ((a.step_of_cell(e.cell) == kNoStep) != (b.step_of_cell(e.cell) == kNoStep)) expected.insert(e.cell);
  CHECK(expected.size() == 22);  // the lesson's figure
  CHECK(std::vector<Pixel>(expected.begin(), expected.end()) == st.mismatched_cells);
  // Every step where the two runs plot different pixels is a listed divergence, and the list
  // starts at the first divergence.
  REQUIRE_FALSE(st.divergences.empty());
  CHECK(st.divergences.front() == st.first_decision_divergence);
  CHECK(std::is_sorted(st.divergences.begin(), st.divergences.end()));
  std::size_t pixel_steps = 0;
  for (std::size_t s = 0; s < std::min(a.size(), b.size()); ++s)
    if (a.pixel_at(s) != b.pixel_at(s)) {
      ++pixel_steps;
      INFO("step " << s);
      CHECK(std::binary_search(st.divergences.begin(), st.divergences.end(), std::uint32_t(s)));
    }
  CHECK(pixel_steps >= 11);  // 22 cells: 11 steps plot a different cell each
}

TEST_CASE("visualizer compare: mismatched pixels are outlined on both canvases, others are not", "[visualizer][compare]") {
  HeadlessHost host(1280, 800);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_lesson(kLesson04));  // zoomed onto step 3939, the first divergence
  const TraceModel& a = *session.model(0);
  // Just past the last divergence: every mismatch is plotted and, as the view follows the step,
  // still on the canvas.
  const std::size_t shown = session.compare_stats()->divergences.back() + 2;
  session.set_step(shown);
  host.render();
  const auto& cells = session.compare_stats()->mismatched_cells;
  const std::set<Pixel> marked(cells.begin(), cells.end());
  const auto current = a.pixel_at(shown);
  auto off_current = [&](Pixel c) { return !current || std::abs(current->x - c.x) > 1 || std::abs(current->y - c.y) > 1; };
  auto isolated = [&](Pixel c) {  // no marked neighbour shares an edge's pixels
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        if ((dx || dy) && marked.count({c.x + dx, c.y + dy})) return false;
    return off_current(c);
  };
  int outlined = 0, clean = 0;
  for (int canvas = 0; canvas < 2; ++canvas) {
    const Canvas* cv = app.canvas(canvas);
    REQUIRE(cv);
    for (Pixel c : cells) {
      const auto r = cv->cell_rect(c);
      if (!r || !off_current(c)) continue;
      INFO("canvas " << canvas << " cell (" << c.x << ", " << c.y << ")");
      CHECK(edges_with(host, *r, theme::kMismatch) == 4);
      ++outlined;
    }
    // Cells both runs plotted, away from any marked one: no outline colour on their edges.
    for (const PlotEvent& e : a.plots()) {
      const auto r = cv->cell_rect(e.cell);
      if (!r || marked.count(e.cell) || !isolated(e.cell)) continue;
      CHECK(edges_with(host, *r, theme::kMismatch) == 0);
      ++clean;
    }
  }
  CHECK(outlined >= 2);  // at least one cell on each canvas
  CHECK(clean >= 2);
}

TEST_CASE("visualizer compare: F fits both canvases", "[visualizer][compare]") {
  HeadlessHost host(1280, 800);
  App& app = host.app();
  REQUIRE(app.session().open_lesson(kLesson04));
  host.render();
  const Pixel at{1968, 656};  // step 3939's cell, where the lesson zooms in
  std::array<float, 2> before{};
  for (int i = 0; i < 2; ++i) {
    const auto r = app.canvas(i)->cell_rect(at);
    REQUIRE(r);
    before[i] = (*r)[2] - (*r)[0];
  }
  host.type('f');
  host.render();
  for (int i = 0; i < 2; ++i) {
    INFO("canvas " << i);
    const auto r = app.canvas(i)->cell_rect(at);
    REQUIRE(r);
    // The whole 3000-column line fits now: a cell is under a screen pixel wide.
    CHECK((*r)[2] - (*r)[0] < before[i] / 10);
    CHECK((*r)[2] - (*r)[0] < 1.f);
  }
}

TEST_CASE("visualizer compare: the |difference| series and the decimal of exact fractions", "[visualizer][compare]") {
  HeadlessHost host(1280, 800);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_lesson(kLesson04));
  host.render();
  const TraceModel &a = *session.model(0), &b = *session.model(1);
  const auto vars = shared_numeric_vars(a, b);
  REQUIRE(std::find(vars.begin(), vars.end(), "qy") != vars.end());
  CHECK(std::find(vars.begin(), vars.end(), "i") == vars.end());  // an integer counter
  // The series' maximum is the largest |qy_float - qy_exact| the state panel shows at any step.
  const DiffSeries s = diff_series(a, b, "qy", 100);
  double max = 0;
  std::size_t max_step = 0;
  for (std::size_t step = 0; step < a.size(); ++step) {
    const auto sa = a.state_at(step), sb = b.state_at(step);
    const auto qa = std::find_if(sa.begin(), sa.end(), [](const VarState& v) { return v.name == "qy"; });
    const auto qb = std::find_if(sb.begin(), sb.end(), [](const VarState& v) { return v.name == "qy"; });
    if (qa == sa.end() || qb == sb.end()) continue;
    if (std::fabs(qa->value - qb->value) > max) max = std::fabs(qa->value - qb->value), max_step = step;
  }
  CHECK(max > 0);
  CHECK(s.max == max);
  CHECK(s.max_step == max_step);
  CHECK(s.bins.size() == 100);
  CHECK(*std::max_element(s.bins.begin(), s.bins.end()) == float(max));
  // Exact fractions show their decimal in both state panels; integers and decimals do not.
  VarState third;
  third.text = "1/3", third.value = 1.0 / 3;
  CHECK(approx_suffix(third) == " \xE2\x89\x88 0.333333333");
  VarState whole;
  whole.text = "1968", whole.value = 1968;
  CHECK(approx_suffix(whole).empty());
}
#endif  // SW_HAVE_VISUALIZER
