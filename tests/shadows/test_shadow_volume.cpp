// shadow-volume: exact and filtered counts against the oracle (the casters whose open volume holds
// each pixel's exact point, by segment-triangle tests in rationals); z-fail against exact
// visibility; z-pass failing with the eye inside a volume; the silhouette against a brute-force
// edge count; bad input; and `scene raster --shadows volume`.
#include <catch2/catch.hpp>
#include "refusals.hpp"
#include <filesystem>
#include <map>
#include "catalog.hpp"
#include "cli_harness.hpp"
#include "data_root.hpp"
#include "run.hpp"
#include "shadows/shadow_volume_input.hpp"
#include "corpus.hpp"
#include "tracer/scene_gen.hpp"

using namespace sw;
using namespace sw::shadowspec;

namespace {

std::shared_ptr<const VolumeInput> input_of(const Json& j) { return parse_volume_input(j).p; }

// Exact and filtered against the oracle on one input; returns the exact counts.
VolumePixels against_oracle(const VolumeInput& in) {
  const VolumePixels want = volume_oracle(in);
  VolumePixels exact;
  for (Numeric n : {Numeric::exact, Numeric::filtered}) {
    const VolumePixels got = stenciled(in, n);
    CHECK(got.zfail == want.zfail);
    CHECK(got.zpass == want.zpass);
    CHECK(got.lit == want.lit);
    CHECK(got.casters == want.casters);
    if (n == Numeric::exact) exact = got;
  }
  return exact;
}

}  // namespace

TEST_CASE("shadow-volume: exact and filtered counts equal the oracle's, and z-fail equals exact visibility", "[shadows][volume]") {
  std::int64_t points = 0, shadowed = 0, directional = 0;
  const auto sets = volume_sets();
  for (const VolumeInputRef& in : sets[0].inputs) {
    INFO("light " << in.p->seen->light << " of " << in.p->seen->scene->scene->lights.size());
    const VolumePixels px = against_oracle(*in.p);
    CHECK(px.wrong_fail == 0);
    points += std::int64_t(in.p->seen->points.size());
    for (int v : px.visible) shadowed += v == 0;
    directional += in.p->light.w == 0;
  }
  CHECK(points > 3000);
  CHECK(shadowed > 100);
  CHECK(directional > 0);
}

TEST_CASE("shadow-volume: the hard cases, counted exactly as the oracle counts", "[shadows][volume]") {
  std::int64_t cases = 0, wrong_pass = 0;
  for (const Json& j : testing::corpus("shadows", "shadow-volume")) {
    INFO(j.dump().substr(0, 200));
    const VolumePixels px = against_oracle(*input_of(j));
    CHECK(px.wrong_fail == 0);
    wrong_pass += px.wrong_pass, ++cases;
  }
  CHECK(cases >= 10);
  CHECK(wrong_pass > 0);  // the eye inside a volume
}

TEST_CASE("shadow-volume: generated scenes, counted exactly as the oracle counts", "[shadows][volume]") {
  std::int64_t scenes = 0, wrong_fail = 0, facing = 0;
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    INFO("seed " << seed);
    const Json scene = testing::random_scene(seed, 16, 12);
    if (scene["lights"].empty()) continue;
    std::shared_ptr<const VolumeInput> in;
    try {
      in = input_of(Json{{"scene", scene}, {"size", {16, 12}}, {"stacks", 3}, {"light", 0}});
    } catch (const InputError&) {  // a fisheye or cylindrical camera
      continue;
    }
    const VolumePixels px = against_oracle(*in);
    wrong_fail += px.wrong_fail, ++scenes;
    for (std::size_t k = 0; k < in->seen->points.size(); ++k) facing += in->seen->faces[k];
  }
  CHECK(scenes >= 6);
  CHECK(facing > 300);
  CHECK(wrong_fail == 0);
}

TEST_CASE("shadow-volume: with the eye inside a volume z-pass is wrong and z-fail is not", "[shadows][volume]") {
  const Json base{{"scene", "scenes/eye-in-shadow.json"}, {"size", {40, 30}}, {"stacks", 4}};
  Json pass = base, fail = base;
  pass["method"] = "zpass", fail["method"] = "zfail";
  const auto zp = input_of(pass), zf = input_of(fail);
  const VolumePixels p = against_oracle(*zp), f = against_oracle(*zf);
  CHECK(f.wrong_fail == 0);
  CHECK(p.wrong_pass > 100);  // the slab's volume holds the eye: every count is off by one
  std::int64_t off_by_one = 0, seen = 0;
  for (std::size_t k = 0; k < p.lit.size(); ++k)
    if (p.lit[k] >= 0) ++seen, off_by_one += p.zpass[k] == p.zfail[k] - 1;
  CHECK(off_by_one == seen);
  // z-pass and z-fail agree once the eye leaves the volume (the example's view of spot-lit).
  const auto out = input_of(Json{{"scene", "scenes/spot-lit.json"}, {"size", {32, 24}}, {"stacks", 4}, {"method", "zpass"}});
  const VolumePixels o = stenciled(*out, Numeric::exact);
  CHECK(o.zpass == o.zfail);
  CHECK(o.wrong_pass == 0);
}

TEST_CASE("shadow-volume: the silhouette is the edges between casters and the rest, counted by brute force", "[shadows][volume]") {
  for (const char* scene : {"scenes/spot-lit.json", "scenes/cornell-box.json", "scenes/eye-in-shadow.json"}) {
    INFO(scene);
    const auto in = input_of(Json{{"scene", scene}, {"size", {8, 6}}, {"stacks", 5}});
    const auto& m = in->mesh;
    const pipe::Vec4<Rational>& L = in->light;
    // Each triangle's corners' directed edges, +1 for a caster as wound toward the light.
    std::map<std::pair<std::int32_t, std::int32_t>, std::int64_t> net;
    std::int64_t casters = 0;
    for (std::size_t t = 0; t < m.tris.size(); ++t) {
      auto c = m.tris[t];
      const auto& a = m.corners[std::size_t(c[0])];
      const auto& b = m.corners[std::size_t(c[1])];
      const auto& d = m.corners[std::size_t(c[2])];
      // The light's side by the plane through a, b, d: its normal from the three corners.
      auto xyz = [](const pipe::Vec4<Rational>& p) { return Vec3<Rational>{p.x, p.y, p.z}; };
      Rational side;
      if (a.w == 1 && b.w == 1 && d.w == 1) {
        const Vec3<Rational> n = cross(Vec3<Rational>(xyz(b) - xyz(a)), Vec3<Rational>(xyz(d) - xyz(a)));
        side = dot(n, L.w == 1 ? Vec3<Rational>(xyz(L) - xyz(a)) : xyz(L));
      } else {
        side = shadow::det4(L, a, b, d);  // a plane's wedge: corners at infinity
      }
      if (side == 0 || (side < 0 && m.closed[t])) continue;
      if (side < 0) std::swap(c[1], c[2]);
      ++casters;
      for (int e = 0; e < 3; ++e) ++net[{c[std::size_t(e)], c[std::size_t((e + 1) % 3)]}];
    }
    std::int64_t silhouette = 0;
    for (const auto& [e, n] : net) {
      const auto back = net.find({e.second, e.first});
      const std::int64_t left = n - (back == net.end() ? 0 : back->second);
      silhouette += left > 0;
    }
    const VolumePixels px = stenciled(*in, Numeric::exact);
    CHECK(px.casters == casters);
    CHECK(px.silhouette == silhouette);
    CHECK(px.silhouette < px.casters * 3);  // shared edges cancel
  }
}

TEST_CASE("shadow-volume: bad input is one line naming the problem", "[shadows][volume][input]") {
  const Algorithm& alg = find_algorithm("shadow-volume");
  for (const auto& [text, needle] : std::vector<std::pair<std::string, std::string>>{
           {R"({"scene":"scenes/cornell-box.json","size":[8,8],"light":1})", "input.light"},
           {R"({"scene":"scenes/cornell-box.json","size":[8,8],"method":"zboth"})", "input.method"},
           {R"({"scene":"scenes/cornell-box.json","size":[8,8],"method":1})", "input.method"},
           {R"({"scene":"scenes/cornell-box.json","size":[8,8],"map":{}})", "map"},
           {R"({"scene":"scenes/cornell-box.json","size":[0,8]})", "input.size"},
           {R"({"size":[8,8]})", "scene"}}) {
    testing::expect_refused(alg, text, needle);
  }
}

TEST_CASE("scene raster --shadows volume: z-fail by default, z-pass on request, a line per light", "[shadows][volume][cli]") {
  const auto dir = testing::scratch("scene-raster-volumes");
  const std::string png = (dir / "r.png").string();
  const std::string scene = testing::sh_quote((data_root() / "scenes" / "eye-in-shadow.json").string());
  const testing::Ran fail = testing::run_stepwise("scene raster " + scene + " --size 40x30 --stacks 4 --shadows volume --out " + testing::sh_quote(png));
  INFO(fail.err);
  REQUIRE(fail.status == 0);
  CHECK(fail.out.find("light 0: z-fail") != std::string::npos);
  CHECK(fail.out.find("wrong 0 by z-fail") != std::string::npos);
  const testing::Ran pass = testing::run_stepwise("scene raster " + scene + " --size 40x30 --stacks 4 --shadows volume --volume zpass --out " + testing::sh_quote(png));
  REQUIRE(pass.status == 0);
  CHECK(pass.out.find("light 0: z-pass") != std::string::npos);
  CHECK(pass.out.find("wrong 0 by z-pass") == std::string::npos);
  for (const std::string bad : {" --volume zboth", " --volume zpass --shadows map"}) {
    (void)testing::expect_cli_refused("scene raster " + scene + " --size 16x16 --shadows volume" + bad + " --out " + testing::sh_quote(png), png);
  }
}

#include "pipeline/raster_shade.hpp"
#include "shadows/scene_shadows.hpp"
#include "tracer/history.hpp"
#include "tracer/render.hpp"

TEST_CASE("scene raster --shadows volume: the planned picture is the all-effects one, byte for byte, with fewer passes", "[shadows][volume][planner]") {
  std::int64_t skipped = 0, passes = 0, differ = 0, scenes = 0;
  auto one = [&](const std::shared_ptr<const pipespec::RasterScene>& s) {
    const MapOptions o;
    const SceneShadows planned = scene_shadows(s, ShadowMethod::volume_zfail, o, Numeric::exact, false),
                       all = scene_shadows(s, ShadowMethod::volume_zfail, o, Numeric::exact, true);
    const pipespec::RasterPixels px = pipespec::draw(*s, Numeric::exact);
    for (std::size_t i = 0; i < all.lights.size(); ++i) {
      passes += all.lights[i].pass;
      if (planned.lights[i].pass) continue;
      ++skipped;
      const LightShadows& l = all.lights[i];
      for (std::size_t k = 0; k < l.in->points.size(); ++k)
        if (l.in->faces[k]) CHECK(l.volume.lit[l.in->points[k].pixel] == 1);  // the planner's proof, and z-fail's exact count
    }
    const auto a = tracer::to_rgb8(pipespec::shade_pixels(*s, px, pipespec::Shading::phong, &planned.blocked));
    const auto b = tracer::to_rgb8(pipespec::shade_pixels(*s, px, pipespec::Shading::phong, &all.blocked));
    for (std::size_t k = 0; k < a.size(); ++k) differ += a[k] != b[k];
    ++scenes;
  };
  for (const char* f : {"scenes/diffuse-convex.json", "scenes/glass-spheres.json", "scenes/eye-in-shadow.json", "scenes/spot-lit.json"}) {
    INFO(f);
    std::string name;
    one(pipespec::raster_scene(tracer::scene_input(Json(f), &name), {40, 30, 6}));
  }
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    INFO("seed " << seed);
    std::string name;
    try {
      one(pipespec::raster_scene(tracer::scene_input(testing::random_scene(seed, 20, 15), &name), {20, 15, 4}));
    } catch (const InputError&) {  // a fisheye or cylindrical camera
    }
  }
  CHECK(scenes >= 10);
  CHECK(skipped >= 2);  // the planner does skip passes
  CHECK(differ == 0);   // and the picture's bytes do not change
  WARN(scenes << " scenes, " << skipped << " of " << passes << " volume passes skipped, " << differ << " bytes differ");
}
