// scanline-polygon in the catalog: the edge-table fill of polygons with holes, even-odd or
// nonzero. Semantics: docs/fill/semantics.md.
#include <random>
#include "register.hpp"
#include "fill/scanline_polygon.hpp"
#include "fill_oracle.hpp"
#include "fill/fill_common.hpp"

namespace sw {
namespace {

using namespace fillspec;

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
  static constexpr std::string_view error_unit = "pixels";
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

SW_REGISTER(ScanlinePolygonSpec);

}  // namespace

}  // namespace sw
