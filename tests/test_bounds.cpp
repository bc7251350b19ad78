// Bounds that hold (docs/cli.md#the-work-budget): `scene render` has a work budget in rays, budget
// options cannot be turned off by a negative or overflowing number, and a scene's textures,
// photons and image are bounded by what they cost.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include "cli_harness.hpp"
#include "input.hpp"
#include "tracer/render.hpp"
#include "tracer/scene.hpp"

using namespace sw::testing;

namespace {

std::size_t lines_in(const std::string& s) { return std::size_t(std::count(s.begin(), s.end(), '\n')); }

// A scene file in `dir` from the example cornell-box with `edit` applied.
std::filesystem::path scene_with(const std::filesystem::path& dir, const std::string& name, const std::function<void(sw::Json&)>& edit) {
  sw::Json s = sw::read_input_arg(std::string(SW_SOURCE_DIR) + "/scenes/cornell-box.json");
  edit(s);
  const auto path = dir / name;
  std::ofstream(path) << s.dump();
  return path;
}

}  // namespace

TEST_CASE("bounds: scene render refuses a render over its ray budget, before any work and with no file", "[cli][budget][tracer]") {
  const auto dir = scratch("bounds-render");
  const std::string scene = sh_quote(std::string(SW_SOURCE_DIR) + "/scenes/cornell-box.json"), out = sh_quote((dir / "x.png").string());
  // cornell-box: 16 samples a pixel, no mirrors or glass, one light with shadows: at most 32 rays a pixel.
  const sw::tracer::Scene s = sw::tracer::read_scene_file(std::string(SW_SOURCE_DIR) + "/scenes/cornell-box.json");
  sw::tracer::RenderOptions o;
  o.width = 100, o.height = 10;
  CHECK(sw::tracer::render_cost(s, sw::tracer::plan_scene(s), o) == 100 * 10 * 16 * 2);
  const auto r = run_stepwise("scene render " + scene + " --size 100x10 --max-rays 31999 --out " + out);
  CHECK(r.status == 2);
  CHECK(lines_in(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("implies up to 32000 rays, more than the budget of 31999 (--max-rays raises it)"));
  CHECK(!std::filesystem::exists(dir / "x.png"));
  CHECK(run_stepwise("scene render " + scene + " --size 100x10 --max-rays 32000 --quiet --out " + out).status == 0);
  // The default budget refuses the largest image at 256 samples a pixel.
  const auto big = run_stepwise("scene render " + scene + " --size 4096x4096 --spp 256 --out " + out);
  CHECK(big.status == 2);
  CHECK_THAT(big.err, Catch::Contains("(--max-rays raises it)"));
  const auto huge = run_stepwise("scene render " + scene + " --size 8192x8192 --out " + out);
  CHECK(huge.status == 2);
  CHECK_THAT(huge.err, Catch::Contains("more than the bound 2^24"));
}

TEST_CASE("bounds: a budget option takes only a whole number, so -1 or 2^64 cannot turn it off", "[cli][budget]") {
  const std::string in = " --input '{\"p0\":[0,0],\"p1\":[9000000,10]}'";
  for (const char* value : {"-1", "18446744073709551616", "1e9", "", "0x10", "4611686018427387905"}) {
    for (const std::string& cmd : {"trace dda-line" + in + " --max-steps ", "trace dda-line" + in + " --max-output ",
                                   "scene render " + sh_quote(std::string(SW_SOURCE_DIR) + "/scenes/cornell-box.json") + " --out /dev/null --max-rays "}) {
      INFO(cmd << value);
      const auto r = run_stepwise(cmd + sh_quote(value));
      CHECK(r.status == 2);
      CHECK(lines_in(r.err) == 1);
    }
  }
  CHECK(run_stepwise("trace dda-line" + in + " --max-steps 4611686018427387904 --max-output 100").err.find("--max-output raises it") != std::string::npos);
}

TEST_CASE("bounds: textures, photons and exact numbers in reference mode are bounded by what they cost", "[budget][tracer]") {
  const auto dir = scratch("bounds-scene");
  // A PNG whose header says 8192 x 8192 (2^26 texels): refused from its header, before decoding.
  std::filesystem::create_directories(dir / "textures");
  const unsigned char header[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R', 0, 0, 0x20, 0, 0, 0, 0x20, 0, 8, 2, 0, 0, 0};
  std::ofstream(dir / "textures" / "big.png", std::ios::binary).write(reinterpret_cast<const char*>(header), sizeof header);
  const auto textured = scene_with(dir, "textured.json", [](sw::Json& s) { s["textures"] = {{"big", {{"type", "image"}, {"file", "textures/big.png"}}}}; });
  CHECK_THROWS_WITH(sw::tracer::read_scene_file(textured.string()), Catch::Contains("more than 2^24 texels"));
  const auto photons = scene_with(dir, "photons.json", [](sw::Json& s) { s["photons"] = {{"count", (1 << 20) + 1}}; });
  CHECK_THROWS_WITH(sw::tracer::read_scene_file(photons.string()), Catch::Contains("scene.photons.count"));
  // Reference mode weighs long exact numbers as exact mode does: 4000-digit vertices make
  // gouraud-vs-phong's 13,728 steps x 256 x 11 too many (it ran 65 s).
  sw::Json in = sw::parse_json_text(sw::find_algorithm("gouraud-vs-phong").example, "example");
  in["vertices"][0]["xy"][0] = "1" + std::string(2000, '0') + "/1" + std::string(2000, '0');
  CHECK_THROWS_WITH(sw::find_algorithm("gouraud-vs-phong").open(in, sw::Numeric::reference).check_budget({}), Catch::Contains("for exact numbers of"));
  CHECK_NOTHROW(sw::find_algorithm("gouraud-vs-phong").open(in, sw::Numeric::f64).check_budget({}));
}
