// `gouraud-vs-phong`: one triangle shaded per vertex and interpolated (Gouraud) against per pixel
// (Phong), over the fill family's triangle-edge, in float, double and reference. Its oracle is the
// reference run (each pixel's Phong colour is `shade`, whose GL convention has the independent
// MPFR oracle). Semantics: docs/lighting/shade.md.
#include <random>
#include "register.hpp"
#include "lighting/gouraud_vs_phong.hpp"
#include "lighting/shade_common.hpp"
#include "lighting/shade_input.hpp"

namespace sw {
namespace {

using namespace lighting;

// The triangle's box: at most this many pixels a side, so that a run shades at most 64 x 64 pixels.
constexpr std::int64_t kMaxBox = 64;

struct GouraudOutput {
  std::size_t pixels = 0, undefined = 0;
  double max_diff = 0;
  std::vector<std::array<double, 8>> rows;  // i, j, gouraud rgb, phong rgb
  friend bool operator==(const GouraudOutput& a, const GouraudOutput& b) { return a.pixels == b.pixels && a.undefined == b.undefined; }
};

struct GouraudSpec {
  static constexpr std::array hooks{Hook::handles, Hook::estimate_steps, Hook::step_cost, Hook::params};
  static std::vector<Param> params() { return shade_params(); }
  using Algo = GouraudVsPhong;
  using Input = ShadedTriangle<Rational>;
  using Output = GouraudOutput;
  static constexpr std::array views{View::plane2d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::reference};
  static inline const std::string example =
      R"({"vertices":[{"xy":[0,0],"p":[-1,-1,0],"n":[-1,-1,2]},{"xy":[12,1],"p":[1,-1,0],"n":[1,-1,2]},{"xy":[5,10],"p":[0,1,0],"n":[0,1,2]}],)"
      R"("eye":[0,0,4],"ambient":[0.1,0.1,0.1],"lights":[{"type":"point","position":[0.3,0.2,1.2],"colour":[1,1,1]}],)"
      R"("material":{"ambient":[0.2,0.2,0.2],"diffuse":[0.7,0.3,0.2],"specular":[0.8,0.8,0.8],"shininess":40}})";
  static Input parse(const Json& j) {
    if (!j.is_object()) throw InputError("input: expected an object");
    only_keys_optional(j, {"vertices", "lights", "material"}, {"eye", "eye_direction", "ambient", "convention"}, "input");
    Input t;
    const Json& vs = j["vertices"];
    if (!vs.is_array() || vs.size() != 3) throw InputError("input.vertices: expected 3 vertices");
    for (int k = 0; k < 3; ++k) {
      const std::string w = "input.vertices[" + std::to_string(k) + "]";
      only_keys(vs[k], {"xy", "p", "n"}, w);
      t.xy[k] = parse_point2(vs[k], "xy");
      for (int a = 0; a < 2; ++a) check_bound(t.xy[k][a], 1e6, w + ".xy");
      ShadeScene<Rational> probe_scene = parse_scene(Json{{"p", vs[k]["p"]}, {"n", vs[k]["n"]}, {"eye_direction", {0, 0, 1}}, {"lights", Json::array()}, {"material", Json::object()}}, w);
      t.p[k] = probe_scene.p, t.n[k] = probe_scene.n;
    }
    parse_scene_rest(j, "input", t.scene);
    for (int a = 0; a < 2; ++a) {
      const Rational lo = std::min({t.xy[0][a], t.xy[1][a], t.xy[2][a]}), hi = std::max({t.xy[0][a], t.xy[1][a], t.xy[2][a]});
      if (hi - lo > kMaxBox) throw InputError("input.vertices: the triangle's box is wider than 64 pixels");
    }
    for (int k = 0; k < 3; ++k)
      if (!t.scene.eye_at_infinity && t.scene.eye == t.p[k]) throw InputError("input.eye: equals a vertex (no direction to the eye)");
    return t;
  }
  template <class Num> static ShadedTriangle<Num> prepare(const Input& in) {
    ShadedTriangle<Num> t;
    for (int k = 0; k < 3; ++k) t.xy[k] = to_num<Num>(in.xy[k]), t.p[k] = to_num<Num>(in.p[k]), t.n[k] = to_num<Num>(in.n[k]);
    t.scene = convert_scene<Num>(in.scene);
    return t;
  }
  template <class Num, class Probe> static Output compute(const ShadedTriangle<Num>& t, Probe& probe) {
    const auto r = gouraud_vs_phong<Num>(t, probe);
    Output o;
    o.pixels = r.pixels.size();
    o.max_diff = num::to_double(r.max_diff);
    for (const auto& p : r.pixels) {
      o.undefined += !p.defined;
      o.rows.push_back({double(p.px.x), double(p.px.y), num::to_double(p.gouraud.x), num::to_double(p.gouraud.y), num::to_double(p.gouraud.z),
                        num::to_double(p.phong.x), num::to_double(p.phong.y), num::to_double(p.phong.z)});
    }
    return o;
  }
  static Json to_json(const Output& o) {
    Json px = Json::array();
    for (const auto& r : o.rows) px.push_back({{"i", r[0]}, {"j", r[1]}, {"gouraud", {r[2], r[3], r[4]}}, {"phong", {r[5], r[6], r[7]}}});
    return Json{{"pixels", o.pixels}, {"undefined", o.undefined}, {"max_diff", o.max_diff}, {"shaded", px}};
  }
  static std::size_t ops(const Output& o) { return std::max<std::size_t>(o.pixels, 1); }
  static Output oracle(const Input& in) {
    NoProbe none;
    return compute<Rational>(prepare<Rational>(in), none);
  }
  // Up to 24 steps a pixel of the triangle's box: the rasterizer's and the shading's for 8 lights.
  static std::size_t estimate_steps(const Input& in) {
    std::size_t pixels = 1;
    for (int a = 0; a < 2; ++a) {
      const Rational lo = std::min({in.xy[0][a], in.xy[1][a], in.xy[2][a]}), hi = std::max({in.xy[0][a], in.xy[1][a], in.xy[2][a]});
      pixels *= static_cast<std::size_t>(num::floor_int(Rational(hi - lo))) + 2;
    }
    return 24 * pixels;
  }
  // Budget units a step costs (measured, docs/cli.md: the largest accepted input within 10 s).
  static std::size_t step_cost(Numeric n) { return n == Numeric::reference ? 256 : 1; }
  static std::vector<Handle> handles() {
    return {{"/vertices/0/xy", Handle::Kind::point2, 1, "v0"}, {"/vertices/1/xy", Handle::Kind::point2, 1, "v1"}, {"/vertices/2/xy", Handle::Kind::point2, 1, "v2"}};
  }
  // The reference shades every pixel in 300-bit MPFR, about 0.1 s a triangle: a quick bench takes 8.
  static std::vector<BenchSet<Input>> bench_sets(BenchSize size) {
    std::mt19937_64 rng(23);
    auto u = [&](double lo, double hi) { return num::to_rational(double(float(std::uniform_real_distribution<double>(lo, hi)(rng)))); };
    const Input base = parse(Json::parse(example));
    BenchSet<Input> small{"small", {}};
    for (int k = 0; k < (size == BenchSize::quick ? 8 : 40); ++k) {
      Input t = base;
      for (auto& xy : t.xy) xy = {u(0, 10), u(0, 10)};
      for (auto& n : t.n) n = {u(-1, 1), u(-1, 1), u(1, 2)};
      small.inputs.push_back(t);
    }
    return {small};
  }
};

SW_REGISTER(GouraudSpec);

}  // namespace

}  // namespace sw
