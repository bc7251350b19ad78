// The scene view of the ray tracer's pixel history (View::scene): the picture drawn is the
// renderer's image (the Spec's picture hook, from the opened input), a click on a pixel traces that
// pixel (the pick hook: its history becomes the trace, one parse, the picture kept), the ray
// tree's table (the summary_table hook) follows, and the 3D view keeps every ray of the tree to the end.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include "headless/headless.hpp"
#include "panels/scene_view.hpp"
#include "run.hpp"

using namespace sw;
using namespace sw::vis;

TEST_CASE("scene view: the preview is drawn and a click on a pixel records that pixel's history", "[visualizer][scene][render]") {
  HeadlessHost host(1280, 800);
  App& app = host.app();
  Session& session = app.session();
  const Algorithm& alg = find_algorithm("whitted");
  REQUIRE(session.open_algorithm(alg, Json::parse(alg.example), Numeric::f64));
  CHECK(session.view() == View::scene);
  auto opened = inputs_opened();
  host.render(3);
  CHECK(inputs_opened() == opened);  // the picture comes from the opened input: the scene is not read again
  const auto* sc = dynamic_cast<const SceneCanvas*>(app.canvas(0));
  REQUIRE(sc);
  const Picture& p = sc->picture();
  REQUIRE(p.width == 80);  // the example's size fits the preview whole
  REQUIRE(p.height == 60);
  // The drawn image is the preview: the centre of a pixel has its colour.
  int same = 0;
  for (int j = 4; j < 60; j += 11)
    for (int i = 3; i < 80; i += 13) {
      const auto r = sc->pixel_rect(i, j);
      const std::uint32_t got = host.pixel(int((r[0] + r[2]) / 2), int((r[1] + r[3]) / 2));
      const std::size_t k = 3 * (std::size_t(j) * 80 + std::size_t(i));
      const int d = std::abs(int(got & 0xff) - p.rgb[k]) + std::abs(int(got >> 8 & 0xff) - p.rgb[k + 1]) + std::abs(int(got >> 16 & 0xff) - p.rgb[k + 2]);
      same += d <= 6;
    }
  CHECK(same >= 28);  // of 36; the status plate covers a few
  // Click the floor pixel under the water sphere (62, 27).
  const auto r = sc->pixel_rect(62, 27);
  const ImVec2 at((r[0] + r[2]) / 2, (r[1] + r[3]) / 2);
  const std::uint8_t* pixels = p.rgb.data();
  opened = inputs_opened();
  host.set_mouse(at, true);
  host.render(1);
  host.set_mouse(at, false);
  host.render(2);
  REQUIRE(session.model(0)->input()["pixel"] == Json::array({62, 27}));
  CHECK(inputs_opened() - opened == 1);       // the edited input, once
  CHECK(sc->picture().rgb.data() == pixels);  // the same scene: the picture is kept
  CHECK(session.view() == View::scene);
  // The ray tree: the primary ray meets the floor, whose shadow ray to light 0 the water sphere blocks.
  const SummaryTable& tree = sc->summary();
  REQUIRE(tree.rows.size() >= 3);
  CHECK(tree.rows[0].cells[2].text == "primary");
  const bool blocked = std::any_of(tree.rows.begin(), tree.rows.end(),
                                   [](const SummaryTable::Row& row) { return row.cells[2].text == "shadow 0: blocked"; });
  CHECK(blocked);
  // The trace is the clicked pixel's: its result is the preview's pixel, rounded to 8 bits.
  const Json& c = session.model(0)->result()["colour"];
  for (std::size_t k = 0; k < 3; ++k) CHECK(std::lround(255 * std::clamp(c[k].get<double>(), 0.0, 1.0)) == p.rgb[3 * (27 * 80 + 62) + k]);
  // The chrome pixel: at the last step the 3D view keeps the depth-2 ray (a recursive call's kept items last).
  REQUIRE(session.open_algorithm(alg, Json::parse(alg.example), Numeric::f64));
  const auto& m = *session.model(0);
  bool depth2 = false;
  for (std::uint32_t g : m.visible_items(m.last()))
    if (const char* l = m.trace().geo_at(g).label) depth2 = depth2 || std::string_view(l) == "depth 2";
  CHECK(depth2);
}
#endif  // SW_HAVE_VISUALIZER
