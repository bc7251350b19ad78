// bvh-traverse's untraced fast path in double: the same walk (bvh_walk), its box tests served
// eight lanes at a time. Every inner node at even depth (the root's is 0) keeps the boxes of its
// two children and up to four grandchildren side by side, one array per axis and bound. Testing
// that node's children tests all six at once, with ray_box's own operations in vector arithmetic:
// the same subtractions, divisions (IEEE division is correctly rounded lane by lane), comparisons
// and selections, so every lane is ray_box's answer bit for bit. The grandchildren's answers wait
// in a slot for their depth until the walk tests their parent's children. So the walk, its order
// and its answer (hit, t, b, prim, and the counts of nodes and triangles) are bvh-traverse's; the
// speed comes from fewer, wider box tests. Not a listing: the adapter of docs/spatial/bvh.md.
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <vector>
#include "core/probe.hpp"
#include "rays/ray_box.hpp"
#include "spatial/bvh_build.hpp"
#include "spatial/bvh_traverse.hpp"

namespace sw::spatial {

namespace wide_detail {
using V8 = double __attribute__((vector_size(64)));
using M8 = std::int64_t __attribute__((vector_size(64)));  // comparison results: all ones or zero
// Vectors are passed by reference: returned by value they would change the ABI without AVX-512.
inline void splat(V8& v, double x) { v = V8{x, x, x, x, x, x, x, x}; }
}  // namespace wide_detail

// Lanes 0-1: the node's left and right child; 2-3: the left child's children; 4-5: the right
// child's; a lane with no node (a leaf child has none below it; 6-7) holds an empty box
// (lo = +inf, hi = -inf), which every ray misses.
struct BvhWideGroup {
  alignas(64) std::array<std::array<double, 8>, 3> lo, hi;
  std::array<std::int32_t, 6> node;  // the lanes' nodes (-1: none)
};

struct BvhWide {
  std::vector<std::int32_t> group_of;  // per node of the binary BVH: its group, or -1
  std::vector<BvhWideGroup> groups;
};

// The groups of b's inner nodes at even depth. Precondition: b built by bvh-build.
inline BvhWide bvh_widen(const Bvh<double>& b) {
  BvhWide w;
  w.group_of.assign(b.nodes.size(), -1);
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (std::size_t n = 0; n < b.nodes.size(); ++n) {  // bounded by the node count
    const BvhNode<double>& nd = b.nodes[n];
    if (nd.left < 0 || nd.depth % 2 != 0) continue;
    BvhWideGroup g;
    for (auto& a : g.lo) a.fill(inf);
    for (auto& a : g.hi) a.fill(-inf);
    g.node.fill(-1);
    auto put = [&](int lane, std::int32_t node) {
      for (int k = 0; k < 3; ++k) g.lo[k][lane] = b.nodes[node].box.lo[k], g.hi[k][lane] = b.nodes[node].box.hi[k];
      g.node[lane] = node;
    };
    const std::int32_t child[2] = {nd.left, nd.right};
    for (int c = 0; c < 2; ++c) {
      put(c, child[c]);
      const BvhNode<double>& cn = b.nodes[child[c]];
      if (cn.left >= 0) put(2 + 2 * c, cn.left), put(3 + 2 * c, cn.right);
    }
    w.group_of[n] = static_cast<std::int32_t>(w.groups.size());
    w.groups.push_back(g);
  }
  return w;
}

// bvh_walk's box tests from w's groups. Precondition: w = bvh_widen(bvh); r.d != 0.
class WideBoxes {
 public:
  WideBoxes(const Bvh<double>& bvh, const BvhWide& w, const ray::Ray3<double>& r) : bvh_(bvh), w_(w), r_(r) {
    for (int k = 0; k < 3; ++k) wide_detail::splat(o_[k], r.o[k]), wide_detail::splat(d_[k], r.d[k]), sign_[k] = num::sign(r.d[k]);
    owner_.fill(-1);
  }

  ray::BoxHit<double> test(std::int32_t node, NoProbe& none) const {
    return ray::ray_box<double>(r_, bvh_.nodes[node].box.lo, bvh_.nodes[node].box.hi, none);
  }

  std::array<ray::BoxHit<double>, 2> children(std::int32_t n, NoProbe& none) {
    const BvhNode<double>& nd = bvh_.nodes[n];
    const std::int32_t g = w_.group_of[static_cast<std::size_t>(n)];
    if (g >= 0) {
      Lanes l;
      const BvhWideGroup& group = w_.groups[static_cast<std::size_t>(g)];
      slab(group, l);
      // The walk reads the nodes it pops: fetch those it may pop while the tests are decided.
      for (int i = 0; i < 6; ++i)
        if (l.hit[i] != 0 && group.node[i] >= 0) __builtin_prefetch(&bvh_.nodes[static_cast<std::size_t>(group.node[i])]);
      Slot& s = slot_[static_cast<std::size_t>(nd.depth) + 1];
      owner_[static_cast<std::size_t>(nd.depth) + 1] = n;
      for (int i = 0; i < 4; ++i) s.hit[i] = l.hit[i + 2] != 0, s.tn[i] = l.tn[i + 2], s.tf[i] = l.tf[i + 2];
      return {lane(l.hit[0] != 0, l.tn[0], l.tf[0]), lane(l.hit[1] != 0, l.tn[1], l.tf[1])};
    }
    // Odd depth: tested with n's parent's children, unless (never, in a walk) the slot moved on.
    const auto depth = static_cast<std::size_t>(nd.depth);
    if (owner_[depth] == nd.parent) {
      const int i = bvh_.nodes[nd.parent].left == n ? 0 : 2;
      const Slot& s = slot_[depth];
      return {lane(s.hit[i], s.tn[i], s.tf[i]), lane(s.hit[i + 1], s.tn[i + 1], s.tf[i + 1])};
    }
    return {test(nd.left, none), test(nd.right, none)};
  }

 private:
  struct Lanes {
    wide_detail::V8 tn, tf;
    wide_detail::M8 hit;
  };
  struct Slot {  // the four grandchildren of the slot's owner
    bool hit[4];
    double tn[4], tf[4];
  };

  // ray_box on eight boxes: its steps in the same order, each lane its own box.
  void slab(const BvhWideGroup& g, Lanes& l) const {
    using wide_detail::V8;
    wide_detail::M8 out{};
    V8 tn{}, tf{};
    bool bounded = false;
    for (int k = 0; k < 3; ++k) {
      V8 lo, hi;
      __builtin_memcpy(&lo, g.lo[k].data(), sizeof lo);
      __builtin_memcpy(&hi, g.hi[k].data(), sizeof hi);
      if (sign_[k] == 0) {
        out |= (o_[k] < lo) | (o_[k] > hi);
        continue;
      }
      const V8 ta = (lo - o_[k]) / d_[k], tb = (hi - o_[k]) / d_[k];
      const V8 t1 = sign_[k] < 0 ? tb : ta, t2 = sign_[k] < 0 ? ta : tb;
      if (!bounded) {
        tn = t1, tf = t2, bounded = true;
      } else {
        tn = t1 > tn ? t1 : tn;
        tf = t2 < tf ? t2 : tf;
      }
    }
    // ray_box stops at a parallel axis that misses, its t's left at zero.
    const V8 zero{};
    const wide_detail::M8 missed_flat = out != 0;
    l.tn = missed_flat ? zero : tn, l.tf = missed_flat ? zero : tf;
    l.hit = ~out & ~(tn > tf) & (tf > zero);
  }

  // A lane as ray_box returns it.
  ray::BoxHit<double> lane(bool hit, double tn, double tf) const {
    ray::BoxHit<double> h;
    h.hit = hit;
    h.t_near = tn, h.t_far = tf;
    h.t = num::select(tn > 0.0, tn, tf);
    return h;
  }

  const Bvh<double>& bvh_;
  const BvhWide& w_;
  const ray::Ray3<double>& r_;
  wide_detail::V8 o_[3], d_[3];
  int sign_[3];
  std::array<std::int32_t, kBvhMaxDepth + 2> owner_;  // the node whose grandchildren a slot holds
  Slot slot_[kBvhMaxDepth + 2];                      // uninitialised: read only under its owner
};

// bvh_query's answer, bit for bit, with the wide box tests. Precondition: w = bvh_widen(bvh).
inline BvhHit<double> bvh_query(const BvhWide& w, const Bvh<double>& bvh, const std::vector<std::array<Vec3<double>, 3>>& tris,
                                const ray::Ray3<double>& r, const BvhQuery<double>& q) {
  WideBoxes boxes(bvh, w, r);
  NoProbe none;
  return bvh_walk<double>(bvh, tris, r, q, boxes, none);
}

}  // namespace sw::spatial
