// What the shadow family needs of a rasterized scene (pipeline/raster_scene.hpp): a light's views
// for its shadow map, the points the eye sees, and whether each one is lit, exactly: the segment
// from it to the light (a ray, toward a directional light) meets nothing. Rules:
// docs/shadows/semantics.md.
#pragma once
#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>
#include "pipeline/raster_truth.hpp"

namespace sw::shadowspec {

using pipespec::RasterScene;

// A spot light of cut-off up to kSpotViewMaxDegrees gets one view (its cone); a wider one, like a
// point light, the six faces of a cube.
inline constexpr int kSpotViewMaxDegrees = 60;

// A light's views, exact: a spot's cone (the tracer-style double frame about its axis, the window
// tan(cut-off) each way); a point light's cube faces (90 degrees each, axis-aligned frames); a
// directional light's box (glOrtho over the finite triangles' extent across the light, near and
// far just around every surface the box holds). Each view is size x size texels, its near plane
// that view's own (near_plane).
struct LightViews {
  std::vector<pipe::RasterCamera<Rational>> views;
  bool cube = false;
  Vec3<Rational> position;  // point and spot lights
};
LightViews light_views(const RasterScene& s, std::size_t light, std::int64_t size);

// A point the eye sees: the pixel's ray where it meets GL's answer (the exact ray cast), on
// object k and its prim (a mesh's triangle; -1 for a plane or a triangle object).
struct SeenPoint {
  std::size_t pixel = 0;
  Vec3<Rational> p;
  Rational t;  // p = o + t d on pixel_ray
  std::int32_t object = -1, prim = -1;
};
std::vector<SeenPoint> seen_points(const RasterScene& s, const pipespec::RasterTruth& truth);

// Whether light i reaches p: nothing on the open segment from p to the light (or the ray toward a
// directional one) but p's own flat surface, which the segment leaves; intervals first, exact
// rationals where they cannot decide.
bool reaches(const RasterScene& s, std::size_t light, const SeenPoint& p);

// The sign of f(std::type_identity<Num>) exactly: in intervals, and in rationals where they cannot decide.
template <class F> int exact_sign_of(F&& f) {
  try {
    const Interval v = f(std::type_identity<Interval>{});
    return v > Interval(0) ? 1 : v < Interval(0) ? -1 : 0;
  } catch (const Uncertain&) {
    return sgn(f(std::type_identity<Rational>{}));
  }
}
template <class Num> pipe::Vec4<Num> v4_in(const pipe::Vec4<Rational>& v) {
  return {num::from_rational<Num>(v.x), num::from_rational<Num>(v.y), num::from_rational<Num>(v.z), num::from_rational<Num>(v.w)};
}

// The window depth GL gives the point at t along view c's pixel ray (pixel_ray: from the near
// plane): 1 - n/e in perspective (e = n + t d), t/(f - n) in orthographic.
Rational window_depth(const pipe::RasterCamera<Rational>& c, const Rational& t);
// max(|dz/dx|, |dz/dy|) of the plane through Y along e1, e2 in the window of view c (matrix M),
// glPolygonOffset's slope; 0 for a plane seen edge-on.
Rational window_slope(const pipe::Mat4<Rational>& M, const pipe::RasterCamera<Rational>& c, const Vec3<Rational>& Y, const Vec3<Rational>& e1,
                      const Vec3<Rational>& e2);

// Whether the segment from X just before it on a ray of direction R (X - e R, e > 0
// infinitesimal) to the light L (the ray toward a directional one, w = 0) crosses the open
// triangle (a, b, c): X on the far side of its plane from L, and the line through X and L inside
// all three edges; each sign exact (intervals, then rationals), at a tie that of -R.
bool segment_crosses(const std::array<pipe::Vec4<Rational>, 3>& t, const pipe::Vec4<Rational>& L, const pipe::Vec4<Rational>& X, const pipe::Vec4<Rational>& R);

// Whether the segment from X to the light L meets the triangle t: inside, through its relative
// interior with X off its plane; touching, its closed triangle at all (X may lie on it). A triangle
// edge-on from the light meets nothing. Exact signs (intervals, then rationals).
struct Meeting {
  bool inside = false, touching = false;
};
Meeting segment_meets(const std::array<pipe::Vec4<Rational>, 3>& t, const pipe::Vec4<Rational>& L, const pipe::Vec4<Rational>& X);

}  // namespace sw::shadowspec
