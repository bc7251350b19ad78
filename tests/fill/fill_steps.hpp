// Closed forms and geometry checks shared by the fill family's step replays.
#pragma once
#include <algorithm>
#include <string_view>
#include <vector>
#include "step_values.hpp"

namespace sw::testing::fill_steps {

using V = Vec2<Rational>;
inline Rational ceil_q(const Rational& x) { return Rational(num::ceil_int(x)); }
// The crossing of the line through p0, p1 (p0.y != p1.y) with the row y.
inline Rational X(const V& p0, const V& p1, const Rational& y) { return p0.x + (y - p0.y) * (p1.x - p0.x) / (p1.y - p0.y); }
// The edge function of p -> q at s: positive left of the edge.
inline Rational E(const V& p, const V& q, const V& s) { return (q.x - p.x) * (s.y - p.y) - (q.y - p.y) * (s.x - p.x); }
// Whether a pixel set in scanline order holds p.
inline bool covered(const std::vector<Pixel>& set, Pixel p) {
  return std::binary_search(set.begin(), set.end(), p, [](Pixel a, Pixel b) { return std::pair(a.y, a.x) < std::pair(b.y, b.x); });
}
using testing::for_each_step;

using testing::check_point;
using testing::check_segment;
inline void check_polygon(GeoItem& g, const std::vector<V>& ring) {
  std::vector<Rational> want;
  for (const V& v : ring) want.push_back(v.x), want.push_back(v.y);
  CHECK(g.values == want);
  CHECK(g.life == "keep");
}
// The geometry of a DDA edge's start: the edge p0 -> p1 kept under its label, and its walker q.
inline void check_edge_start(StepGeometry& g, const V& p0, const V& p1, const char* label, const V& q) {
  GeoItem& edge = g.take(GeoKind::segment2);
  check_segment(edge, p0, p1);
  CHECK(edge.label == label);
  CHECK(edge.life == "keep");
  GeoItem& walker = g.take(GeoKind::point2);
  check_point(walker, q);
  CHECK(walker.label == "q");
}

}  // namespace sw::testing::fill_steps
