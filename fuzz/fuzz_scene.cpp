// libFuzzer harness for the ray tracer's scene reader (runtime/tracer/scene.hpp): JSON text within
// the readers' bounds, then every key, type, bound and reference of the scene. Files are not opened
// (SceneOptions::load_files = false): the mesh reader has its own harness through fuzz_run. A valid
// scene without meshes or image textures is also planned and rendered at 4x3 (a few objects and
// photons, so that one input stays fast).
#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <string_view>
#include "input.hpp"
#include "tracer/plan.hpp"
#include "tracer/render.hpp"
#include "tracer/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const sw::Json j = sw::parse_json_text(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
    sw::tracer::SceneOptions opt;
    opt.load_files = false;
    sw::tracer::Scene s = sw::tracer::parse_scene(j, opt);
    (void)sw::tracer::scene_summary_text(s);
    (void)sw::tracer::plan_text(sw::tracer::plan_scene(s));
    bool files = !s.meshes.empty();
    for (const auto& t : s.textures) files = files || t.kind == sw::tracer::TextureKind::image;
    if (!files && s.objects.size() <= 16) {
      s.photons.count = std::min<std::int64_t>(s.photons.count, 500);
      s.sampling = {};
      sw::tracer::RenderOptions o;
      o.width = 4, o.height = 3, o.threads = 1;
      (void)sw::tracer::render(s, o);
    }
  } catch (const sw::InputError&) {
  }
  return 0;
}
