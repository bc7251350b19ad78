#include "spatial_oracle.hpp"
#include <CGAL/Intersections_2/Iso_rectangle_2_Segment_2.h>
#include <CGAL/Intersections_3/Iso_cuboid_3_Segment_3.h>
#include <CGAL/Intersections_3/Iso_cuboid_3_Triangle_3.h>
#include <algorithm>
#include "cgal_bridge.hpp"

namespace sw::oracle {
namespace {

using K = ExactKernel;

template <class P> Rational dist2(const P& a, const P& b, int dim) {
  Rational s = 0;
  for (int k = 0; k < dim; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return s;
}

template <class P> std::vector<std::pair<Rational, std::int32_t>> nearest(const std::vector<P>& points, const P& query, std::size_t k, int dim) {
  std::vector<std::pair<Rational, std::int32_t>> all;
  all.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) all.emplace_back(dist2(points[i], query, dim), static_cast<std::int32_t>(i));
  std::partial_sort(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(std::min(k, all.size())), all.end());
  all.resize(std::min(k, all.size()));
  return all;
}

}  // namespace

ClosestHit closest_hit(const Vec3<Rational>& o, const Vec3<Rational>& d, const std::vector<Triangle3>& tris) {
  ClosestHit best;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    RayResult r = ray_triangle(o, d, tris[i]);
    if (r.hit && (!best.hit || r.t < best.r.t)) best = {true, static_cast<std::int32_t>(i), std::move(r)};
  }
  return best;
}

std::vector<std::pair<Rational, std::int32_t>> k_nearest(const std::vector<Vec3<Rational>>& points, const Vec3<Rational>& q, std::size_t k) {
  return nearest(points, q, k, 3);
}
std::vector<std::pair<Rational, std::int32_t>> k_nearest(const std::vector<Vec2<Rational>>& points, const Vec2<Rational>& q, std::size_t k) {
  return nearest(points, q, k, 2);
}

bool triangle_meets_box(const Triangle3& t, const Vec3<Rational>& lo, const Vec3<Rational>& hi) {
  const K::Iso_cuboid_3 box(point(lo), point(hi));
  const K::Point_3 a = point(t[0]), b = point(t[1]), c = point(t[2]);
  if (!CGAL::collinear(a, b, c)) return CGAL::do_intersect(K::Triangle_3(a, b, c), box);
  // A zero-area triangle is the segment between its two farthest vertices, or a point.
  if (a == b && b == c) return !box.has_on_unbounded_side(a);
  const K::Segment_3 s[3] = {{a, b}, {b, c}, {c, a}};
  for (const auto& e : s)
    if (!e.is_degenerate() && CGAL::do_intersect(e, box)) return true;
  return false;
}

bool segment_meets_box(const Vec2<Rational>& a, const Vec2<Rational>& b, const Vec2<Rational>& lo, const Vec2<Rational>& hi) {
  const K::Iso_rectangle_2 box(point(lo), point(hi));
  if (a == b) return !box.has_on_unbounded_side(point(a));
  return CGAL::do_intersect(K::Segment_2(point(a), point(b)), box);
}

int orient2d(const Vec2<Rational>& p, const Vec2<Rational>& q, const Vec2<Rational>& r) {
  return static_cast<int>(CGAL::orientation(point(p), point(q), point(r)));
}

}  // namespace sw::oracle
