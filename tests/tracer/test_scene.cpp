// The ray tracer's scene reader (runtime/tracer/scene.hpp): every example scene parses, each class
// of bad input is refused with one line naming its JSON path, and `stepwise scene check` exits 2
// with one line on a bad scene.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include "cli_harness.hpp"
#include "tracer/scene.hpp"
#include "source_paths.hpp"

using namespace sw;
using sw::testing::kScenes;
namespace fs = std::filesystem;

namespace {

// A small valid scene; each bad case patches it with a JSON merge patch (RFC 7386).
Json base_scene() {
  return Json::parse(R"({
    "camera": {"eye": [0, 1, 5], "vpn": [0, 0, 1], "vup": [0, 1, 0], "d": 1, "fov": 60, "resolution": [8, 6]},
    "textures": {"check": {"type": "checker"}},
    "materials": {"white": {"diffuse": [0.8, 0.8, 0.8]}, "glass": {"kt": "9/10", "ior": 1.5}},
    "lights": [{"type": "point", "position": [0, 5, 5]}],
    "objects": [{"type": "sphere", "center": [0, 1, 0], "radius": 1, "material": "glass"},
                {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"}]
  })");
}

std::string error_of(const Json& scene, const std::string& dir = ".") {
  try {
    tracer::SceneOptions opt;
    opt.base_dir = dir;
    (void)tracer::parse_scene(scene, opt);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("scene: every example scene parses", "[scene]") {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(kScenes)) {
    if (e.path().extension() != ".json") continue;
    INFO(e.path().string());
    const tracer::Scene s = tracer::read_scene_file(e.path().string());
    CHECK(!s.objects.empty());
    CHECK(!s.materials.empty());
    ++n;
  }
  CHECK(n >= 8);
}

TEST_CASE("scene: the examples hold what the summary counts", "[scene]") {
  const tracer::Scene bunny = tracer::read_scene_file((kScenes / "bunny.json").string());
  REQUIRE(bunny.meshes.size() == 1);
  CHECK(bunny.mesh_triangles == 75408);
  const tracer::Scene glass = tracer::read_scene_file((kScenes / "glass-spheres.json").string());
  const Json sum = tracer::scene_summary(glass);
  CHECK(sum["objects"]["sphere"] == 3);
  CHECK(sum["transparent_materials"] == Json::array({"glass", "water"}));
  CHECK(sum["mirror_materials"] == Json::array({"chrome", "glass"}));
  CHECK(sum["sampling"]["samples_per_pixel"] == 16);
  const tracer::Scene cornell = tracer::read_scene_file((kScenes / "cornell-box.json").string());
  CHECK(cornell.camera.has_window);
  CHECK(cornell.camera.window[0].q == Rational(-1, 2));
  const tracer::Scene tiny = tracer::read_scene_file((kScenes / "tiny-scale.json").string());
  CHECK(tiny.objects[1].radius.q == Rational(1, 1000000));  // exact, not the double near 1e-6
  CHECK(tiny.objects[1].radius.d == 1e-6);
  CHECK(error_of(base_scene()).empty());
}

TEST_CASE("scene: each bad input is one line naming its JSON path", "[scene]") {
  struct Case {
    const char* patch;  // merged into the base scene
    const char* expect; // the start of the message
  };
  const Case cases[] = {
      {R"({"colour": 1})", "scene: unknown field \"colour\""},
      {R"({"camera": {"zoom": 2}})", "scene.camera: unknown field \"zoom\""},
      {R"({"camera": {"eye": null}})", "scene.camera: missing field \"eye\""},
      {R"({"camera": {"eye": [0, "x", 0]}})", "scene.camera.eye[1]:"},
      {R"({"camera": {"eye": [0, "NaN", 0]}})", "scene.camera.eye[1]: not a finite number"},
      {R"({"camera": {"eye": [0, "Infinity", 0]}})", "scene.camera.eye[1]: not a finite number"},
      {R"({"camera": {"eye": [0, 1e16, 0]}})", "scene.camera.eye[1]:"},
      {R"({"camera": {"vpn": [0, 0, 0]}})", "scene.camera.vpn: zero-length direction"},
      {R"({"camera": {"vup": [0, 0, "1/3"], "vpn": [0, 0, "2/7"]}})", "scene.camera.vup: parallel to vpn"},
      {R"({"camera": {"fov": null, "window": [1, 1, 0, 1]}})", "scene.camera.window: umin must be < umax"},
      {R"({"camera": {"fov": null, "window": [0, 1, 2, 1]}})", "scene.camera.window: vmin must be < vmax"},
      {R"({"camera": {"window": [0, 1, 0, 1]}})", "scene.camera: give exactly one of \"fov\""},
      {R"({"camera": {"fov": 180}})", "scene.camera.fov: must be <= 179"},
      {R"({"camera": {"d": 0}})", "scene.camera.d: must be > 0"},
      {R"({"camera": {"projection": "ortho"}})", "scene.camera.projection: unknown projection 'ortho'"},
      {R"({"camera": {"resolution": [0, 6]}})", "scene.camera.resolution[0]:"},
      {R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 0, "material": "white"}]})", "scene.objects[0].radius: must be > 0"},
      {R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": -2, "material": "white"}]})", "scene.objects[0].radius: must be > 0"},
      {R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "gold"}]})", "scene.objects[0].material: unknown material 'gold'"},
      {R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "material": "white"}]})", "scene.objects[0]: missing field \"radius\""},
      {R"({"objects": [{"type": "torus", "material": "white"}]})", "scene.objects[0].type: unknown object type 'torus'"},
      {R"({"objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 0], "material": "white"}]})", "scene.objects[0].normal: zero-length direction"},
      {R"({"objects": [{"type": "box", "min": [0, 2, 0], "max": [1, 1, 1], "material": "white"}]})", "scene.objects[0].max[1]: below min[1]"},
      {R"({"objects": [{"type": "triangle", "vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]], "material": "white"}]})", "scene.objects[0].vertices: the vertices are collinear"},
      {R"({"objects": [{"type": "mesh", "file": "no-such.off", "material": "white"}]})", "scene.objects[0].file: 'no-such.off' is missing"},
      {R"({"objects": [{"type": "mesh", "file": "/etc/passwd", "material": "white"}]})", "scene.objects[0].file: '/etc/passwd' is absolute"},
      {R"({"objects": []})", "scene.objects: expected a non-empty array"},
      {R"({"materials": {"white": {"diffuse_model": "phong"}}})", "scene.materials.white.diffuse_model: unknown model 'phong'"},
      {R"({"materials": {"white": {"specular_model": "glossy"}}})", "scene.materials.white.specular_model: unknown model 'glossy'"},
      {R"({"materials": {"white": {"kr": "1/2", "kt": "3/5"}}})", "scene.materials.white: kr + kt = 11/10 exceeds 1"},
      {R"({"materials": {"white": {"kr": 0.1, "kt": 0.9}}})", "scene.materials.white: kr + kt = 36028797018963969/36028797018963968 exceeds 1"},
      {R"({"materials": {"white": {"kr": 1.5}}})", "scene.materials.white.kr: must be <= 1"},
      {R"({"materials": {"white": {"ior": 0.5}}})", "scene.materials.white.ior: must be >= 1"},
      {R"({"materials": {"white": {"texture": "wood"}}})", "scene.materials.white.texture: unknown texture 'wood'"},
      {R"({"materials": {"white": {"bump": {"amplitude": 0, "scale": 1}}}})", "scene.materials.white.bump.amplitude: must be > 0"},
      {R"({"materials": {"white": {"shine": 3}}})", "scene.materials.white: unknown field \"shine\""},
      {R"({"materials": {"white": {"diffuse": [1, -1, 1]}}})", "scene.materials.white.diffuse[1]: must be >= 0"},
      {R"({"textures": {"check": {"type": "image", "file": "missing.png"}}})", "scene.textures.check.file: 'missing.png' is missing"},
      {R"({"textures": {"check": {"type": "plaid"}}})", "scene.textures.check.type: unknown texture type 'plaid'"},
      {R"({"textures": {"check": {"type": "marble", "seed": -1}}})", "scene.textures.check.seed:"},
      {R"({"lights": [{"type": "spot", "position": [0, 1, 0], "spot_direction": [0, 0, 0], "cutoff": 30}]})", "scene.lights[0].spot_direction: zero-length direction"},
      {R"({"lights": [{"type": "directional", "direction": [0, 0, 0]}]})", "scene.lights[0].direction: zero-length direction"},
      {R"({"lights": [{"type": "point", "position": [0, 1, 0], "attenuation": [0, 0, 0]}]})", "scene.lights[0].attenuation: all three factors are 0"},
      {R"({"lights": [{"type": "point", "position": [0, 1, 0], "attenuation": [1, -1, 0]}]})", "scene.lights[0].attenuation[1]: must be >= 0"},
      {R"({"lights": [{"type": "spot", "position": [0, 1, 0], "spot_direction": [0, -1, 0], "cutoff": 120}]})", "scene.lights[0].cutoff: degrees in [0, 90]"},
      {R"({"lights": [{"type": "area"}]})", "scene.lights[0].type: unknown light type 'area'"},
      {R"({"max_depth": 17})", "scene.max_depth:"},
      {R"({"max_depth": 0})", "scene.max_depth:"},
      {R"({"sampling": {"type": "regular", "n": 17}})", "scene.sampling.n:"},
      {R"({"sampling": {"type": "adaptive", "threshold": 0, "max_n": 4}})", "scene.sampling.threshold: must be > 0"},
      {R"({"sampling": {"type": "jittered", "n": 8}, "rays_per_pixel": 32})", "scene.sampling: 64 primary rays per pixel, more than rays_per_pixel 32"},
      {R"({"photons": {"count": -1}})", "scene.photons.count:"},
      {R"({"photons": {"count": 4194305}})", "scene.photons.count:"},
      {R"({"photons": {"gather": 0}})", "scene.photons.gather:"},
      {R"({"photons": {"radius": 0}})", "scene.photons.radius:"},
      {R"({"photons": {"radius": "NaN"}})", "scene.photons.radius: not a finite number"},
      {R"({"photons": {"beams": 3}})", "scene.photons: unknown field \"beams\""},
      {R"({"photons": 5})", "scene.photons: expected an object"},
      {R"({"sampling": {"type": "stratified"}})", "scene.sampling.type: unknown sampling 'stratified'"},
      {R"({"background": [0, 0]})", "scene.background: expected a colour"},
  };
  for (const Case& c : cases) {
    Json scene = base_scene();
    scene.merge_patch(Json::parse(c.patch));
    const std::string err = error_of(scene);
    INFO(c.patch << " -> " << err);
    CHECK(err.rfind(c.expect, 0) == 0);
    CHECK(err.find('\n') == std::string::npos);
  }
}

TEST_CASE("scene: meshes beyond the bound and broken mesh or image files are refused", "[scene]") {
  const auto dir = testing::scratch("scene-files");
  std::ofstream(dir / "flat.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  std::ofstream(dir / "broken.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n";
  std::ofstream(dir / "fake.png") << "GIF89a, not a PNG at all";
  Json scene = base_scene();
  scene["objects"] = Json::array();
  for (int i = 0; i < 3; ++i) scene["objects"].push_back({{"type", "mesh"}, {"file", "flat.off"}, {"material", "white"}});
  tracer::SceneOptions opt;
  opt.base_dir = dir.string();
  const tracer::Scene ok = tracer::parse_scene(scene, opt);
  CHECK(ok.meshes.size() == 1);  // read once, used three times
  CHECK(ok.mesh_triangles == 3);
  Json broken = scene;
  broken["objects"][1]["file"] = "broken.off";
  CHECK(error_of(broken, dir.string()).rfind("scene.objects[1].file: ", 0) == 0);
  Json far = base_scene();
  far["objects"][0] = {{"type", "mesh"}, {"file", "flat.off"}, {"material", "white"}, {"scale", 1e6}, {"translate", {1e15, 0, 0}}};
  CHECK(error_of(far, dir.string()) == "scene.objects[0]: the placed mesh reaches beyond 1e15");
  Json png = base_scene();
  png["textures"]["check"] = {{"type", "image"}, {"file", "fake.png"}};
  CHECK(error_of(png, dir.string()) == "scene.textures.check.file: 'fake.png' is not a PNG file");
  // The documented size bound: 2^20 mesh triangles over the scene.
  {
    std::ofstream big(dir / "big.off");
    const int n = 1 << 19;  // triangles: n - 2 fan triangles from one polygon would be slow to write; use a strip
    big << "OFF\n" << n + 2 << " " << n << " 0\n";
    for (int i = 0; i < n + 2; ++i) big << i << " " << (i % 2) << " 0\n";
    for (int i = 0; i < n; ++i) big << "3 " << i << " " << i + 1 << " " << i + 2 << "\n";
  }
  Json huge = base_scene();
  huge["objects"] = Json::array();
  for (int i = 0; i < 3; ++i) huge["objects"].push_back({{"type", "mesh"}, {"file", "big.off"}, {"material", "white"}});
  CHECK(error_of(huge, dir.string()) == "scene.objects[2]: the scene's meshes exceed 1048576 triangles");
}

TEST_CASE("scene check: a bad scene exits 2 with one line, a good one prints its summary", "[scene]") {
  const auto dir = testing::scratch("scene-cli");
  Json bad = base_scene();
  bad["objects"][0]["radius"] = -1;
  std::ofstream(dir / "bad.json") << bad.dump();
  const auto r = testing::run_stepwise("scene check " + testing::sh_quote((dir / "bad.json").string()));
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err == "stepwise: error: scene.objects[0].radius: must be > 0, got -1\n");
  const auto ok = testing::run_stepwise("scene check --json " + testing::sh_quote((kScenes / "spot-lit.json").string()));
  REQUIRE(ok.status == 0);
  const Json sum = Json::parse(ok.out);
  CHECK(sum["lights"]["spot"] == 3);
  CHECK(sum["objects"]["sphere"] == 3);
  const auto missing = testing::run_stepwise("scene check " + testing::sh_quote((dir / "none.json").string()));
  CHECK(missing.status == 2);
  CHECK(std::count(missing.err.begin(), missing.err.end(), '\n') == 1);
}
