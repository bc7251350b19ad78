// Octree build over 3D points or triangles. A leaf with more than `capacity` items splits at its
// cell's midpoint into 8 children, unless it is at max_depth or the reference budget is spent.
// A point goes to exactly one child (the half-open rule of cell_tree.hpp); a triangle goes to
// every child whose closed cell it meets, decided by the separating axis test below.
// Semantics: docs/spatial/point-trees.md.
#pragma once
#include <array>
#include <string_view>
#include <utility>
#include <vector>
#include "core/probe.hpp"
#include "spatial/cell_tree.hpp"

namespace sw::spatial {

// Is axis a a separating axis of the closed triangle t and the closed box b: do their projections
// onto a fail to overlap? (A zero axis never separates.)
template <NumberType Num> bool separates(const Vec3<Num>& a, const std::array<Vec3<Num>, 3>& t, const Box<Num, 3>& b) {
  Num bmin(0), bmax(0);
  for (int k = 0; k < 3; ++k) {
    Num lo = a[k] * b.lo[k], hi = a[k] * b.hi[k];
    if (hi < lo) std::swap(lo, hi);
    bmin = bmin + lo, bmax = bmax + hi;
  }
  Num tmin = dot(a, t[0]), tmax = tmin;
  for (int v = 1; v < 3; ++v) {
    const Num p = dot(a, t[v]);
    if (p < tmin) tmin = p;
    if (tmax < p) tmax = p;
  }
  return tmax < bmin || bmax < tmin;
}

// Closed triangle against closed box, exact when Num is: they are disjoint iff one of 13 axes
// separates them: the box's 3 face normals, the triangle's normal, and the 9 cross products of a
// triangle edge with a box axis. A zero-area triangle's segment or point is covered by the same axes.
template <NumberType Num> bool triangle_meets_cell(const std::array<Vec3<Num>, 3>& t, const Box<Num, 3>& b) {
  std::array<Vec3<Num>, 3> unit{};
  for (int k = 0; k < 3; ++k) unit[k][k] = Num(1);
  for (int k = 0; k < 3; ++k)
    if (separates(unit[k], t, b)) return false;
  const std::array<Vec3<Num>, 3> e{t[1] - t[0], t[2] - t[1], t[0] - t[2]};
  if (separates(cross(e[0], e[1]), t, b)) return false;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      if (separates(cross(e[i], unit[k]), t, b)) return false;
  return true;
}

struct OctreeBuild {
  static constexpr std::string_view id = "octree-build";
  static constexpr std::string_view summary =
      "Octree build over points or triangles: split a cell into 8 while it holds more than capacity items";
#define SW_SPATIAL_OCTREE_BUILD(X) \
  X(root, "root <- the bounding box (closed) of the points or triangles, holding every item; stack <- [root]") \
  X(visit, \
    "pop a node N until the stack is empty; if |N| <= capacity, depth(N) = max_depth or the budget is spent: N stays a leaf") \
  X(split, "mid <- (lo + hi) / 2; child c of N gets [lo_a, mid_a] or [mid_a, hi_a] by bit a of c") \
  X(place_point, "    a point p goes to child c = sum of 2^a over the axes with p_a >= mid_a    -- one child") \
  X(place_triangle, "    a triangle T goes to every child whose closed cell it meets (13 separating axes)") \
  X(push, "    push the 8 children, child 0 on top") \
  X(done, "done")
  SW_LISTING("Octree build", SW_SPATIAL_OCTREE_BUILD)
#undef SW_SPATIAL_OCTREE_BUILD
};

// The items: points, or else triangles (exactly one list is non-empty).
template <class Num> struct OctreeItems {
  std::vector<Vec3<Num>> points;
  std::vector<std::array<Vec3<Num>, 3>> triangles;
};

// Preconditions: one list is non-empty; capacity >= 1; max_depth >= 0. A node is split only if the
// references placed so far plus the most it can place (1 per point, 8 per triangle) stay within
// max_refs, so the work is bounded for any input (e.g. many copies of one large triangle).
template <NumberType Num, StepProbe Probe = NoProbe> CellTree<Num, 3> octree_build(const OctreeItems<Num>& in,
                                                                                   std::size_t capacity, int max_depth,
                                                                                   std::size_t max_refs, Probe& probe) {
  using L = OctreeBuild;
  const bool tris = in.points.empty();
  const std::size_t count = tris ? in.triangles.size() : in.points.size();
  CellTree<Num, 3> tree;
  CellNode<Num, 3> root;
  root.cell = Box<Num, 3>::at(tris ? in.triangles[0][0] : in.points[0]);
  for (const auto& p : in.points) root.cell.grow(p);
  for (const auto& t : in.triangles) root.cell.grow(triangle_bounds(t));
  for (std::size_t i = 0; i < count; ++i) root.items.push_back(static_cast<std::int32_t>(i));
  tree.nodes.push_back(root);
  if constexpr (Probe::on) {
    probe.step(L::root, StepKind::init)
        .idx("items", static_cast<std::int64_t>(count))
        .node(0, -1, root.cell.lo, root.cell.hi)
        .keep();
    for (const auto& p : in.points) probe.point(p).keep();
    for (const auto& t : in.triangles) probe.triangle(t[0], t[1], t[2]).keep();
  }
  std::size_t refs = count;
  std::vector<std::int32_t> stack{0};
  while (!stack.empty()) {
    const std::int32_t n = stack.back();
    stack.pop_back();
    const Box<Num, 3> cell = tree.nodes[n].cell;  // copied: the children's push_back moves the nodes
    const int depth = tree.nodes[n].depth;
    const std::size_t size = tree.nodes[n].items.size();
    const bool over = size > capacity && depth < max_depth;
    const bool in_budget = refs + (tris ? 8 : 1) * size <= max_refs;
    if constexpr (Probe::on)
      probe.step(L::visit, StepKind::visit)
          .idx("node", n)
          .idx("count", static_cast<std::int64_t>(size))
          .idx("depth", depth)
          .idx("split", over && in_budget)
          .node(n, tree.nodes[n].parent, cell.lo, cell.hi);
    if (!over || !in_budget) {
      tree.budget_stops += over;
      if (tree.depth < static_cast<std::size_t>(depth)) tree.depth = static_cast<std::size_t>(depth);
      continue;
    }
    const Vec3<Num> mid = midpoint(cell);
    add_children(tree, n, mid);
    const std::int32_t first = tree.nodes[n].first_child;
    if constexpr (Probe::on) {
      probe.step(L::split, StepKind::advance).idx("node", n).num("mid_x", mid.x).num("mid_y", mid.y).num("mid_z", mid.z);
      for (int c = 0; c < 8; ++c) probe.node(first + c, n, tree.nodes[first + c].cell.lo, tree.nodes[first + c].cell.hi).keep();
    }
    std::vector<std::int32_t> items;
    items.swap(tree.nodes[n].items);
    refs -= items.size();
    for (const std::int32_t i : items) {
      if (!tris) {
        const int c = child_of<Num, 3>(in.points[i], mid);
        tree.nodes[first + c].items.push_back(i), ++refs;
        if constexpr (Probe::on)
          probe.step(L::place_point, StepKind::decide).idx("point", i).idx("child", first + c).point(in.points[i]);
        continue;
      }
      std::int64_t mask = 0;
      for (int c = 0; c < 8; ++c)
        if (triangle_meets_cell(in.triangles[i], tree.nodes[first + c].cell))
          tree.nodes[first + c].items.push_back(i), ++refs, mask |= 1 << c;
      const auto& t = in.triangles[i];
      if constexpr (Probe::on)
        probe.step(L::place_triangle, StepKind::decide).idx("triangle", i).idx("children", mask).triangle(t[0], t[1], t[2]);
    }
    for (int c = 7; c >= 0; --c) stack.push_back(first + c);
    if constexpr (Probe::on)
      probe.step(L::push, StepKind::advance)
          .idx("stack", static_cast<std::int64_t>(stack.size()))
          .idx("refs", static_cast<std::int64_t>(refs));
  }
  if constexpr (Probe::on)
    probe.step(L::done, StepKind::done)
        .idx("nodes", static_cast<std::int64_t>(tree.nodes.size()))
        .idx("depth", static_cast<std::int64_t>(tree.depth))
        .idx("budget_stops", static_cast<std::int64_t>(tree.budget_stops));
  return tree;
}

}  // namespace sw::spatial
