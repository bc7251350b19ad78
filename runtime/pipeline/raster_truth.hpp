// What the exact ray cast through each pixel's centre sees in a rasterized scene: scene-raster's
// oracle, and the visibility identity of `stepwise scene raster --identity`.
//
// The ray is the tracer's own closest-hit search (scene-hit: watertight triangles closed on their
// edges, planes, meshes through their BVH; equal t keeps the lower id) over the same triangles the
// rasterizer draws, from the near plane, in intervals and, where they cannot decide, exact
// rationals. Where its closest hit lies inside a triangle (or on a plane), GL's answer is the same
// surface: no projection is involved. Where it lies exactly on a triangle's boundary, GL's answer
// follows triangle-edge's tie rule instead: every triangle the ray meets there is tested, the rule
// decided by the exact direction of the edge's image on the screen, and the closest that covers
// the sample wins (equal depth: the first drawn). Rules: docs/pipeline/semantics.md#scene-raster.
#pragma once
#include <cstdint>
#include <vector>
#include "pipeline/raster_scene.hpp"

namespace sw::pipespec {

struct PixelTruth {
  std::int32_t object = -1, prim = -1;          // GL's answer (prims as named_prim names them)
  std::int32_t ray_object = -1, ray_prim = -1;  // scene-hit's closest hit
  bool boundary = false;                        // that hit lies on a triangle's edge or corner
  double depth = 1;                             // GL's answer's window depth, exact then rounded
  Rational t;                                   // where pixel_ray meets GL's answer (0: none)
};

struct RasterTruth {
  std::int64_t width = 0, height = 0;
  std::vector<PixelTruth> px;  // row 0 at the top
  std::int64_t exact_rays = 0;  // pixels the intervals could not decide
};

// threads: 0 for every core. The result does not depend on it.
RasterTruth raster_truth(const RasterScene& s, unsigned threads = 1);

// A raster image against the truth, per pixel, at the level of primitives and of objects.
struct Identity {
  std::int64_t pixels = 0;
  std::int64_t differ = 0;       // the raster names another primitive than scene-hit's closest hit
  std::int64_t ties = 0;         // ... of which GL's tie rule explains (the raster equals GL's answer)
  std::int64_t wrong = 0;        // the raster names another primitive than GL's answer
  std::int64_t wrong_inside = 0;  // ... of which where the ray's closest hit lies inside a triangle (no tie at all)
  std::int64_t holes = 0;         // ... of which where the raster shows nothing: a crack between triangles
  std::int64_t objects_differ = 0, objects_wrong = 0;  // the same two counts, for objects
};
Identity identity(const RasterTruth& truth, const RasterPixels& raster);

}  // namespace sw::pipespec
