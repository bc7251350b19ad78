// The closest hit of a ray in a triangle mesh through a BVH (bvh-build): a stack of nodes with
// their entry t, the nearer child popped first, each box tested with the slab test (ray-box) and
// each leaf triangle with the watertight test (ray-triangle-watertight). A node is pruned only
// when its entry t is beyond the best hit (t_entry > t_best): one entered exactly at t_best may
// still hold a lower-id triangle hit at t_best. Any-hit (shadow-ray) mode stops at the first hit
// with t < t_max. Boxes are closed and bound their triangles exactly, so in exact arithmetic no
// hit is lost. Semantics: docs/spatial/bvh.md.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "rays/ray_box.hpp"
#include "rays/ray_triangle_watertight.hpp"
#include "spatial/tree_hit.hpp"
#include "spatial/bvh_build.hpp"

namespace sw::spatial {

template <class Num> using BvhHit = TreeHit<Num>;

// The query: closest hit, or (any) the first hit found with t < t_max (t_max > 0).
template <class Num> struct BvhQuery {
  bool any = false;
  Num t_max{};
  std::int32_t skip = -1;  // the triangle a secondary ray leaves: a ray cannot meet its own plane again
};

struct BvhTraverse {
  static constexpr std::string_view id = "bvh-traverse";
  static constexpr std::string_view summary =
      "Ray through a BVH: nearer child first, prune on entry t > best t; closest hit (ties by id) or any hit";
#define SW_LINES_BVH_TRAVERSE(X) \
  X(build, "build the BVH over the triangles with bvh-build") \
  X(root, "test the root's box with ray-box; a miss: no hit; else push (root, t_entry)") \
  X(pop, "while the stack is not empty: pop (node, t_entry)") \
  X(prune, "    if t_entry > t_best (any hit: t_entry >= t_max): skip it   -- entering at t_best may still find a lower id") \
  X(test, "    if a leaf: for each triangle i but the one the ray leaves: test it with ray-triangle-watertight") \
  X(keep, "        if it is hit and (t, i) < (t_best, i_best): best <- (t, i)") \
  X(stop, "        any hit: if it is hit with t < t_max: stop with it") \
  X(boxes, "    else: test both children's boxes with ray-box") \
  X(push, "        push the children hit, the farther first (ties: the right), so the nearer is popped next") \
  X(done, "the best hit, or none")
  SW_LISTING("BVH ray traversal", SW_LINES_BVH_TRAVERSE)
#undef SW_LINES_BVH_TRAVERSE
};

namespace bvh_detail {
template <class Num> struct Entry {
  std::int32_t node = 0;
  Num t{};  // the ray's entry t into the node's box (t_near: negative when the origin is inside)
};
// Depth first, a pop pushes at most two: at most one sibling per level waits, so the stack never
// holds more than depth + 2 entries; a fixed array (no allocation per ray).
template <class Num> struct Stack {
  std::array<Entry<Num>, kBvhMaxDepth + 2> at;
  std::size_t size = 0;
  bool empty() const { return size == 0; }
  void push_back(const Entry<Num>& e) { at[size++] = e; }
  const Entry<Num>& back() const { return at[size - 1]; }
  void pop_back() { --size; }
  void clear() { size = 0; }
};
// The stack's depth and its nodes' boxes, on the step s.
template <class Step, class Num> void record_stack(Step& s, const Bvh<Num>& bvh, const Stack<Num>& stack) {
  s.idx("stack", static_cast<std::int64_t>(stack.size));
  for (std::size_t k = 0; k < stack.size; ++k)
    s.box(bvh.nodes[stack.at[k].node].box.lo, bvh.nodes[stack.at[k].node].box.hi).label("stack");
}
}  // namespace bvh_detail

// The traversal of a built BVH (what bvh-traverse does after its build). Precondition: bvh built
// over tris; r.d != 0; q.t_max > 0 when q.any.
template <NumberType Num, StepProbe Probe = NoProbe>
BvhHit<Num> bvh_query(const Bvh<Num>& bvh, const std::vector<std::array<Vec3<Num>, 3>>& tris, const ray::Ray3<Num>& r,
                      const BvhQuery<Num>& q, Probe& probe) {
  using L = BvhTraverse;
  BvhHit<Num> out;
  auto box_test = [&](std::int32_t node) __attribute__((always_inline)) {
    const auto call = nested<ray::RayBox>(probe);
    return ray::ray_box<Num>(r, bvh.nodes[node].box.lo, bvh.nodes[node].box.hi, probe);
  };
  const ray::BoxHit<Num> root = box_test(0);
  if constexpr (Probe::on) {
    auto& s = probe.step(L::root, root.hit ? StepKind::decide : StepKind::miss).idx("hit", root.hit);
    if (root.hit) s.num("t_entry", root.t_near);
  }
  bvh_detail::Stack<Num> stack;
  if (root.hit) stack.push_back({0, root.t_near});
  // Bounded: every node is pushed at most once (by its parent, popped once).
  while (!stack.empty()) {
    const bvh_detail::Entry<Num> e = stack.back();
    stack.pop_back();
    const BvhNode<Num>& nd = bvh.nodes[e.node];
    const bool pruned = q.any ? !(e.t < q.t_max) : out.hit && out.t < e.t;
    if (pruned) {
      if constexpr (Probe::on)
        probe.step(L::prune, StepKind::decide)
            .idx("node", e.node)
            .num("t_entry", e.t)
            .num(q.any ? "t_max" : "t_best", q.any ? q.t_max : out.t);
      continue;
    }
    ++out.nodes_visited;
    if constexpr (Probe::on) {
      auto& s = probe.step(L::pop, StepKind::visit)
                    .idx("node", e.node)
                    .num("t_entry", e.t)
                    .node(e.node, nd.parent, nd.box.lo, nd.box.hi);
      bvh_detail::record_stack(s, bvh, stack);
    }
    if (nd.left < 0) {
      for (std::int32_t j = nd.first; j < nd.first + nd.count; ++j) {
        const std::int32_t i = bvh.order[j];
        if (i == q.skip) continue;
        const ray::TriangleHit<Num> h = leaf_test<L>(out, tris, r, i, probe);
        if (!q.any) {
          keep_closest<L>(out, h, i, r, probe);
        } else if (h.hit && h.t < q.t_max) {
          take_hit<L>(out, h, i, r, L::stop, probe);
          stack.clear();
          break;
        }
      }
      continue;
    }
    const ray::BoxHit<Num> hl = box_test(nd.left), hr = box_test(nd.right);
    if constexpr (Probe::on) {
      auto& s = probe.step(L::boxes, StepKind::decide)
                    .idx("left", nd.left)
                    .idx("right", nd.right)
                    .idx("left_hit", hl.hit)
                    .idx("right_hit", hr.hit);
      if (hl.hit) s.num("t_left", hl.t_near);
      if (hr.hit) s.num("t_right", hr.t_near);
    }
    if (!hl.hit && !hr.hit) continue;
    // The nearer on top: the left unless the right's entry is strictly nearer.
    const bool right_first = hl.hit && hr.hit ? hr.t_near < hl.t_near : hr.hit;
    if (hl.hit && hr.hit) {
      if (right_first) stack.push_back({nd.left, hl.t_near}), stack.push_back({nd.right, hr.t_near});
      else stack.push_back({nd.right, hr.t_near}), stack.push_back({nd.left, hl.t_near});
    } else {
      stack.push_back(hl.hit ? bvh_detail::Entry<Num>{nd.left, hl.t_near} : bvh_detail::Entry<Num>{nd.right, hr.t_near});
    }
    if constexpr (Probe::on) {
      auto& s = probe.step(L::push, StepKind::advance).idx("next", stack.back().node);
      bvh_detail::record_stack(s, bvh, stack);
    }
  }
  if constexpr (Probe::on) record_done<L>(out, probe);
  return out;
}

// The listing: the build (a nested bvh-build), then the query.
template <NumberType Num, StepProbe Probe = NoProbe> BvhHit<Num> bvh_traverse(const std::vector<std::array<Vec3<Num>, 3>>& tris,
                                                                              const ray::Ray3<Num>& r, const BvhQuery<Num>& q,
                                                                              Probe& probe) {
  using L = BvhTraverse;
  const Bvh<Num> bvh = [&] {
    const auto call = nested<BvhBuild>(probe);
    return bvh_build<Num>(tris, probe);
  }();
  if constexpr (Probe::on) {
    auto& s = probe.step(L::build, StepKind::init)
                  .idx("nodes", static_cast<std::int64_t>(bvh.nodes.size()))
                  .idx("depth", static_cast<std::int64_t>(bvh.depth));
    s.ray(r.o, r.d).keep();
    for (const auto& t : tris) s.triangle(t[0], t[1], t[2]).keep();  // the build's own items end with it
  }
  return bvh_query<Num>(bvh, tris, r, q, probe);
}

}  // namespace sw::spatial
