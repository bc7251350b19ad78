// Quadtree build: a bucket quadtree over 2D points. A leaf with more than `capacity` points splits
// at its cell's midpoint into 4 children, unless it is at max_depth. Each point goes to exactly one
// child by the half-open rule of cell_tree.hpp. Semantics: docs/spatial/point-trees.md.
#pragma once
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "spatial/cell_tree.hpp"

namespace sw::spatial {

struct QuadtreeBuild {
  static constexpr std::string_view id = "quadtree-build";
  static constexpr std::string_view summary = "Quadtree build: split a cell into 4 while it holds more than capacity points";
#define SW_SPATIAL_QUADTREE_BUILD(X) \
  X(root, "root <- the points' bounding box (closed) holding every point; stack <- [root]") \
  X(visit, "pop a node N until the stack is empty; if |N| <= capacity or depth(N) = max_depth: N stays a leaf") \
  X(split, "mid <- (lo + hi) / 2; child c of N gets [lo_a, mid_a) or [mid_a, hi_a) by bit a of c") \
  X(place, "    for each point p of N: c <- sum of 2^a over the axes with p_a >= mid_a; p goes to child c") \
  X(push, "    push the 4 children, child 0 on top") \
  X(done, "done")
  SW_LISTING("Quadtree build", SW_SPATIAL_QUADTREE_BUILD)
#undef SW_SPATIAL_QUADTREE_BUILD
};

// Preconditions: points is not empty; capacity >= 1; max_depth >= 0. Every loop is bounded: a
// node is pushed once, and only a node above max_depth is split.
template <NumberType Num, StepProbe Probe = NoProbe>
CellTree<Num, 2> quadtree_build(const std::vector<Vec2<Num>>& points, std::size_t capacity, int max_depth, Probe& probe) {
  using L = QuadtreeBuild;
  CellTree<Num, 2> tree;
  CellNode<Num, 2> root;
  root.cell = Box<Num, 2>::at(points[0]);
  for (const auto& p : points) root.cell.grow(p);
  for (std::size_t i = 0; i < points.size(); ++i) root.items.push_back(static_cast<std::int32_t>(i));
  tree.nodes.push_back(root);
  if constexpr (Probe::on) {
    probe.step(L::root, StepKind::init)
        .idx("points", static_cast<std::int64_t>(points.size()))
        .node(0, -1, root.cell.lo, root.cell.hi)
        .keep();
    for (const auto& p : points) probe.point(p).keep();
  }
  std::vector<std::int32_t> stack{0};
  while (!stack.empty()) {
    const std::int32_t n = stack.back();
    stack.pop_back();
    // A reference into tree.nodes would dangle once the children are appended: copy what is needed.
    const Box<Num, 2> cell = tree.nodes[n].cell;
    const int depth = tree.nodes[n].depth;
    const std::int32_t parent = tree.nodes[n].parent;
    const bool split = tree.nodes[n].items.size() > capacity && depth < max_depth;
    if constexpr (Probe::on)
      probe.step(L::visit, StepKind::visit)
          .idx("node", n)
          .idx("count", static_cast<std::int64_t>(tree.nodes[n].items.size()))
          .idx("depth", depth)
          .idx("split", split)
          .node(n, parent, cell.lo, cell.hi);
    if (!split) {
      if (tree.depth < static_cast<std::size_t>(depth)) tree.depth = static_cast<std::size_t>(depth);
      continue;
    }
    const Vec2<Num> mid = midpoint(cell);
    add_children(tree, n, mid);
    const std::int32_t first = tree.nodes[n].first_child;
    if constexpr (Probe::on) {
      probe.step(L::split, StepKind::advance).idx("node", n).num("mid_x", mid.x).num("mid_y", mid.y);
      for (int c = 0; c < 4; ++c) probe.node(first + c, n, tree.nodes[first + c].cell.lo, tree.nodes[first + c].cell.hi).keep();
    }
    std::vector<std::int32_t> items;
    items.swap(tree.nodes[n].items);
    for (const std::int32_t i : items) {
      const int c = child_of<Num, 2>(points[i], mid);
      tree.nodes[first + c].items.push_back(i);
      if constexpr (Probe::on) probe.step(L::place, StepKind::decide).idx("point", i).idx("child", first + c).point(points[i]);
    }
    for (int c = 3; c >= 0; --c) stack.push_back(first + c);
    if constexpr (Probe::on) probe.step(L::push, StepKind::advance).idx("stack", static_cast<std::int64_t>(stack.size()));
  }
  if constexpr (Probe::on)
    probe.step(L::done, StepKind::done)
        .idx("nodes", static_cast<std::int64_t>(tree.nodes.size()))
        .idx("depth", static_cast<std::int64_t>(tree.depth));
  return tree;
}

}  // namespace sw::spatial
