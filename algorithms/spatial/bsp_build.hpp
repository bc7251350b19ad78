// A 2D BSP tree over segments by auto-partition: every node's splitter is the supporting line of
// one of the node's own fragments, chosen by a bounded cost; a fragment crossing it is cut at the
// crossing point, collinear fragments stay in the node. Semantics: docs/spatial/bsp.md.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"
#include "spatial/bounds.hpp"

namespace sw::spatial {

template <class Num> struct Segment2 {
  Vec2<Num> a, b;  // a != b (validated)
};

// A piece of input segment `seg`, from a to b in the segment's own direction. An end made by a cut
// names the segment whose line cut it (cut_a, cut_b), or -1 for the segment's own endpoint, so
// the end is exactly the crossing of the two lines whatever the mode computed.
template <class Num> struct BspFragment {
  std::int32_t seg = -1, cut_a = -1, cut_b = -1;
  Vec2<Num> a, b;
};

// A node: its splitter (an input segment's id: the node's line is that segment's line), the
// fragments on that line, and the children in front (left of the line's a -> b) and behind it,
// -1 for an empty side.
struct BspNode {
  std::int32_t parent = -1, splitter = -1, front = -1, back = -1, depth = 0;
  std::vector<std::int32_t> frags;
};

template <class Num> struct BspTree {
  std::vector<BspNode> nodes;           // node 0 is the root
  std::vector<BspFragment<Num>> frags;  // 0..n-1 start as the input segments
  std::vector<Box<Num, 2>> boxes;       // per node: the box of the fragments it received
  std::size_t depth = 0, splits = 0, leaves = 0;
  bool exhausted = false;  // a cut would pass the fragment budget: the build stopped
};

// Candidates per node: the cost of a candidate costs one pass over the node's fragments.
inline constexpr std::size_t kBspCandidates = 8;

// Twice the signed area of p, q, r: > 0 when r is left of p -> q (in front), < 0 right (behind).
template <class Num> Num orient2(const Vec2<Num>& p, const Vec2<Num>& q, const Vec2<Num>& r) {
  return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
}

enum class BspSide : std::int8_t { back = -1, on = 0, front = 1, split = 2 };
// Where a fragment with end orientations sa, sb goes. Touching the line counts as the other end's side.
template <class Num> BspSide bsp_side(const Num& sa, const Num& sb) {
  const Num zero(0);
  if (sa == zero && sb == zero) return BspSide::on;
  if (!(sa < zero) && !(sb < zero)) return BspSide::front;
  if (!(zero < sa) && !(zero < sb)) return BspSide::back;
  return BspSide::split;
}

struct BspCost {
  std::int64_t splits = 0, front = 0, back = 0, cost = 0;
};
// A candidate line's cost over a node's fragments: 3 splits + |front - back| (a cut piece counts on both sides).
template <class Num> BspCost bsp_cost(const std::vector<Segment2<Num>>& segs, std::int32_t seg,
                                      const std::vector<std::int32_t>& list, const std::vector<BspFragment<Num>>& frags) {
  BspCost c;
  const Segment2<Num>& line = segs[seg];
  for (std::int32_t f : list) {         // bounded: the node's fragments
    if (frags[f].seg == seg) continue;  // on the line
    const BspSide s = bsp_side(orient2(line.a, line.b, frags[f].a), orient2(line.a, line.b, frags[f].b));
    c.splits += s == BspSide::split;
    c.front += s == BspSide::front || s == BspSide::split;
    c.back += s == BspSide::back || s == BspSide::split;
  }
  c.cost = 3 * c.splits + (c.front > c.back ? c.front - c.back : c.back - c.front);
  return c;
}

// The box of the fragments, for views and the result. Its corners are picked by comparing in
// double (the first of equals kept): a box is no decision of the build, so a filter's interval is
// never asked about a cut point's coordinate that equals another exactly.
template <class Num> Box<Num, 2> bsp_box(const std::vector<std::int32_t>& list, const std::vector<BspFragment<Num>>& frags) {
  Box<Num, 2> b = Box<Num, 2>::at(frags[list[0]].a);
  std::array<double, 2> lo{num::to_double(b.lo.x), num::to_double(b.lo.y)}, hi = lo;
  for (std::int32_t f : list)
    for (const Vec2<Num>* p : {&frags[f].a, &frags[f].b})
      for (int k = 0; k < 2; ++k) {
        const double d = num::to_double((*p)[k]);
        if (d < lo[k]) lo[k] = d, b.lo[k] = (*p)[k];
        if (hi[k] < d) hi[k] = d, b.hi[k] = (*p)[k];
      }
  return b;
}

// The line through s across the box, for views: clipped to the box's slab on the axis along which
// s moves most (chosen in double: a view's choice, never a decision of the algorithm).
template <class Num> std::array<Vec2<Num>, 2> bsp_line_across(const Segment2<Num>& s, const Box<Num, 2>& box) {
  const Vec2<Num> d = s.b - s.a;
  const double dx = num::to_double(d.x), dy = num::to_double(d.y);
  const int k = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy) ? 0 : 1;
  if (dx == 0 && dy == 0) return {s.a, s.b};  // a float-rounded zero-length segment
  const Num t0 = (box.lo[k] - s.a[k]) / d[k], t1 = (box.hi[k] - s.a[k]) / d[k];
  return {s.a + t0 * d, s.a + t1 * d};
}

struct BspBuild {
  static constexpr std::string_view id = "bsp-build";
  static constexpr std::string_view summary =
      "2D BSP tree over segments by auto-partition: splitters by cost, crossing segments cut";
#define SW_LINES_BSP_BUILD(X) \
  X(root, "root <- a node holding every segment as a fragment") \
  X(loop, "while some node waits to be partitioned:               -- depth first, front child first") \
  X(take, "    take node N and its fragments F") \
  X(choose, "    cost(c) <- 3 splits + |front - back| for 8 candidates c spread over F; keep the cheapest (first on ties)") \
  X(splitter, "    N's line <- the line through the chosen fragment's segment") \
  X(classify, "    for each fragment ab of F: s_a, s_b <- orient(line, a), orient(line, b):") \
  X(on_line, "        s_a = s_b = 0 (a piece of the splitter's segment: 0 by construction): ab stays in N") \
  X(front, "        s_a >= 0 and s_b >= 0: ab goes in front") \
  X(back, "        s_a <= 0 and s_b <= 0: ab goes behind") \
  X(split, "        else: x <- a + s_a / (s_a - s_b) (b - a); ax to a's side, xb to b's side") \
  X(child, "    a child node for each non-empty side, front then back") \
  X(done, "done: the nodes, the fragments, the depth")
  SW_LISTING("BSP tree by auto-partition", SW_LINES_BSP_BUILD)
#undef SW_LINES_BSP_BUILD
};

// Precondition: 1 <= segs.size() <= max_fragments. In exact arithmetic the fragments number at most
// n + the pairs (i, j) whose line i crosses segment j, which the caller checks against the budget.
template <NumberType Num, StepProbe Probe = NoProbe>
BspTree<Num> bsp_build(const std::vector<Segment2<Num>>& segs, std::size_t max_fragments, Probe& probe) {
  using L = BspBuild;
  BspTree<Num> t;
  std::vector<std::int32_t> all;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    t.frags.push_back({static_cast<std::int32_t>(i), -1, -1, segs[i].a, segs[i].b});
    all.push_back(static_cast<std::int32_t>(i));
  }
  t.nodes.emplace_back();
  t.boxes.push_back(bsp_box(all, t.frags));
  const Box<Num, 2> view = t.boxes[0];
  if constexpr (Probe::on) {
    probe.step(L::root, StepKind::init)
        .idx("node", 0)
        .idx("m", static_cast<std::int64_t>(all.size()))
        .node(0, -1, view.lo, view.hi)
        .keep();
    for (std::size_t i = 0; i < segs.size(); ++i)
      probe.segment(segs[i].a, segs[i].b).label("seg").value(Num(static_cast<std::int64_t>(i))).keep();
  }
  std::vector<std::pair<std::int32_t, std::vector<std::int32_t>>> work;
  work.emplace_back(0, std::move(all));
  // Each pass takes one node, which keeps at least the chosen fragment (a piece of its splitter's
  // segment): passes <= fragments <= budget.
  while (!work.empty()) {
    const std::int32_t id = work.back().first;
    const std::vector<std::int32_t> list = std::move(work.back().second);
    work.pop_back();
    const std::size_t m = list.size(), k_max = std::min(m, kBspCandidates);
    if constexpr (Probe::on)
      probe.step(L::take, StepKind::visit)
          .idx("node", id)
          .idx("m", static_cast<std::int64_t>(m))
          .node(id, t.nodes[id].parent, t.boxes[id].lo, t.boxes[id].hi);
    std::size_t best = 0;
    std::int64_t best_cost = -1;
    for (std::size_t k = 0; k < k_max; ++k) {
      const std::size_t pos = k * m / k_max;
      const BspFragment<Num>& c = t.frags[list[pos]];
      const BspCost cost = bsp_cost(segs, c.seg, list, t.frags);
      if (best_cost < 0 || cost.cost < best_cost) best = pos, best_cost = cost.cost;
      if constexpr (Probe::on)
        probe.step(L::choose, StepKind::decide)
            .idx("cand", list[pos])
            .idx("seg", c.seg)
            .idx("splits", cost.splits)
            .idx("front", cost.front)
            .idx("back", cost.back)
            .idx("cost", cost.cost)
            .idx("best", list[best])
            .segment(c.a, c.b)
            .label("candidate")
            .value(Num(cost.cost));
    }
    const std::int32_t s = t.frags[list[best]].seg;
    const Segment2<Num>& line = segs[s];
    t.nodes[id].splitter = s;
    if constexpr (Probe::on) {
      const auto across = bsp_line_across(line, view);
      probe.step(L::splitter, StepKind::advance)
          .idx("node", id)
          .idx("seg", s)
          .segment(across[0], across[1])
          .label("splitter")
          .keep();
    }
    std::vector<std::int32_t> front, back;
    for (const std::int32_t f : list) {  // bounded: the node's fragments
      const BspFragment<Num> ab = t.frags[f];
      // A piece of the splitter's own segment is on its line by construction, in every mode (a
      // rounded cut end of it may not be), so that every node keeps at least its chosen fragment.
      const bool own = ab.seg == s;
      const Num sa = own ? Num(0) : orient2(line.a, line.b, ab.a), sb = own ? Num(0) : orient2(line.a, line.b, ab.b);
      const BspSide side = own ? BspSide::on : bsp_side(sa, sb);
      if (side != BspSide::split) {
        (side == BspSide::on ? t.nodes[id].frags : side == BspSide::front ? front : back).push_back(f);
        if constexpr (Probe::on) {
          const L::Line at = side == BspSide::on ? L::on_line : side == BspSide::front ? L::front : L::back;
          probe.step(at, StepKind::decide)
              .idx("frag", f)
              .idx("seg", ab.seg)
              .num("s_a", sa)
              .num("s_b", sb)
              .point(ab.a)
              .value(sa)
              .point(ab.b)
              .value(sb)
              .segment(ab.a, ab.b)
              .value(sa + sb);
        }
        continue;
      }
      if (t.frags.size() >= max_fragments) {  // only rounded modes get here (docs/spatial/bsp.md)
        t.exhausted = true;
        return t;
      }
      const Vec2<Num> x = ab.a + (sa / (sa - sb)) * (ab.b - ab.a);
      const auto g = static_cast<std::int32_t>(t.frags.size());
      t.frags.push_back({ab.seg, s, ab.cut_b, x, ab.b});
      t.frags[f].b = x, t.frags[f].cut_b = s;
      (sa < Num(0) ? back : front).push_back(f);
      (sa < Num(0) ? front : back).push_back(g);
      ++t.splits;
      if constexpr (Probe::on)
        probe.step(L::split, StepKind::advance)
            .idx("frag", f)
            .idx("seg", ab.seg)
            .num("s_a", sa)
            .num("s_b", sb)
            .idx("new", g)
            .vec("x", x)
            .point(ab.a)
            .value(sa)
            .point(ab.b)
            .value(sb)
            .segment(ab.a, x)
            .value(sa)
            .segment(x, ab.b)
            .value(sb)
            .point(x)
            .label("x");
    }
    const std::int32_t depth = t.nodes[id].depth + 1;
    for (int side : {1, -1}) {
      std::vector<std::int32_t>& part = side > 0 ? front : back;
      if (part.empty()) continue;
      const auto c = static_cast<std::int32_t>(t.nodes.size());
      t.nodes.emplace_back();
      t.nodes[c].parent = id, t.nodes[c].depth = depth;
      (side > 0 ? t.nodes[id].front : t.nodes[id].back) = c;
      t.boxes.push_back(bsp_box(part, t.frags));
      t.depth = std::max(t.depth, static_cast<std::size_t>(depth));
      if constexpr (Probe::on)
        probe.step(L::child, StepKind::init)
            .idx("node", c)
            .idx("parent", id)
            .idx("side", side)
            .idx("m", static_cast<std::int64_t>(part.size()))
            .node(c, id, t.boxes[c].lo, t.boxes[c].hi)
            .keep();
    }
    if (front.empty() && back.empty()) ++t.leaves;
    if (!back.empty()) work.emplace_back(t.nodes[id].back, std::move(back));
    if (!front.empty()) work.emplace_back(t.nodes[id].front, std::move(front));
  }
  if constexpr (Probe::on)
    probe.step(L::done, StepKind::done)
        .idx("nodes", static_cast<std::int64_t>(t.nodes.size()))
        .idx("fragments", static_cast<std::int64_t>(t.frags.size()))
        .idx("splits", static_cast<std::int64_t>(t.splits))
        .idx("depth", static_cast<std::int64_t>(t.depth))
        .idx("leaves", static_cast<std::int64_t>(t.leaves));
  return t;
}

}  // namespace sw::spatial
