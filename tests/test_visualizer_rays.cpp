// The 3D ray canvas: the ray lessons load into it, the hit marker is drawn at the hit point on
// the hit step and not before, and dragging the ray's handles edits the input and re-records.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <cmath>
#include "headless.hpp"
#include "ray_canvas.hpp"

using namespace sw;
using namespace sw::vis;

namespace {

constexpr int kW = 1280, kH = 800;

int channel_distance(std::uint32_t a, std::uint32_t b) {
  int d = 0;
  for (int ch = 0; ch < 3; ++ch) d = std::max(d, std::abs(int((a >> (8 * ch)) & 255) - int((b >> (8 * ch)) & 255)));
  return d;
}

// Pixels of colour `want` in a 5x5 square around p.
int near_colour(const HeadlessHost& host, std::array<float, 2> p, ImU32 want) {
  int n = 0;
  for (int dx = -2; dx <= 2; ++dx)
    for (int dy = -2; dy <= 2; ++dy) n += channel_distance(host.pixel(int(p[0]) + dx, int(p[1]) + dy), want) <= 3;
  return n;
}

const RayCanvas& ray_canvas(const App& app, int i) {
  const auto* c = dynamic_cast<const RayCanvas*>(app.canvas(i));
  REQUIRE(c);
  return *c;
}

// The step of kind hit and its point.
std::pair<std::size_t, V3> hit_of(const TraceModel& m) {
  for (std::size_t s = 0; s < m.size(); ++s) {
    const StepRecord& st = m.trace().at(s);
    if (st.kind != StepKind::hit) continue;
    for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g) {
      const GeoRecord& geo = m.trace().geo_at(g);
      if (geo.kind == GeoKind::point3) return {s, V3{m.trace().geo_double(geo, 0), m.trace().geo_double(geo, 1), m.trace().geo_double(geo, 2)}};
    }
  }
  FAIL("no hit step");
  return {};
}

}  // namespace

TEST_CASE("visualizer rays: the ray lessons load into the 3D canvas", "[visualizer][rays]") {
  const auto dir = default_lessons_dir();
  const auto lessons = lesson_manifest(dir);
  int rays = 0;
  HeadlessHost host(640, 400);
  for (const auto& path : lessons) {
    const Lesson l = load_lesson(path);
    if (l.algorithm->family != "rays") continue;
    ++rays;
    INFO(path);
    REQUIRE(host.app().open_lesson(path));
    host.render();
    CHECK(dynamic_cast<const RayCanvas*>(host.app().canvas(0)));
    CHECK(host.app().highlighted_line() == host.app().model(0)->trace().at(host.app().step()).line);
  }
  CHECK(rays >= 2);
}

TEST_CASE("visualizer rays: the hit marker is at the hit point on the hit step only", "[visualizer][rays]") {
  HeadlessHost host(kW, kH);
  App& app = host.app();
  // Opens the lesson, checks the marker on the exact run's hit step and its absence one step
  // earlier; returns the hit point (rendered at the hit step) for further checks.
  auto marker_only_on_hit_step = [&](const char* lesson) {
    REQUIRE(app.open_lesson(default_lessons_dir() / lesson));
    const auto [step, p] = hit_of(*app.model(0));
    app.set_step(step - 1);
    host.render();
    CHECK(near_colour(host, *ray_canvas(app, 0).screen_of(p), kRayHit) == 0);
    app.set_step(step);
    host.render();
    const auto at = ray_canvas(app, 0).screen_of(p);
    REQUIRE(at);
    CHECK(near_colour(host, *at, kRayHit) >= 20);
    return p;
  };
  SECTION("the shared-edge crack: exact hits, float misses") {
    const auto p = marker_only_on_hit_step("05-triangle-crack.md");
    // The float run (right) missed: no marker at the same world point.
    const auto at_float = ray_canvas(app, 1).screen_of(p);
    REQUIRE(at_float);
    CHECK(near_colour(host, *at_float, kRayHit) == 0);
  }
  SECTION("the far sphere, zoomed onto it") {
    marker_only_on_hit_step("06-far-sphere.md");
  }
}

TEST_CASE("visualizer rays: ray_input_edit moves o or o + d", "[visualizer][rays]") {
  const Json in = parse_json_text(R"({"ray":{"o":[0,0,10],"d":[1,2,-10]},"sphere":{"c":[0,0,0],"r":1}})", "t");
  const auto moved_o = ray_input_edit(in, 0, V3{1.3, -2.26, 9.9}, 0.25);
  REQUIRE(moved_o);
  CHECK((*moved_o)["ray"]["o"] == Json::array({1.25, -2.25, 10.0}));
  CHECK((*moved_o)["ray"]["d"] == in["ray"]["d"]);
  CHECK((*moved_o)["sphere"] == in["sphere"]);
  const auto moved_d = ray_input_edit(in, 1, V3{3, 0.5, 1}, 0.5);  // d = p - o
  REQUIRE(moved_d);
  CHECK((*moved_d)["ray"]["d"] == Json::array({3.0, 0.5, -9.0}));
  CHECK((*moved_d)["ray"]["o"] == in["ray"]["o"]);
  CHECK_FALSE(ray_input_edit(in, 1, V3{0.1, 0, 10}, 0.5));  // d would snap to zero
  CHECK_FALSE(ray_input_edit(parse_json_text(R"({"p0":[0,0],"p1":[1,1]})", "t"), 0, V3{}, 1));
  // Snapped values stay float-representable, and -0 never appears.
  const auto tiny = ray_input_edit(in, 0, V3{-0.01, 0.3, 10}, 0.5);
  REQUIRE(tiny);
  CHECK_FALSE(std::signbit((*tiny)["ray"]["o"][0].get<double>()));
}

TEST_CASE("visualizer rays: dragging o + d re-records the trace and keeps the relative position", "[visualizer][rays]") {
  HeadlessHost host(kW, kH);
  App& app = host.app();
  const Algorithm& alg = find_algorithm("ray-box");
  REQUIRE(app.open_algorithm(alg, parse_json_text(R"({"ray":{"o":[-3,0.5,0.5],"d":[1,0.25,0.125]},"box":{"min":[0,0,0],"max":[1,1,1]}})", "t"), Numeric::exact));
  host.render();
  app.set_step(app.steps() - 1);
  const Json before = app.model(0)->input();
  const V3 o{-3, 0.5, 0.5}, tip{-2, 0.75, 0.625};
  const auto at = ray_canvas(app, 0).screen_of(tip);
  REQUIRE(at);
  const ImVec2 start(at->at(0), at->at(1));
  host.set_mouse(start, false);
  host.render(1);
  host.set_mouse(start, true);
  host.render(1);
  for (int k = 1; k <= 4; ++k) {
    host.set_mouse(ImVec2(start.x + 6.f * float(k), start.y - 5.f * float(k)), true);
    host.render(1);
  }
  host.set_mouse(ImVec2(start.x + 24, start.y - 20), false);
  host.render(1);
  const TraceModel& m = *app.model(0);
  CHECK(m.input()["ray"]["o"] == before["ray"]["o"]);
  CHECK(m.input()["ray"]["d"] != before["ray"]["d"]);
  CHECK(m.input()["box"] == before["box"]);
  // The trace was re-recorded with the new ray: its geometry carries the edited direction.
  const RayScene sc = RayScene::from_model(m);
  CHECK(Json::array({sc.d.x, sc.d.y, sc.d.z}) == m.input()["ray"]["d"]);
  CHECK(app.step() == m.last());  // it was at the end, and stays at the end
  // The o handle is still where the input says.
  const auto o_at = ray_canvas(app, 0).screen_of(o);
  REQUIRE(o_at);
  CHECK(near_colour(host, *o_at, kRayOrigin) >= 9);

  // A left-drag on empty space orbits the camera and leaves the input alone.
  const Json edited = m.input();
  const double yaw = ray_canvas(app, 0).camera().yaw;
  const auto& cam = ray_canvas(app, 0).camera();
  const ImVec2 empty(float(cam.origin[0] + 30), float(cam.origin[1] + cam.size[1] / 2));
  host.set_mouse(empty, false);
  host.render(1);
  host.set_mouse(empty, true);
  host.render(1);
  host.set_mouse(ImVec2(empty.x + 40, empty.y), true);
  host.render(1);
  host.set_mouse(ImVec2(empty.x + 40, empty.y), false);
  host.render(1);
  CHECK(ray_canvas(app, 0).camera().yaw != yaw);
  CHECK(app.model(0)->input() == edited);
}
#endif  // SW_HAVE_VISUALIZER
