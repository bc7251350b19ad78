// What the shadow family needs of a rasterized scene (pipeline/raster_scene.hpp): a light's views
// for its shadow map, the points the eye sees, and whether each one is lit, exactly: the segment
// from it to the light (a ray, toward a directional light) meets nothing. Rules:
// docs/shadows/semantics.md.
#pragma once
#include <cstdint>
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
  std::int32_t object = -1, prim = -1;
};
std::vector<SeenPoint> seen_points(const RasterScene& s, const pipespec::RasterTruth& truth);

// Whether light i reaches p: nothing on the open segment from p to the light (or the ray toward a
// directional one) but p's own flat surface, which the segment leaves; intervals first, exact
// rationals where they cannot decide.
bool reaches(const RasterScene& s, std::size_t light, const SeenPoint& p);

}  // namespace sw::shadowspec
