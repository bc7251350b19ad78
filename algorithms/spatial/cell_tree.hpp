// What the quadtree and the octree share: a tree of cells, each split at its midpoint into 2^D
// children, and the half-open rule that sends each point to exactly one child.
// Semantics: docs/spatial/point-trees.md.
#pragma once
#include <cstdint>
#include <vector>
#include "spatial/bounds.hpp"

namespace sw::spatial {

template <class Num, int D> struct CellNode {
  std::int32_t parent = -1;
  std::int32_t first_child = -1;  // children are first_child .. first_child + 2^D - 1; -1: a leaf
  int depth = 0;
  Box<Num, D> cell;                 // closed bounds; see child_of for which points it owns
  std::vector<std::int32_t> items;  // a leaf's point or triangle ids, ascending
};

template <class Num, int D> struct CellTree {
  std::vector<CellNode<Num, D>> nodes;  // node 0 is the root
  std::size_t budget_stops = 0;         // leaves left unsplit because of the reference budget (octree)
  std::size_t depth = 0;                // the deepest leaf
};

// Child c of a cell split at mid: bit a of c says which half on axis a (1: [mid_a, hi_a]).
template <class Num, int D> Box<Num, D> child_cell(const Box<Num, D>& b, const VecN<Num, D>& mid, int c) {
  Box<Num, D> out = b;
  for (int a = 0; a < D; ++a) (c >> a & 1 ? out.lo : out.hi)[a] = mid[a];
  return out;
}

// The child that owns p: on each axis the upper half if p_a >= mid_a (a point on the split plane
// goes up). So a cell owns [lo, hi) on each axis, closed at the root's top.
template <class Num, int D> int child_of(const VecN<Num, D>& p, const VecN<Num, D>& mid) {
  int c = 0;
  for (int a = 0; a < D; ++a)
    if (!(p[a] < mid[a])) c |= 1 << a;
  return c;
}

template <class Num, int D> VecN<Num, D> midpoint(const Box<Num, D>& b) {
  VecN<Num, D> m;
  for (int a = 0; a < D; ++a) m[a] = (b.lo[a] + b.hi[a]) / Num(2);
  return m;
}

// Splits leaf n at mid: appends its 2^D children (child c's cell is child_cell(cell, mid, c)).
template <class Num, int D> void add_children(CellTree<Num, D>& tree, std::int32_t n, const VecN<Num, D>& mid) {
  const Box<Num, D> cell = tree.nodes[n].cell;
  const int depth = tree.nodes[n].depth;
  tree.nodes[n].first_child = static_cast<std::int32_t>(tree.nodes.size());
  for (int c = 0; c < (1 << D); ++c) {
    CellNode<Num, D> child;
    child.parent = n, child.depth = depth + 1, child.cell = child_cell(cell, mid, c);
    tree.nodes.push_back(std::move(child));
  }
}

}  // namespace sw::spatial
