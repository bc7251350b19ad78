// The k nearest points to a query through a kd-tree: depth first with a stack, the near child
// first, a child skipped when its closed cell is farther (squared, exactly) than the largest of k
// held; the held ones in a bounded max-heap ordered by (d2, id), so ties go to the lower id.
// Semantics: docs/spatial/kd.md.
#pragma once
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>
#include "core/probe.hpp"
#include "spatial/kd_build.hpp"

namespace sw::spatial {

template <class Num> struct KdNearestResult {
  std::vector<std::int32_t> ids;  // by (d2, id)
  std::vector<Num> d2;
  std::size_t nodes_visited = 0, dist_tests = 0;
};

struct KdNearest {
  static constexpr std::string_view id = "kd-nearest";
  static constexpr std::string_view summary =
      "k nearest points through a kd-tree: near child first, far cells pruned by exact squared distance";
#define SW_LINES_KD_NEAREST(X) \
  X(build, "build the kd-tree over the points with kd-build") \
  X(push, "push (root, d2 of q to the root cell)   -- d2 to a cell: the sum over axes of (the gap outside [lo_k, hi_k])^2") \
  X(pop, "while the stack is not empty: pop (node, d2_cell)") \
  X(prune, \
    "    if d2_cell > r^2, or k are held and d2_cell > the largest held d2: skip the node   -- equal may still tie by id") \
  X(children, \
    "    inner, plane x_k = p: push the far child, then the near one (q's side; left if q_k = p), each with its cell's d2") \
  X(point, "    leaf: for each point i: d2 <- |p_i - q|^2") \
  X(take, \
    "        if d2 <= r^2 and (fewer than k are held or (d2, i) < the largest held): hold (d2, i), dropping the largest beyond " \
    "k") \
  X(done, "the held points, sorted by (d2, id)")
  SW_LISTING("kd-tree k nearest", SW_LINES_KD_NEAREST)
#undef SW_LINES_KD_NEAREST
};

// The squared distance from q to the closed box (0 inside).
template <class Num, int D> Num kd_cell_d2(const Box<Num, D>& c, const VecN<Num, D>& q) {
  Num s(0);
  for (int k = 0; k < D; ++k) {
    if (q[k] < c.lo[k]) s = s + (c.lo[k] - q[k]) * (c.lo[k] - q[k]);
    else if (c.hi[k] < q[k]) s = s + (q[k] - c.hi[k]) * (q[k] - c.hi[k]);
  }
  return s;
}

template <class Num, int D> Num kd_point_d2(const VecN<Num, D>& p, const VecN<Num, D>& q) {
  Num s(0);
  for (int k = 0; k < D; ++k) s = s + (p[k] - q[k]) * (p[k] - q[k]);
  return s;
}

// The search over a built tree (kd_nearest below builds it first). Precondition: the tree is
// kd_build's over these points; 1 <= k <= pts.size().
// r2, if given, bounds the search: only points with d2 <= r2 are held (the photon map's radius).
template <NumberType Num, int D, StepProbe Probe = NoProbe>
KdNearestResult<Num> kd_nearest_tree(const KdTree<Num, D>& tree, const std::vector<VecN<Num, D>>& pts, const VecN<Num, D>& q,
                                     std::size_t k, Probe& probe, const std::optional<Num>& r2 = std::nullopt) {
  using L = KdNearest;
  using Held = std::pair<Num, std::int32_t>;
  // (d2, id) order; the heap's front is the largest held.
  auto less = [](const Held& a, const Held& b) { return a.first < b.first || (!(b.first < a.first) && a.second < b.second); };
  std::vector<Held> heap;
  heap.reserve(k);
  struct Entry {
    std::int32_t node;
    Num d2;
  };
  auto record_stack = [&](auto& s, const std::vector<Entry>& stack) {
    std::vector<std::int64_t> ids;
    for (const Entry& e : stack) ids.push_back(e.node);
    s.ilist("stack", ids);
  };
  KdNearestResult<Num> out;
  std::vector<Entry> stack;
  stack.reserve(tree.depth + 2);  // depth first, two pushed a level: at most depth + 2 held
  stack.push_back({0, kd_cell_d2<Num, D>(tree.nodes[0].cell, q)});
  if constexpr (Probe::on) probe.step(L::push, StepKind::init).idx("node", 0).num("d2_cell", stack[0].d2);
  // Bounded: each node is pushed at most once.
  while (!stack.empty()) {
    const Entry e = stack.back();
    stack.pop_back();
    const KdNode<Num, D>& nd = tree.nodes[e.node];
    ++out.nodes_visited;
    if constexpr (Probe::on) {
      auto& s = probe.step(L::pop, StepKind::visit)
                    .idx("node", e.node)
                    .num("d2_cell", e.d2)
                    .node(e.node, nd.parent, nd.cell.lo, nd.cell.hi);
      record_stack(s, stack);
    }
    if (heap.size() == k || r2) {
      const bool skip = (r2 && *r2 < e.d2) || (heap.size() == k && heap.front().first < e.d2);
      if constexpr (Probe::on) {
        auto& st = probe.step(L::prune, StepKind::decide).idx("skip", skip);
        if (heap.size() == k) st.num("worst", heap.front().first);
      }
      if (skip) continue;
    }
    if (nd.left >= 0) {
      const bool near_left = q[nd.axis] <= nd.split;
      const std::int32_t near = near_left ? nd.left : nd.right, far = near_left ? nd.right : nd.left;
      const Num dn = kd_cell_d2<Num, D>(tree.nodes[near].cell, q), df = kd_cell_d2<Num, D>(tree.nodes[far].cell, q);
      stack.push_back({far, df});
      stack.push_back({near, dn});
      if constexpr (Probe::on)
        probe.step(L::children, StepKind::advance).idx("near", near).idx("far", far).num("d2_near", dn).num("d2_far", df);
      continue;
    }
    for (const std::int32_t i : nd.prims) {
      const Num d2 = kd_point_d2<Num, D>(pts[i], q);
      ++out.dist_tests;
      if constexpr (Probe::on)
        probe.step(L::point, StepKind::visit).idx("i", i).num("d2", d2).point(pts[i]).segment(pts[i], q).value(d2);
      const Held h{d2, i};
      if ((!r2 || !(*r2 < d2)) && (heap.size() < k || less(h, heap.front()))) {
        if (heap.size() == k) std::pop_heap(heap.begin(), heap.end(), less), heap.pop_back();
        heap.push_back(h);
        std::push_heap(heap.begin(), heap.end(), less);
        if constexpr (Probe::on)
          probe.step(L::take, StepKind::hit)
              .idx("i", i)
              .idx("held", static_cast<std::int64_t>(heap.size()))
              .num("worst", heap.front().first);
      }
    }
  }
  std::sort_heap(heap.begin(), heap.end(), less);
  out.ids.reserve(heap.size()), out.d2.reserve(heap.size());
  for (const Held& h : heap) out.ids.push_back(h.second), out.d2.push_back(h.first);
  if constexpr (Probe::on) {
    auto& s = probe.step(L::done, StepKind::done).idx("held", static_cast<std::int64_t>(heap.size()));
    for (const Held& h : heap) s.point(pts[h.second]).label("nearest").keep();
  }
  return out;
}

// Precondition: 1 <= k <= pts.size() <= 2^21.
template <NumberType Num, int D, StepProbe Probe = NoProbe>
KdNearestResult<Num> kd_nearest(const std::vector<VecN<Num, D>>& pts, const VecN<Num, D>& q, std::size_t k, Probe& probe) {
  using L = KdNearest;
  std::vector<Box<Num, D>> bounds;
  bounds.reserve(pts.size());
  for (const auto& p : pts) bounds.push_back(Box<Num, D>::at(p));
  const KdTree<Num, D> tree = [&] {
    const auto call = nested<KdBuild>(probe);
    return kd_build<Num, D>(bounds, true, probe);
  }();
  if constexpr (Probe::on) {
    auto& s = probe.step(L::build, StepKind::init)
                  .idx("nodes", static_cast<std::int64_t>(tree.nodes.size()))
                  .idx("depth", static_cast<std::int64_t>(tree.depth));
    s.point(q).label("q").keep();
    for (const auto& p : pts) s.point(p).keep();  // the build's own items end with it
  }
  return kd_nearest_tree<Num, D>(tree, pts, q, k, probe);
}

}  // namespace sw::spatial
