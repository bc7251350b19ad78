// The caustic photon map of a scene (algorithms/tracer/photon_trace.hpp): every point and spot light's
// photons traced in blocks on a few threads and joined in block order, then put in a kd-tree.
#pragma once
#include <cstdint>
#include "tracer/photon_map.hpp"
#include "tracer/scene.hpp"
#include "tracer/whitted.hpp"

namespace sw::tracer {

// Adds the photon rays traced to `rays`.
void build_photon_map(const Scene& s, const TraceScene<double>& ts, unsigned threads, PhotonMap& map, std::uint64_t& rays);

}  // namespace sw::tracer
