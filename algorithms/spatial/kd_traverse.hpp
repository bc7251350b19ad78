// The closest hit of a ray in a triangle mesh through a kd-tree: the root cell clipped by the
// slab test (ray-box), then the leaves front to back with a stack of (node, t0, t1), each leaf's
// triangles tested watertight (ray-triangle-watertight), and an early exit once the best hit lies
// before the current leaf's far end. Exact with ties: cells are closed and every triangle meeting
// a leaf's closed cell is in that leaf (kd_build.hpp), so a hit on a shared face is found in
// either leaf. Semantics: docs/spatial/kd.md.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "rays/ray_box.hpp"
#include "rays/ray_triangle_watertight.hpp"
#include "spatial/tree_hit.hpp"
#include "spatial/kd_build.hpp"

namespace sw::spatial {

template <class Num> using KdHit = TreeHit<Num>;

struct KdTraverse {
  static constexpr std::string_view id = "kd-traverse";
  static constexpr std::string_view summary =
      "Ray through a kd-tree: front to back, t-interval clipping, early exit; closest hit, ties by id";
#define SW_LINES_KD_TRAVERSE(X) \
  X(build, "build the kd-tree over the triangles' bounds with kd-build") \
  X(clip, "[t0, t1] <- the ray's interval in the root cell, with ray-box (a miss: no hit); t0 <- max(t0, 0)") \
  X(push, "push (root, t0, t1); best <- none") \
  X(pop, "while the stack is not empty: pop (node, t0, t1)") \
  X(descend, "    while the node is inner, with plane x_k = p:") \
  X(parallel, \
    "        if d_k = 0: node <- left if o_k <= p, else right   -- in the plane, both sides hold what the ray can hit") \
  X(cross, "        t_s <- (p - o_k) / d_k; first, second <- left, right if d_k > 0, else right, left") \
  X(one, "        if t_s >= t1: node <- first; else if t_s <= t0: node <- second") \
  X(both, "        else: push (second, t_s, t1); node <- first; t1 <- t_s") \
  X(test, "    for each triangle i of the leaf: test it with ray-triangle-watertight") \
  X(keep, "        if it is hit and (t, i) < (t_best, i_best): best <- (t, i)") \
  X(exit, "    if best and t_best <= t1: stop   -- every hit before t1 lies in a leaf already visited") \
  X(done, "the best hit, or none")
  SW_LISTING("kd-tree ray traversal", SW_LINES_KD_TRAVERSE)
#undef SW_LINES_KD_TRAVERSE
};

// The stacked nodes: their ids (the tree view marks them) and their boxes.
template <class Step, class Num> void kd_record_stack(Step& s, const KdTree<Num, 3>& tree, const auto& stack) {
  std::vector<std::int64_t> ids;
  for (const auto& e : stack) ids.push_back(e.node);
  s.ilist("stack", ids);
  for (const auto& e : stack) s.box(tree.nodes[e.node].cell.lo, tree.nodes[e.node].cell.hi).label("stack");
}

// The walk over a built tree (kd_traverse below builds it first). Precondition: the tree is
// kd_build's over these triangles' bounds; r.d != 0.
template <NumberType Num, StepProbe Probe = NoProbe>
KdHit<Num> kd_traverse_tree(const KdTree<Num, 3>& tree, const std::vector<std::array<Vec3<Num>, 3>>& tris,
                            const ray::Ray3<Num>& r, Probe& probe) {
  using L = KdTraverse;
  KdHit<Num> out;
  const Box<Num, 3>& root = tree.nodes[0].cell;
  const ray::BoxHit<Num> box = [&] {
    const auto call = nested<ray::RayBox>(probe);
    return ray::ray_box<Num>(r, root.lo, root.hi, probe);
  }();
  const Num zero(0);
  const Num t_root = box.t_near > zero ? box.t_near : zero;
  if constexpr (Probe::on) {
    auto& s = probe.step(L::clip, box.hit ? StepKind::decide : StepKind::miss).idx("hit", box.hit);
    if (box.hit) s.num("t0", t_root).num("t1", box.t_far);
  }
  if (!box.hit) {
    if constexpr (Probe::on) probe.step(L::done, StepKind::miss).idx("hit", 0);
    return out;
  }
  struct Entry {
    std::int32_t node;
    Num t0, t1;
  };
  std::vector<Entry> stack{{0, t_root, box.t_far}};
  if constexpr (Probe::on) probe.step(L::push, StepKind::init).idx("node", 0).num("t0", t_root).num("t1", box.t_far);
  // Bounded: each node is pushed at most once (its parent is popped once); the descent is at
  // most the tree's depth.
  while (!stack.empty()) {
    Entry e = stack.back();
    stack.pop_back();
    if constexpr (Probe::on) {
      const auto& c = tree.nodes[e.node].cell;
      auto& s = probe.step(L::pop, StepKind::visit)
                    .idx("node", e.node)
                    .num("t0", e.t0)
                    .num("t1", e.t1)
                    .node(e.node, tree.nodes[e.node].parent, c.lo, c.hi);
      kd_record_stack(s, tree, stack);
      s.segment(Vec3<Num>(r.o + e.t0 * r.d), Vec3<Num>(r.o + e.t1 * r.d)).label("[t0, t1]");
    }
    ++out.nodes_visited;
    for (int guard = 0; tree.nodes[e.node].left >= 0 && guard <= kKdHardDepth; ++guard) {
      const KdNode<Num, 3>& nd = tree.nodes[e.node];
      const int k = nd.axis;
      std::int32_t next;
      if (num::sign(r.d[k]) == 0) {
        next = r.o[k] <= nd.split ? nd.left : nd.right;
        if constexpr (Probe::on)
          probe.step(L::parallel, StepKind::decide).idx("axis", k).num("p", nd.split).idx("left", next == nd.left);
      } else {
        const Num ts = (nd.split - r.o[k]) / r.d[k];
        const bool up = r.d[k] > zero;
        const std::int32_t first = up ? nd.left : nd.right, second = up ? nd.right : nd.left;
        if constexpr (Probe::on)
          probe.step(L::cross, StepKind::decide)
              .idx("axis", k)
              .num("p", nd.split)
              .num("t_s", ts)
              .idx("first", first)
              .idx("second", second);
        if (!(ts < e.t1) || !(e.t0 < ts)) {  // the interval lies on one side of the plane
          next = !(ts < e.t1) ? first : second;
          if constexpr (Probe::on) probe.step(L::one, StepKind::advance).idx("node", next);
        } else {
          stack.push_back({second, ts, e.t1});
          e.t1 = ts;
          next = first;
          if constexpr (Probe::on) {
            auto& s = probe.step(L::both, StepKind::advance).idx("node", next).idx("pushed", second).num("t1", e.t1);
            kd_record_stack(s, tree, stack);
          }
        }
      }
      e.node = next;
      ++out.nodes_visited;
      if constexpr (Probe::on) {
        const auto& c = tree.nodes[e.node].cell;
        probe.step(L::descend, StepKind::visit)
            .idx("node", e.node)
            .num("t0", e.t0)
            .num("t1", e.t1)
            .node(e.node, tree.nodes[e.node].parent, c.lo, c.hi);
      }
    }
    for (const std::int32_t i : tree.nodes[e.node].prims) keep_closest<L>(out, leaf_test<L>(out, tris, r, i, probe), i, r, probe);
    if (out.hit && !(e.t1 < out.t)) {
      if constexpr (Probe::on) probe.step(L::exit, StepKind::decide).num("t_best", out.t).num("t1", e.t1);
      break;
    }
  }
  if constexpr (Probe::on) record_done<L>(out, probe);
  return out;
}

// Precondition: tris non-empty (at most 2^21), r.d != 0.
template <NumberType Num, StepProbe Probe = NoProbe>
KdHit<Num> kd_traverse(const std::vector<std::array<Vec3<Num>, 3>>& tris, const ray::Ray3<Num>& r, Probe& probe) {
  using L = KdTraverse;
  std::vector<Box<Num, 3>> bounds;
  bounds.reserve(tris.size());
  for (const auto& t : tris) bounds.push_back(triangle_bounds(t));
  const KdTree<Num, 3> tree = [&] {
    const auto call = nested<KdBuild>(probe);
    return kd_build<Num, 3>(bounds, false, probe);
  }();
  if constexpr (Probe::on) {
    auto& s = probe.step(L::build, StepKind::init)
                  .idx("nodes", static_cast<std::int64_t>(tree.nodes.size()))
                  .idx("depth", static_cast<std::int64_t>(tree.depth));
    s.ray(r.o, r.d).keep();
    for (const auto& t : tris) s.triangle(t[0], t[1], t[2]).keep();
  }
  return kd_traverse_tree<Num>(tree, tris, r, probe);
}

}  // namespace sw::spatial
