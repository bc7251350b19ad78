// The curves family's catalog entries: poly-forward-diff, poly-horner, circle-interior,
// circle-midpoint. Semantics and bounds: docs/curves/semantics.md.
#include <algorithm>
#include <random>
#include "adapter.hpp"
#include "curves/circle_interior.hpp"
#include "curves/circle_midpoint.hpp"
#include "curves/poly_horner.hpp"
#include "curves_oracle.hpp"
#include "pixels.hpp"

namespace sw {
namespace {

// Bounds (docs/curves/semantics.md): x within 2^22, at most 2^21 columns, |P| on the range at
// most 2^60 (so int64 and float never overflow), coefficients of at most 64-bit numerator and
// denominator; circles: |centre| <= 2^24, 0 <= r <= 2^22.
constexpr std::int64_t kMaxX = std::int64_t{1} << 22, kMaxColumns = std::int64_t{1} << 21;
constexpr std::int64_t kMaxCentre = std::int64_t{1} << 24, kMaxRadius = std::int64_t{1} << 22;

struct CubicInput {
  std::array<Rational, 4> c;
  std::int64_t xs = 0, xe = 0;
};

CubicInput parse_cubic(const Json& j, Numeric n) {
  only_keys(j, {"coeffs", "xs", "xe"}, "input");
  CubicInput in;
  const Json& c = j["coeffs"];
  if (!c.is_array() || c.size() != 4) throw InputError("input.coeffs: expected [a, b, c, d] (y = a x^3 + b x^2 + c x + d)");
  for (int k = 0; k < 4; ++k) {
    const std::string what = "input.coeffs[" + std::to_string(k) + "]";
    in.c[k] = parse_rational(c[k], what);
    if (mpz_sizeinbase(in.c[k].get_num_mpz_t(), 2) > 64 || mpz_sizeinbase(in.c[k].get_den_mpz_t(), 2) > 64)
      throw InputError(what + ": numerator or denominator beyond 64 bits");
    if (n == Numeric::integer && in.c[k].get_den() != 1) throw InputError(what + ": " + in.c[k].get_str() + " is not an integer (int mode takes integer coefficients)");
  }
  in.xs = parse_integer(j["xs"], "input.xs", -kMaxX, kMaxX);
  in.xe = parse_integer(j["xe"], "input.xe", -kMaxX, kMaxX);
  if (in.xe < in.xs) throw InputError("input.xe: " + std::to_string(in.xe) + " is below xs = " + std::to_string(in.xs));
  if (in.xe - in.xs > kMaxColumns) throw InputError("input: xe - xs = " + std::to_string(in.xe - in.xs) + " columns, beyond the bound 2^21");
  // |P(x)| <= sum |c_k| X^k over the range, with X covering the four table samples past xs.
  const Rational X(std::max(std::abs(in.xs), std::abs(in.xe)) + 4);
  const Rational bound = abs(in.c[0]) * X * X * X + abs(in.c[1]) * X * X + abs(in.c[2]) * X + abs(in.c[3]);
  if (bound > Rational(std::ldexp(1.0, 60)))
    throw InputError("input: |P(x)| may reach " + num::to_text(bound.get_d()) + " on the range, beyond the bound 2^60");
  return in;
}

template <class AlgoT> struct CubicSpec {
  using Algo = AlgoT;
  using Input = CubicInput;
  using Output = PixelsOutput;
  static constexpr std::string_view family = "curves";
  static constexpr std::array views{View::plane2d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::integer, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"coeffs":["1/64",0,"-3/2",2],"xs":-12,"xe":13})";
  static Input parse(const Json& j, Numeric n) { return parse_cubic(j, n); }
  template <class Num> static curves::Cubic<Num> prepare(const Input& in) {
    curves::Cubic<Num> p;
    for (int k = 0; k < 4; ++k) p.c[k] = num::from_rational<Num>(in.c[k]);
    p.xs = in.xs, p.xe = in.xe;
    return p;
  }
  template <class Num, class Probe> static Output compute(const curves::Cubic<Num>& p, Probe& probe) {
    Output o;
    if constexpr (std::is_same_v<Algo, curves::PolyForwardDiff>) curves::poly_forward_diff<Num>(p, o.pixels, probe);
    else curves::poly_horner<Num>(p, o.pixels, probe);
    return o;
  }
  static Json to_json(const Output& o) { return pixels_json("pixels", o); }
  static void write_members(const Output& o, std::ostream& os) { pixels_members("pixels", o, os); }
  static std::size_t ops(const Output& o) { return o.pixels.size(); }
  static std::size_t estimate_steps(const Input& in) { return 2 * static_cast<std::size_t>(in.xe - in.xs) + 8; }
  static Output oracle(const Input& in) { return {oracle::poly_pixels(in.c, in.xs, in.xe)}; }
  // The int mode runs only on the sets with integer coefficients.
  static bool bench_runs(const std::string& set, Numeric n) { return n != Numeric::integer || set != "long"; }
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(20261123);
    auto small = [&](int lo, int hi) { return Rational(std::uniform_int_distribution<int>(lo, hi)(rng)); };
    BenchSet<Input> random{"random", {}}, long_runs{"long", {}};
    // Integer cubics over 64 columns: every mode is exact unless a value leaves its significand.
    for (int i = 0; i < 2000; ++i) {
      const std::int64_t xs = std::uniform_int_distribution<std::int64_t>(-512, 448)(rng);
      random.inputs.push_back({{small(-3, 3), small(-50, 50), small(-500, 500), small(-9999, 9999)}, xs, xs + 64});
    }
    // 10^6 columns with dyadic coefficients: float's table drifts, Horner's error stays local.
    for (int i = 0; i < 4; ++i) {
      const Rational a = small(1, 9) / Rational(mpz_class(1) << 40), b = -small(1, 9) / Rational(mpz_class(1) << 21);
      long_runs.inputs.push_back({{a, b, small(-3, 3) / Rational(8), small(-99, 99)}, 0, 1000000});
    }
    return {random, long_runs};
  }
};

curves::CircleInput parse_circle(const Json& j) {
  only_keys(j, {"c", "r"}, "input");
  const Json& c = j["c"];
  if (!c.is_array() || c.size() != 2) throw InputError("input.c: expected the centre [cx, cy] (integers)");
  curves::CircleInput in;
  in.cx = parse_integer(c[0], "input.c[0]", -kMaxCentre, kMaxCentre);
  in.cy = parse_integer(c[1], "input.c[1]", -kMaxCentre, kMaxCentre);
  in.r = parse_integer(j["r"], "input.r", 0, kMaxRadius);
  return in;
}

template <class AlgoT> struct CircleSpec {
  using Algo = AlgoT;
  using Input = curves::CircleInput;
  using Output = PixelsOutput;
  static constexpr bool midpoint = std::is_same_v<Algo, curves::CircleMidpoint>;
  static constexpr std::string_view family = "curves";
  static constexpr std::array views{View::plane2d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::integer, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"c":[0,0],"r":9})";
  static Input parse(const Json& j, Numeric) { return parse_circle(j); }
  template <class Num> static Input prepare(const Input& in) { return in; }
  template <class Num, class Probe> static Output compute(const Input& in, Probe& probe) {
    Output o;
    if constexpr (midpoint) curves::circle_midpoint<Num>(in, o.pixels, probe);
    else curves::circle_interior<Num>(in, o.pixels, probe);
    return o;
  }
  static Json to_json(const Output& o) { return pixels_json("pixels", o); }
  static void write_members(const Output& o, std::ostream& os) { pixels_members("pixels", o, os); }
  static std::size_t ops(const Output& o) { return o.pixels.size(); }
  // Four steps per octant row, about r / sqrt(2) rows.
  static std::size_t estimate_steps(const Input& in) { return 3 * static_cast<std::size_t>(in.r) + 8; }
  // The oracle states the set; the walk plots it octant by octant. Compared as sorted sets.
  static Output oracle(const Input& in) {
    return {midpoint ? oracle::circle_midpoint_pixels(in.cx, in.cy, in.r) : oracle::circle_interior_pixels(in.cx, in.cy, in.r)};
  }
  static Json canonical(Json result) {
    auto& px = result["pixels"];
    std::sort(px.begin(), px.end());
    return result;
  }
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(20261124);
    BenchSet<Input> random{"random", {}}, large{"large", {}};
    for (int i = 0; i < 2000; ++i) {
      const auto u = [&](std::int64_t lo, std::int64_t hi) { return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng); };
      random.inputs.push_back({u(-1000, 1000), u(-1000, 1000), u(0, 400)});
    }
    // Radii around 2^21 and 2^22, where float's decision variable runs out of significand bits.
    for (std::int64_t r : {(std::int64_t{1} << 21) - 3, (std::int64_t{1} << 21) + 5, (std::int64_t{1} << 22) - 1}) large.inputs.push_back({0, 0, r});
    return {random, large};
  }
};

}  // namespace

void register_curves(std::vector<Algorithm>& out) {
  out.push_back(make_algorithm<CubicSpec<curves::PolyForwardDiff>>());
  out.push_back(make_algorithm<CubicSpec<curves::PolyHorner>>());
  out.push_back(make_algorithm<CircleSpec<curves::CircleInterior>>());
  out.push_back(make_algorithm<CircleSpec<curves::CircleMidpoint>>());
}

}  // namespace sw
