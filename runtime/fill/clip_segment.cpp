// cohen-sutherland in the catalog (registered here).
// Semantics, bounds and the region comparison: docs/fill/clipping.md.
#include <numbers>
#include "fill/cohen_sutherland.hpp"
#include "fill/clip_common.hpp"

namespace sw {
namespace {

using namespace clipspec;
using oracle::Polygon2;

struct SegmentClipInput {
  Vec2<Rational> p0, p1, lo, hi;
};

struct SegmentClipOutput : SegmentPoints {
  // The same set: exact ends compared as an unordered pair.
  friend bool operator==(const SegmentClipOutput& a, const SegmentClipOutput& b) {
    return clip_equal<SegmentPoints>(a, b, [](const auto& x, const auto& y) { return x == y || (x[0] == y[1] && x[1] == y[0]); });
  }
};

struct CohenSutherlandSpec {
  static constexpr std::array hooks{Hook::handles, Hook::estimate_steps, Hook::canonical, Hook::error};
  using Algo = fill::CohenSutherland;
  using Input = SegmentClipInput;
  using Output = SegmentClipOutput;
  static constexpr std::array views{View::plane2d, View::table};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"segment":[[-3,1.5],[9,6]],"window":{"min":[0,0],"max":[8,5]}})";

  static Input parse(const Json& j) {
    only_keys(j, {"segment", "window"}, "input");
    const Json& s = j["segment"];
    if (!s.is_array() || s.size() != 2) throw InputError("input.segment: expected [[x, y], [x, y]]");
    const auto w = parse_window(j["window"], false);
    return {clip_point(s[0], "input.segment[0]"), clip_point(s[1], "input.segment[1]"), w[0], w[1]};
  }
  template <class Num> static std::array<Vec2<Num>, 4> prepare(const Input& in) {
    return {to_num<Num>(in.p0), to_num<Num>(in.p1), to_num<Num>(in.lo), to_num<Num>(in.hi)};
  }
  template <class Num, class Probe> static Output compute(const std::array<Vec2<Num>, 4>& p, Probe& probe) {
    const fill::ClippedSegment<Num> c = fill::cohen_sutherland<Num>(p[0], p[1], p[2], p[3], probe);
    Output o;
    if (c.segment) set_points<Num>(o, *c.segment);
    else o.present = false;
    o.bound_hit = c.bound_hit;
    return o;
  }
  static Json to_json(const Output& o) {
    Json r{{"segment", o.present ? points_json(o) : Json(nullptr)}};
    if (o.bound_hit) r["bound_hit"] = true;
    return r;
  }
  static std::size_t ops(const Output&) { return 1; }  // ns per clipped segment
  static std::size_t estimate_steps(const Input&) { return 16; }
  static Output oracle(const Input& in) {
    const auto s = oracle::clip_segment(in.p0, in.p1, in.lo, in.hi);
    Output o;
    if (s) set_points<Rational>(o, *s);
    else o.present = false;
    return o;
  }
  // The oracle states a set: the ends in (x, y) order.
  static Json canonical(Json result) {
    result.erase("fallback");  // informational, not part of the set
    Json& s = result["segment"];
    if (s.is_array() && s.size() == 2) {
      const Polygon2 e = points_of(s, "result.segment");
      if (e[1].x < e[0].x || (e[1].x == e[0].x && e[1].y < e[0].y)) std::swap(s[0], s[1]);
    }
    return result;
  }
  static constexpr std::string_view error_unit = "ulps";
  static double error(const Output& got, const Output& exact) {
    if (!exact.exact || got.present != exact.present || got.exact) return 0;
    return ulps_error(got, *exact.exact);
  }
  static std::vector<Handle> handles() {
    return {{"/segment/0", Handle::Kind::point2, 8, "p0"}, {"/segment/1", Handle::Kind::point2, 8, "p1"},
            {"/window/min", Handle::Kind::point2, 8, "min"}, {"/window/max", Handle::Kind::point2, 8, "max"}};
  }
  static std::vector<BenchSet<Input>> bench_sets();
};

// random: windows of 64 to 512 units and segments anywhere around them. hard: through and along
// the corners and edges, points, and crossings near a corner at 2^30, the last perturbed by 2^-40.
std::vector<BenchSet<SegmentClipInput>> CohenSutherlandSpec::bench_sets() {
  ClipRng g{std::mt19937_64(20261130)};
  BenchSet<Input> random{"random", {}}, hard{"hard", {}};
  for (int i = 0; i < 10000; ++i) {
    const Vec2<Rational> lo = g.point(-256, 0);
    const Vec2<Rational> hi{lo.x + g.coord(64, 512), lo.y + g.coord(64, 512)};
    random.inputs.push_back({g.point(-800, 800), g.point(-800, 800), lo, hi});
  }
  for (int i = 0; i < 2000; ++i) {
    const double s = i % 2 ? 1 : 1073741823.0 / 1024;  // unit windows, and windows scaled toward 2^30
    const Vec2<Rational> lo{num::to_rational(-256 * s), num::to_rational(-256 * s)}, hi{num::to_rational(512 * s), num::to_rational(256 * s)};
    const Vec2<Rational> corner = g.pick(0, 1) ? lo : hi, other{g.pick(0, 1) ? lo.x : hi.x, g.pick(0, 1) ? hi.y : lo.y};
    const Vec2<Rational> d = g.point(-300 * s, 300 * s);
    switch (i % 5) {
      case 0: hard.inputs.push_back({corner - d, corner + d, lo, hi}); break;           // through a corner
      case 1: hard.inputs.push_back({Vec2<Rational>{lo.x - d.x, other.y}, Vec2<Rational>{hi.x + d.y, other.y}, lo, hi}); break;  // along an edge line
      case 2: hard.inputs.push_back({corner + d, corner + d, lo, hi}); break;           // a point
      case 3: {  // within 2^-40 of a corner
        const Vec2<Rational> nudge{num::to_rational(std::ldexp(g.pick(-4, 4), -40)), num::to_rational(std::ldexp(g.pick(-4, 4), -40))};
        hard.inputs.push_back({corner - d + nudge, corner + d, lo, hi});
        break;
      }
      default: hard.inputs.push_back({other - d, other + Vec2<Rational>{d.y, d.x}, lo, hi}); break;
    }
  }
  // Keep every case within the input bounds (the corner cases reach past 2^30 at the largest scale).
  for (auto* set : {&random, &hard})
    std::erase_if(set->inputs, [](const Input& in) {
      for (const auto* p : {&in.p0, &in.p1})
        if (abs(p->x) > Rational(fillspec::kCoordBound) || abs(p->y) > Rational(fillspec::kCoordBound)) return true;
      return false;
    });
  return {random, hard};
}

SW_REGISTER(CohenSutherlandSpec);

}  // namespace

}  // namespace sw
