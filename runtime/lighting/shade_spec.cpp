// `shade` (the full local lighting model at one point) and `gouraud-vs-phong` (a triangle shaded
// per vertex and interpolated, against per pixel, over the fill family's triangle-edge), in float,
// double and reference (Rational with sqrt, cos and pow in 300-bit MPFR). The decisions (n.l > 0,
// n.e > 0, inside a spot cone) are exact in reference mode; `shade`'s oracle in GL's convention is
// oracle/lighting_shade_oracle (MPFR from the spec's formulas). Semantics: docs/lighting/shade.md.
#include <cmath>
#include <memory>
#include <random>
#include "register.hpp"
#include "lighting/shade_input.hpp"
#include "lighting/shade_common.hpp"
#include "lighting/shade_oracle_case.hpp"

namespace sw {
namespace {

using namespace lighting;

ShadeOutput from_oracle(const ShadeScene<Rational>& in, const oracle::ShadeResult& r) {
  ShadeOutput o;
  o.facing = sgn(dot(in.n, in.eye_at_infinity ? in.eye : Vec3<Rational>(in.eye - in.p))) > 0;
  for (int k = 0; k < 3; ++k) o.ambient[k] = Rational(in.material.emission[k] + in.scene_ambient[k] * in.material.ka[k]).get_d();
  auto ref = std::make_shared<std::vector<Rational>>();
  for (int k = 0; k < 3; ++k) o.rgb[k] = r.rgb[k].get_d(), ref->push_back(r.rgb[k]);
  for (const auto& l : r.lights) {
    o.flags.push_back({l.at_point, l.lit, l.inside});
    o.terms.push_back({l.attenuation.get_d(), l.spot.get_d(), l.diffuse.get_d(), l.specular.get_d(), l.rgb[0].get_d(), l.rgb[1].get_d(), l.rgb[2].get_d()});
  }
  o.ref = std::move(ref);
  return o;
}

struct ShadeSpec {
  static constexpr std::array hooks{Hook::error, Hook::handles, Hook::params};
  static std::vector<Param> params() { return shade_params(); }
  using Algo = Shade;
  using Input = ShadeScene<Rational>;
  using Output = ShadeOutput;
  static constexpr std::array views{View::orbit3d, View::table};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::reference};
  static inline const std::string example =
      R"({"p":[0,0,0],"n":[0,0,2],"eye":[0,0,5],"ambient":[0.1,0.1,0.1],)"
      R"("lights":[{"type":"point","position":[2,0,3],"attenuation":[1,0.1,0.01],"colour":[1,0.9,0.8]},)"
      R"({"type":"spot","position":[0,3,3],"spot_direction":[0,-1,-1],"cutoff":45,"exponent":2,"colour":[0.3,0.3,1]},)"
      R"({"type":"directional","direction":[-1,1,1],"colour":[0.2,0.2,0.2],"ambient":[0.05,0.05,0.05]}],)"
      R"("material":{"ambient":[0.2,0.2,0.2],"diffuse":[0.8,0.5,0.3],"specular":[0.5,0.5,0.5],"shininess":20}})";
  static Input parse(const Json& j) { return parse_scene(j, "input"); }
  template <class Num> static ShadeScene<Num> prepare(const Input& in) { return convert_scene<Num>(in); }
  template <class Num, class Probe> static Output compute(const ShadeScene<Num>& s, Probe& probe) {
    return shade_output<Num>(shade<Num>(s, probe));
  }
  static Json to_json(const Output& o) { return shade_json(o); }
  static std::size_t ops(const Output&) { return 1; }
  static Output oracle(const Input& in) {
    NoProbe none;
    if (in.convention == Convention::gl) return from_oracle(in, oracle::shade_gl(oracle_case(in)));
    return compute<Rational>(prepare<Rational>(in), none);
  }
  static constexpr std::string_view error_unit = "ulps of 1";
  static double error(const Output& got, const Output& ref) { return shade_error(got, ref); }
  static std::vector<Handle> handles() {
    return {{"/lights/0/position", Handle::Kind::point3, 8, "light"}, {"/eye", Handle::Kind::point3, 8, "eye"}, {"/n", Handle::Kind::direction3, 0, "n"}};
  }
  static std::vector<BenchSet<Input>> bench_sets();
};

std::vector<BenchSet<ShadeScene<Rational>>> ShadeSpec::bench_sets() {
  BenchSet<Input> random{"random", shade_random_scenes(2000, 5)}, hard{"hard", shade_hard_scenes()};
  return {random, hard};
}

SW_REGISTER(ShadeSpec);

}  // namespace


}  // namespace sw
