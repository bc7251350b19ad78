// The fill family's triangle fills: triangle-dda, triangle-dda-no-offset, triangle-edge
// (scanline-polygon: scanline_spec.cpp). Semantics: docs/fill/semantics.md.
#include <random>
#include "register.hpp"
#include "fill/triangle_dda.hpp"
#include "fill/triangle_edge.hpp"
#include "fill_oracle.hpp"
#include "fill/fill_common.hpp"

namespace sw {
namespace {

using namespace fillspec;

struct TriangleInput {
  std::array<Vec2<Rational>, 3> v;
  std::vector<std::vector<Rational>> attrs;  // empty, or 3 lists of n values
};

TriangleInput parse_triangle(const Json& j, bool with_attrs) {
  if (with_attrs) only_keys_optional(j, {"triangle"}, {"attrs"}, "input");
  else only_keys(j, {"triangle"}, "input");
  const Json& t = j["triangle"];
  if (!t.is_array() || t.size() != 3) throw InputError("input.triangle: expected three vertices [[x,y],[x,y],[x,y]]");
  TriangleInput in;
  for (int k = 0; k < 3; ++k) in.v[k] = parse_vertex(t[k], "input.triangle[" + std::to_string(k) + "]", kCoordBound);
  check_budget({in.v.begin(), in.v.end()}, "input.triangle");
  if (with_attrs && j.contains("attrs")) in.attrs = parse_attrs(j["attrs"], 3);
  return in;
}

// int mode is fixed point in 1/256 pixel: vertices on that grid, within the fixed-point bound.
void require_fixed_point(const TriangleInput& in) {
  for (int k = 0; k < 3; ++k)
    for (int a = 0; a < 2; ++a) {
      const std::string what = "input.triangle[" + std::to_string(k) + "][" + std::to_string(a) + "]";
      check_bound(in.v[k][a], kFixedCoordBound, what);
      if (Rational(in.v[k][a] * kFixedUnit).get_den() != 1)
        throw InputError(what + ": " + in.v[k][a].get_str() + " is not a multiple of 1/256 (int mode is fixed point in 1/256 pixel)");
    }
}

// Random triangles on the 1/256 grid whose boxes are about `side` samples wide, around the origin.
std::vector<TriangleInput> random_triangles(std::mt19937_64& rng, int count, double side, bool attrs) {
  std::uniform_real_distribution<double> u(-side / 2, side / 2), c(-256, 256);
  auto grid = [&](double x) -> Rational { return Rational(static_cast<long>(std::floor(x * 256))) / 256; };
  std::vector<TriangleInput> out;
  for (int i = 0; i < count; ++i) {
    TriangleInput in;
    const double cx = c(rng), cy = c(rng);
    for (auto& v : in.v) v = {grid(cx + u(rng)), grid(cy + u(rng))};
    if (attrs)
      for (int k = 0; k < 3; ++k) in.attrs.push_back({grid(u(rng) + side), grid(u(rng)), grid(u(rng) - side)});
    out.push_back(std::move(in));
  }
  return out;
}

// Triangles of 8, 128 and 2048 px^2 on average: a random triangle in a square of side s has mean
// area 11/144 s^2, so s = 10, 41 and 164.
std::vector<BenchSet<TriangleInput>> triangle_bench_sets(bool attrs) {
  std::mt19937_64 rng(20261123);
  return {{"8px", random_triangles(rng, 4000, 10, attrs)}, {"128px", random_triangles(rng, 1000, 41, attrs)}, {"2048px", random_triangles(rng, 100, 164, attrs)}};
}

// The box's samples (each a plot or a test and a step at most), and the rows' own steps.
std::size_t triangle_steps(const TriangleInput& in) {
  const Rational height = std::max({in.v[0].y, in.v[1].y, in.v[2].y}) - std::min({in.v[0].y, in.v[1].y, in.v[2].y});
  return static_cast<std::size_t>(2 * box_samples({in.v.begin(), in.v.end()})) + 4 * static_cast<std::size_t>(num::ceil_int(height)) + 64;
}

std::vector<Handle> triangle_handles() {
  std::vector<Handle> h;
  for (int k = 0; k < 3; ++k) h.push_back({"/triangle/" + std::to_string(k), Handle::Kind::point2, 8, "p" + std::to_string(k)});
  return h;
}

template <bool Offset> struct TriangleDdaSpec {
  static constexpr std::array hooks{Hook::handles, Hook::error, Hook::estimate_steps};
  using Algo = std::conditional_t<Offset, fill::TriangleDda, fill::TriangleDdaNoOffset>;
  using Input = TriangleInput;
  using Output = FillOutput;
  static constexpr std::array views{View::plane2d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example = Offset ? R"({"triangle":[[1.5,0.75],[12.25,4.5],[5,10.5]],"attrs":[[1,0,0],[0,1,0],[0,0,1]]})"
                                                   : R"({"triangle":[[1.5,0.75],[12.25,4.5],[5,10.5]]})";
  static Input parse(const Json& j) { return parse_triangle(j, true); }
  static std::vector<Handle> handles() { return triangle_handles(); }
  template <class Num> static fill::Triangle<Num> prepare(const Input& in) {
    fill::Triangle<Num> t;
    for (int k = 0; k < 3; ++k) {
      t[k].p = to_num<Num>(in.v[k]);
      t[k].n = in.attrs.empty() ? 0 : in.attrs[k].size();
      for (std::size_t c = 0; c < t[k].n; ++c) t[k].a[c] = num::from_rational<Num>(in.attrs[k][c]);
    }
    return t;
  }
  template <class Num, class Probe> static Output compute(const fill::Triangle<Num>& t, Probe& probe) {
    fill::FillResult<Num> r;
    fill::triangle_dda<Offset, Num>(t, r, probe);
    return fill_output<Num>(std::move(r.pixels), t[0].n, r.values);
  }
  static Json to_json(const Output& o) { return fill_json(o); }
  static std::size_t ops(const Output& o) { return o.pixels.size(); }
  static constexpr std::string_view error_unit = "pixels";
  static double error(const Output& got, const Output& exact) { return wrong_pixels(got, exact); }
  // The box's samples (each a plot and a step at most) and two steps per row.
  static std::size_t estimate_steps(const Input& in) { return triangle_steps(in); }
  // The covered samples, and at each the plane through the vertices' attributes. The no-offset
  // variant has no specification but its procedure: its oracle is its exact run, and the tests
  // count how far that is from the covered samples.
  static Output oracle(const Input& in) {
    if constexpr (!Offset) {
      NoProbe none;
      return compute<Rational>(prepare<Rational>(in), none);
    }
    return plane_values(oracle::triangle_samples(in.v), in.v, in.attrs);
  }
  static std::vector<BenchSet<Input>> bench_sets() { return triangle_bench_sets(true); }
};

struct TriangleEdgeSpec {
  static constexpr std::array hooks{Hook::handles, Hook::error, Hook::estimate_steps, Hook::admit};
  using Algo = fill::TriangleEdge;
  using Input = TriangleInput;
  using Output = FillOutput;
  static constexpr std::array views{View::plane2d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::integer, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"triangle":[[1.5,0.75],[12.25,4.5],[5,10.5]]})";
  static Input parse(const Json& j) { return parse_triangle(j, false); }
  static void admit(const Input& in, Numeric n) {
    if (n == Numeric::integer) require_fixed_point(in);
  }
  static std::vector<Handle> handles() { return triangle_handles(); }
  template <class Num> static fill::EdgeTriangle<Num> prepare(const Input& in) {
    if constexpr (std::is_same_v<Num, std::int64_t>) {
      fill::EdgeTriangle<Num> t{{}, kFixedUnit};
      for (int k = 0; k < 3; ++k) t.v[k] = {num::floor_int(Rational(in.v[k].x * kFixedUnit)), num::floor_int(Rational(in.v[k].y * kFixedUnit))};
      return t;
    } else {
      return {{to_num<Num>(in.v[0]), to_num<Num>(in.v[1]), to_num<Num>(in.v[2])}, Num(1)};
    }
  }
  template <class Num, class Probe> static Output compute(const fill::EdgeTriangle<Num>& t, Probe& probe) {
    Output o;
    fill::triangle_edge<Num>(t, o.pixels, probe);
    return o;
  }
  static Json to_json(const Output& o) { return fill_json(o); }
  static std::size_t ops(const Output& o) { return o.pixels.size(); }
  static constexpr std::string_view error_unit = "pixels";
  static double error(const Output& got, const Output& exact) { return wrong_pixels(got, exact); }
  static std::size_t estimate_steps(const Input& in) { return triangle_steps(in); }
  static Output oracle(const Input& in) { return {oracle::triangle_samples(in.v), 0, {}, {}}; }
  static std::vector<BenchSet<Input>> bench_sets() { return triangle_bench_sets(false); }
};

SW_REGISTER(TriangleDdaSpec<true>);
SW_REGISTER(TriangleDdaSpec<false>);
SW_REGISTER(TriangleEdgeSpec);

}  // namespace

}  // namespace sw
