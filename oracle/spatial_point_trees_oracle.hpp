// The quadtree's and octree's specification, stated without the build's bookkeeping: a cell's items
// are found by testing every input item against the cell (half-open for points, CGAL's closed
// triangle-box overlap for triangles), not by handing the parent's list down. GMP rationals;
// independent of algorithms/spatial/. Semantics: docs/spatial/point-trees.md.
#pragma once
#include <cstdint>
#include <limits>
#include <vector>
#include "spatial_oracle.hpp"

namespace sw::oracle {

struct CellSpecNode {
  std::int32_t parent = -1;
  std::vector<std::int32_t> children;  // 2^D, or none for a leaf
  std::vector<std::int32_t> items;     // a leaf's item ids, ascending
  std::vector<Rational> lo, hi;        // D values each
};
struct CellSpecTree {
  std::vector<CellSpecNode> nodes;  // depth first, children numbered when their parent splits
  std::size_t depth = 0, budget_stops = 0;
};

// Points of D = 2 or 3 coordinates: the root is their bounding box; a cell with more than `cap`
// points below max_depth splits at its midpoint; a point belongs to [lo, hi) on each axis, closed
// at the root's upper faces. `max_refs`: split only if N + |cell| <= max_refs (the octree's budget).
CellSpecTree point_cell_tree(const std::vector<std::vector<Rational>>& points, std::size_t cap, int max_depth,
                             std::size_t max_refs = std::numeric_limits<std::size_t>::max());
// Triangles: a cell holds every triangle meeting its closed box; split only if the leaf entries so
// far plus 8 |cell| stay within max_refs (depth first, child 0 first).
CellSpecTree triangle_cell_tree(const std::vector<Triangle3>& tris, std::size_t cap, int max_depth, std::size_t max_refs);

}  // namespace sw::oracle
