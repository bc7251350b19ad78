// The renderer (runtime/tracer/render.hpp) and the planner (plan.hpp):
//  - skipping is free: the planned render is byte-identical to the all-effects render on every
//    example scene and on 200 generated ones, and casts no more rays (fewer on most);
//  - no shadow acne: on hard scenes a lone convex object never shadows itself with robust offsets,
//    while the naive offsets do (so the check can fail);
//  - determinism: the same bytes on 1 and 2 threads;
//  - the CLI: a summary, and bad input refused with one line, exit 2 and no image.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include "cli_harness.hpp"
#include "scale.hpp"
#include "scene_gen.hpp"
#include "tracer/plan.hpp"
#include "tracer/render.hpp"
#include "source_paths.hpp"

using namespace sw;
using sw::testing::kScenes;
namespace fs = std::filesystem;

namespace {

tracer::Scene scene_of(const Json& j) {
  tracer::SceneOptions opt;
  return tracer::parse_scene(j, opt);
}

tracer::RenderResult render(const tracer::Scene& s, bool all, int w, int h, unsigned threads = 0, tracer::Offset off = tracer::Offset::robust) {
  tracer::RenderOptions o;
  o.width = w, o.height = h, o.all_effects = all, o.threads = threads, o.offset = off, o.spp = 1;
  return tracer::render(s, o);
}

// A lone convex object lit from a grazing direction, at a scale.
Json lone(const std::string& kind, double scale, const Json& light) {
  Json obj;
  if (kind == "sphere") obj = {{"type", "sphere"}, {"center", {scale, 2 * scale, -scale}}, {"radius", scale}};
  else if (kind == "box") obj = {{"type", "box"}, {"min", {-scale, 0, -scale}}, {"max", {scale, 1.5 * scale, 0.7 * scale}}};
  else obj = {{"type", "triangle"}, {"vertices", {{-2 * scale, 0, 0}, {2 * scale, 0.25 * scale, -scale}, {0, 3 * scale, -0.5 * scale}}}};
  obj["material"] = "m";
  return {{"camera", {{"eye", {0.5 * scale, 2 * scale, 8 * scale}}, {"vpn", {0, 0.1, 1}}, {"vup", {0, 1, 0}}, {"d", 1}, {"fov", 40}, {"resolution", {64, 48}}}},
          {"materials", {{"m", {{"diffuse", {0.8, 0.8, 0.8}}}}}},
          {"lights", {light}},
          {"objects", {obj}},
          {"max_depth", 1}};  // primary hits only: all on the outside, where no self-shadow exists
}

}  // namespace

TEST_CASE("planned renders are byte-identical to all-effects renders on the example scenes", "[tracer][planner]") {
  for (const auto& e : fs::directory_iterator(kScenes)) {
    if (e.path().extension() != ".json") continue;
    DYNAMIC_SECTION(e.path().filename().string()) {
      const tracer::Scene s = tracer::read_scene_file(e.path().string());
      const auto planned = render(s, false, 48, 36), all = render(s, true, 48, 36);
      CHECK(tracer::to_rgb8(planned) == tracer::to_rgb8(all));
      CHECK(planned.counts.total() < all.counts.total());  // every example has a material without mirror or glass
      CHECK(planned.counts.primary == all.counts.primary);
    }
  }
}

TEST_CASE("planned renders are byte-identical to all-effects renders on 200 generated scenes", "[tracer][planner]") {
  int fewer = 0, shadows_off = 0;
  for (std::uint32_t seed = 1; seed <= sw::testing::cases(200u); ++seed) {
    const tracer::Scene s = scene_of(testing::random_scene(seed, 20, 15));
    const auto planned = render(s, false, 20, 15), all = render(s, true, 20, 15);
    INFO("seed " << seed);
    REQUIRE(tracer::to_rgb8(planned) == tracer::to_rgb8(all));
    REQUIRE(planned.counts.total() <= all.counts.total());
    fewer += planned.counts.total() < all.counts.total();
    for (const tracer::Decision& d : planned.plan.decisions) shadows_off += d.effect == "shadows" && !d.on;
  }
  CHECK(fewer >= sw::testing::cases(100));  // 122 of 200 at this writing: max_depth 1 and shadow-casting scenes save nothing
  CHECK(shadows_off >= sw::testing::cases(10));  // and the shadow proof succeeds on some sparse ones
}

TEST_CASE("the planner turns shadows off only with a proof", "[tracer][planner]") {
  const tracer::Scene convex = tracer::read_scene_file((kScenes / "diffuse-convex.json").string());
  const tracer::Plan p = tracer::plan_scene(convex);
  REQUIRE(p.decisions.at(0).effect == "shadows");
  CHECK_FALSE(p.decisions[0].on);
  CHECK_FALSE(p.effects.shadows[0]);
  // A sphere over a plane, lit from above, shadows it: on.
  Json j = lone("sphere", 1, {{"type", "directional"}, {"direction", {0, 1, 0}}});
  j["objects"].push_back({{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "m"}});
  const tracer::Plan q = tracer::plan_scene(scene_of(j));
  CHECK(q.decisions.at(0).on);
  CHECK(q.decisions[0].reason.find("may lie between") != std::string::npos);
  // Lit from below the plane, the sphere cannot come between the plane and the light... but the
  // plane can between the sphere and the light: still on, with the plane named.
  j["lights"][0]["direction"] = {0, -1, 0};
  CHECK(tracer::plan_scene(scene_of(j)).decisions.at(0).on);
}

TEST_CASE("the planner's proof for boxes: a gap within 2^-30 M proves nothing, a point light's region reaches it", "[tracer][planner]") {
  // Two boxes side by side under a light straight above: each one's shadow falls straight down,
  // so the other is harmless when a gap separates them along x. The margin is 2^-30 of the largest
  // coordinate (8 here: 7.5e-9); a gap of 2^-34 is within it and proves nothing
  // (docs/tracer/planner.md). (Next to a plane the margin never decides: a plane and any object
  // always have one pair, plane or object as the receiver, that may shadow.)
  auto scene = [](double gap) {
    return scene_of({{"camera", {{"eye", {0, 4, 8}}, {"vpn", {0, 0.5, 1}}, {"vup", {0, 1, 0}}, {"d", 1}, {"fov", 40}, {"resolution", {32, 24}}}},
                     {"materials", {{"m", {{"diffuse", {0.8, 0.8, 0.8}}}}}},
                     {"lights", {{{"type", "directional"}, {"direction", {0, 1, 0}}}}},
                     {"objects", {{{"type", "box"}, {"min", {-2, 0, -1}}, {"max", {-1, 1, 1}}, {"material", "m"}},
                                  {{"type", "box"}, {"min", {-1 + gap, 0, -1}}, {"max", {1, 2, 1}}, {"material", "m"}}}},
                     {"max_depth", 1}});
  };
  CHECK_FALSE(tracer::plan_scene(scene(0.5)).effects.shadows.at(0));            // apart
  CHECK(tracer::plan_scene(scene(std::ldexp(1.0, -34))).effects.shadows.at(0));  // within the margin
  CHECK(tracer::plan_scene(scene(0)).effects.shadows.at(0));                     // touching
  // Skipping stays free on them: the planned render is the all-effects one.
  for (double gap : {0.5, std::ldexp(1.0, -34), 0.0}) {
    const tracer::Scene s = scene(gap);
    CHECK(render(s, false, 32, 24).rgb == render(s, true, 32, 24).rgb);
  }
  // A point light's shadow region reaches the light: a box hanging between another and the light
  // shadows it (on), one beside the way does not (off).
  auto hanging = [](double x) {
    return scene_of({{"camera", {{"eye", {0, 4, 8}}, {"vpn", {0, 0.5, 1}}, {"vup", {0, 1, 0}}, {"d", 1}, {"fov", 40}, {"resolution", {32, 24}}}},
                     {"materials", {{"m", {{"diffuse", {0.8, 0.8, 0.8}}}}}},
                     {"lights", {{{"type", "point"}, {"position", {0, 10, 0}}}}},
                     {"objects", {{{"type", "box"}, {"min", {-1, 0, -1}}, {"max", {1, 1, 1}}, {"material", "m"}},
                                  {{"type", "box"}, {"min", {x - 0.5, 3, -0.5}}, {"max", {x + 0.5, 4, 0.5}}, {"material", "m"}}}},
                     {"max_depth", 1}});
  };
  const tracer::Scene between = hanging(0);
  CHECK(tracer::plan_scene(between).effects.shadows.at(0));
  CHECK(render(between, false, 32, 24).rgb == render(between, true, 32, 24).rgb);
  CHECK_FALSE(tracer::plan_scene(hanging(6)).effects.shadows.at(0));
}

TEST_CASE("no shadow acne: a lone convex object never shadows itself with robust offsets", "[tracer][acne]") {
  std::uint64_t naive_blocked = 0;
  for (const char* kind : {"sphere", "box", "triangle"})
    for (double scale : {1e-6, 1.0, 1e6})
      for (const Json& light : {Json{{"type", "directional"}, {"direction", {1, 0.001, 0.3}}},  // grazing
                                Json{{"type", "point"}, {"position", {3 * scale, 5 * scale, 4 * scale}}}}) {
        const tracer::Scene s = scene_of(lone(kind, scale, light));
        const auto r = render(s, true, 64, 48, 0, tracer::Offset::robust);
        INFO(kind << " at scale " << scale << ", light " << light.dump());
        CHECK(r.counts.shadow > 0);
        CHECK(r.counts.shadow_blocked == 0);
        naive_blocked += render(s, true, 64, 48, 0, tracer::Offset::none).counts.shadow_blocked;
      }
  CHECK(naive_blocked > 100);  // the origin at the computed point self-shadows: acne
}

TEST_CASE("renders do not depend on the thread count", "[tracer]") {
  for (const char* name : {"glass-spheres.json", "textured.json", "cornell-box.json"}) {
    const tracer::Scene s = tracer::read_scene_file((kScenes / name).string());
    tracer::RenderOptions o;
    o.width = 40, o.height = 30, o.threads = 1;
    const auto one = tracer::to_rgb8(tracer::render(s, o));
    o.threads = 2;
    CHECK(one == tracer::to_rgb8(tracer::render(s, o)));
  }
}

TEST_CASE("a hall of mirrors finishes within max_depth and the ray budget", "[tracer]") {
  // Off-centre, so that no ray meets an edge exactly (where a box has no normal, and a mirror ray may leave).
  Json j = {{"camera", {{"eye", {0.1, 0.05, 0.03}}, {"vpn", {0, 0, 1}}, {"vup", {0, 1, 0}}, {"d", 1}, {"fov", 60}, {"resolution", {8, 6}}}},
            {"materials", {{"mirror", {{"kr", 1}, {"diffuse", {0, 0, 0}}}}}},
            {"lights", {{{"type", "point"}, {"position", {0, 0, 0}}}}},
            {"objects", {{{"type", "box"}, {"min", {-1, -1, -1}}, {"max", {1, 1, 1}}, {"material", "mirror"}}}},
            {"max_depth", 16}, {"rays_per_pixel", 10}};
  const tracer::Scene s = scene_of(j);
  const auto r = render(s, false, 8, 6);
  CHECK(r.counts.reflection == 8 * 6 * 9);  // 1 primary + 9 mirror rays spend each pixel's budget of 10
  CHECK(r.budget_pixels == 8 * 6);
}

TEST_CASE("scene render and plan on the command line", "[tracer][cli]") {
  const auto dir = testing::scratch("scene-render");
  const std::string scene = (kScenes / "diffuse-convex.json").string();
  const auto out = dir / "x.png";
  const auto ok = testing::run_stepwise("scene render " + scene + " --size 32x24 --out " + out.string());
  CHECK(ok.status == 0);
  CHECK(fs::exists(out));
  CHECK(ok.out.find("19200") == std::string::npos);  // --size replaced the resolution
  CHECK(ok.out.find("768 primary") != std::string::npos);
  const auto plan = testing::run_stepwise("scene plan " + scene + " --json");
  CHECK(plan.status == 0);
  CHECK(Json::parse(plan.out)["decisions"][0]["on"] == false);
  struct Bad {
    std::string args, expect;
  };
  const auto bad_out = dir / "bad.png";
  for (const Bad& b : {Bad{"--size 0x10", "--size"}, Bad{"--size 10", "--size"}, Bad{"--size 9000x10", "--size"}, Bad{"--spp 3", "--spp"},
                       Bad{"--spp 4 --adaptive", "exclude"}, Bad{"--offset sideways", "offset"}}) {
    const auto r = testing::run_stepwise("scene render " + scene + " " + b.args + " --out " + bad_out.string());
    INFO(b.args << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find(b.expect) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(bad_out));
  }
  const auto missing = testing::run_stepwise("scene render " + (dir / "none.json").string() + " --out " + bad_out.string());
  CHECK(missing.status == 2);
  CHECK_FALSE(fs::exists(bad_out));
}

TEST_CASE("render: adaptive sampling refines exactly the pixels its definition names", "[tracer][render][adaptive]") {
  // The definition: a pixel is refined when its centre sample differs from a 4-neighbour's by more
  // than the threshold (1/16 by default) in some channel, both clamped to [0, 1]. The centre samples
  // are a 1-sample render's; the sphere's outline gives horizontal and vertical edges alike.
  const tracer::Scene s = scene_of(lone("sphere", 1, {{"type", "directional"}, {"direction", {1, 1, 1}}}));
  const tracer::RenderResult centre = render(s, false, 64, 48);
  tracer::RenderOptions o;
  o.width = 64, o.height = 48, o.adaptive = true;
  const tracer::RenderResult adaptive = tracer::render(s, o);
  auto differs = [&](std::size_t a, std::size_t b) {
    for (int k = 0; k < 3; ++k)
      if (std::abs(std::clamp(centre.rgb[a][k], 0.0, 1.0) - std::clamp(centre.rgb[b][k], 0.0, 1.0)) > 1.0 / 16) return true;
    return false;
  };
  std::uint64_t want = 0;
  std::size_t changed = 0;
  for (std::size_t j = 0; j < 48; ++j)
    for (std::size_t i = 0; i < 64; ++i) {
      const std::size_t p = j * 64 + i;
      const bool refine = (i > 0 && differs(p, p - 1)) || (i < 63 && differs(p, p + 1)) || (j > 0 && differs(p, p - 64)) || (j < 47 && differs(p, p + 64));
      want += refine;
      // A pixel not refined keeps its centre sample exactly.
      if (!refine) changed += !(adaptive.rgb[p] == centre.rgb[p]);
    }
  REQUIRE(want > 20);  // the outline is there to refine
  CHECK(adaptive.refined_pixels == want);
  CHECK(changed == 0);
}

TEST_CASE("render: adaptive sampling refines only differences strictly above the threshold", "[tracer][render][adaptive]") {
  // An emitting sphere of exactly 1/4 on a black background: every outline difference is exactly
  // 1/4. At threshold 1/4 nothing is refined; just below it, the outline is.
  auto scene = [](double threshold) {
    return scene_of({{"camera", {{"eye", {0, 0, 8}}, {"vpn", {0, 0, 1}}, {"vup", {0, 1, 0}}, {"d", 1}, {"fov", 40}, {"resolution", {32, 24}}}},
                     {"materials", {{"m", {{"emission", {0.25, 0.25, 0.25}}, {"ambient", {0, 0, 0}}, {"diffuse", {0, 0, 0}}}}}},
                     {"ambient", {0, 0, 0}},
                     {"lights", Json::array()},
                     {"objects", {{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1.5}, {"material", "m"}}}},
                     {"sampling", {{"type", "adaptive"}, {"threshold", threshold}, {"max_n", 4}}}});
  };
  tracer::RenderOptions o;
  o.adaptive = true;
  const tracer::RenderResult at = tracer::render(scene(0.25), o);
  std::size_t lit = 0;
  for (const auto& c : at.rgb) lit += c.x == 0.25;
  REQUIRE(lit > 20);  // the sphere is there, at exactly 1/4
  CHECK(at.refined_pixels == 0);
  CHECK(tracer::render(scene(0.2499), o).refined_pixels > 20);
}
