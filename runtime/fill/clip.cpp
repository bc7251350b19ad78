// The fill family's clippers in the catalog: cohen-sutherland and sutherland-hodgman (registered
// by specs.cpp). Semantics, bounds and the region comparison: docs/fill/clipping.md.
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include "adapter.hpp"
#include "fill/cohen_sutherland.hpp"
#include "fill/sutherland_hodgman.hpp"
#include "fill_clip_oracle.hpp"

namespace sw {
namespace {

using oracle::Polygon2;

// |coordinate| <= 2^30, numerator and denominator of at most 64 bits: float's products of two
// differences stay far from overflow, and exact arithmetic stays small.
constexpr double kClipBound = 1073741824.0;
constexpr std::size_t kMaxSubject = 256, kMaxClip = 32;  // vertices: keeps every traced polygon < 2^15 points

Vec2<Rational> clip_point(const Json& v, const std::string& what) {
  if (!v.is_array() || v.size() != 2) throw InputError(what + ": expected [x, y]");
  Vec2<Rational> p;
  for (int a = 0; a < 2; ++a) {
    const std::string w = what + "[" + std::to_string(a) + "]";
    p[a] = parse_rational(v[a], w);
    check_bound(p[a], kClipBound, w);
    check_digits(p[a], w);
  }
  return p;
}

// {"min":[x,y],"max":[x,y]} with min <= max; `need_area`: min < max (a clip polygon needs an inside).
std::array<Vec2<Rational>, 2> parse_window(const Json& j, bool need_area) {
  only_keys(j, {"min", "max"}, "input.window");
  const Vec2<Rational> lo = clip_point(j["min"], "input.window.min"), hi = clip_point(j["max"], "input.window.max");
  for (int a = 0; a < 2; ++a) {
    const std::string k = "[" + std::to_string(a) + "]";
    if (lo[a] > hi[a]) throw InputError("input.window: min" + k + " > max" + k + " (min is the lower-left corner)");
    if (need_area && lo[a] == hi[a]) throw InputError("input.window: zero area (min" + k + " = max" + k + ")");
  }
  return {lo, hi};
}

Polygon2 parse_polygon(const Json& j, const std::string& what, std::size_t max_vertices) {
  if (!j.is_array()) throw InputError(what + ": expected an array of [x, y] vertices");
  if (j.size() < 3) throw InputError(what + ": expected at least 3 vertices, got " + std::to_string(j.size()));
  if (j.size() > max_vertices) throw InputError(what + ": more than " + std::to_string(max_vertices) + " vertices");
  Polygon2 p;
  for (std::size_t i = 0; i < j.size(); ++i) p.push_back(clip_point(j[i], what + "[" + std::to_string(i) + "]"));
  return p;
}

Rational cross(const Vec2<Rational>& a, const Vec2<Rational>& b, const Vec2<Rational>& v) {
  return (b.x - a.x) * (v.y - a.y) - (b.y - a.y) * (v.x - a.x);
}

// Convex and winding once: a nonzero area, every vertex on the inner side of (or on) every edge's
// line, and winding number +-1 around a point inside. Repeated and collinear vertices are fine.
void check_convex(const Polygon2& c, const std::string& what) {
  const int o = sgn(oracle::twice_signed_area(c));
  if (o == 0) throw InputError(what + ": the clip polygon has zero area");
  const std::size_t m = c.size();
  for (std::size_t k = 0; k < m; ++k)
    for (std::size_t i = 0; i < m; ++i)
      if (o * sgn(cross(c[k], c[(k + 1) % m], c[i])) < 0)
        throw InputError(what + ": the clip polygon is not convex (vertex " + std::to_string(i) + " is outside edge " + std::to_string(k) + ")");
  for (std::size_t i = 1; i + 1 < m; ++i)
    if (sgn(cross(c[0], c[i], c[i + 1])) != 0) {
      const Vec2<Rational> inside{(c[0].x + c[i].x + c[i + 1].x) / 3, (c[0].y + c[i].y + c[i + 1].y) / 3};
      const std::int64_t w = oracle::winding_at(c, inside);
      if (w != 1 && w != -1) throw InputError(what + ": the clip polygon winds " + std::to_string(w) + " times around its inside");
      return;
    }
}

// What every mode returns: per point an enclosure [lo, hi] of doubles (lo = hi, the mode's own
// value, for float and double; the certified interval for filtered) and, in exact mode (and from
// the oracle), the exact points. A segment's two ends live in arrays: no allocation per run.
template <class Doubles, class Exacts> struct ClipPoints {
  bool present = true;     // cohen-sutherland: false when the segment misses the window
  bool bound_hit = false;  // cohen-sutherland's cut bound stopped a rounded mode
  int bits = 53;           // significand bits of the mode (24: float)
  bool certified = false;  // filtered: lo and hi enclose the exact value
  Doubles lo{}, hi{};
  std::shared_ptr<const Exacts> exact;
};
using SegmentPoints = ClipPoints<std::array<Vec2<double>, 2>, std::array<Vec2<Rational>, 2>>;
using PolygonPoints = ClipPoints<std::vector<Vec2<double>>, Polygon2>;

template <class Num, class Out, class Points> void set_points(Out& o, const Points& pts) {
  if constexpr (std::is_same_v<Num, float>) o.bits = 24;
  o.certified = is_filtered<Num>;
  if constexpr (std::is_same_v<Num, Rational>) o.exact = std::make_shared<const Points>(pts);
  if constexpr (requires { o.lo.resize(0); }) o.lo.resize(pts.size()), o.hi.resize(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if constexpr (is_filtered<Num>) {
      o.lo[i] = {pts[i].x.lo(), pts[i].y.lo()}, o.hi[i] = {pts[i].x.hi(), pts[i].y.hi()};
    } else {
      o.lo[i] = o.hi[i] = {num::to_double(pts[i].x), num::to_double(pts[i].y)};
    }
  }
}

template <class P> bool encloses(const P& got, const auto& exact) {
  for (std::size_t i = 0; i < exact.size(); ++i)
    for (int a = 0; a < 2; ++a)
      if (exact[i][a] < num::to_rational(got.lo[i][a]) || num::to_rational(got.hi[i][a]) < exact[i][a]) return false;
  return true;
}

// The largest coordinate error in units in the last place of the mode at the result's scale (its
// largest exact coordinate): a cut near 0 is computed from coordinates of the input's size.
template <class P> double ulps_error(const P& got, const auto& exact) {
  double scale = 0, worst = 0;
  for (const auto& p : exact) scale = std::max({scale, std::fabs(p.x.get_d()), std::fabs(p.y.get_d())});
  if (scale == 0) scale = 1;
  for (std::size_t i = 0; i < exact.size() && i < got.lo.size(); ++i)
    for (int a = 0; a < 2; ++a) {
      const double mid = got.lo[i][a] == got.hi[i][a] ? got.lo[i][a] : 0.5 * got.lo[i][a] + 0.5 * got.hi[i][a];
      const Rational diff = abs(Rational(num::to_rational(mid) - exact[i][a]));
      worst = std::max(worst, std::ldexp(diff.get_d(), got.bits - 1 - std::ilogb(scale)));
    }
  return worst;
}

// Equal: the same decisions (present, vertex count) and then, both exact: the same set (`same`);
// one exact: a filtered result encloses it (a rounded one is judged by error(), not here).
template <class P, class Same> bool clip_equal(const P& a, const P& b, Same&& same) {
  if (a.present != b.present || a.lo.size() != b.lo.size()) return false;
  if (!a.present) return true;
  if (a.exact && b.exact) return same(*a.exact, *b.exact);
  const P* e = a.exact ? &a : b.exact ? &b : nullptr;
  const P& g = e == &a ? b : a;
  if (!e) return a.lo == b.lo && a.hi == b.hi;
  return !g.certified || encloses(g, *e->exact);
}

Json number_json(double lo, double hi, const Rational* exact) {
  if (exact) return Json(exact->get_str());
  return Json(lo == hi ? lo : 0.5 * lo + 0.5 * hi);
}

template <class P> Json points_json(const P& o) {
  Json a = Json::array();
  for (std::size_t i = 0; i < o.lo.size(); ++i) {
    const Vec2<Rational>* e = o.exact ? &(*o.exact)[i] : nullptr;
    a.push_back({number_json(o.lo[i].x, o.hi[i].x, e ? &e->x : nullptr), number_json(o.lo[i].y, o.hi[i].y, e ? &e->y : nullptr)});
  }
  return a;
}

Polygon2 points_of(const Json& a, const std::string& what) {
  Polygon2 p;
  if (!a.is_array()) throw InputError(what + ": expected an array of points");
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Json& v = a[i];
    if (!v.is_array() || v.size() != 2) throw InputError(what + ": expected [x, y]");
    p.push_back({parse_rational(v[0], what), parse_rational(v[1], what)});
  }
  return p;
}

// Seeded values on a 2^-20 grid (exact in double): inputs every mode reads without rounding.
struct ClipRng {
  std::mt19937_64 rng;
  Rational coord(double lo, double hi) {
    return num::to_rational(std::ldexp(std::floor(std::ldexp(std::uniform_real_distribution<double>(lo, hi)(rng), 20)), -20));
  }
  Vec2<Rational> point(double lo, double hi) { return {coord(lo, hi), coord(lo, hi)}; }
  int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
};

// ---- cohen-sutherland ----

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
  static constexpr std::string_view family = "fill";
  static constexpr std::array views{View::plane2d, View::table};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"segment":[[-3,1.5],[9,6]],"window":{"min":[0,0],"max":[8,5]}})";

  static Input parse(const Json& j, Numeric) {
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
        if (abs(p->x) > Rational(kClipBound) || abs(p->y) > Rational(kClipBound)) return true;
      return false;
    });
  return {random, hard};
}

// ---- sutherland-hodgman ----

struct PolygonClipInput {
  Polygon2 subject, clip;
};

struct PolygonClipOutput : PolygonPoints {
  // Exact results compared as regions (winding numbers), not vertex lists.
  friend bool operator==(const PolygonClipOutput& a, const PolygonClipOutput& b) {
    if (a.exact && b.exact) return oracle::same_region(*a.exact, *b.exact);
    return clip_equal<PolygonPoints>(a, b, [](const Polygon2&, const Polygon2&) { return true; });
  }
};

template <class Num> struct PreparedPolygons {
  std::vector<Vec2<Num>> subject, clip;
};

Polygon2 window_polygon(const Vec2<Rational>& lo, const Vec2<Rational>& hi) { return {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}; }

struct SutherlandHodgmanSpec {
  static constexpr std::array hooks{Hook::handles, Hook::estimate_steps, Hook::canonical, Hook::error, Hook::table_lines};
  using Algo = fill::SutherlandHodgman;
  using Input = PolygonClipInput;
  using Output = PolygonClipOutput;
  static constexpr std::string_view family = "fill";
  static constexpr std::array views{View::plane2d, View::table};
  static constexpr std::array<std::string_view, 1> table_lines{"side"};  // one row per vertex decision
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"polygon":[[0,0],[10,0],[10,8],[5,3],[0,8]],"clip":[[2,-2],[12,2],[9,9],[1,7],[-1,2]]})";

  static Input parse(const Json& j, Numeric) {
    if (!j.is_object()) throw InputError("input: expected an object");
    Input in;
    if (j.contains("window")) {
      only_keys(j, {"polygon", "window"}, "input");
      const auto w = parse_window(j["window"], true);
      in.clip = window_polygon(w[0], w[1]);
    } else {
      only_keys(j, {"polygon", "clip"}, "input");
      in.clip = parse_polygon(j["clip"], "input.clip", kMaxClip);
      check_convex(in.clip, "input.clip");
    }
    in.subject = parse_polygon(j["polygon"], "input.polygon", kMaxSubject);
    return in;
  }
  template <class Num> static PreparedPolygons<Num> prepare(const Input& in) {
    PreparedPolygons<Num> p;
    for (const auto& v : in.subject) p.subject.push_back(to_num<Num>(v));
    for (const auto& v : in.clip) p.clip.push_back(to_num<Num>(v));
    return p;
  }
  template <class Num, class Probe> static Output compute(const PreparedPolygons<Num>& p, Probe& probe) {
    Output o;
    set_points<Num>(o, fill::sutherland_hodgman<Num>(p.subject, p.clip, probe));
    return o;
  }
  static Json to_json(const Output& o) { return {{"polygon", points_json(o)}}; }
  static std::size_t ops(const Output&) { return 1; }  // ns per clipped polygon
  // Per clip edge: its own step and up to three per vertex of a polygon that can at most double.
  static std::size_t estimate_steps(const Input& in) { return in.clip.size() * (2 + 6 * in.subject.size()) + 4; }
  static Output oracle(const Input& in) {
    Output o;
    set_points<Rational>(o, oracle::clip_polygon(in.subject, in.clip));
    return o;
  }
  // The region: the polygon's reduced boundary chain, [x0, y0, x1, y1, weight] per piece.
  static Json canonical(Json result) {
    Json chain = Json::array();
    for (const oracle::BoundaryPiece& p : oracle::boundary_chain(points_of(result["polygon"], "result.polygon")))
      chain.push_back({p.a.x.get_str(), p.a.y.get_str(), p.b.x.get_str(), p.b.y.get_str(), p.weight});
    return {{"boundary", chain}};
  }
  static double error(const Output& got, const Output& exact) {
    if (!exact.exact || got.exact || got.lo.size() != exact.exact->size()) return 0;
    return ulps_error(got, *exact.exact);
  }
  static std::vector<Handle> handles() {
    std::vector<Handle> h;  // the example's vertices
    for (int i = 0; i < 5; ++i) h.push_back({"/polygon/" + std::to_string(i), Handle::Kind::point2, 8, "v" + std::to_string(i)});
    for (int i = 0; i < 5; ++i) h.push_back({"/clip/" + std::to_string(i), Handle::Kind::point2, 8, "c" + std::to_string(i)});
    return h;
  }
  static std::vector<BenchSet<Input>> bench_sets();
};

// A star-shaped polygon of n vertices around c (random angles and radii): often concave.
Polygon2 random_star(ClipRng& g, const Vec2<Rational>& c, double r, int n) {
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) angles.push_back(std::uniform_real_distribution<double>(0, 2 * std::numbers::pi)(g.rng));
  std::sort(angles.begin(), angles.end());
  Polygon2 p;
  for (double a : angles) {
    const double rr = r * std::uniform_real_distribution<double>(0.2, 1.0)(g.rng);
    p.push_back({c.x + num::to_rational(std::ldexp(std::round(std::ldexp(rr * std::cos(a), 20)), -20)),
                 c.y + num::to_rational(std::ldexp(std::round(std::ldexp(rr * std::sin(a), 20)), -20))});
  }
  return p;
}

// A convex polygon of n vertices on a circle (angles at least 2 pi / 4n apart), either orientation.
Polygon2 random_convex(ClipRng& g, const Vec2<Rational>& c, double r, int n) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    Polygon2 p;
    const double start = std::uniform_real_distribution<double>(0, 2 * std::numbers::pi)(g.rng);
    for (int i = 0; i < n; ++i) {
      const double a = start + 2 * std::numbers::pi * (i + std::uniform_real_distribution<double>(0, 0.75)(g.rng)) / n;
      p.push_back({c.x + num::to_rational(std::ldexp(std::round(std::ldexp(r * std::cos(a), 20)), -20)),
                   c.y + num::to_rational(std::ldexp(std::round(std::ldexp(r * std::sin(a), 20)), -20))});
    }
    if (g.pick(0, 1)) std::reverse(p.begin(), p.end());
    try {
      check_convex(p, "bench");
      return p;
    } catch (const InputError&) {
    }
  }
  return window_polygon(c - Vec2<Rational>{1, 1}, c + Vec2<Rational>{1, 1});
}

// random: star-shaped subjects of 3 to 16 vertices against convex polygons of 3 to 8 and windows.
// hard: the subject equal to the window, combs whose teeth leave bridges, collinear and repeated
// vertices on the clip lines, clockwise clip polygons, coordinates near 2^30.
std::vector<BenchSet<PolygonClipInput>> SutherlandHodgmanSpec::bench_sets() {
  ClipRng g{std::mt19937_64(20261131)};
  BenchSet<Input> random{"random", {}}, hard{"hard", {}};
  for (int i = 0; i < 2000; ++i) {
    Input in;
    in.subject = random_star(g, g.point(-64, 64), 200, g.pick(3, 16));
    if (i % 4 == 0) {
      const Vec2<Rational> lo = g.point(-200, 0);
      in.clip = window_polygon(lo, lo + g.point(50, 250));
    } else {
      in.clip = random_convex(g, g.point(-64, 64), g.coord(60, 220).get_d(), g.pick(3, 8));
    }
    random.inputs.push_back(std::move(in));
  }
  for (int i = 0; i < 500; ++i) {
    const double s = i % 2 ? 1 : 1048576;  // unit scale and 2^20 (coordinates up to 2^30)
    auto at = [&](double x, double y) { return Vec2<Rational>{num::to_rational(x * s), num::to_rational(y * s)}; };
    Input in;
    in.clip = window_polygon(at(0, 0), at(512, 256));
    switch (i % 5) {
      case 0: in.subject = in.clip; break;  // the window itself
      case 1: {  // a comb with teeth up through y = 256: bridges along the top edge
        const int teeth = g.pick(2, 6);
        in.subject = {at(-8, 8)};
        for (int k = 0; k < teeth; ++k) {
          const double x0 = 8 + 480.0 * k / teeth, x1 = x0 + 240.0 / teeth;
          for (const auto& v : {at(x0, 300), at(x0 + 0.5, 300), at(x1, 300), at(x1, 100)}) in.subject.push_back(v);
        }
        in.subject.push_back(at(520, 40));
        break;
      }
      case 2:  // collinear and repeated vertices, some on the window's edge lines
        in.subject = {at(-100, 0), at(0, 0), at(0, 0), at(200, 0), at(600, 0), at(600, 128), at(256, 256), at(256, 256), at(-100, 256)};
        break;
      case 3:  // the window clockwise, a random subject
        std::reverse(in.clip.begin(), in.clip.end());
        in.subject = random_star(g, at(256, 128), 400 * s, g.pick(3, 16));
        break;
      default:  // vertices within 2^-40 (relative) of the window's edge lines
        in.subject = {at(-10, std::ldexp(g.pick(-3, 3), -40)), at(600, std::ldexp(g.pick(-3, 3), -40)), at(512 + std::ldexp(g.pick(-3, 3), -30), 300),
                      at(256, 256 + std::ldexp(g.pick(-3, 3), -32))};
        break;
    }
    hard.inputs.push_back(std::move(in));
  }
  for (auto* set : {&random, &hard})
    std::erase_if(set->inputs, [](const Input& in) {
      for (const auto& p : in.subject)
        if (abs(p.x) > Rational(kClipBound) || abs(p.y) > Rational(kClipBound)) return true;
      return false;
    });
  return {random, hard};
}

}  // namespace

void register_clip(std::vector<Algorithm>& out) {
  out.push_back(make_algorithm<CohenSutherlandSpec>());
  out.push_back(make_algorithm<SutherlandHodgmanSpec>());
}

}  // namespace sw
