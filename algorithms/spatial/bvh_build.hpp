// Bounding volume hierarchy over triangles by the binned surface area heuristic (Wald 2007, "On
// fast construction of SAH-based bounding volume hierarchies"): per node, the triangles' centroids
// fall into 16 equal bins of the centroid box on each axis, and the split between two bins with
// the least A(left) n(left) + A(right) n(right) wins. Node boxes are the exact union of their
// triangles' vertex boxes (min and max only, no rounding), so a box bounds its triangles in every
// number type. Bounded: at most 8 triangles per leaf and depth <= kBvhMaxDepth (past depth 48 the
// split is the median, so 10^4 identical triangles stop too). Semantics: docs/spatial/bvh.md.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "spatial/bounds.hpp"

namespace sw::spatial {

inline constexpr int kBvhBins = 16;
inline constexpr std::int32_t kBvhMaxLeaf = 8;  // a node of more triangles is always split
inline constexpr int kBvhSahDepth = 48;         // from this depth on, median splits (log depth)
// The SAH's cost of visiting an inner node, against 1 per triangle tested: a visit runs two slab
// tests, each about as costly as one watertight triangle test.
inline constexpr int kBvhTraversalCost = 2;
inline constexpr int kBvhMaxDepth = kBvhSahDepth + 22;  // 2^21 triangles halve to 8 in 18 levels

template <class Num> struct BvhNode {
  Box<Num, 3> box;
  std::int32_t parent = -1, left = -1, right = -1;  // children; -1 for a leaf
  std::int32_t first = 0, count = 0;                // the triangles order[first, first + count)
  std::int32_t depth = 0;
  std::int8_t axis = -1;  // the split axis; -1 for a leaf
};

template <class Num> struct Bvh {
  std::vector<BvhNode<Num>> nodes;  // node 0 is the root; children are created in pairs
  std::vector<std::int32_t> order;  // triangle ids; every node's triangles are one run
  std::size_t leaves = 0, depth = 0;
};

struct BvhBuild {
  static constexpr std::string_view id = "bvh-build";
  static constexpr std::string_view summary =
      "BVH over triangles by binned SAH (16 bins per axis), exact node boxes, median split past depth 48";
#define SW_LINES_BVH_BUILD(X) \
  X(bounds, "for each triangle i: B_i <- the box of its vertices; c_i <- lo + hi   -- twice the centroid, no division") \
  X(root, "root <- all triangles, its box the union of the B_i; push root") \
  X(pop, "while the stack is not empty: pop a node (n triangles, box B, centroid box C)") \
  X(one, "    if n = 1: leaf") \
  X(bins, "    for each axis k with C_lo,k < C_hi,k: c_i goes to bin floor((c_ik - C_lo,k) 16 / (C_hi,k - C_lo,k)), at most 15") \
  X(sweep, "        for each split s between bins: cost <- A(left) n(left) + A(right) n(right), both sides non-empty") \
  X(decide, "    best <- the least cost (ties: lowest axis, then lowest s); leaf if n <= 8 and n A(B) <= 2 A(B) + best") \
  X(median, \
    "    if no split was found, or depth >= 48: split at the median of (c_ik, i) on C's longest axis k (leaf if n <= 8 at " \
    "depth >= 48)") \
  X(leaf, "    leaf: keep its triangles") \
  X(split, "    else: left, right <- the two sides, each boxed exactly; push right, then left") \
  X(done, "done: nodes, leaves, depth")
  SW_LISTING("BVH build (binned SAH)", SW_LINES_BVH_BUILD)
#undef SW_LINES_BVH_BUILD
};

namespace bvh_detail {
// A triangle as the build moves it: its box, its doubled centroid and its id.
template <class Num> struct Prim {
  Box<Num, 3> box;
  Vec3<Num> c;
  std::int32_t id;
};
// The union of the boxes of prim[first, first + count).
template <class Num> Box<Num, 3> union_of(const std::vector<Prim<Num>>& prim, std::int32_t first, std::int32_t count) {
  Box<Num, 3> b = prim[first].box;
  for (std::int32_t j = first + 1; j < first + count; ++j) b.grow(prim[j].box);
  return b;
}
// The bin of centroid coordinate c >= lo, given scale = 16 / (hi - lo), clamped to the last bin.
// The test also catches a rounded scale that overflowed (inf, and 0 * inf = NaN) for tiny hi - lo.
template <class Num> int bin_of(const Num& c, const Num& lo, const Num& scale) {
  const Num x = (c - lo) * scale;
  if (!(x < Num(kBvhBins))) return kBvhBins - 1;
  return static_cast<int>(num::floor_int(x));
}
}  // namespace bvh_detail

// Precondition: 1 <= tris.size() <= 2^21 (validated by the Spec).
// The triangles' boxes and centroids are kept in node order and move with the ids when a node is
// split, so every pass over a node reads memory in sequence (not through the ids, which scatter).
template <NumberType Num, StepProbe Probe = NoProbe>
Bvh<Num> bvh_build(const std::vector<std::array<Vec3<Num>, 3>>& tris, Probe& probe) {
  using L = BvhBuild;
  using B3 = Box<Num, 3>;
  using bvh_detail::Prim;
  const auto n_tris = static_cast<std::int32_t>(tris.size());
  std::vector<Prim<Num>> prim, scratch(tris.size());
  prim.reserve(tris.size());
  for (std::int32_t i = 0; i < n_tris; ++i) {
    const B3 b = triangle_bounds(tris[i]);
    prim.push_back({b, b.lo + b.hi, i});
  }
  if constexpr (Probe::on) {
    auto& s = probe.step(L::bounds, StepKind::init).idx("triangles", n_tris);
    for (const auto& t : tris) s.triangle(t[0], t[1], t[2]).keep();
  }
  Bvh<Num> out;
  out.nodes.reserve(2 * tris.size());
  out.nodes.push_back({bvh_detail::union_of(prim, 0, n_tris), -1, -1, -1, 0, n_tris, 0, -1});
  if constexpr (Probe::on)
    probe.step(L::root, StepKind::init).idx("node", 0).node(0, -1, out.nodes[0].box.lo, out.nodes[0].box.hi).keep();
  std::vector<std::int32_t> stack{0};
  std::vector<std::uint8_t> bins(3 * tris.size());  // each position's bin on each axis, at its latest node
  // Per node, reused (not cleared: a bin's box is set by its first triangle, right_area[s] only
  // read where right_n[s] > 0).
  std::array<std::array<B3, kBvhBins>, 3> bin;
  std::array<Num, kBvhBins> right_area;
  std::array<std::int32_t, kBvhBins> right_n;
  // Bounded: every node is pushed once, and a split makes two non-empty sides, so at most 2n - 1 nodes.
  while (!stack.empty()) {
    const std::int32_t id = stack.back();
    stack.pop_back();
    const BvhNode<Num> nd = out.nodes[id];
    const std::int32_t n = nd.count, first = nd.first;
    B3 c = B3::at(prim[first].c);
    for (std::int32_t j = first + 1; j < first + n; ++j) c.grow(prim[j].c);
    if constexpr (Probe::on)
      probe.step(L::pop, StepKind::visit)
          .idx("node", id)
          .idx("n", n)
          .idx("depth", nd.depth)
          .vec("C_lo", c.lo)
          .vec("C_hi", c.hi)
          .node(id, nd.parent, nd.box.lo, nd.box.hi);
    out.depth = std::max<std::size_t>(out.depth, static_cast<std::size_t>(nd.depth));
    auto leaf = [&] {
      ++out.leaves;
      if constexpr (Probe::on) {
        std::vector<std::int64_t> prims;
        for (std::int32_t j = first; j < first + n; ++j) prims.push_back(prim[j].id);
        probe.step(L::leaf, StepKind::visit).idx("node", id).ilist("prims", prims);
      }
    };
    if (n == 1) {
      if constexpr (Probe::on) probe.step(L::one, StepKind::decide).idx("node", id);
      leaf();
      continue;
    }
    // The binned SAH: the least-cost split over the axes where the centroids spread. One pass
    // bins the node's triangles on all three axes.
    int best_axis = -1, best_split = 0;
    std::int32_t best_left = 0;  // the triangles left of the best split
    Num best_cost{};
    std::array<std::array<std::int32_t, kBvhBins>, 3> count{};
    if (nd.depth < kBvhSahDepth) {
      std::array<Num, 3> scale{};
      std::array<bool, 3> spread{};
      for (int k = 0; k < 3; ++k)
        if ((spread[k] = c.lo[k] < c.hi[k])) scale[k] = Num(kBvhBins) / (c.hi[k] - c.lo[k]);
      for (std::int32_t j = first; j < first + n; ++j)
        for (int k = 0; k < 3; ++k) {
          if (!spread[k]) continue;
          const int b = bvh_detail::bin_of(prim[j].c[k], c.lo[k], scale[k]);
          bins[3 * j + k] = static_cast<std::uint8_t>(b);
          if (count[k][b]++ == 0) bin[k][b] = prim[j].box;
          else bin[k][b].grow(prim[j].box);
        }
      for (int k = 0; k < 3; ++k) {
        if (!spread[k]) continue;
        if constexpr (Probe::on) {
          std::vector<std::int64_t> counts(count[k].begin(), count[k].end());
          auto& s = probe.step(L::bins, StepKind::advance).idx("axis", k).ilist("counts", counts);
          for (int b = 0; b < kBvhBins; ++b)
            if (count[k][b] > 0) s.box(bin[k][b].lo, bin[k][b].hi).label("bin");
        }
        // Right-to-left areas first, then the left-to-right sweep.
        B3 acc{};
        std::int32_t m = 0;
        for (int b = kBvhBins - 1; b > 0; --b) {
          if (count[k][b] > 0) {
            if (m == 0) acc = bin[k][b];
            else acc.grow(bin[k][b]);
            m += count[k][b];
          }
          right_n[b] = m;
          if (m > 0) right_area[b] = acc.half_area();
        }
        m = 0;
        int axis_split = 0;
        std::int32_t axis_left = 0;
        Num axis_cost{};
        for (int s = 1; s < kBvhBins; ++s) {
          if (count[k][s - 1] > 0) {
            if (m == 0) acc = bin[k][s - 1];
            else acc.grow(bin[k][s - 1]);
            m += count[k][s - 1];
          }
          if (m == 0 || right_n[s] == 0) continue;
          const Num cost = acc.half_area() * Num(m) + right_area[s] * Num(right_n[s]);
          if (axis_split == 0 || cost < axis_cost) axis_cost = cost, axis_split = s, axis_left = m;
        }
        if constexpr (Probe::on)
          probe.step(L::sweep, StepKind::advance).idx("axis", k).idx("s", axis_split).num("cost", axis_cost);
        if (axis_split > 0 && (best_axis < 0 || axis_cost < best_cost))
          best_axis = k, best_split = axis_split, best_cost = axis_cost, best_left = axis_left;
      }
    }
    const Num area = nd.box.half_area();
    std::int32_t left_n = 0;  // the left child's triangles
    B3 left_box, right_box;
    if (best_axis >= 0) {
      const Num leaf_cost = Num(n) * area, split_cost = Num(kBvhTraversalCost) * area + best_cost;
      const bool make_leaf = n <= kBvhMaxLeaf && !(split_cost < leaf_cost);
      if constexpr (Probe::on)
        probe.step(L::decide, StepKind::decide)
            .idx("axis", best_axis)
            .idx("s", best_split)
            .num("leaf_cost", leaf_cost)
            .num("split_cost", split_cost)
            .idx("leaf", make_leaf);
      if (make_leaf) {
        leaf();
        continue;
      }
      const int k = best_axis;
      // A stable partition: the left side's triangles, then the right side's, each in order.
      std::int32_t nl = first, nr = first + best_left;
      for (std::int32_t j = first; j < first + n; ++j) scratch[bins[3 * j + k] < best_split ? nl++ : nr++] = prim[j];
      std::copy(scratch.begin() + first, scratch.begin() + first + n, prim.begin() + first);
      out.nodes[id].axis = static_cast<std::int8_t>(k);
      left_n = best_left;
      // Each side's box is the union of its bins' boxes: the same exact min and max.
      auto bins_union = [&](int from, int to) {
        int b = from;
        while (count[k][b] == 0) ++b;  // a side is never empty
        B3 u = bin[k][b];
        for (++b; b < to; ++b)
          if (count[k][b] > 0) u.grow(bin[k][b]);
        return u;
      };
      left_box = bins_union(0, best_split), right_box = bins_union(best_split, kBvhBins);
    } else {
      // No spread left to bin, or past the SAH depth: the median of (c_ik, i); ranges stay in id
      // order (stable partitions), so a stable sort by c_ik sorts by (c_ik, i).
      const int k = c.longest_axis();
      const bool make_leaf = n <= kBvhMaxLeaf;
      if constexpr (Probe::on) probe.step(L::median, StepKind::decide).idx("axis", k).idx("leaf", make_leaf);
      if (make_leaf) {
        leaf();
        continue;
      }
      std::stable_sort(prim.begin() + first, prim.begin() + first + n,
                       [&](const Prim<Num>& a, const Prim<Num>& b) { return a.c[k] < b.c[k]; });
      out.nodes[id].axis = static_cast<std::int8_t>(k);
      left_n = n / 2;
      left_box = bvh_detail::union_of(prim, first, left_n), right_box = bvh_detail::union_of(prim, first + left_n, n - left_n);
    }
    const auto l = static_cast<std::int32_t>(out.nodes.size()), r = l + 1;
    out.nodes[id].left = l, out.nodes[id].right = r;
    out.nodes.push_back({left_box, id, -1, -1, first, left_n, nd.depth + 1, -1});
    out.nodes.push_back({right_box, id, -1, -1, first + left_n, n - left_n, nd.depth + 1, -1});
    if constexpr (Probe::on)
      probe.step(L::split, StepKind::advance)
          .idx("node", id)
          .idx("axis", out.nodes[id].axis)
          .idx("left", l)
          .idx("right", r)
          .idx("n_left", left_n)
          .idx("n_right", n - left_n)
          .node(l, id, out.nodes[l].box.lo, out.nodes[l].box.hi)
          .keep()
          .node(r, id, out.nodes[r].box.lo, out.nodes[r].box.hi)
          .keep();
    stack.push_back(r), stack.push_back(l);
  }
  out.order.reserve(tris.size());
  for (const auto& p : prim) out.order.push_back(p.id);
  if constexpr (Probe::on)
    probe.step(L::done, StepKind::done)
        .idx("nodes", static_cast<std::int64_t>(out.nodes.size()))
        .idx("leaves", static_cast<std::int64_t>(out.leaves))
        .idx("depth", static_cast<std::int64_t>(out.depth));
  return out;
}

}  // namespace sw::spatial
