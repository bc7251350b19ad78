// shadow-volume in the catalog: one light's stencil shadow volumes over a rasterized scene, counted
// by z-pass and z-fail at every pixel, against exact visibility. The oracle counts, for each
// pixel's exact point, the casters whose open volume holds it (segment-triangle tests in
// rationals), with no rasterization. Semantics: docs/shadows/semantics.md#shadow-volume.
#include "register.hpp"
#include "shadows/shadow_volume.hpp"
#include "shadows/shadow_volume_input.hpp"

namespace sw {
namespace {

using namespace shadowspec;

template <class Num> struct SVPrepared {
  std::shared_ptr<const VolumeInput> in;
  pipe::RasterCamera<Num> cam;
  std::vector<pipe::RasterTriangle<Num>> tris;
  shadow::VolumeMesh<Num> mesh;
  pipe::Vec4<Num> light;
};

struct SVOutput {
  VolumePixels px;
  friend bool operator==(const SVOutput& a, const SVOutput& b) {
    return a.px.lit == b.px.lit && a.px.zpass == b.px.zpass && a.px.zfail == b.px.zfail;
  }
};

struct ShadowVolumeSpec {
  static constexpr std::array hooks{Hook::error, Hook::estimate_steps};
  using Algo = shadow::ShadowVolume;
  using Input = VolumeInputRef;
  using Output = SVOutput;
  static constexpr std::array views{View::plane2d, View::orbit3d, View::table};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  // The spot-lit scene's first spot over two spheres and the floor at 24 x 18, counted by z-fail.
  static inline const std::string example = R"({"scene":"scenes/spot-lit.json","size":[24,18],"stacks":3,"light":0,"method":"zfail"})";
  static Input parse(const Json& j) { return parse_volume_input(j); }
  template <class Num> static SVPrepared<Num> prepare(const Input& in) {
    const RasterScene& s = *in.p->seen->scene;
    const pipe::Vec4<Rational>& L = in.p->light;
    return {in.p, pipespec::camera_in<Num>(s.camera), pipespec::triangles_in<Num>(s.tris), mesh_in<Num>(in.p->mesh),
            {num::from_rational<Num>(L.x), num::from_rational<Num>(L.y), num::from_rational<Num>(L.z), num::from_rational<Num>(L.w)}};
  }
  template <class Num, class Probe> static Output compute(const SVPrepared<Num>& p, Probe& probe) {
    return {stencil_pixels(*p.in, shadow::shadow_volume(p.cam, p.tris, p.mesh, p.light, p.in->zfail, probe))};
  }
  static Json to_json(const Output& o) { return volume_json(o.px); }
  static std::size_t ops(const Output& o) { return std::max<std::size_t>(1, o.px.lit.size()); }
  static constexpr std::string_view error_unit = "pixels";
  static double error(const Output& got, const Output& exact) {
    double wrong = 0;
    for (std::size_t i = 0; i < got.px.lit.size() && i < exact.px.lit.size(); ++i) wrong += got.px.lit[i] != exact.px.lit[i];
    return wrong;
  }
  static std::size_t estimate_steps(const Input& in) { return volume_steps(*in.p); }
  static Output oracle(const Input& in) { return {volume_oracle(*in.p)}; }
  static std::vector<BenchSet<Input>> bench_sets() { return volume_sets(); }
};

SW_REGISTER(ShadowVolumeSpec);

}  // namespace
}  // namespace sw
