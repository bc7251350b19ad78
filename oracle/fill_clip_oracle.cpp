#include "fill_clip_oracle.hpp"
#include <algorithm>
#include <map>
#include <tuple>
#include <CGAL/Intersections_2/Iso_rectangle_2_Segment_2.h>
#include <CGAL/Intersections_2/Triangle_2_Triangle_2.h>
#include "cgal_bridge.hpp"

namespace sw::oracle {
namespace {

using K = ExactKernel;
using P2 = K::Point_2;

Vec2<Rational> vec(const P2& p) { return {r(p.x()), r(p.y())}; }
bool before(const Vec2<Rational>& a, const Vec2<Rational>& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// The fan of a closed polygon from its first vertex: triangles (v0, v_i, v_i+1). Their winding
// numbers add up to the polygon's at every point off the fan's segments, for any polygon (the
// diagonals v0 -> v_i cancel in the sum of the triangles' boundaries).
std::vector<K::Triangle_2> fan(const Polygon2& poly) {
  std::vector<K::Triangle_2> out;
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) out.emplace_back(point(poly[0]), point(poly[i]), point(poly[i + 1]));
  return out;
}

}  // namespace

std::optional<std::array<Vec2<Rational>, 2>> clip_segment(const Vec2<Rational>& p0, const Vec2<Rational>& p1, const Vec2<Rational>& lo,
                                                          const Vec2<Rational>& hi) {
  const K::Iso_rectangle_2 window(point(lo), point(hi));
  if (p0 == p1) {  // a point: in the closed window or not
    if (window.has_on_unbounded_side(point(p0))) return std::nullopt;
    return std::array{p0, p0};
  }
  const auto hit = CGAL::intersection(K::Segment_2(point(p0), point(p1)), window);
  if (!hit) return std::nullopt;
  if (const P2* p = boost::get<P2>(&*hit)) return std::array{vec(*p), vec(*p)};
  const K::Segment_2& s = boost::get<K::Segment_2>(*hit);
  std::array ends{vec(s.source()), vec(s.target())};
  if (before(ends[1], ends[0])) std::swap(ends[0], ends[1]);
  return ends;
}

Polygon2 clip_polygon(const Polygon2& subject, const Polygon2& clip) {
  // w_S 1_C = (sum_i w_Ti) (o sum_j w_Cj) = sum_ij o s_i t_j 1(Ti ∩ Cj), with s_i, t_j the fan
  // triangles' orientations and o = t_j for the clip polygon's proper triangles (convex, once).
  Polygon2 out;
  const Vec2<Rational> base = subject.front();  // where the bridges to the pieces start
  const std::vector<K::Triangle_2> subject_fan = fan(subject);
  for (const K::Triangle_2& c : fan(clip)) {
    const CGAL::Orientation tc = c.orientation();
    if (tc == CGAL::COLLINEAR) continue;
    const K::Triangle_2 cc = tc == CGAL::POSITIVE ? c : c.opposite();
    const CGAL::Bbox_2 cbox = cc.bbox();  // outward-rounded: disjoint boxes, disjoint triangles
    for (const K::Triangle_2& t : subject_fan) {
      const CGAL::Orientation ts = t.orientation();
      if (ts == CGAL::COLLINEAR || !CGAL::do_overlap(t.bbox(), cbox)) continue;
      const auto hit = CGAL::intersection(ts == CGAL::POSITIVE ? t : t.opposite(), cc);
      if (!hit) continue;
      Polygon2 piece;  // counter-clockwise
      if (const K::Triangle_2* tri = boost::get<K::Triangle_2>(&*hit)) {
        for (int k = 0; k < 3; ++k) piece.push_back(vec(tri->vertex(k)));
        if (tri->orientation() == CGAL::NEGATIVE) std::reverse(piece.begin(), piece.end());
      } else if (const auto* pts = boost::get<std::vector<P2>>(&*hit)) {
        for (const P2& p : *pts) piece.push_back(vec(p));
        if (sgn(twice_signed_area(piece)) < 0) std::reverse(piece.begin(), piece.end());
      } else {
        continue;  // a point or a segment: no area
      }
      if (ts == CGAL::NEGATIVE) std::reverse(piece.begin(), piece.end());  // weight s_i (o t_j = 1)
      // base -> the piece's first vertex, around it, back to its first vertex and to base: the
      // bridge is run both ways and cancels.
      out.push_back(base);
      out.insert(out.end(), piece.begin(), piece.end());
      out.push_back(piece.front());
    }
  }
  return out;
}

std::vector<BoundaryPiece> boundary_chain(const Polygon2& polygon) {
  // A line: vertical (x = c) or y = m x + c; a point on it by its parameter t (y, or x), which
  // increases in (x, y) order. events[line][t]: the change of the multiplicity at t.
  using Line = std::tuple<bool, Rational, Rational>;
  std::map<Line, std::map<Rational, std::int64_t>> events;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2<Rational>& a = polygon[i];
    const Vec2<Rational>& b = polygon[(i + 1) % n];
    if (a == b) continue;
    Line line;
    Rational ta, tb;
    if (a.x == b.x) {
      line = {true, a.x, 0}, ta = a.y, tb = b.y;
    } else {
      const Rational m = (b.y - a.y) / (b.x - a.x);
      line = {false, m, Rational(a.y - m * a.x)}, ta = a.x, tb = b.x;
    }
    const std::int64_t w = ta < tb ? 1 : -1;
    auto& e = events[line];
    e[std::min(ta, tb)] += w;
    e[std::max(ta, tb)] -= w;
  }
  std::vector<BoundaryPiece> out;
  for (const auto& entry : events) {
    const auto& e = entry.second;
    auto at = [&line = entry.first](const Rational& t) {
      const auto& [vertical, m, c] = line;
      return vertical ? Vec2<Rational>{m, t} : Vec2<Rational>{t, Rational(m * t + c)};
    };
    std::int64_t running = 0;
    const Rational* from = nullptr;
    for (const auto& [t, delta] : e) {
      if (delta == 0) continue;  // the multiplicity does not change here: merge the two stretches
      if (running != 0) out.push_back({at(*from), at(t), running});
      running += delta;
      from = &t;
    }
  }
  return out;
}

bool same_region(const Polygon2& a, const Polygon2& b) { return boundary_chain(a) == boundary_chain(b); }

Rational twice_signed_area(const Polygon2& polygon) {
  Rational s = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2<Rational>& a = polygon[i];
    const Vec2<Rational>& b = polygon[(i + 1) % polygon.size()];
    s += a.x * b.y - a.y * b.x;
  }
  return s;
}

std::int64_t winding_at(const Polygon2& polygon, const Vec2<Rational>& p) {
  // Crossings of the ray from p to +x with the edges, each edge taken as half-open in y.
  std::int64_t w = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2<Rational>& a = polygon[i];
    const Vec2<Rational>& b = polygon[(i + 1) % polygon.size()];
    const bool up = a.y <= p.y && p.y < b.y, down = b.y <= p.y && p.y < a.y;
    if (!up && !down) continue;
    const int side = sgn(Rational((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)));  // > 0: p left of a -> b
    if (up && side > 0) ++w;
    if (down && side < 0) --w;
  }
  return w;
}

}  // namespace sw::oracle
