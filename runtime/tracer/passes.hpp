// Per-pixel passes of our tracer, to compare with a peer's (docs/tracer/povray.md): one ray per
// pixel centre (camera-ray), no supersampling. The object id of the closest hit (scene-hit), and a
// light's shadow mask: the hit faces the light (N towards the ray, as whitted.hpp decides it) and
// the shadow ray from the offset origin, leaving the hit surface, finds no occluder.
#pragma once
#include <cstdint>
#include <vector>
#include "tracer/whitted.hpp"

namespace sw::tracer {

struct ShadowPass {
  std::vector<char> lit;       // 1: lit by the light; 0: no hit, facing away, or occluded
  std::vector<double> cosine;  // cos(N, L) at the hit with N towards the ray (0 without a hit)
};

// Row 0 at the top, width x height of ts.camera. -1: no hit (or outside a fisheye's circle).
std::vector<int> object_id_pass(const TraceScene<double>& ts);
// Precondition: light < ts.lights.size().
ShadowPass shadow_pass(const TraceScene<double>& ts, std::size_t light);

}  // namespace sw::tracer
