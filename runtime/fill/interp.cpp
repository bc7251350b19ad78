// The fill family's attribute interpolation in perspective: perspective-interp (the guide's
// hyperbolic interpolation) and affine-interp (linear on screen), both clipping at w = w_near
// before any divide (registered here). Semantics: docs/fill/interpolation.md.
#include <random>
#include "register.hpp"
#include "fill/perspective_interp.hpp"
#include "fill_interp_oracle.hpp"
#include "fill/fill_common.hpp"

namespace sw {
namespace {

using namespace fillspec;  // kCoordBound (|x|, |y|, |z|, |w| and every attribute), kMaxSamples, FillOutput
using InterpOutput = FillOutput;

struct InterpInput {
  std::array<oracle::ClipPoint, 3> v;
  std::array<std::vector<Rational>, 3> attrs;  // n values each, 1 <= n <= 8
};

template <class Num> fill::ClipTriangle<Num> to_clip(const InterpInput& in) {
  fill::ClipTriangle<Num> t;
  t.n = in.attrs[0].size();
  for (int k = 0; k < 3; ++k) {
    for (int a = 0; a < 4; ++a) t.v[k].c[a] = num::from_rational<Num>(in.v[k][a]);
    for (std::size_t c = 0; c < t.n; ++c) t.v[k].a[c] = num::from_rational<Num>(in.attrs[k][c]);
  }
  return t;
}

// The samples in the box of the clipped polygon's projection (0 when nothing is kept).
// The corners of the clipped polygon's projection on the screen (none when nothing is kept).
std::vector<Vec2<Rational>> projected_corners(const InterpInput& in) {
  const oracle::ClippedPolygon poly = oracle::clip_w(in.v, in.attrs, fill::w_near<Rational>());
  if (poly.corners.size() < 3) return {};
  return oracle::project(poly.corners);
}

InterpInput parse_interp(const Json& j) {
  only_keys(j, {"triangle", "attrs"}, "input");
  const Json& t = j["triangle"];
  if (!t.is_array() || t.size() != 3) throw InputError("input.triangle: expected three clip-space vertices [[x,y,z,w],[x,y,z,w],[x,y,z,w]]");
  InterpInput in;
  for (int k = 0; k < 3; ++k) {
    const std::string what = "input.triangle[" + std::to_string(k) + "]";
    if (!t[k].is_array() || t[k].size() != 4) throw InputError(what + ": expected [x, y, z, w]");
    for (int a = 0; a < 4; ++a) {
      const std::string w = what + "[" + std::to_string(a) + "]";
      in.v[k][a] = parse_rational(t[k][a], w);
      check_bound(in.v[k][a], kCoordBound, w);
      check_digits(in.v[k][a], w);
    }
  }
  const auto attrs = parse_attrs(j["attrs"], 3);
  for (int k = 0; k < 3; ++k) in.attrs[k] = attrs[k];
  check_budget(projected_corners(in), "input.triangle (projected, clipped at w = 1)");
  return in;
}

// A floor in perspective: a triangle on the plane y_world = -1 seen from the origin, with clip
// w = -z_world (depth), at `depth` in [d0, d1], `scale` pixels per unit; attributes (u, v, 1).
InterpInput floor_triangle(std::mt19937_64& rng, double scale, double d0, double d1, double spread) {
  std::uniform_real_distribution<double> z(d0, d1), x(-spread, spread);
  auto grid = [](double v) -> Rational { return Rational(static_cast<long>(std::floor(v * 256))) / 256; };
  InterpInput in;
  for (int k = 0; k < 3; ++k) {
    const double w = z(rng), xw = x(rng);
    in.v[k] = {grid(xw * scale), grid(-scale), grid(w - 2), grid(w)};
    in.attrs[k] = {grid(xw), grid(w), 1};
  }
  return in;
}

// Random floor triangles whose projections are about 8, 128 and 2048 px^2, and a set with one
// vertex behind the eye (clipped: two triangles each).
std::vector<BenchSet<InterpInput>> interp_bench_sets() {
  std::mt19937_64 rng(20261125);
  std::vector<BenchSet<InterpInput>> sets{{"8px", {}}, {"128px", {}}, {"2048px", {}}, {"clipped", {}}};
  for (int i = 0; i < 4000; ++i) sets[0].inputs.push_back(floor_triangle(rng, 52, 4, 8, 1));
  for (int i = 0; i < 1000; ++i) sets[1].inputs.push_back(floor_triangle(rng, 198, 4, 8, 1));
  for (int i = 0; i < 100; ++i) sets[2].inputs.push_back(floor_triangle(rng, 829, 4, 8, 1));
  std::uniform_real_distribution<double> u(-1, 1), behind(-2, 0);
  for (int i = 0; i < 100; ++i) {  // two vertices in front, one behind the eye
    InterpInput in = floor_triangle(rng, 96, 2, 4, 1);
    const double w = behind(rng), xw = u(rng);
    in.v[2] = {Rational(static_cast<long>(xw * 96 * 256)) / 256, Rational(-96), Rational(static_cast<long>((w - 2) * 256)) / 256, Rational(static_cast<long>(w * 256)) / 256};
    in.attrs[2] = {Rational(static_cast<long>(xw * 256)) / 256, Rational(static_cast<long>(w * 256)) / 256, 1};
    sets[3].inputs.push_back(std::move(in));
  }
  return sets;
}

template <bool Persp> struct InterpSpec {
  static constexpr std::array hooks{Hook::error, Hook::estimate_steps, Hook::step_cost};
  using Algo = std::conditional_t<Persp, fill::PerspectiveInterp, fill::AffineInterp>;
  using Input = InterpInput;
  using Output = InterpOutput;
  static constexpr std::array views{View::plane2d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  // A floor square's half seen in perspective, its far corner behind the eye: clipped to two triangles.
  static inline const std::string example =
      R"({"triangle":[[-24,-16,0,2],[24,-16,0,2],[0,-4,-1,-0.5]],"attrs":[[0,0],[4,0],[2,3]]})";
  static Input parse(const Json& j) { return parse_interp(j); }
  template <class Num> static fill::ClipTriangle<Num> prepare(const Input& in) { return to_clip<Num>(in); }
  template <class Num, class Probe> static Output compute(const fill::ClipTriangle<Num>& t, Probe& probe) {
    fill::FillResult<Num> r;
    fill::perspective_interp<Persp, Num>(t, r, probe);
    return fill_output<Num>(std::move(r.pixels), t.n, r.values);
  }
  static Json to_json(const Output& o) { return fill_json(o); }
  static std::size_t ops(const Output& o) { return o.pixels.size(); }
  static constexpr std::string_view error_unit = "pixels";
  static double error(const Output& got, const Output& exact) { return wrong_pixels(got, exact); }
  // The box's samples (a plot and a step each at most), two steps per row, the clipping.
  static std::size_t estimate_steps(const Input& in) { return static_cast<std::size_t>(2.5 * box_samples(projected_corners(in))) + 128; }
  // Budget units a step costs (measured, docs/cli.md: the largest accepted input within 10 s).
  static std::size_t step_cost(Numeric n) { return n == Numeric::filtered || n == Numeric::exact ? 3 : 1; }
  static Output oracle(const Input& in) {
    const oracle::InterpSamples s = Persp ? oracle::perspective_samples(in.v, in.attrs, fill::w_near<Rational>())
                                          : oracle::affine_samples(in.v, in.attrs, fill::w_near<Rational>());
    Output o{s.pixels, in.attrs[0].size(), {}, s.values};
    for (const Rational& v : o.exact_values) o.values.push_back(v.get_d());
    return o;
  }
  static std::vector<BenchSet<Input>> bench_sets() { return interp_bench_sets(); }
};

SW_REGISTER(InterpSpec<true>);
SW_REGISTER(InterpSpec<false>);

}  // namespace

}  // namespace sw
