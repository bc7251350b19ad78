// Headless renders through OSMesa with the same App the window uses: the plotted pixels are where
// the trace says and nowhere else, the listing highlights the step's line, and dragging an
// endpoint re-runs the trace keeping the timeline's relative position.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <set>
#include "cli_harness.hpp"
#include "headless/headless.hpp"
#include "host_pixels.hpp"
#include "panels/pixel_layer.hpp"

using namespace sw;
using namespace sw::vis;
using sw::testing::channel_distance;
using sw::testing::kHostH;
using sw::testing::kHostW;

namespace {

// Samples a 5x5 grid over the inner 60% of a cell: how many samples have colour `want`.
int samples_matching(const HeadlessHost& host, const std::array<float, 4>& r, std::uint32_t want) {
  int hits = 0;
  for (int a = 0; a < 5; ++a)
    for (int b = 0; b < 5; ++b) {
      const int x = int(std::lround(r[0] + (r[2] - r[0]) * (0.2 + 0.15 * a)));
      const int y = int(std::lround(r[1] + (r[3] - r[1]) * (0.2 + 0.15 * b)));
      if (x >= 0 && y >= 0 && x < host.width() && y < host.height() && channel_distance(host.pixel(x, y), want) <= 3) ++hits;
    }
  return hits;
}

// Every visible cell around the segment: plotted by `step` -> its plot colour; not plotted -> no
// plot colour at all. `whole`: the canvas shows the whole trace, so every plotted cell is checked.
void check_canvas(HeadlessHost& host, const TraceModel& m, std::size_t step, int canvas = 0, bool whole = true) {
  const Canvas* c = host.app().canvas(canvas);
  REQUIRE(c);
  const WorldRect b = m.bounds();
  int plotted = 0;
  for (std::int64_t i = std::int64_t(std::floor(b.x0)) - 1; i <= std::int64_t(std::ceil(b.x1)) + 1; ++i)
    for (std::int64_t j = std::int64_t(std::floor(b.y0)) - 1; j <= std::int64_t(std::ceil(b.y1)) + 1; ++j) {
      const auto r = c->cell_rect({i, j});
      if (!r) continue;
      const std::uint32_t first = m.step_of_cell({i, j});
      INFO("cell (" << i << ", " << j << ") step " << step << " first plotted at " << first);
      if (first != kNoStep && first <= step) {
        ++plotted;
        CHECK(samples_matching(host, *r, plot_colour(first, m.last())) >= 18);
      } else {
        // Not yet plotted: none of the plot colours of this trace appear in the cell.
        for (const PlotEvent& e : m.plots()) REQUIRE(samples_matching(host, *r, plot_colour(e.step, m.last())) <= 3);
      }
    }
  if (whole) CHECK(plotted == int(m.plots_through(step)));
  else CHECK(plotted > 0);
}

}  // namespace

TEST_CASE("visualizer render: plotted pixels and the listing line at known steps", "[visualizer][render]") {
  HeadlessHost host(kHostW, kHostH);
  App& app = host.app();
  Session& session = app.session();
  const Algorithm& alg = find_algorithm("dda-line");
  REQUIRE(session.open_algorithm(alg, parse_json_text(R"({"p0":[1.25,2.5],"p1":[12.75,7.25]})", "t"), Numeric::exact));
  const TraceModel& m = *session.model(0);
  for (std::size_t step : {std::size_t(0), std::size_t(5), std::size_t(12), m.last()}) {
    session.set_step(step);
    host.render();
    INFO("step " << step);
    CHECK(app.highlighted_line() == m.trace().at(step).line);
    check_canvas(host, m, step);
  }
}

TEST_CASE("visualizer render: the drawn highlight band is on the step's listing line and no other", "[visualizer][render]") {
  HeadlessHost host(kHostW, kHostH);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_algorithm(find_algorithm("dda-line"), parse_json_text(R"({"p0":[1.25,2.5],"p1":[12.75,7.25]})", "t"), Numeric::exact));
  const TraceModel& m = *session.model(0);
  auto blue = [](std::uint32_t c) { return int((c >> 16) & 255) - int(c & 255); };  // RGBA in memory: blue minus red
  std::set<std::uint32_t> lines_seen;
  for (std::size_t step = 0; step <= m.last(); ++step) {
    session.set_step(step);
    host.render();
    host.render();  // the listing scrolls to the line on the frame after
    const std::uint32_t line = m.trace().at(step).line;
    const auto& rows = app.listing_rows();
    REQUIRE(rows.size() == find_algorithm("dda-line").listing.lines.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const int x = int(std::lround(rows[i][0] - 2)), y = int(std::lround(rows[i][1] + 2));
      if (y < 0 || y >= host.height()) continue;
      INFO("step " << step << " line " << line << " row " << i + 1);
      // The band is the highlight blue over the panel; every other row shows the panel's grey.
      if (i + 1 == line) CHECK(blue(host.pixel(x, y)) >= 40);
      else CHECK(std::abs(blue(host.pixel(x, y))) < 20);
    }
    lines_seen.insert(line);
  }
  CHECK(lines_seen.size() >= 8);  // the band visited most lines of the listing
}

TEST_CASE("visualizer render: the grid walk's corner case and the compare view", "[visualizer][render]") {
  HeadlessHost host(kHostW, kHostH);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_algorithm(find_algorithm("dda-grid-walk"), parse_json_text(R"({"p0":[0,3.75],"p1":[8,-0.25]})", "t"),
                             Numeric::exact, Numeric::f32));
  const TraceModel &a = *session.model(0), &b = *session.model(1);
  session.set_step(6);  // both cells of the first corner crossing are visited
  host.render();
  CHECK(app.highlighted_line() == 10);
  check_canvas(host, a, 6, 0, false);
  check_canvas(host, b, 6, 1, false);
  REQUIRE(session.compare_stats());
  CHECK_FALSE(session.compare_stats()->first_decision_divergence);  // this input is exact in float too
}

TEST_CASE("visualizer render: a lesson that fails to load shows its error, never crashes", "[visualizer][render]") {
  HeadlessHost host(640, 400);
  App& app = host.app();
  Session& session = app.session();
  const auto dir = sw::testing::scratch("bad-lesson");
  const auto bad = dir / "bad.md";
  std::ofstream(bad) << "---\nalgorithm: dda-line\ninput: {\"p0\":[0,0]}\n---\n";
  CHECK_FALSE(session.open_lesson(bad));
  CHECK_THAT(session.error(), Catch::Contains("bad.md") && Catch::Contains("p1"));
  CHECK_FALSE(session.loaded());
  host.render();  // draws the message
  // A good lesson still opens afterwards, and a failing one then keeps it open.
  REQUIRE(session.open_first_lesson());
  CHECK_FALSE(session.open_lesson(dir / "missing.md"));
  CHECK(session.loaded());
  host.render();
}

TEST_CASE("visualizer render: dragging p1 re-runs the trace and keeps the relative position", "[visualizer][render]") {
  HeadlessHost host(kHostW, kHostH);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_algorithm(find_algorithm("dda-line"), parse_json_text(R"({"p0":[1,2],"p1":[13,7]})", "t"), Numeric::exact));
  host.render();
  const std::size_t before_steps = session.steps();
  session.set_step(before_steps / 2);
  host.render();
  // The world-to-screen map from the rectangle of cell (1, 2), whose centre is the point (1, 2).
  const auto c0 = app.canvas(0)->cell_rect({1, 2});
  REQUIRE(c0);
  const float scale = (*c0)[2] - (*c0)[0], ox = ((*c0)[0] + (*c0)[2]) / 2 - scale, oy = ((*c0)[1] + (*c0)[3]) / 2 + 2 * scale;
  auto screen = [&](double x, double y) { return ImVec2(float(ox + x * scale), float(oy - y * scale)); };
  host.set_mouse(screen(13, 7), false);
  host.render(1);
  host.set_mouse(screen(13, 7), true);
  host.render(1);
  for (int k = 1; k <= 4; ++k) {
    host.set_mouse(screen(13 + 2 * k, 7 + k), true);  // drag toward (21, 11)
    host.render(1);
  }
  host.set_mouse(screen(21, 11), false);
  host.render(1);
  const TraceModel& m = *session.model(0);
  CHECK(m.input()["p1"] == Json::array({21, 11}));
  CHECK(session.steps() > before_steps);
  const double before = double(before_steps / 2) / double(before_steps - 1), after = double(session.step()) / double(session.steps() - 1);
  CHECK(std::fabs(before - after) < 0.02);
}
#endif  // SW_HAVE_VISUALIZER

#ifdef SW_HAVE_VISUALIZER
TEST_CASE("visualizer render: the timeline keys step, play, jump and change speed", "[visualizer][render]") {
  HeadlessHost host(640, 400);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_algorithm(find_algorithm("dda-line"), parse_json_text(R"({"p0":[0,0],"p1":[30,7]})", "t"), Numeric::exact));
  host.render();
  REQUIRE(session.step() == 0);
  host.press(ImGuiKey_RightArrow);
  host.render();
  CHECK(session.step() == 1);
  host.press(ImGuiKey_End);
  host.render();
  CHECK(session.step() == session.steps() - 1);
  host.press(ImGuiKey_LeftArrow);
  host.render();
  CHECK(session.step() == session.steps() - 2);
  host.press(ImGuiKey_Home);
  host.render();
  CHECK(session.step() == 0);
  // Space plays at the current speed (4 steps/s at 60 frames/s: a step every 15 frames); '+'
  // doubles it.
  host.press(ImGuiKey_Space);
  host.render(31);
  const std::size_t slow = session.step();
  CHECK(slow >= 1);
  host.type('+');
  host.type('+');
  host.render(31);
  CHECK(session.step() - slow > slow);
  host.press(ImGuiKey_Space);  // pause
  host.render();
  const std::size_t paused = session.step();
  host.render(30);
  CHECK(session.step() == paused);
}
#endif  // SW_HAVE_VISUALIZER
