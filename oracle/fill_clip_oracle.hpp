// The exact specification of the fill family's clippers (docs/fill/clipping.md), independent of
// both algorithms: no outcodes, no half-plane passes.
//  - cohen-sutherland: the segment intersected with the closed window as point sets (CGAL's exact
//    Segment_2 / Iso_rectangle_2 intersection).
//  - sutherland-hodgman: the region whose winding number is the subject's inside the clip polygon
//    and 0 outside, built from CGAL's exact triangle-triangle intersections of the two polygons'
//    fans. Regions are compared by their reduced boundary chains (boundary_chain), so that zero-width
//    bridges, repeated and collinear vertices and the starting vertex do not matter.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <vector>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::oracle {

using Polygon2 = std::vector<Vec2<Rational>>;

// The segment p0 p1 (p0 = p1 allowed) meets the closed window [lo, hi] (lo <= hi) in: nothing, or
// the segment between the two returned ends, ordered by (x, y); equal ends when it is one point.
std::optional<std::array<Vec2<Rational>, 2>> clip_segment(const Vec2<Rational>& p0, const Vec2<Rational>& p1, const Vec2<Rational>& lo,
                                                          const Vec2<Rational>& hi);

// A polygon with the winding number of `subject` at every point inside `clip` and 0 outside
// (points on either boundary aside). Precondition: `clip` is convex and winds once (either
// orientation). The pieces are joined into one vertex list by zero-width bridges.
Polygon2 clip_polygon(const Polygon2& subject, const Polygon2& clip);

// One piece of a reduced boundary chain: the segment a -> b, a before b in (x, y) order, run
// `weight` times from a to b (negative: from b to a). That is the winding number just left of it
// (looking from a to b) minus the one just right.
struct BoundaryPiece {
  Vec2<Rational> a, b;
  std::int64_t weight = 0;
  friend bool operator==(const BoundaryPiece&, const BoundaryPiece&) = default;
};

// The polygon's edges as a chain, reduced: on each line, overlapping edges summed with their
// directions, zero stretches dropped and equal neighbours merged; sorted by line, then along it.
// Two polygons have the same winding number at every point off their edges exactly when their
// chains are equal, so this is the canonical form of a region with multiplicities.
std::vector<BoundaryPiece> boundary_chain(const Polygon2& polygon);

// Same winding number at every point off both polygons' edges.
bool same_region(const Polygon2& a, const Polygon2& b);

// Twice the signed area (the shoelace sum): the integral of the winding number, times 2.
Rational twice_signed_area(const Polygon2& polygon);

// The winding number of `polygon` around p, by exact crossing counts. Precondition: p lies on no
// edge.
std::int64_t winding_at(const Polygon2& polygon, const Vec2<Rational>& p);

}  // namespace sw::oracle
