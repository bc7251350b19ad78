// The fill family's fills: triangle-dda, triangle-dda-no-offset, triangle-edge, scanline-polygon
// (registered here). Semantics: docs/fill/semantics.md.
#include <random>
#include "register.hpp"
#include "fill/scanline_polygon.hpp"
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
  static double error(const Output& got, const Output& exact) { return wrong_pixels(got, exact); }
  static std::size_t estimate_steps(const Input& in) { return triangle_steps(in); }
  static Output oracle(const Input& in) { return {oracle::triangle_samples(in.v), 0, {}, {}}; }
  static std::vector<BenchSet<Input>> bench_sets() { return triangle_bench_sets(false); }
};

struct PolygonInput {
  std::vector<std::vector<Vec2<Rational>>> rings;
  fill::WindingRule rule = fill::WindingRule::even_odd;
};

struct ScanlinePolygonSpec {
  static constexpr std::array hooks{Hook::handles, Hook::error, Hook::estimate_steps, Hook::table_lines};
  using Algo = fill::ScanlinePolygon;
  using Input = PolygonInput;
  using Output = FillOutput;
  static constexpr std::array views{View::plane2d, View::table};
  static constexpr std::array<std::string_view, 2> table_lines{"bucket", "sort"};  // the edge table, then the active list per row
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example =
      R"({"polygon":[[8,1.5],[10.5,13.25],[1.25,5.5],[14.75,5.5],[5.5,13.25]],"rule":"even-odd"})";
  static std::vector<Vec2<Rational>> parse_ring(const Json& r, const std::string& what) {
    if (!r.is_array() || r.size() < 3) throw InputError(what + ": expected at least 3 vertices [[x,y],...]");
    std::vector<Vec2<Rational>> ring;
    for (std::size_t k = 0; k < r.size(); ++k) ring.push_back(parse_vertex(r[k], what + "[" + std::to_string(k) + "]", kCoordBound));
    return ring;
  }
  static Input parse(const Json& j) {
    only_keys_optional(j, {"polygon", "rule"}, {"rings"}, "input");
    Input in;
    in.rings.push_back(parse_ring(j["polygon"], "input.polygon"));
    if (j.contains("rings")) {
      if (!j["rings"].is_array()) throw InputError("input.rings: expected a list of rings [[[x,y],...],...]");
      for (std::size_t k = 0; k < j["rings"].size(); ++k) in.rings.push_back(parse_ring(j["rings"][k], "input.rings[" + std::to_string(k) + "]"));
    }
    const Json& rule = j["rule"];
    if (rule == "even-odd") in.rule = fill::WindingRule::even_odd;
    else if (rule == "nonzero") in.rule = fill::WindingRule::nonzero;
    else throw InputError("input.rule: expected \"even-odd\" or \"nonzero\", got " + rule.dump().substr(0, 40));
    std::vector<Vec2<Rational>> all;
    for (const auto& r : in.rings) all.insert(all.end(), r.begin(), r.end());
    if (all.size() > kMaxRingVertices) throw InputError("input: " + std::to_string(all.size()) + " vertices in all rings, more than the bound of 4096");
    check_budget(all, "input.polygon");
    return in;
  }
  static std::vector<Handle> handles() {
    std::vector<Handle> h;
    for (int k = 0; k < 3; ++k) h.push_back({"/polygon/" + std::to_string(k), Handle::Kind::point2, 8, "p" + std::to_string(k)});
    return h;
  }
  template <class Num> static fill::Polygon<Num> prepare(const Input& in) {
    fill::Polygon<Num> p{{}, in.rule};
    for (const auto& r : in.rings) {
      p.rings.emplace_back();
      for (const auto& v : r) p.rings.back().push_back(to_num<Num>(v));
    }
    return p;
  }
  template <class Num, class Probe> static Output compute(const fill::Polygon<Num>& p, Probe& probe) {
    Output o;
    fill::scanline_polygon<Num>(p, o.pixels, probe);
    return o;
  }
  static Json to_json(const Output& o) { return fill_json(o); }
  static std::size_t ops(const Output& o) { return o.pixels.size(); }
  static double error(const Output& got, const Output& exact) { return wrong_pixels(got, exact); }
  // Two steps an edge, then per row of the box: add, drop, sort, advance and a span (two steps) per
  // pair of the at most n active edges.
  static std::size_t estimate_steps(const Input& in) {
    std::size_t n = 0;
    Rational lo = in.rings[0][0].y, hi = lo;
    for (const auto& r : in.rings) {
      n += r.size();
      for (const auto& v : r) lo = std::min(lo, v.y), hi = std::max(hi, v.y);
    }
    const auto rows = static_cast<std::size_t>(num::floor_int(Rational(hi - lo))) + 2;
    return 2 * n + rows * (4 + 2 * n) + 8;
  }
  static Output oracle(const Input& in) {
    return {oracle::polygon_samples(in.rings, in.rule == fill::WindingRule::nonzero ? oracle::FillRule::nonzero : oracle::FillRule::even_odd), 0, {}, {}};
  }
  // Random stars of 5 to 12 points, half of them with a hole.
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(20261124);
    std::uniform_real_distribution<double> r(4, 40), a(0, 6.283185307179586);
    auto grid = [&](double x) -> Rational { return Rational(static_cast<long>(std::floor(x * 256))) / 256; };
    BenchSet<Input> stars{"stars", {}};
    for (int s = 0; s < 400; ++s) {
      Input in;
      in.rule = s % 2 ? fill::WindingRule::nonzero : fill::WindingRule::even_odd;
      const int n = 5 + s % 8;
      in.rings.emplace_back();
      for (int k = 0; k < n; ++k) {
        const double t = a(rng), rad = r(rng);
        in.rings.back().push_back({grid(rad * std::cos(t)), grid(rad * std::sin(t))});
      }
      if (s % 4 < 2) in.rings.push_back({{-2, -2}, {-2, 2}, {2, 2}, {2, -2}});
      stars.inputs.push_back(std::move(in));
    }
    return {stars};
  }
};

SW_REGISTER(TriangleDdaSpec<true>);
SW_REGISTER(TriangleDdaSpec<false>);
SW_REGISTER(TriangleEdgeSpec);
SW_REGISTER(ScanlinePolygonSpec);

}  // namespace

}  // namespace sw
