// shadow-map: exact and filtered against the oracle (the exact ray cast from the light through every
// texel, with GL's rules); the exact visibility against brute force; bias trading acne for
// peter-panning; PCF's fractions; a point light's cube holding every point; bad input; and
// `scene raster --shadows map`.
#include <catch2/catch.hpp>
#include "refusals.hpp"
#include <filesystem>
#include "catalog.hpp"
#include "cli_harness.hpp"
#include "data_root.hpp"
#include "run.hpp"
#include "shadows/scene_shadows.hpp"

using namespace sw;
using namespace sw::shadowspec;

namespace {

std::shared_ptr<const MapInput> input_of(const std::string& text) { return parse_map_input(Json::parse(text)).p; }

}  // namespace

TEST_CASE("shadow-map: exact and filtered equal the oracle's exact ray casts from the light", "[shadows][map]") {
  std::size_t points = 0, cubes = 0, boxes = 0, cones = 0;
  const auto sets = map_sets();
  for (const MapInputRef& in : sets[0].inputs) {
    const MapPixels want = oracle_pixels(*in.p);
    for (Numeric n : {Numeric::exact, Numeric::filtered}) {
      const MapPixels got = looked_up(*in.p, n);
      CHECK(got.lit == want.lit);
      CHECK(got.fraction == want.fraction);
      CHECK(got.acne == want.acne);
      CHECK(got.peter_panning == want.peter_panning);
    }
    points += in.p->points.size();
    const auto& v = in.p->views;
    cubes += v.cube, boxes += !v.cube && v.views[0].orthographic, cones += !v.cube && !v.views[0].orthographic;
  }
  CHECK(points > 3000);
  CHECK(cubes > 0);
  CHECK(boxes > 0);
  CHECK(cones > 0);
}

TEST_CASE("shadow-map: the exact visibility is the brute-force segment test", "[shadows][map]") {
  for (const char* text : {R"({"scene":"scenes/spot-lit.json","size":[24,18],"stacks":4,"light":1})", R"({"scene":"scenes/glass-spheres.json","size":[24,18],"stacks":4,"light":1})",
                           R"({"scene":"scenes/cornell-box.json","size":[24,24],"light":0})"}) {
    INFO(text);
    const auto in = input_of(text);
    const RasterScene& s = *in->scene;
    const lighting::Light<Rational>& li = s.scene->lights[in->light];
    std::size_t shadowed = 0;
    for (std::size_t k = 0; k < in->points.size(); ++k) {
      const SeenPoint& p = in->points[k];
      const bool directional = li.type == lighting::LightType::directional;
      const Vec3<Rational> d = directional ? li.where : Vec3<Rational>(li.where - p.p);
      bool blocked = false;
      NoProbe none;
      // Every triangle but the point's own, every plane but its own: a hit at t in (0, 1), or t > 0 toward a directional light.
      for (std::size_t t = 0; t < s.tris.size() && !blocked; ++t) {
        const auto& tri = s.tris[t];
        const bool own = tri.object == p.object && (p.prim < 0 || tri.prim == p.prim);
        if (own) continue;
        if (s.objects[std::size_t(tri.object)].kind == tracer::ObjectKind::plane) {
          const auto& o = s.traced.objects[std::size_t(tri.object)];
          const auto h = ray::ray_plane<Rational>({p.p, d}, o.a, o.b, none);
          blocked = h.hit && (directional || h.t < 1);
          continue;
        }
        const std::array<Vec3<Rational>, 3> v{Vec3<Rational>{tri.x[0].x, tri.x[0].y, tri.x[0].z}, Vec3<Rational>{tri.x[1].x, tri.x[1].y, tri.x[1].z},
                                              Vec3<Rational>{tri.x[2].x, tri.x[2].y, tri.x[2].z}};
        const auto h = ray::ray_triangle_watertight<Rational>({p.p, d}, v, none);
        blocked = h.hit && (directional || h.t < 1);
      }
      CHECK(bool(in->reaches[k]) == !blocked);
      shadowed += blocked;
    }
    CHECK(shadowed > 0);
  }
}

TEST_CASE("shadow-map: a bias removes acne and adds peter-panning, monotonically", "[shadows][map]") {
  std::int64_t acne_prev = -1, peter_prev = -1;
  for (const char* bias : {"0", "1/100000", "1/10000", "1/1000", "1/100", "1"}) {
    INFO(bias);
    const auto in = input_of(std::string(R"({"scene":"scenes/spot-lit.json","size":[48,36],"stacks":6,"light":0,"map":{"size":48,"depth_bits":0,"bias":")") + bias + "\"}}");
    const MapPixels m = looked_up(*in, Numeric::exact);
    if (acne_prev >= 0) {
      CHECK(m.acne <= acne_prev);
      CHECK(m.peter_panning >= peter_prev);
    } else {
      CHECK(m.acne > 0);  // no bias: the floor's own depth against itself
    }
    acne_prev = m.acne, peter_prev = m.peter_panning;
  }
  CHECK(acne_prev == 0);    // a bias of 1: everything on the map is called lit
  CHECK(peter_prev > 0);    // so every shadowed point on it is peter-panning
}

TEST_CASE("shadow-map: PCF fractions count the passing taps, softening the shadow's edge", "[shadows][map]") {
  const auto in = input_of(R"({"scene":"scenes/cornell-box.json","size":[48,48],"light":0,"map":{"size":64,"pcf":5,"slope":2}})");
  const MapPixels m = looked_up(*in, Numeric::exact);
  std::size_t soft = 0, on = 0;
  for (std::size_t k = 0; k < m.fraction.size(); ++k) {
    if (m.lit[k] < 0) continue;
    ++on;
    const double f = m.fraction[k];
    CHECK(f >= 0);
    CHECK(f <= 1);
    soft += f > 0 && f < 1;
    // A count of the taps inside the map: 9 to 25 of them.
    bool count = false;
    for (int taps = 9; taps <= 25; ++taps) count = count || std::abs(f * taps - std::round(f * taps)) < 1e-12;
    CHECK(count);
  }
  CHECK(on > 1000);
  CHECK(soft > 20);
  CHECK(m.outside == 0);  // a point light's cube holds every point
}

TEST_CASE("shadow-map: bad input is one line naming the problem", "[shadows][map][input]") {
  const Algorithm& alg = find_algorithm("shadow-map");
  for (const auto& [text, needle] : std::vector<std::pair<std::string, std::string>>{
           {R"({"scene":"scenes/cornell-box.json","size":[8,8],"light":1})", "input.light"},
           {R"({"scene":"scenes/cornell-box.json","size":[8,8],"map":{"pcf":2}})", "input.map.pcf"},
           {R"({"scene":"scenes/cornell-box.json","size":[8,8],"map":{"depth_bits":8}})", "input.map.depth_bits"},
           {R"({"scene":"scenes/cornell-box.json","size":[8,8],"map":{"size":0}})", "input.map.size"},
           {R"({"scene":"scenes/cornell-box.json","size":[8,8],"map":{"slope":"x"}})", "input.map.slope"},
           {R"({"scene":"scenes/cornell-box.json","size":[8,8],"map":{"bias":2}})", "input.map.bias"},
           {R"({"scene":"scenes/cornell-box.json","size":[8,8],"map":{"zz":1}})", "input.map"},
           {R"({"scene":"scenes/tiny-scale.json","size":[8,8]})", "perspective only"}}) {
    testing::expect_refused(alg, text, needle);
  }
}

TEST_CASE("scene raster --shadows map: a pass per light the planner keeps, and bad map options leave no file", "[shadows][map][cli]") {
  const auto dir = testing::scratch("scene-raster-shadows");
  const std::string png = (dir / "r.png").string();
  auto scene = [](const char* f) { return testing::sh_quote((data_root() / "scenes" / f).string()); };
  const testing::Ran planned = testing::run_stepwise("scene raster " + scene("diffuse-convex.json") + " --size 64x48 --shadows map --map-size 64 --out " + testing::sh_quote(png));
  INFO(planned.err);
  REQUIRE(planned.status == 0);
  CHECK(planned.out.find("light 0: no shadow pass") != std::string::npos);  // the planner's proof: convex, separated
  const testing::Ran all = testing::run_stepwise("scene raster " + scene("diffuse-convex.json") + " --size 64x48 --shadows map --map-size 64 --all-effects --out " + testing::sh_quote(png));
  REQUIRE(all.status == 0);
  CHECK(all.out.find("light 0: 1 orthographic view of 64^2") != std::string::npos);
  const testing::Ran cube = testing::run_stepwise("scene raster " + scene("cornell-box.json") + " --size 32x32 --shadows map --map-size 32 --out " + testing::sh_quote(png));
  CHECK(cube.out.find("light 0: 6 cube faces of 32^2") != std::string::npos);
  for (const std::string bad : {" --map-pcf 2", " --map-bits 8", " --map-size 0", " --map-size 4096", " --map-slope 1e9", " --map-bias 2", " --shadows volume-zz"}) {
    (void)testing::expect_cli_refused("scene raster " + scene("cornell-box.json") + " --size 16x16 --shadows map" + bad + " --out " + testing::sh_quote(png), png);
  }
}

#include "pipeline/raster_shade.hpp"
#include "tracer/history.hpp"
#include "tracer/scene_gen.hpp"

namespace {

// Planned against all effects on one scene: the shadow masks differ only for lights the planner
// skipped, and there only at points that face away from the light or where the all-effects map
// is wrong (acne); the pictures differ only at such pixels. Returns the differing pixels.
std::int64_t planned_against_all(const std::shared_ptr<const pipespec::RasterScene>& s, std::int64_t* skipped) {
  const MapOptions o = parse_map_options(Json{{"size", 64}}, "map", kMaxMapSize);
  const SceneShadows planned = scene_shadows(s, o, Numeric::f64, false), all = scene_shadows(s, o, Numeric::f64, true);
  const pipespec::RasterPixels px = pipespec::draw(*s, Numeric::f64);
  std::vector<char> excused(px.objects.size(), 0);
  for (std::size_t i = 0; i < all.lights.size(); ++i) {
    if (planned.lights[i].pass) continue;
    ++*skipped;
    const LightShadows& l = all.lights[i];
    for (std::size_t k = 0; k < l.in->points.size(); ++k) {
      const std::size_t p = l.in->points[k].pixel;
      const bool map_lit = l.map.lit[p] == 1, wrong = map_lit != bool(l.in->reaches[k]);
      if (!l.in->faces[k] || wrong) excused[p] = 1;
      else CHECK(map_lit);  // the planner's proof: nothing shadows a point facing the light
    }
  }
  const auto a = pipespec::shade_pixels(*s, px, pipespec::Shading::phong, &planned.blocked);
  const auto b = pipespec::shade_pixels(*s, px, pipespec::Shading::phong, &all.blocked);
  std::int64_t differ = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!(a[k] == b[k])) {
      ++differ;
      CHECK(excused[k]);
    }
  return differ;
}

}  // namespace

TEST_CASE("scene raster --shadows map: the planned picture is the all-effects one but where that map errs or a point faces away", "[shadows][map][planner]") {
  std::int64_t skipped = 0, differ = 0, scenes = 0;
  for (const char* f : {"scenes/diffuse-convex.json", "scenes/cornell-box.json", "scenes/glass-spheres.json"}) {
    INFO(f);
    std::string name;
    differ += planned_against_all(pipespec::raster_scene(tracer::scene_input(Json(f), &name), {40, 30, 6}), &skipped), ++scenes;
  }
  for (std::uint32_t seed = 1; seed <= 24; ++seed) {
    INFO("seed " << seed);
    std::string name;
    const Json j = testing::random_scene(seed, 20, 15);
    std::shared_ptr<const tracer::Scene> scene;
    try {
      scene = tracer::scene_input(j, &name);
      differ += planned_against_all(pipespec::raster_scene(scene, {20, 15, 4}), &skipped), ++scenes;
    } catch (const InputError&) {  // a fisheye or cylindrical camera
    }
  }
  CHECK(scenes >= 15);
  CHECK(skipped >= 3);  // the planner does skip passes
  WARN(scenes << " scenes, " << skipped << " shadow passes skipped, " << differ << " pixels differ, each where the all-effects map errs or faces away");
}
