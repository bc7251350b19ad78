// scene-raster in the catalog: a ray-tracer scene drawn by the pipeline (clip-volume, the divide,
// the viewport, the z-buffer). Its oracle is the exact ray cast of every pixel (raster_truth.hpp).
// Semantics: docs/pipeline/semantics.md#scene-raster.
#include <filesystem>
#include "data_root.hpp"
#include "register.hpp"
#include "pipeline/raster_shade.hpp"
#include "pipeline/raster_truth.hpp"
#include "tracer/history.hpp"
#include "tracer/render.hpp"

namespace sw {
namespace {

using namespace pipespec;

inline constexpr std::int64_t kMaxSide = 512;  // the catalog's images; `scene raster` draws larger ones

struct SRInput {
  std::shared_ptr<const RasterScene> scene;
};

template <class Num> struct SRPrepared {
  std::shared_ptr<const RasterScene> scene;
  pipe::RasterCamera<Num> camera;
  std::vector<pipe::RasterTriangle<Num>> tris;
};

struct SROutput {
  RasterPixels px;
  // Modes agree when every pixel shows the same primitive.
  friend bool operator==(const SROutput& a, const SROutput& b) { return a.px.objects == b.px.objects && a.px.prims == b.px.prims; }
};

SRInput parse_sr(const Json& j) {
  if (!j.is_object()) throw InputError("input: expected an object with a scene");
  only_keys_optional(j, {"scene"}, {"size", "stacks"}, "input");
  std::string name;
  std::shared_ptr<const tracer::Scene> scene = tracer::scene_input(j["scene"], &name);
  RasterOptions o;
  if (j.contains("size")) {
    const Json& s = j["size"];
    if (!s.is_array() || s.size() != 2) throw InputError("input.size: expected [width, height]");
    o.width = parse_integer(s[0], "input.size[0]", 1, kMaxSide), o.height = parse_integer(s[1], "input.size[1]", 1, kMaxSide);
  } else if (scene->camera.width > kMaxSide || scene->camera.height > kMaxSide) {
    throw InputError("input.size: the scene's resolution " + std::to_string(scene->camera.width) + "x" + std::to_string(scene->camera.height) +
                     " exceeds " + std::to_string(kMaxSide) + " on a side; give a size (`stepwise scene raster` draws larger images)");
  }
  if (j.contains("stacks")) o.stacks = static_cast<int>(parse_integer(j["stacks"], "input.stacks", kMinStacks, kMaxStacks));
  try {
    return {raster_scene(std::move(scene), o)};
  } catch (const InputError& e) {
    throw InputError("input." + std::string(e.what()));
  }
}

RasterPixels truth_pixels(const RasterScene& s) {
  const RasterTruth t = raster_truth(s);
  RasterPixels o{t.width, t.height, {}, {}, {}, 0, 0, 0, 0, 0};
  for (const PixelTruth& p : t.px) o.objects.push_back(p.object), o.prims.push_back(p.prim), o.depth.push_back(p.depth);
  return o;
}

// The example scenes the rasterizer takes (perspective cameras), small, but the bunny: its 75,412
// triangles take 19 s in rationals (bench/scene_raster_identity.sh draws it at full size).
std::vector<BenchSet<SRInput>> sr_sets() {
  BenchSet<SRInput> set{"examples", {}};
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(data_root() / "scenes"))
    if (e.path().extension() == ".json") files.push_back("scenes/" + e.path().filename().string());
  std::sort(files.begin(), files.end());
  for (const std::string& f : files) {
    try {
      SRInput in = parse_sr(Json{{"scene", f}, {"size", {48, 36}}, {"stacks", 8}});
      if (in.scene->scene->mesh_triangles <= 10000) set.inputs.push_back(std::move(in));
    } catch (const InputError&) {  // a fisheye or cylindrical camera, or a mesh not extracted
    }
  }
  return {set};
}

struct SceneRasterSpec {
  static constexpr std::array hooks{Hook::error, Hook::estimate_steps, Hook::canonical, Hook::picture, Hook::summary_table, Hook::result_keys};
  using Algo = pipe::SceneRaster;
  using Input = SRInput;
  using Output = SROutput;
  static constexpr std::array views{View::scene, View::plane2d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  // Two glass balls on a checker floor, small: the floor's wedges reach the horizon, the spheres
  // are 6 bands of latitude.
  static inline const std::string example = R"({"scene":"scenes/glass-spheres.json","size":[40,30],"stacks":6})";
  static Input parse(const Json& j) { return parse_sr(j); }
  template <class Num> static SRPrepared<Num> prepare(const Input& in) {
    return {in.scene, camera_in<Num>(in.scene->camera), triangles_in<Num>(in.scene->tris)};
  }
  template <class Num, class Probe> static Output compute(const SRPrepared<Num>& p, Probe& probe) {
    return {raster_pixels(*p.scene, pipe::scene_raster<Num>(p.camera, p.tris, probe))};
  }
  static Json to_json(const Output& o) {
    const RasterPixels& p = o.px;
    return Json{{"width", p.width},   {"height", p.height}, {"objects", p.objects}, {"prims", p.prims}, {"depth", p.depth},
                {"drawn", p.drawn},   {"culled", p.culled}, {"cut", p.cut},         {"fragments", p.fragments}, {"passed", p.passed}};
  }
  // The ray cast knows what each pixel sees, not the work of drawing it.
  static Json canonical(const Json& r) {
    Json c = r;
    for (const char* k : {"drawn", "culled", "cut", "fragments", "passed"}) c.erase(k);
    return c;
  }
  static constexpr std::array result_keys{std::string_view("objects"), std::string_view("depth")};
  static std::size_t ops(const Output& o) { return static_cast<std::size_t>(std::max<std::int64_t>(1, o.px.width * o.px.height)); }
  static constexpr std::string_view error_unit = "pixels";
  static double error(const Output& got, const Output& exact) {
    double wrong = 0;
    for (std::size_t i = 0; i < got.px.objects.size() && i < exact.px.objects.size(); ++i)
      wrong += got.px.objects[i] != exact.px.objects[i] || got.px.prims[i] != exact.px.prims[i];
    return wrong;
  }
  // Per triangle its corners, the clip (at most 5 planes of 8 edges, 3 steps each, and 2 more),
  // the divide and the fan; the z-buffer's 3 per window triangle and 3 per fragment, its fragments
  // bounded by twice double's (rounding moves a few samples across edges) and a pixel each.
  static std::size_t estimate_steps(const Input& in) {
    const RasterScene& s = *in.scene;
    const RasterPixels px = draw(s, Numeric::f64);
    const double n = double(s.tris.size()), w = double(px.drawn + std::int64_t(s.tris.size()));
    return static_cast<std::size_t>(4 + n * 126 + 3 * w + 3 * (2 * double(px.fragments) + double(s.width * s.height)));
  }
  static Output oracle(const Input& in) { return {truth_pixels(*in.scene)}; }
  // The scene view: the raster shaded per fragment (Phong), in double.
  static Picture picture(const Input& in, std::int64_t) {
    const RasterScene& s = *in.scene;
    const RasterPixels px = draw(s, Numeric::f64);
    Picture pic{s.width, s.height, 1, tracer::to_rgb8(shade_pixels(s, px, Shading::phong)), 0, "Rasterizer", {}, {}, {}};
    pic.notes.push_back({std::to_string(s.tris.size()) + " triangles, " + std::to_string(px.drawn) + " drawn after clipping", "", std::nullopt});
    pic.notes.push_back({"Local lighting only (Phong, in double)", "a rasterizer casts no shadow, mirror or glass ray", std::nullopt});
    pic.grey = depth_grey(px);
    pic.grey_caption = "Depth buffer: near dark, far light";
    return pic;
  }
  // Beside the picture: each number type's pixels against the exact ray cast (the identity).
  static SummaryTable summary_table(const Input& in, const TraceView&) {
    const RasterScene& s = *in.scene;
    const RasterTruth truth = raster_truth(s);
    SummaryTable t{"Against the exact ray cast", {"mode", "differ", "ties", "wrong", "holes"}, {}, std::nullopt};
    for (Numeric n : {Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact}) {
      const Identity id = identity(truth, draw(s, n));
      t.rows.push_back({0, 0, {{std::string(numeric_name(n)), std::nullopt}, {std::to_string(id.differ), std::nullopt},
                               {std::to_string(id.ties), std::nullopt}, {std::to_string(id.wrong), std::nullopt},
                               {std::to_string(id.holes), std::nullopt}}});
    }
    t.total = SummaryTable::Row{0, 0, {{"of " + std::to_string(truth.px.size()) + " pixels", std::nullopt}, {}, {}, {}, {}}};
    return t;
  }
  static std::vector<BenchSet<Input>> bench_sets() { return sr_sets(); }
};

SW_REGISTER(SceneRasterSpec);
SW_REGISTER_CALLEE(pipe::ClipVolume);

}  // namespace
}  // namespace sw
