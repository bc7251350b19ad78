// libFuzzer harness for the files a scene names: the mesh readers (OFF and OBJ) and the PNG
// texture reader (signature and IHDR bound, then stb's decoder). The first byte chooses the
// reader (0: .off, 1: .obj, 2: .png); the rest is the file. A file the reader accepts goes into a
// one-object scene, which is planned and rendered at 4x3 (mesh placed in its BVH, texture
// decoded and sampled). Every failure must be one InputError.
#include <unistd.h>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include "input.hpp"
#include "spatial/spatial_common.hpp"
#include "tracer/render.hpp"
#include "tracer/scene.hpp"

namespace {

// One directory per fuzzing process, for its file of the moment; removed when the fuzzer exits
// normally (a crash leaves it beside the crash file).
const std::string& work_dir() {
  struct Dir {
    std::string path = (std::filesystem::temp_directory_path() / "sw-fuzz-files-XXXXXX").string();
    Dir() {
      if (!mkdtemp(path.data())) std::abort();
    }
    ~Dir() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Dir dir;
  return dir.path;
}

sw::Json scene_with(int kind, const std::string& file) {
  sw::Json material = {{"diffuse", {0.8, 0.8, 0.8}}};
  sw::Json object = {{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"material", "m"}};
  sw::Json scene = {{"camera", {{"eye", {0, 0, 5}}, {"vpn", {0, 0, 1}}, {"vup", {0, 1, 0}}, {"d", 1}, {"fov", 40}, {"resolution", {4, 3}}}},
                    {"lights", {{{"type", "directional"}, {"direction", {1, 1, 1}}}}}};
  if (kind == 2) {
    scene["textures"] = {{"t", {{"type", "image"}, {"file", file}}}};
    material = {{"texture", "t"}};
  } else {
    object = {{"type", "mesh"}, {"file", file}, {"material", "m"}};
  }
  scene["materials"] = {{"m", material}};
  scene["objects"] = {object};
  return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0 || data[0] > 2) return 0;
  const int kind = data[0];
  const std::string name = kind == 0 ? "f.off" : kind == 1 ? "f.obj" : "f.png";
  {
    std::ofstream out(work_dir() + "/" + name, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  }
  try {
    if (kind != 2) (void)sw::spatial::read_mesh_file(work_dir() + "/" + name);
    sw::tracer::SceneOptions opt;
    opt.base_dir = work_dir();
    const sw::tracer::Scene s = sw::tracer::parse_scene(scene_with(kind, name), opt);
    sw::tracer::RenderOptions o;
    o.threads = 1;
    (void)sw::tracer::render(s, o);
  } catch (const sw::InputError&) {
  }
  return 0;
}
