// A kd-tree by the surface area heuristic in O(N log N) (Wald and Havran 2006): each axis's split
// events are sorted once; each node sweeps its sorted lists for the cheapest plane and hands its
// children two lists that are still sorted. Cells are closed boxes. A primitive goes to every
// child whose closed half-space its bounds meet, so one touching the plane goes to both; a flat
// primitive lying in the plane goes to the cheaper side when it is a point (every point is held
// by exactly one leaf) and to both sides when it is a triangle (it meets both closed cells).
// Semantics: docs/spatial/kd.md.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "spatial/bounds.hpp"

namespace sw::spatial {

// The costs of one traversal step and one primitive test (Wald and Havran's 15 : 20), and the
// empty-side bonus lambda = 4/5 as lambda5 / 5, all scaled to integers.
inline constexpr int kKdTraverseCost = 3, kKdIntersectCost = 4;
inline constexpr int kKdHardDepth = 40;  // the depth bound never exceeds this (also the stack's)
// The documented termination bounds: depth <= 8 + 1.3 log2 N (at most kKdHardDepth); at most
// 16 N + 64 nodes (pending nodes become leaves beyond that).
inline int kd_max_depth(std::size_t n) {
  const double d = 8 + 1.3 * std::log2(static_cast<double>(std::max<std::size_t>(n, 1)));
  return std::min(kKdHardDepth, static_cast<int>(d));
}
inline std::size_t kd_max_nodes(std::size_t n) { return 16 * n + 64; }

template <class Num, int D> struct KdNode {
  Box<Num, D> cell;
  std::int32_t parent = -1, left = -1, right = -1;  // left = -1: a leaf
  std::int32_t depth = 0;
  std::int8_t axis = -1;
  bool flat_left = true;  // points on the plane went left (else right)
  Num split{};
  std::vector<std::int32_t> prims;  // a leaf's, by id
};

template <class Num, int D> struct KdTree {
  std::vector<KdNode<Num, D>> nodes;  // node 0 is the root; children are created in pairs
  std::size_t leaves = 0, depth = 0, refs = 0;
  std::size_t events_touched = 0;  // events swept or split below the root: the O(N log N) work
  bool points = true;
};

template <class Num> struct KdEvent {
  enum Type : std::uint8_t { end = 0, flat = 1, start = 2 };  // the order at one position
  Num pos;
  std::int32_t prim;
  Type type;
};

struct KdBuild {
  static constexpr std::string_view id = "kd-build";
  static constexpr std::string_view summary =
      "kd-tree by the surface area heuristic in O(N log N): events sorted once, split lists kept sorted";
#define SW_LINES_KD_BUILD(X) \
  X(events, "for each primitive and axis k: a start and an end event at lo_k and hi_k, or one flat event if lo_k = hi_k") \
  X(sort, "sort each axis's events once, by (position, end < flat < start, id)") \
  X(root, "root <- a node whose cell is the bounds of all primitives; push it") \
  X(pop, "while a node is pending: take the last pushed; A <- its cell's half area, N <- its primitives") \
  X(sweep, "    for each axis k, sweep its events in order; at each position p strictly inside the cell:") \
  X(best, \
    "        C(p) <- lambda (K_T A + K_I (A_L N_L + A_R N_R)); keep the least, the first of equals   -- N_L: lo_k <= p, N_R: " \
    "hi_k >= p") \
  X(leaf, "    if no C(p) < K_I N A, or depth = max depth, or N <= 1: the node is a leaf; next") \
  X(classify, "    left if lo_k <= p, right if hi_k >= p; flat at p: the cheaper side (points) or both (triangles)") \
  X(split, "    split every axis's events into the children's lists in order: they stay sorted, nothing is re-sorted") \
  X(children, "    the children: the cell cut at p; push them") \
  X(done, "done: nodes, leaves, depth")
  SW_LISTING("kd-tree build (SAH, O(N log N))", SW_LINES_KD_BUILD)
#undef SW_LINES_KD_BUILD
};

// The box with its side k moved to p: hi_k (keep_lo) or lo_k.
template <class Num, int D> Box<Num, D> kd_cut(const Box<Num, D>& b, int k, const Num& p, bool keep_lo) {
  Box<Num, D> c = b;
  (keep_lo ? c.hi[k] : c.lo[k]) = p;
  return c;
}

// The tree over the primitives' bounds. points: the primitives are points (flat ones at a plane
// go to the cheaper side); else triangles (flat ones at a plane go to both). Precondition:
// 1 <= bounds.size() <= 2^21, every lo <= hi.
template <NumberType Num, int D, StepProbe Probe = NoProbe>
KdTree<Num, D> kd_build(const std::vector<Box<Num, D>>& b, bool points, Probe& probe) {
  using L = KdBuild;
  using Ev = KdEvent<Num>;
  using List = std::array<std::vector<Ev>, D>;
  const std::size_t n = b.size();
  const int max_depth = kd_max_depth(n);
  const std::size_t max_nodes = kd_max_nodes(n);
  const Num lam_empty(4), lam_full(5), kt(kKdTraverseCost), ki(kKdIntersectCost);
  KdTree<Num, D> tree;
  tree.points = points;
  List ev;
  for (int k = 0; k < D; ++k)
    for (std::size_t i = 0; i < n; ++i) {
      const auto id = static_cast<std::int32_t>(i);
      if (b[i].lo[k] == b[i].hi[k]) ev[k].push_back({b[i].lo[k], id, Ev::flat});
      else ev[k].push_back({b[i].lo[k], id, Ev::start}), ev[k].push_back({b[i].hi[k], id, Ev::end});
    }
  if constexpr (Probe::on) {
    std::size_t total = 0;
    for (int k = 0; k < D; ++k) total += ev[k].size();
    probe.step(L::events, StepKind::init).idx("events", static_cast<std::int64_t>(total));
  }
  auto before = [](const Ev& x, const Ev& y) {
    if (x.pos < y.pos) return true;
    if (y.pos < x.pos) return false;
    return x.type != y.type ? x.type < y.type : x.prim < y.prim;
  };
  for (int k = 0; k < D; ++k) std::sort(ev[k].begin(), ev[k].end(), before);
  if constexpr (Probe::on) probe.step(L::sort, StepKind::init);
  Box<Num, D> all = b[0];
  for (const auto& x : b) all.grow(x);
  tree.nodes.push_back({all, -1, -1, -1, 0, -1, true, Num(0), {}});
  if constexpr (Probe::on) {
    probe.step(L::root, StepKind::init).idx("node", 0).node(0, -1, all.lo, all.hi).keep();
    if (points)
      for (const auto& x : b) probe.point(x.lo).keep();
  }
  struct Pending {
    std::int32_t node;
    std::size_t count;
    List ev;
  };
  std::vector<Pending> pending;
  pending.push_back({0, n, std::move(ev)});
  std::vector<std::uint8_t> side(n, 0);  // 1 left, 2 right, 3 both
  // Bounded: every node is taken once, and there are at most max_nodes.
  while (!pending.empty()) {
    Pending cur = std::move(pending.back());
    pending.pop_back();
    const std::int32_t id = cur.node;
    const Box<Num, D> cell = tree.nodes[id].cell;
    const int depth = tree.nodes[id].depth;
    const Num a = cell.half_area(), nn(static_cast<int>(cur.count));
    if constexpr (Probe::on)
      probe.step(L::pop, StepKind::visit)
          .idx("node", id)
          .idx("n", static_cast<std::int64_t>(cur.count))
          .idx("depth", depth)
          .num("A", a)
          .node(id, tree.nodes[id].parent, cell.lo, cell.hi);
    bool found = false, flat_left = true;
    int axis = 0;
    Num best{}, pos{};
    std::size_t best_l = 0, best_r = 0;
    for (int k = 0; k < D; ++k) {
      const std::vector<Ev>& e = cur.ev[k];
      bool found_k = false;
      Num best_k{}, pos_k{};
      std::size_t nl_k = 0, nr_k = 0;
      std::size_t below = 0, above = cur.count;  // N_L and N_R before the position p
      for (std::size_t i = 0; i < e.size();) {   // bounded: i grows at each position
        const Num p = e[i].pos;
        std::size_t ends = 0, flats = 0, starts = 0;
        for (; i < e.size() && e[i].pos == p; ++i) (e[i].type == Ev::end ? ends : e[i].type == Ev::flat ? flats : starts)++;
        tree.events_touched += ends + flats + starts;
        if (cell.lo[k] < p && p < cell.hi[k]) {  // a plane on the cell's boundary cuts nothing off a closed cell
          const Num al = kd_cut(cell, k, p, true).half_area(), ar = kd_cut(cell, k, p, false).half_area();
          const int s_first = points ? 0 : 2, s_end = points ? (flats ? 2 : 1) : 3;
          for (int s = s_first; s < s_end; ++s) {  // the flat ones at p: left, right (points) or both
            const std::size_t nl = below + starts + (s != 1 ? flats : 0), nr = above - (s == 0 ? flats : 0);
            // With N_L = N_R the cost is K_T A + K_I N_L (A_L + A_R), and A_L + A_R = A + the
            // face's measure whatever p is: equal to the kept one with the same counts, so not
            // less. (Skipping it spares filtered mode an undecidable tie; the first stays kept.)
            if (found_k && nl == nr && nl == nl_k && nr == nr_k) continue;
            const Num lam = nl == 0 || nr == 0 ? lam_empty : lam_full;
            const Num c = lam * (kt * a + ki * (al * Num(static_cast<int>(nl)) + ar * Num(static_cast<int>(nr))));
            if (!found_k || c < best_k) found_k = true, best_k = c, pos_k = p, nl_k = nl, nr_k = nr;
            if (!found || c < best) found = true, best = c, axis = k, pos = p, best_l = nl, best_r = nr, flat_left = s != 1;
          }
        }
        below += starts + flats;
        above -= ends + flats;
      }
      if constexpr (Probe::on) {
        auto& s = probe.step(L::best, StepKind::decide).idx("axis", k).idx("found", found_k);
        if (found_k) {
          s.num("p", pos_k)
              .num("cost", best_k)
              .idx("n_left", static_cast<std::int64_t>(nl_k))
              .idx("n_right", static_cast<std::int64_t>(nr_k));
          const Box<Num, D> face = kd_cut(kd_cut(cell, k, pos_k, true), k, pos_k, false);
          if constexpr (D == 2) s.segment(face.lo, face.hi).label("cost").value(best_k);
          else s.box(face.lo, face.hi).label("cost").value(best_k);
        }
      }
    }
    const Num leaf_cost = lam_full * (ki * (nn * a));
    const bool leaf = !found || !(best < leaf_cost) || depth >= max_depth || cur.count <= 1 || tree.nodes.size() + 2 > max_nodes;
    if (leaf) {
      auto& node = tree.nodes[id];
      for (const Ev& x : cur.ev[0])
        if (x.type != Ev::end) node.prims.push_back(x.prim);
      std::sort(node.prims.begin(), node.prims.end());
      ++tree.leaves, tree.refs += node.prims.size();
      tree.depth = std::max(tree.depth, static_cast<std::size_t>(depth));
      if constexpr (Probe::on)
        probe.step(L::leaf, StepKind::advance)
            .idx("node", id)
            .idx("n", static_cast<std::int64_t>(cur.count))
            .num("leaf_cost", leaf_cost)
            .idx("found", found)
            .node(id, node.parent, cell.lo, cell.hi)
            .keep();
      continue;
    }
    for (const Ev& x : cur.ev[axis]) {
      if (x.type == Ev::end) continue;
      const Box<Num, D>& bx = b[x.prim];
      if (x.type == Ev::flat && bx.lo[axis] == pos) side[x.prim] = points ? (flat_left ? 1 : 2) : 3;
      else side[x.prim] = (bx.lo[axis] <= pos ? 1 : 0) | (pos <= bx.hi[axis] ? 2 : 0);
    }
    if constexpr (Probe::on)
      probe.step(L::classify, StepKind::decide)
          .idx("axis", axis)
          .num("p", pos)
          .num("cost", best)
          .num("leaf_cost", leaf_cost)
          .idx("n_left", static_cast<std::int64_t>(best_l))
          .idx("n_right", static_cast<std::int64_t>(best_r))
          .idx("flat_left", flat_left);
    List lo, hi;
    for (int k = 0; k < D; ++k) {
      for (const Ev& x : cur.ev[k]) {
        if (side[x.prim] & 1) lo[k].push_back(x);
        if (side[x.prim] & 2) hi[k].push_back(x);
      }
      tree.events_touched += cur.ev[k].size();
      cur.ev[k] = {};
    }
    if constexpr (Probe::on)
      probe.step(L::split, StepKind::advance)
          .idx("events_left", static_cast<std::int64_t>(lo[0].size()))
          .idx("events_right", static_cast<std::int64_t>(hi[0].size()));
    const auto l = static_cast<std::int32_t>(tree.nodes.size()), r = l + 1;
    tree.nodes[id].left = l, tree.nodes[id].right = r, tree.nodes[id].axis = static_cast<std::int8_t>(axis);
    tree.nodes[id].split = pos, tree.nodes[id].flat_left = flat_left;
    const Box<Num, D> lc = kd_cut(cell, axis, pos, true), rc = kd_cut(cell, axis, pos, false);
    tree.nodes.push_back({lc, id, -1, -1, depth + 1, -1, true, Num(0), {}});
    tree.nodes.push_back({rc, id, -1, -1, depth + 1, -1, true, Num(0), {}});
    if constexpr (Probe::on)
      probe.step(L::children, StepKind::advance)
          .idx("left", l)
          .idx("right", r)
          .node(l, id, lc.lo, lc.hi)
          .keep()
          .node(r, id, rc.lo, rc.hi)
          .keep();
    pending.push_back({r, best_r, std::move(hi)});
    pending.push_back({l, best_l, std::move(lo)});
  }
  if constexpr (Probe::on)
    probe.step(L::done, StepKind::done)
        .idx("nodes", static_cast<std::int64_t>(tree.nodes.size()))
        .idx("leaves", static_cast<std::int64_t>(tree.leaves))
        .idx("depth", static_cast<std::int64_t>(tree.depth));
  return tree;
}

}  // namespace sw::spatial
