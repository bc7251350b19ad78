// The 3D ray canvas: the ray lessons load into it, the hit marker is drawn at the hit point on
// the hit step and not before, and dragging the ray's handles edits the input and re-records.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <cmath>
#include "headless/headless.hpp"
#include "host_pixels.hpp"
#include "panels/orbit_canvas.hpp"
#include "panels/theme.hpp"

using namespace sw;
using namespace sw::vis;
using sw::testing::channel_distance;

namespace {

constexpr int kWideW = 1280, kWideH = 800;

// Pixels of colour `want` in a 5x5 square around p.
int near_colour(const HeadlessHost& host, std::array<float, 2> p, ImU32 want) {
  int n = 0;
  for (int dx = -2; dx <= 2; ++dx)
    for (int dy = -2; dy <= 2; ++dy) n += channel_distance(host.pixel(int(p[0]) + dx, int(p[1]) + dy), want) <= 3;
  return n;
}

const OrbitCanvas& ray_canvas(const App& app, int i) {
  const auto* c = dynamic_cast<const OrbitCanvas*>(app.canvas(i));
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
    if (l.algorithm->family != "rays" && l.algorithm->id != "ray-triangles") continue;  // ray tests, alone or in a loop
    ++rays;
    INFO(path);
    REQUIRE(host.app().session().open_lesson(path));
    host.render();
    CHECK(dynamic_cast<const OrbitCanvas*>(host.app().canvas(0)));
    CHECK(host.app().highlighted_line() == host.app().session().model(0)->trace().at(host.app().session().step()).line);
  }
  CHECK(rays >= 2);
}

TEST_CASE("visualizer rays: the hit marker is at the hit point on the hit step only", "[visualizer][rays]") {
  HeadlessHost host(kWideW, kWideH);
  App& app = host.app();
  Session& session = app.session();
  // Opens the lesson, checks the marker on the exact run's hit step and its absence one step
  // earlier; returns the hit point (rendered at the hit step) for further checks.
  auto marker_only_on_hit_step = [&](const char* lesson) {
    REQUIRE(session.open_lesson(default_lessons_dir() / lesson));
    const auto [step, p] = hit_of(*session.model(0));
    session.set_step(step - 1);
    host.render();
    CHECK(near_colour(host, *ray_canvas(app, 0).screen_of(p), kHitColour) == 0);
    session.set_step(step);
    host.render();
    const auto at = ray_canvas(app, 0).screen_of(p);
    REQUIRE(at);
    CHECK(near_colour(host, *at, kHitColour) >= 20);
    return p;
  };
  SECTION("the shared-edge crack: exact hits, float misses") {
    const auto p = marker_only_on_hit_step("05-triangle-crack.md");
    // The float run (right) missed: no marker at the same world point.
    const auto at_float = ray_canvas(app, 1).screen_of(p);
    REQUIRE(at_float);
    CHECK(near_colour(host, *at_float, kHitColour) == 0);
  }
  SECTION("the far sphere, zoomed onto it") {
    marker_only_on_hit_step("06-far-sphere.md");
  }
}

TEST_CASE("visualizer rays: handle_edit3 moves the declared o or o + d", "[visualizer][rays]") {
  const Algorithm& alg = find_algorithm("ray-sphere-stable");
  auto ray_input_edit = [&](const Json& input, std::size_t k, V3 p, double snap) { return handle_edit3(alg, input, k, p, snap); };
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
  HeadlessHost host(kWideW, kWideH);
  App& app = host.app();
  Session& session = app.session();
  const Algorithm& alg = find_algorithm("ray-box");
  REQUIRE(session.open_algorithm(alg, parse_json_text(R"({"ray":{"o":[-3,0.5,0.5],"d":[1,0.25,0.125]},"box":{"min":[0,0,0],"max":[1,1,1]}})", "t"), Numeric::exact));
  host.render();
  session.set_step(session.steps() - 1);
  const Json before = session.model(0)->input();
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
  const TraceModel& m = *session.model(0);
  CHECK(m.input()["ray"]["o"] == before["ray"]["o"]);
  CHECK(m.input()["ray"]["d"] != before["ray"]["d"]);
  CHECK(m.input()["box"] == before["box"]);
  // The trace was re-recorded with the new ray: its geometry carries the edited direction.
  const Scene3 sc = Scene3::from_model(m, {});
  REQUIRE(sc.first_ray);
  CHECK(Json::array({sc.first_ray->second.x, sc.first_ray->second.y, sc.first_ray->second.z}) == m.input()["ray"]["d"]);
  CHECK(session.step() == m.last());  // it was at the end, and stays at the end
  // The o handle is still where the input says.
  const auto o_at = ray_canvas(app, 0).screen_of(o);
  REQUIRE(o_at);
  CHECK(near_colour(host, *o_at, theme::kHandleP0) >= 9);

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
  CHECK(session.model(0)->input() == edited);
}

TEST_CASE("visualizer rays: the GLM orbit camera is a pinhole camera in doubles", "[visualizer][rays]") {
  // Expectations restated from the camera's definition, not from its code: the eye on the sphere
  // of radius dist around the target (yaw around z from +x, pitch above the xy plane), looking
  // at the target; right is horizontal, up completes the frame; a point at depth z and camera
  // offsets (x, y) lands at the rectangle's centre plus focal * (x, -y) / z, focal = 0.5 h / tan(fov / 2).
  OrbitCamera cam;
  cam.target = V3(1.25e8, -0.75e8, 0.5e8);
  cam.yaw = 2.1, cam.pitch = -0.35, cam.dist = 40, cam.fov = 0.9;
  cam.origin = {100, 60}, cam.size = {900, 500};
  const double cy = std::cos(cam.yaw), sy = std::sin(cam.yaw), cp = std::cos(cam.pitch), sp = std::sin(cam.pitch);
  const V3 fwd(-cp * cy, -cp * sy, -sp), right(-sy, cy, 0), up(-sp * cy, -sp * sy, cp);
  const double focal = 0.5 * 500 / std::tan(0.9 / 2), mid_x = 100 + 450, mid_y = 60 + 250;
  CHECK(glm::length(cam.forward() - fwd) < 1e-14);
  CHECK(glm::length(cam.right() - right) < 1e-14);
  CHECK(glm::length(cam.up() - up) < 1e-14);
  CHECK(glm::length(cam.eye() - (cam.target - 40.0 * fwd)) < 1e-6);
  // The view is glm's right-handed lookAt (eye space looks down -z), and to_camera applies it.
  const glm::dmat4 look = glm::lookAt(cam.eye(), cam.target, V3(0, 0, 1)), view = cam.view();
  for (int c = 0; c < 4; ++c) CHECK(glm::length(look[c] - view[c]) <= 1e-9 * (c == 3 ? 1e8 : 1));
  for (const V3& p : {cam.target, cam.target + V3(5, -3, 2), V3(0.0)}) {
    const glm::dvec4 by_matrix = view * glm::dvec4(p, 1.0);
    CHECK(glm::length(V3(by_matrix) - cam.to_camera(p)) <= 1e-7);
  }
  auto screen = [&](V3 p) {
    const auto s = cam.project(p);
    REQUIRE(s);
    return *s;
  };

  SECTION("a point on the view axis projects to the rectangle's centre") {
    for (double along : {-39.0, 0.0, 25.0, 1e7}) {
      const auto s = screen(cam.target + along * fwd);
      CHECK(s[0] == Approx(mid_x).margin(1e-6));
      CHECK(s[1] == Approx(mid_y).margin(1e-6));
    }
  }
  SECTION("offsets right and up move right and up by focal * offset / depth") {
    for (double behind : {0.0, 60.0}) {  // at the target's depth and further away
      const double depth = 40 + behind;
      const auto s = screen(cam.target + behind * fwd + 3.0 * right + 2.0 * up);
      CHECK(s[0] == Approx(mid_x + focal * 3 / depth).margin(1e-5));
      CHECK(s[1] == Approx(mid_y - focal * 2 / depth).margin(1e-5));  // up on screen: y decreases
      const auto l = screen(cam.target + behind * fwd - 0.5 * right - 4.0 * up);
      CHECK(l[0] == Approx(mid_x - focal * 0.5 / depth).margin(1e-5));
      CHECK(l[1] == Approx(mid_y + focal * 4 / depth).margin(1e-5));
    }
    CHECK(cam.units_per_pixel(cam.target) == Approx(40 / focal).epsilon(1e-12));
  }
  SECTION("project then unproject on the facing plane gives the point back, 1e8 from the origin") {
    auto round_trip = [&](V3 p) {
      const auto s = screen(p);
      const V3 q = cam.unproject_on_facing_plane(s[0], s[1], p);
      CHECK(glm::length(q - p) <= 1e-9 * glm::length(p));
      const auto back = screen(q);
      CHECK(back[0] == Approx(s[0]).margin(1e-5));
      CHECK(back[1] == Approx(s[1]).margin(1e-5));
    };
    // Zoomed in on the far target...
    round_trip(cam.target + 3.0 * right - 7.0 * up);
    round_trip(cam.target + 30.0 * fwd - 11.0 * right + 5.0 * up);
    // ...and framing a scene 1e8 across.
    cam.frame(V3(0.0), 1e8);
    for (const V3& p : {V3(1e8, 0, 0), V3(-0.5e8, 0.8e8, 0.3e8), V3(0.2e8, -0.9e8, -0.6e8), V3(0.6e8, 0.6e8, 0.7e8)}) round_trip(p);
    // A screen position off the point's own: the facing plane through p, offset in the camera's axes.
    cam.frame(V3(1e8, 1e8, -1e8), 1);
    const V3 p = cam.target + 0.25 * right;
    const double depth = cam.dist;
    const V3 q = cam.unproject_on_facing_plane(mid_x + 50, mid_y - 20, p);
    CHECK(glm::length(q - (cam.eye() + depth * fwd + (50 * depth / focal) * right + (20 * depth / focal) * up)) <= 1e-6);
  }
  SECTION("a segment crossing the near plane is clipped to it") {
    cam.target = V3(3, -2, 1);  // near the origin: the clipped end lies far off screen, at focal / n pixels per unit
    const double n = cam.near_plane();
    CHECK(n == 40 * 1e-4);
    const V3 e = cam.eye();
    const V3 a = e + 5.0 * fwd + 2.0 * right + 1.0 * up, b = e - 5.0 * fwd - 2.0 * right + 3.0 * up;
    CHECK_FALSE(cam.project(b));
    const double t = (5 - n) / 10;  // where the depth 5 - 10 t reaches the near plane
    const double x = 2 - 4 * t, y = 1 + 2 * t;
    for (bool reversed : {false, true}) {
      const auto s = reversed ? cam.project_segment(b, a) : cam.project_segment(a, b);
      REQUIRE(s);
      const std::array<double, 2> sa = screen(a), sc{mid_x + focal * x / n, mid_y - focal * y / n};
      const std::size_t ia = reversed ? 2 : 0, ic = reversed ? 0 : 2;
      CHECK((*s)[ia] == Approx(sa[0]).margin(1e-6));
      CHECK((*s)[ia + 1] == Approx(sa[1]).margin(1e-6));
      CHECK((*s)[ic] == Approx(sc[0]).epsilon(1e-6));
      CHECK((*s)[ic + 1] == Approx(sc[1]).epsilon(1e-6));
    }
    CHECK_FALSE(cam.project_segment(b, e - 1.0 * fwd));  // wholly behind the near plane
    const auto front = cam.project_segment(a, cam.target);  // wholly in front: both ends as projected
    REQUIRE(front);
    CHECK((*front)[2] == Approx(mid_x).margin(1e-6));
    CHECK((*front)[3] == Approx(mid_y).margin(1e-6));
  }
}
#endif  // SW_HAVE_VISUALIZER
