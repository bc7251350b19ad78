// libFuzzer harness for the ray tracer's scene reader (runtime/tracer/scene.hpp): JSON text within
// the readers' bounds, then every key, type, bound and reference of the scene. Files are not opened
// (SceneOptions::load_files = false): the mesh reader has its own harness through fuzz_run.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include "input.hpp"
#include "tracer/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const sw::Json j = sw::parse_json_text(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
    sw::tracer::SceneOptions opt;
    opt.load_files = false;
    const sw::tracer::Scene s = sw::tracer::parse_scene(j, opt);
    (void)sw::tracer::scene_summary_text(s);
  } catch (const sw::InputError&) {
  }
  return 0;
}
