// The POV-Ray exporter and peer (runtime/tracer/pov_export.hpp, pov_compare.hpp, passes.hpp):
//  - the id colours decode back, within the rounding POV-Ray may add;
//  - POV's fade (2 / (1 + (d/fd)^p), times the exported colour scale) equals our attenuation
//    1/(k0 + k1 d + k2 d^2) where the mapping claims to be exact;
//  - what does not map is refused with one line naming the JSON path; ids and shadow modes ignore
//    materials, so scenes the image mode refuses still export there;
//  - with povray installed: the object ids of three example scenes at 32x24 differ from ours only on
//    silhouette pixels or where the exact oracle says POV-Ray is wrong; glass-spheres' shadow masks only
//    where lighting grazes, on the mask's edges or where POV-Ray is wrong;
//  - the CLI: a .pov file, and bad input refused with one line, exit 2 and no file.
#include <catch2/catch.hpp>
#include "peers.hpp"
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include "cli_harness.hpp"
#include "tracer/passes.hpp"
#include "tracer/pov_compare.hpp"
#include "tracer/pov_export.hpp"
#include "tracer/render.hpp"
#include "source_paths.hpp"

using namespace sw;
using sw::testing::kScenes;
namespace fs = std::filesystem;

namespace {

tracer::Scene example(const std::string& name) { return tracer::read_scene_file((kScenes / (name + ".json")).string()); }

std::string refusal(const tracer::Scene& s, tracer::PovMode mode) {
  tracer::PovOptions o;
  o.mode = mode;
  try {
    tracer::export_pov(s, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("POV-Ray id colours decode back", "[tracer][povray]") {
  for (int id = 0; id <= tracer::kMaxPovIds; ++id) {
    const auto c = tracer::pov_id_colour(id);
    REQUIRE((c[0] | c[1] | c[2]) != 0);  // never the background's black
    for (const int off : {-4, 0, 4}) {
      auto ch = [&](std::uint8_t v) { return static_cast<std::uint8_t>(std::clamp(int(v) + off, 0, 255)); };
      REQUIRE(tracer::pov_id_of(ch(c[0]), ch(c[1]), ch(c[2])) == id);
    }
  }
  CHECK(tracer::pov_id_of(0, 0, 0) == -1);
  CHECK(tracer::pov_id_of(0, 0, 8) == -2);  // halfway between two levels: no id
}

TEST_CASE("POV-Ray fade equals our attenuation where the mapping is exact", "[tracer][povray]") {
  struct Case {
    std::string scene;
    double k0, k1, k2;
  };
  for (const Case& c : {Case{"cornell-box", 1, 0, 0.02}, Case{"mirror-room", 1, 0.1, 0}}) {
    const tracer::PovScene pov = tracer::export_pov(example(c.scene), tracer::PovOptions{});
    INFO(c.scene);
    CHECK(pov.approximations.empty());
    std::smatch m;
    REQUIRE(std::regex_search(
        pov.text, m, std::regex("light_source \\{ <[^>]*> color rgb <([^,]*),[^>]*> fade_distance ([^ ]*) fade_power ([12])")));
    const double scale = std::stod(m[1]), fd = std::stod(m[2]), p = std::stod(m[3]);
    for (const double d : {0.25, 1.0, 3.0, 10.0, 40.0}) {
      const double povray = scale * 2 / (1 + std::pow(d / fd, p)), ours = 1 / (c.k0 + c.k1 * d + c.k2 * d * d);
      CHECK(povray == Approx(ours).epsilon(1e-12));
    }
  }
}

TEST_CASE("POV-Ray export refuses what does not map, naming the JSON path", "[tracer][povray]") {
  CHECK(refusal(example("tiny-scale"), tracer::PovMode::ids).rfind("scene.camera.projection: fisheye", 0) == 0);
  CHECK(refusal(example("panorama"), tracer::PovMode::shadow).rfind("scene.camera.projection: cylindrical", 0) == 0);
  CHECK(refusal(example("diffuse-convex"), tracer::PovMode::image).rfind("scene.materials.", 0) == 0);
  CHECK(refusal(example("textured"), tracer::PovMode::image).find("texture") != std::string::npos);
  CHECK(refusal(example("bunny"), tracer::PovMode::image).find("scene.materials.clay.specular_model") == 0);
  for (const char* name : {"diffuse-convex", "textured", "bunny"})  // materials play no part in ids and shadows
    for (const auto mode : {tracer::PovMode::ids, tracer::PovMode::shadow}) CHECK(refusal(example(name), mode).empty());
  tracer::PovOptions o;
  o.mode = tracer::PovMode::shadow, o.light = 1;
  CHECK_THROWS_WITH(tracer::export_pov(example("cornell-box"), o), Catch::Contains("--light"));
  // A glass material maps with its approximation flagged, and the checker floor exactly.
  const tracer::PovScene glass = tracer::export_pov(example("glass-spheres"), {});
  CHECK(glass.approximations.size() == 2);  // glass and water: POV transmits kt
  CHECK(glass.text.find("checker") != std::string::npos);
}

TEST_CASE("POV-Ray object ids differ from ours only on silhouettes or where POV-Ray is wrong", "[tracer][povray]") {
  SW_REQUIRE_PEER(tracer::povray_available(), "povray");
  const auto dir = testing::scratch("povray-ids");
  for (const char* name : {"cornell-box", "glass-spheres", "diffuse-convex"}) {
    INFO(name);
    const tracer::Scene s = example(name);
    const std::int64_t w = 32, h = 24;
    tracer::PovOptions o;
    o.mode = tracer::PovMode::ids, o.width = w, o.height = h;
    const std::string pov = (dir / (std::string(name) + ".pov")).string(), png = (dir / (std::string(name) + ".png")).string();
    std::ofstream(pov) << tracer::export_pov(s, o).text;
    tracer::run_povray(pov, png, w, h);
    const std::vector<int> theirs = tracer::read_pov_ids(png), ours = tracer::object_id_pass(tracer::trace_scene(s, w, h));
    REQUIRE(theirs.size() == ours.size());
    const tracer::IdCounts c = tracer::compare_ids(s, w, h, ours, theirs);
    CHECK(c.unknown_colour == 0);
    CHECK(c.unexplained == 0);
    CHECK(c.differ <= c.silhouette + c.pov_wrong_inside);
    INFO("differ " << c.differ << ", POV right " << c.pov_right << ", ours right " << c.ours_right << ", ties " << c.both_right
                   << ", both wrong " << c.both_wrong);
    // The camera maps to the pixel: off by half a pixel, POV-Ray would be wrong along every edge.
    CHECK(c.ours_right + c.both_wrong <= c.pixels / 200);
    CHECK(c.differ * 10 < c.pixels);
    CHECK(std::count(ours.begin(), ours.end(), -1) < std::int64_t(ours.size()));  // something is seen
    // Each light's shadow mask: differences are grazing, on the mask's edge, or POV-Ray's error.
    // (glass-spheres only: a point and a directional light; each povray run costs about 0.6 s.)
    for (std::size_t l = 0; std::string(name) == "glass-spheres" && l < s.lights.size(); ++l) {
      INFO("light " << l);
      o.mode = tracer::PovMode::shadow, o.light = l;
      const std::string spov = (dir / (std::string(name) + "-shadow.pov")).string(),
                        spng = (dir / (std::string(name) + "-shadow.png")).string();
      std::ofstream(spov) << tracer::export_pov(s, o).text;
      tracer::run_povray(spov, spng, w, h);
      const tracer::ShadowPass mine = tracer::shadow_pass(tracer::trace_scene(s, w, h), l);
      const tracer::ShadowCounts sc =
          tracer::compare_shadows(s, w, h, l, ours, theirs, mine.lit, mine.cosine, tracer::read_pov_lit(spng));
      CHECK(sc.compared > 0);
      CHECK(std::count(mine.lit.begin(), mine.lit.end(), 1) > 0);
      INFO("differ " << sc.differ << ", grazing " << sc.grazing << ", edge " << sc.silhouette << ", POV right " << sc.pov_right
                     << ", ours right " << sc.ours_right);
      CHECK(sc.unexplained == 0);
      CHECK(sc.pov_right * 200 <= sc.compared);
      CHECK(sc.ours_right * 200 <= sc.compared);  // an exported light 0.5 off makes POV-Ray wrong on 9 of 675
      CHECK(sc.differ * 20 <= sc.compared);
    }
  }
}

TEST_CASE("scene export-pov on the command line", "[tracer][povray][cli]") {
  const auto dir = testing::scratch("export-pov");
  const auto out = dir / "x.pov";
  const auto ok = testing::run_stepwise("scene export-pov " + (kScenes / "cornell-box.json").string() +
                                        " --mode shadow --light 0 --out " + out.string());
  CHECK(ok.status == 0);
  const std::string text = testing::slurp(out);
  CHECK(text.find("camera { perspective") != std::string::npos);
  CHECK(std::count(text.begin(), text.end(), '\n') > 10);
  const auto bad_out = dir / "bad.pov";
  struct Bad {
    std::string scene, args, expect;
  };
  for (const Bad& b :
       {Bad{"tiny-scale", "", "scene.camera.projection"}, Bad{"diffuse-convex", "--mode image", "scene.materials."},
        Bad{"cornell-box", "--mode shadow --light 3", "--light"}, Bad{"cornell-box", "--mode sideways", "mode"},
        Bad{"cornell-box", "--size 0x3", "--size"}}) {
    const auto r = testing::run_stepwise("scene export-pov " + (kScenes / (b.scene + ".json")).string() + " " + b.args +
                                         " --out " + bad_out.string());
    INFO(b.scene << " " << b.args << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find(b.expect) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(bad_out));
  }
}
