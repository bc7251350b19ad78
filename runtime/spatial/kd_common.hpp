// What the kd-tree Specs share (kd.cpp: kd-build; kd_query.cpp: kd-traverse, kd-nearest): point
// sets of 2 or 3 coordinates, the built tree as a TreeOutput, and the trace budget.
// Semantics: docs/spatial/kd.md.
#pragma once
#include <string>
#include <vector>
#include "spatial/kd_build.hpp"
#include "spatial/spatial_common.hpp"
#include "catalog.hpp"

namespace sw::kdspec {

using namespace spatial;

// A traced run (record, stream) is refused when its estimated steps pass this bound, which only a
// raised --max-steps reaches (the recorder's memory); untraced runs take everything up to the size
// bounds (kMaxTriangles, kMaxPoints).
inline constexpr std::size_t kTraceBudget = std::size_t{1} << 26;

// Points of 2 or 3 coordinates (all of one length, the first one's).
struct PointSet {
  int dim = 2;
  std::vector<std::array<double, 2>> p2;
  std::vector<std::array<double, 3>> p3;
  std::size_t size() const { return dim == 2 ? p2.size() : p3.size(); }
};
PointSet parse_point_set(const Json& arr, const std::string& what);

// The build's steps: at most kd_max_nodes(n) nodes, each a visit, one sweep result per axis and a
// leaf or a split (three steps), plus five.
inline std::size_t build_steps(std::size_t n, int dim) { return kd_max_nodes(n) * static_cast<std::size_t>(dim + 4) + 5; }
// Throws InputError if a trace of `steps` would pass the budget.
void check_trace_budget(std::size_t steps, std::size_t n, const std::string& what);

// Seeded random inputs (kd.cpp): points in [-1, 1]^3 and triangles of edge about 2/sqrt(n) there,
// all on the 2^-20 grid.
Mesh random_mesh_for(std::uint64_t seed, std::size_t n);
std::vector<std::array<double, 3>> random_points_for(std::uint64_t seed, std::size_t n);

template <class Num, int D> TreeOutput tree_output(const KdTree<Num, D>& tree) {
  TreeOutput t;
  t.dim = D;
  t.bits = std::is_same_v<Num, float> ? 24 : 53;
  double inner = 0, leaf = 0;
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    const KdNode<Num, D>& n = tree.nodes[i];
    const std::int32_t id = add_node(t, n.parent);
    set_bounds<Num, D>(t, id, n.cell);
    const double a = num::to_double(n.cell.half_area());
    if (n.left >= 0) {
      t.nodes[i].axis = n.axis;
      inner += kKdTraverseCost * a;
    } else {
      t.nodes[i].prims = n.prims;
      leaf += kKdIntersectCost * static_cast<double>(n.prims.size()) * a;
    }
  }
  t.leaves = tree.leaves, t.depth = tree.depth;
  t.bytes = tree.nodes.size() * sizeof(KdNode<Num, D>) + tree.refs * sizeof(std::int32_t);
  // SAH cost: sum of K_T A(inner) + K_I N A(leaf), over A(root); a root of no area is one leaf.
  const double root = num::to_double(tree.nodes[0].cell.half_area());
  t.sah_cost = root > 0 ? (inner + leaf) / root : kKdIntersectCost * static_cast<double>(tree.nodes[0].prims.size());
  return t;
}

}  // namespace sw::kdspec

namespace sw {
}
