// The curves family's catalog entries: poly-forward-diff, poly-horner, circle-interior,
// circle-midpoint, implicit-curve. Semantics and bounds: docs/curves/semantics.md and (the
// implicit walk) docs/curves/implicit.md.
#include <algorithm>
#include <random>
#include "register.hpp"
#include "curves/circle_interior.hpp"
#include "curves/circle_midpoint.hpp"
#include "curves/implicit_curve.hpp"
#include "curves/outlines.hpp"
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

CubicInput parse_cubic(const Json& j) {
  only_keys(j, {"coeffs", "xs", "xe"}, "input");
  CubicInput in;
  const Json& c = j["coeffs"];
  if (!c.is_array() || c.size() != 4) throw InputError("input.coeffs: expected [a, b, c, d] (y = a x^3 + b x^2 + c x + d)");
  for (int k = 0; k < 4; ++k) {
    const std::string what = "input.coeffs[" + std::to_string(k) + "]";
    in.c[k] = parse_rational(c[k], what);
    check_digits(in.c[k], what);
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
  static constexpr std::array hooks{Hook::table_lines, Hook::outline, Hook::write_members, Hook::estimate_steps, Hook::bench_runs, Hook::admit};
  using Algo = AlgoT;
  using Input = CubicInput;
  using Output = PixelsOutput;
  static constexpr bool forward = std::is_same_v<Algo, curves::PolyForwardDiff>;
  static constexpr std::array views{View::plane2d, View::table, View::plot};
  // One row per column: the difference table (x, y, j, d1, d2), or Horner's x, y, j.
  static constexpr auto table_lines = [] {
    if constexpr (forward) return std::array<std::string_view, 2>{"start", "step"};
    else return std::array<std::string_view, 1>{"eval"};
  }();
  static std::vector<Polyline2> outline(const Input& in, const Rect2& w, double cell) { return curves::cubic_outline(in.c, in.xs, in.xe, w, cell); }
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::integer, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"coeffs":["1/64",0,"-3/2",2],"xs":-12,"xe":13})";
  static Input parse(const Json& j) { return parse_cubic(j); }
  static void admit(const Input& in, Numeric n) {
    for (int k = 0; k < 4 && n == Numeric::integer; ++k)
      if (in.c[k].get_den() != 1)
        throw InputError("input.coeffs[" + std::to_string(k) + "]: " + in.c[k].get_str() + " is not an integer (int mode takes integer coefficients)");
  }
  template <class Num> static curves::Cubic<Num> prepare(const Input& in) {
    curves::Cubic<Num> p;
    for (int k = 0; k < 4; ++k) p.c[k] = num::from_rational<Num>(in.c[k]);
    p.xs = in.xs, p.xe = in.xe;
    return p;
  }
  template <class Num, class Probe> static Output compute(const curves::Cubic<Num>& p, Probe& probe) {
    Output o;
    Algo{}(p, o.pixels, probe);
    return o;
  }
  static Json to_json(const Output& o) { return pixels_json("pixels", o); }
  static void write_members(const Output& o, std::ostream& os) { pixels_members("pixels", o, os); }
  static std::size_t ops(const Output& o) { return o.pixels.size(); }
  static std::size_t estimate_steps(const Input& in) { return 2 * static_cast<std::size_t>(in.xe - in.xs) + 8; }
  static Output oracle(const Input& in) { return {oracle::poly_pixels(in.c, in.xs, in.xe)}; }
  // The int mode runs only on the sets with integer coefficients.
  static bool bench_runs(const std::string& set, Numeric n) { return n != Numeric::integer || set != "long"; }
  static std::vector<BenchSet<Input>> bench_sets(BenchSize size) {
    std::mt19937_64 rng(20261123);
    auto small = [&](int lo, int hi) { return Rational(std::uniform_int_distribution<int>(lo, hi)(rng)); };
    BenchSet<Input> random{"random", {}}, long_runs{"long", {}};
    // Integer cubics over 64 columns: every mode is exact unless a value leaves its significand.
    for (int i = 0; i < 2000; ++i) {
      const std::int64_t xs = std::uniform_int_distribution<std::int64_t>(-512, 448)(rng);
      random.inputs.push_back({{small(-3, 3), small(-50, 50), small(-500, 500), small(-9999, 9999)}, xs, xs + 64});
    }
    // 10^6 columns with dyadic coefficients: float's table drifts, Horner's error stays local.
    // Quick: 62500 columns.
    for (int i = 0; i < 4; ++i) {
      const Rational a = small(1, 9) / Rational(mpz_class(1) << 40), b = -small(1, 9) / Rational(mpz_class(1) << 21);
      long_runs.inputs.push_back({{a, b, small(-3, 3) / Rational(8), small(-99, 99)}, 0, size == BenchSize::full ? 1000000 : 62500});
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
  static constexpr std::array hooks{Hook::table_lines, Hook::outline, Hook::handles, Hook::write_members, Hook::estimate_steps, Hook::result_sets};
  using Algo = AlgoT;
  using Input = curves::CircleInput;
  using Output = PixelsOutput;
  static constexpr bool midpoint = std::is_same_v<Algo, curves::CircleMidpoint>;
  static constexpr std::array views{View::plane2d, View::table, View::plot};
  static constexpr std::array<std::string_view, 1> table_lines{"plot"};  // one row per octant pixel
  static std::vector<Polyline2> outline(const Input& in, const Rect2& w, double cell) { return curves::circle_outline(in.cx, in.cy, in.r, w, cell); }
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::integer, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"c":[0,0],"r":9})";
  static Input parse(const Json& j) { return parse_circle(j); }
  static std::vector<Handle> handles() { return {{"/c", Handle::Kind::point2, 1, "c"}}; }
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
  static constexpr std::array<std::string_view, 1> result_sets{"pixels"};
  static std::vector<BenchSet<Input>> bench_sets(BenchSize size) {
    std::mt19937_64 rng(20261124);
    BenchSet<Input> random{"random", {}}, large{"large", {}};
    for (int i = 0; i < 2000; ++i) {
      const auto u = [&](std::int64_t lo, std::int64_t hi) { return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng); };
      random.inputs.push_back({u(-1000, 1000), u(-1000, 1000), u(0, 400)});
    }
    // Radii around 2^21 and 2^22, where float's decision variable runs out of significand bits.
    // Quick: 64 times smaller (12 million pixels become 190 thousand), where float is still exact.
    const std::int64_t shift = size == BenchSize::full ? 0 : 6;
    for (std::int64_t r : {(std::int64_t{1} << 21) - 3, (std::int64_t{1} << 21) + 5, (std::int64_t{1} << 22) - 1}) large.inputs.push_back({0, 0, r >> shift});
    return {random, large};
  }
};

// --- implicit-curve ---

// Bounds: |start| <= 2^20, 1 <= max_steps <= 2^20, terms [coef, i, j] with i + j <= 3, each (i, j)
// once, coefficients of at most 64-bit numerator and denominator, and |P| <= 2^100 wherever the
// walk can go (so float neither overflows nor writes inf into a trace).
constexpr std::int64_t kMaxStart = std::int64_t{1} << 20, kMaxWalk = std::int64_t{1} << 20;

struct ImplicitInput {
  std::array<std::array<Rational, 4>, 4> c;  // c[i][j]: the coefficient of x^i y^j
  Pixel start;
  std::int64_t max_steps = 1;
  int degree = 1;
};

ImplicitInput parse_implicit(const Json& j) {
  only_keys(j, {"P", "start", "max_steps"}, "input");
  ImplicitInput in;
  const Json& P = j["P"];
  if (!P.is_array() || P.empty())
    throw InputError("input.P: expected a non-empty list of terms [coef, i, j] (P = sum coef x^i y^j)");
  std::array<std::array<int, 4>, 4> seen{};  // 1 + the index of the term that set (i, j)
  int degree = 0;
  for (std::size_t k = 0; k < P.size(); ++k) {
    const std::string what = "input.P[" + std::to_string(k) + "]";
    const Json& t = P[k];
    if (!t.is_array() || t.size() != 3) throw InputError(what + ": expected a term [coef, i, j]");
    const Rational coef = parse_rational(t[0], what + "[0]");
    check_digits(coef, what + "[0]");
    const auto i = parse_integer(t[1], what + "[1]", 0, 3), e = parse_integer(t[2], what + "[2]", 0, 3);
    if (i + e > 3)
      throw InputError(what + ": x^" + std::to_string(i) + " y^" + std::to_string(e) + " has degree " + std::to_string(i + e) +
                       ", beyond 3");
    if (seen[i][e])
      throw InputError(what + ": duplicate term x^" + std::to_string(i) + " y^" + std::to_string(e) + " (also input.P[" +
                       std::to_string(seen[i][e] - 1) + "])");
    seen[i][e] = static_cast<int>(k) + 1;
    in.c[i][e] = coef;
    if (coef != 0) degree = std::max(degree, static_cast<int>(i + e));
  }
  if (degree == 0) throw InputError("input.P: no term of degree >= 1 with a nonzero coefficient (P is constant)");
  in.degree = degree;
  const Json& s = j["start"];
  if (!s.is_array() || s.size() != 2) throw InputError("input.start: expected the start pixel [x, y] (integers)");
  in.start = {parse_integer(s[0], "input.start[0]", -kMaxStart, kMaxStart),
              parse_integer(s[1], "input.start[1]", -kMaxStart, kMaxStart)};
  in.max_steps = parse_integer(j["max_steps"], "input.max_steps", 1, kMaxWalk);
  // |P| <= sum |c_ij| X^(i + j) for |x|, |y| <= X. Midpoints stay within max_steps of the start and
  // the table's first corners within 2.
  const Rational X(std::max(std::abs(in.start.x), std::abs(in.start.y)) + in.max_steps + 2);
  Rational bound = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; a + b < 4; ++b) {
      Rational term = abs(in.c[a][b]);
      for (int k = 0; k < a + b; ++k) term *= X;
      bound += term;
    }
  if (bound > Rational(std::ldexp(1.0, 100)))
    throw InputError("input: |P| may reach " + num::to_text(bound.get_d()) +
                     " within max_steps of the start, beyond the bound 2^100");
  return in;
}

struct ImplicitOutput {
  std::vector<Pixel> pixels;
  curves::WalkStop stopped = curves::WalkStop::max_steps;
  std::int64_t steps = 0;
  friend bool operator==(const ImplicitOutput&, const ImplicitOutput&) = default;
};

// No int mode: coefficients may be fractions, and P at the half-integer midpoints is not an integer.
struct ImplicitSpec {
  static constexpr std::array hooks{Hook::table_lines, Hook::outline, Hook::handles, Hook::estimate_steps};
  using Algo = curves::ImplicitCurve;
  using Input = ImplicitInput;
  using Output = ImplicitOutput;
  static constexpr std::array views{View::plane2d, View::table};
  static constexpr std::array<std::string_view, 1> table_lines{"grad"};  // one row per move
  static std::vector<Polyline2> outline(const Input& in, const Rect2& w, double cell) { return curves::implicit_outline(in.c, w, cell); }
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"P":[["1/4",2,0],[1,0,2],[-36,0,0]],"start":[-12,0],"max_steps":200})";
  static Input parse(const Json& j) { return parse_implicit(j); }
  static std::vector<Handle> handles() { return {{"/start", Handle::Kind::point2, 1, "start"}}; }
  template <class Num> static curves::ImplicitPoly<Num> prepare(const Input& in) {
    curves::ImplicitPoly<Num> p;
    for (int i = 0; i < 4; ++i)
      for (int k = 0; i + k < 4; ++k) p.c[i][k] = num::from_rational<Num>(in.c[i][k]);
    p.start = in.start, p.max_steps = in.max_steps, p.degree = in.degree;
    return p;
  }
  template <class Num, class Probe> static Output compute(const curves::ImplicitPoly<Num>& p, Probe& probe) {
    Output o;
    const curves::WalkEnd end = curves::implicit_curve<Num>(p, o.pixels, probe);
    o.stopped = end.stopped, o.steps = end.steps;
    return o;
  }
  static Json to_json(const Output& o) {
    Json r = pixels_json("pixels", {o.pixels, true});
    r["closed"] = o.stopped == curves::WalkStop::closed;
    r["steps"] = o.steps;
    r["stopped"] = std::string(curves::kWalkStopNames[static_cast<std::size_t>(o.stopped)]);
    return r;
  }
  static std::size_t ops(const Output& o) { return o.pixels.size(); }
  // Six steps per move (grad, axes, probe, decide, move, plot) and a few around them.
  static std::size_t estimate_steps(const Input& in) { return 6 * static_cast<std::size_t>(in.max_steps) + 8; }
  static Output oracle(const Input& in) {
    oracle::ImplicitWalkEnd end;
    Output o{oracle::implicit_walk_pixels(in.c, in.start, in.max_steps, &end), curves::WalkStop::max_steps, end.steps};
    for (std::size_t k = 0; k < curves::kWalkStopNames.size(); ++k)
      if (curves::kWalkStopNames[k] == end.stopped) o.stopped = static_cast<curves::WalkStop>(k);
    return o;
  }
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(20261125);
    const auto u = [&](std::int64_t lo, std::int64_t hi) { return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng); };
    auto input = [](std::initializer_list<std::array<Rational, 3>> terms, Pixel start, std::int64_t max_steps) {
      Input in;
      for (const auto& t : terms) {
        const int i = static_cast<int>(t[1].get_num().get_si()), k = static_cast<int>(t[2].get_num().get_si());
        in.c[i][k] = t[0];
        if (t[0] != 0) in.degree = std::max(in.degree, i + k);
      }
      in.start = start, in.max_steps = max_steps;
      return in;
    };
    BenchSet<Input> random{"random", {}}, hard{"hard", {}};
    // a x^2 + b y^2 = r^2 with a, b in {1/4, 1/2, ..., 4} (dyadic), started on the curve's left.
    for (int i = 0; i < 500; ++i) {
      const Rational a = Rational(1 << u(0, 4)) / 4, b = Rational(1 << u(0, 4)) / 4;  // canonical: no mpq_class(p, q)
      const std::int64_t r = u(1, 200);
      const std::int64_t x0 = -std::llround(static_cast<double>(r) / std::sqrt(a.get_d()));
      random.inputs.push_back(input({{a, 2, 0}, {b, 0, 2}, {Rational(-r * r), 0, 0}}, {x0, 0}, 8192));
    }
    // The corpus kinds: a line, a hyperbola along its asymptote, a nodal cubic, a cusp, a far start.
    for (int i = 0; i < 8; ++i) {
      hard.inputs.push_back(input({{3, 1, 0}, {-7, 0, 1}, {Rational(u(-9, 9)) / 2, 0, 0}}, {0, 0}, 4096));
      hard.inputs.push_back(input({{1, 1, 1}, {-30, 0, 0}}, {1, 30}, 4096));
      hard.inputs.push_back(input({{1, 0, 2}, {-1, 3, 0}, {-8, 2, 0}}, {-3 - i, 4}, 4096));
      hard.inputs.push_back(input({{1, 0, 2}, {-1, 3, 0}}, {9 + i, 27}, 4096));
      hard.inputs.push_back(input({{1, 2, 0}, {1, 0, 2}, {-100, 0, 0}}, {40 + i, 3}, 4096));
    }
    // Large off-centre circles: P reaches 2^24 and more, where float's table starts to round.
    for (std::int64_t r : {3000, 4097}) {
      const std::int64_t cx = 1000, cy = -700;
      hard.inputs.push_back(input({{1, 2, 0}, {1, 0, 2}, {-2 * cx, 1, 0}, {-2 * cy, 0, 1}, {cx * cx + cy * cy - r * r, 0, 0}},
                                  {cx - r, cy}, 30000));
    }
    return {random, hard};
  }
};

SW_REGISTER(CubicSpec<curves::PolyForwardDiff>);
SW_REGISTER(CubicSpec<curves::PolyHorner>);
SW_REGISTER(CircleSpec<curves::CircleInterior>);
SW_REGISTER(CircleSpec<curves::CircleMidpoint>);
SW_REGISTER(ImplicitSpec);

}  // namespace


}  // namespace sw
