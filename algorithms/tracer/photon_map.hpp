// The caustic photon map: the photons stored on diffuse surfaces (photon_trace.hpp) in a balanced
// kd-tree searched by kd-nearest, and the irradiance the tracer adds there: the k nearest within
// r, sum(power) / (pi r^2) (Jensen). Semantics and units: docs/tracer/renderer.md#caustics.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>
#include "spatial/kd_build.hpp"
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

// The photon map's kd-tree: median splits on the longest axis of the points' box, at most 8 points a
// leaf, each cell the box of its points. kd-nearest needs of a tree only that every cell holds its
// subtree's points (its answer, by (d2, id), is the same for any such tree), and this one builds in
// O(N log N) with no sweep: kd-build's SAH took 2.4 s for the 416k photons of mirror-room.
inline spatial::KdTree<double, 3> photon_tree(const std::vector<Vec3<double>>& at) {
  constexpr std::int32_t kLeaf = 8;
  spatial::KdTree<double, 3> t;
  std::vector<std::int32_t> ids(at.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<std::int32_t>(i);
  struct Task {
    std::int32_t node, first, last;
  };
  std::vector<Task> todo{{0, 0, static_cast<std::int32_t>(ids.size())}};
  t.nodes.emplace_back();
  while (!todo.empty()) {  // bounded: a task halves its range, so depth <= log2(N) + 1
    const Task w = todo.back();
    todo.pop_back();
    spatial::Box<double, 3> b = spatial::Box<double, 3>::at(at[static_cast<std::size_t>(ids[w.first])]);
    for (std::int32_t j = w.first + 1; j < w.last; ++j) b.grow(at[static_cast<std::size_t>(ids[j])]);
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (b.extent(k) > b.extent(axis)) axis = k;
    t.nodes[w.node].cell = b;
    t.depth = std::max(t.depth, static_cast<std::size_t>(t.nodes[w.node].depth));
    if (w.last - w.first <= kLeaf || !(b.extent(axis) > 0)) {  // few, or all at one point
      t.nodes[w.node].prims.assign(ids.begin() + w.first, ids.begin() + w.last);
      t.refs += static_cast<std::size_t>(w.last - w.first), ++t.leaves;
      continue;
    }
    const std::int32_t mid = w.first + (w.last - w.first) / 2;
    std::nth_element(ids.begin() + w.first, ids.begin() + mid, ids.begin() + w.last, [&](std::int32_t a, std::int32_t c) {
      const double pa = at[static_cast<std::size_t>(a)][axis], pc = at[static_cast<std::size_t>(c)][axis];
      return pa < pc || (pa == pc && a < c);
    });
    const auto l = static_cast<std::int32_t>(t.nodes.size());
    spatial::KdNode<double, 3> child;
    child.parent = w.node, child.depth = t.nodes[w.node].depth + 1;
    t.nodes.push_back(child), t.nodes.push_back(child);
    spatial::KdNode<double, 3>& nd = t.nodes[w.node];
    nd.left = l, nd.right = l + 1, nd.axis = static_cast<std::int8_t>(axis);
    nd.split = at[static_cast<std::size_t>(ids[mid])][axis];
    todo.push_back({l + 1, mid, w.last});
    todo.push_back({l, w.first, mid});
  }
  return t;
}

// Puts the stored photons (`at`) in the kd-tree and their bounding box; none: an empty map.
inline void index_photons(PhotonMap& map) {
  if (map.at.empty()) return;
  map.tree = photon_tree(map.at);
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
