// The caustic photon map: the photons stored on diffuse surfaces (photon_trace.hpp) in a balanced
// kd-tree searched by kd-nearest, and the irradiance the tracer adds there: the k nearest within
// r, sum(power) / (pi r^2) (Jensen). Semantics and units: docs/tracer/renderer.md#caustics.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>
#include "spatial/kd_point_tree.hpp"
#include "spatial/kd_nearest.hpp"

namespace sw::tracer {

struct PhotonSettings {
  std::int64_t count = 0;  // photons emitted over all point and spot lights
  std::int64_t gather = 64;
  double radius = 0;
  std::uint32_t seed = 0;
};

struct PhotonMap {
  std::vector<Vec3<double>> at, power;
  spatial::KdTree<double, 3> tree;
  std::int64_t gather = 64;
  double radius = 0;
  spatial::Box<double, 3> bounds;  // of `at`: a point farther than the radius from it has no photon near
};

// Puts the stored photons (`at`) in the kd-tree and their bounding box; none: an empty map.
inline void index_photons(PhotonMap& map) {
  if (map.at.empty()) return;
  map.tree = spatial::kd_point_tree<double, 3>(map.at, 8);  // median splits, 8 photons a leaf
  map.bounds = map.tree.nodes[0].cell;
}

// r is the farthest photon taken when k are within the radius, else the radius. 0 if none.
inline Vec3<double> caustic_irradiance(const PhotonMap& map, const Vec3<double>& p) {
  if (map.at.empty() || spatial::kd_cell_d2<double, 3>(map.bounds, p) > map.radius * map.radius) return {};
  NoProbe none;
  const double max_r2 = map.radius * map.radius;
  const auto near = spatial::kd_nearest_tree<double, 3>(map.tree, map.at, p, static_cast<std::size_t>(map.gather), none, max_r2);
  Vec3<double> sum{};
  std::size_t taken = 0;
  while (taken < near.ids.size() && near.d2[taken] <= max_r2)
    sum = sum + map.power[static_cast<std::size_t>(near.ids[taken])], ++taken;  // sorted by d2
  if (taken == 0) return {};
  const double r2 = static_cast<std::int64_t>(taken) == map.gather && near.d2[taken - 1] > 0 ? near.d2[taken - 1] : max_r2;
  return (1 / (3.141592653589793 * r2)) * sum;
}

}  // namespace sw::tracer
