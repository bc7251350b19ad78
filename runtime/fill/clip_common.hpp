// What the clippers' Specs share (clip_segment.cpp, clip_polygon.cpp): input parsing, the convexity
// check, the points every mode returns and how they compare, and seeded inputs.
// Semantics, bounds and the region comparison: docs/fill/clipping.md.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include "register.hpp"
#include "fill/fill_common.hpp"
#include "fill_clip_oracle.hpp"

namespace sw::clipspec {

using oracle::Polygon2;

// |coordinate| <= 2^30 (fillspec::kCoordBound), numerator and denominator of at most 64 bits:
// float's products of two differences stay far from overflow, and exact arithmetic stays small.
inline constexpr std::size_t kMaxSubject = 256, kMaxClip = 32;  // vertices: keeps every traced polygon < 2^15 points

inline Vec2<Rational> clip_point(const Json& v, const std::string& what) { return fillspec::parse_vertex(v, what, fillspec::kCoordBound); }

// {"min":[x,y],"max":[x,y]} with min <= max; `need_area`: min < max (a clip polygon needs an inside).
inline std::array<Vec2<Rational>, 2> parse_window(const Json& j, bool need_area) {
  only_keys(j, {"min", "max"}, "input.window");
  const Vec2<Rational> lo = clip_point(j["min"], "input.window.min"), hi = clip_point(j["max"], "input.window.max");
  for (int a = 0; a < 2; ++a) {
    const std::string k = "[" + std::to_string(a) + "]";
    if (lo[a] > hi[a]) throw InputError("input.window: min" + k + " > max" + k + " (min is the lower-left corner)");
    if (need_area && lo[a] == hi[a]) throw InputError("input.window: zero area (min" + k + " = max" + k + ")");
  }
  return {lo, hi};
}

inline Polygon2 parse_polygon(const Json& j, const std::string& what, std::size_t max_vertices) {
  if (!j.is_array()) throw InputError(what + ": expected an array of [x, y] vertices");
  if (j.size() < 3) throw InputError(what + ": expected at least 3 vertices, got " + std::to_string(j.size()));
  if (j.size() > max_vertices) throw InputError(what + ": more than " + std::to_string(max_vertices) + " vertices");
  Polygon2 p;
  for (std::size_t i = 0; i < j.size(); ++i) p.push_back(clip_point(j[i], what + "[" + std::to_string(i) + "]"));
  return p;
}

inline Rational cross(const Vec2<Rational>& a, const Vec2<Rational>& b, const Vec2<Rational>& v) {
  return (b.x - a.x) * (v.y - a.y) - (b.y - a.y) * (v.x - a.x);
}

// Convex and winding once: a nonzero area, every vertex on the inner side of (or on) every edge's
// line, and winding number +-1 around a point inside. Repeated and collinear vertices are fine.
inline void check_convex(const Polygon2& c, const std::string& what) {
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

inline Json number_json(double lo, double hi, const Rational* exact) {
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

inline Polygon2 points_of(const Json& a, const std::string& what) {
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

}  // namespace sw::clipspec
