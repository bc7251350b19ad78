// projective-shadow in the catalog: occluders squashed onto a receiver's plane and drawn over it,
// the depth tie and the stencil as GL has them, against exact visibility. The oracle is the closed
// form on the eye's rays (projective_shadow_input.hpp), with no rasterization.
// Semantics: docs/shadows/semantics.md#projective-shadow.
#include "register.hpp"
#include "shadows/projective_shadow.hpp"
#include "shadows/projective_shadow_input.hpp"

namespace sw {
namespace {

using namespace shadowspec;

template <class Num> struct PSPrepared {
  std::shared_ptr<const ProjectiveInput> in;
  pipe::RasterCamera<Num> cam;
  std::vector<pipe::RasterTriangle<Num>> tris;
  pipe::Vec4<Num> plane, light;
  shadow::ProjectiveParams<Num> params;
};

struct PSOutput {
  ProjectivePixels px;
  friend bool operator==(const PSOutput& a, const PSOutput& b) { return a.px.shadowed == b.px.shadowed; }
};

struct ProjectiveShadowSpec {
  static constexpr std::array hooks{Hook::error, Hook::estimate_steps};
  using Algo = shadow::ProjectiveShadow;
  using Input = ProjectiveInputRef;
  using Output = PSOutput;
  static constexpr std::array views{View::plane2d, View::table};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  // spot-lit's first spot over the floor at 24 x 18, GL_LEQUAL: exact keeps every tie, float
  // z-fights.
  static inline const std::string example = R"({"scene":"scenes/spot-lit.json","size":[24,18],"stacks":3,"light":0,"depth":"lequal"})";
  static Input parse(const Json& j) { return parse_projective_input(j); }
  template <class Num> static PSPrepared<Num> prepare(const Input& in) {
    const RasterScene& s = *in.p->seen->scene;
    return {in.p, pipespec::camera_in<Num>(s.camera), pipespec::triangles_in<Num>(s.tris), v4_in<Num>(in.p->plane), v4_in<Num>(in.p->light),
            params_in<Num>(in.p->params)};
  }
  template <class Num, class Probe> static Output compute(const PSPrepared<Num>& p, Probe& probe) {
    return {projective_pixels(*p.in, shadow::projective_shadow(p.cam, p.tris, p.in->receiver, p.plane, p.light, p.params, probe))};
  }
  static Json to_json(const Output& o) { return projective_json(o.px); }
  static std::size_t ops(const Output& o) { return std::max<std::size_t>(1, o.px.shadowed.size()); }
  static constexpr std::string_view error_unit = "pixels";
  static double error(const Output& got, const Output& exact) {
    double wrong = 0;
    for (std::size_t i = 0; i < got.px.shadowed.size() && i < exact.px.shadowed.size(); ++i) wrong += got.px.shadowed[i] != exact.px.shadowed[i];
    return wrong;
  }
  static std::size_t estimate_steps(const Input& in) { return projective_steps(*in.p); }
  static Output oracle(const Input& in) { return {projective_oracle(*in.p)}; }
  static std::vector<BenchSet<Input>> bench_sets() { return projective_sets(); }
};

SW_REGISTER(ProjectiveShadowSpec);

}  // namespace
}  // namespace sw
