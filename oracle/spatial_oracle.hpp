// Exact specifications of the spatial family's queries and invariants, stated by brute force over
// all primitives on GMP rationals (CGAL stays in spatial_oracle.cpp), independently of
// algorithms/spatial/. Semantics: docs/spatial/semantics.md.
#pragma once
#include <array>
#include <cstdint>
#include <utility>
#include <vector>
#include "core/number.hpp"
#include "core/vec.hpp"
#include "rays_oracle.hpp"

namespace sw::oracle {

using Triangle3 = std::array<Vec3<Rational>, 3>;

// The closest hit of the ray o + t d (t > 0) over all triangles, each tested with the rays
// family's closed-triangle semantics (ray_triangle); ties on t go to the lowest index.
struct ClosestHit {
  bool hit = false;
  std::int32_t prim = -1;
  RayResult r;
};
ClosestHit closest_hit(const Vec3<Rational>& o, const Vec3<Rational>& d, const std::vector<Triangle3>& tris);

// The k nearest points to q by exact squared distance, ties broken by the lower index: (d2, id)
// pairs in that order. Precondition: 1 <= k <= points.size().
std::vector<std::pair<Rational, std::int32_t>> k_nearest(const std::vector<Vec3<Rational>>& points, const Vec3<Rational>& q, std::size_t k);
std::vector<std::pair<Rational, std::int32_t>> k_nearest(const std::vector<Vec2<Rational>>& points, const Vec2<Rational>& q, std::size_t k);

// Does the closed triangle meet the closed box [lo, hi]? (CGAL's exact do_intersect; a
// zero-area triangle counts as the segment or point it is.)
bool triangle_meets_box(const Triangle3& t, const Vec3<Rational>& lo, const Vec3<Rational>& hi);
// Does the closed segment ab meet the closed rectangle [lo, hi]?
bool segment_meets_box(const Vec2<Rational>& a, const Vec2<Rational>& b, const Vec2<Rational>& lo, const Vec2<Rational>& hi);
// The sign of the orientation of (p, q, r): +1 counterclockwise, -1 clockwise, 0 collinear.
int orient2d(const Vec2<Rational>& p, const Vec2<Rational>& q, const Vec2<Rational>& r);

}  // namespace sw::oracle
