// The model of bsp-build's steps, written from the semantics (docs/spatial/bsp.md): orientations
// E(p, q, r), the cost 3 splits + |front - back| from its definition, cuts as line-line crossings
// by Cramer's rule, boxes as minima and maxima. Fed one step at a time: the build's own trace, or
// the painter's nested one (test_bsp_steps.cpp).
#pragma once
#include <catch2/catch.hpp>
#include <deque>
#include "spatial/bsp_build.hpp"
#include "spatial/bsp_run.hpp"
#include "step_values.hpp"

namespace sw::testing::bsp_model {

using namespace sw::testing;

using V = Vec2<Rational>;
inline Rational E(const V& p, const V& q, const V& r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); }
// Where the lines p0 p1 and q0 q1 cross (not parallel), by Cramer's rule.
inline V crossing(const V& p0, const V& p1, const V& q0, const V& q1) {
  const Rational a1 = p1.y - p0.y, b1 = p0.x - p1.x, c1 = a1 * p0.x + b1 * p0.y;
  const Rational a2 = q1.y - q0.y, b2 = q0.x - q1.x, c2 = a2 * q0.x + b2 * q0.y;
  const Rational det = a1 * b2 - a2 * b1;
  return {(c1 * b2 - c2 * b1) / det, (a1 * c2 - a2 * c1) / det};
}
inline void check_values(GeoItem& g, const std::vector<Rational>& want) { CHECK(g.values == want); }

struct Frag {
  std::int32_t seg;
  V a, b;
};
struct Node {
  std::int32_t parent = -1, depth = 0, splitter = -1, front = -1, back = -1;
  std::vector<std::int32_t> list, frags;  // the fragments it received; those on its line
  V lo, hi;
};

// The build's model, fed one step at a time (the build's own trace, or the painter's nested one).
struct BuildModel {
  std::vector<V> p, q;  // the segments' ends
  std::vector<Frag> frags;
  std::vector<Node> nodes;
  std::vector<std::int32_t> pending;  // nodes to take, the next on top
  std::deque<std::int32_t> children;  // children the current node's child steps announce
  std::int32_t cur = -1;
  std::size_t k = 0, kmax = 0, best = 0, classified = 0, splits = 0;
  std::int64_t best_cost = -1;
  std::int32_t line_seg = -1;
  std::vector<std::int32_t> front, back;

  explicit BuildModel(const std::vector<bsp::Seg>& segs) {
    for (std::size_t i = 0; i < segs.size(); ++i) {
      p.push_back({num::to_rational(segs[i][0]), num::to_rational(segs[i][1])});
      q.push_back({num::to_rational(segs[i][2]), num::to_rational(segs[i][3])});
      frags.push_back({static_cast<std::int32_t>(i), p.back(), q.back()});
    }
  }
  Node make_node(std::int32_t parent, std::int32_t depth, std::vector<std::int32_t> list) const {
    const V first = frags[list[0]].a;
    Node n{parent, depth, -1, -1, -1, std::move(list), {}, first, first};
    // Minima and maxima as the build picks them, by comparing doubles (the first of equals kept).
    for (std::int32_t f : n.list)
      for (const V& v : {frags[f].a, frags[f].b})
        for (int k = 0; k < 2; ++k) {
          if (v[k].get_d() < n.lo[k].get_d()) n.lo[k] = v[k];
          if (n.hi[k].get_d() < v[k].get_d()) n.hi[k] = v[k];
        }
    return n;
  }
  // The line of segment s across the root's box, on the slab of the axis it moves most along.
  std::array<V, 2> across(std::int32_t s) const {
    const V d = q[s] - p[s];
    const int k = std::abs(d.x.get_d()) >= std::abs(d.y.get_d()) ? 0 : 1;
    const Rational t0 = (nodes[0].lo[k] - p[s][k]) / d[k], t1 = (nodes[0].hi[k] - p[s][k]) / d[k];
    return {p[s] + t0 * d, p[s] + t1 * d};
  }
  void check_node(GeoItem& g, std::int32_t id) {
    const Node& n = nodes[id];
    check_values(g, {id, n.parent, n.lo.x, n.lo.y, n.hi.x, n.hi.y});
  }
  static std::int64_t cost_of(std::int64_t splits, std::int64_t f, std::int64_t b) { return 3 * splits + (f > b ? f - b : b - f); }

  void step(std::string_view line, StepValues& sv, StepGeometry& g) {
    if (line == "root") {
      std::vector<std::int32_t> all;
      for (std::size_t i = 0; i < frags.size(); ++i) all.push_back(static_cast<std::int32_t>(i));
      nodes.push_back(make_node(-1, 0, all));
      pending.push_back(0);
      CHECK(sv["node"] == 0);
      CHECK(sv["m"] == Rational(static_cast<long>(all.size())));
      GeoItem& n = g.take(GeoKind::node2);
      check_node(n, 0);
      CHECK(n.life == "keep");
      for (std::size_t i = 0; i < p.size(); ++i) {
        GeoItem& s = g.take(GeoKind::segment2);
        check_segment(s, p[i], q[i]);
        CHECK(s.label == "seg");
        CHECK(s.value == Rational(static_cast<long>(i)));
        CHECK(s.life == "keep");
      }
    } else if (line == "take") {
      REQUIRE(children.empty());
      REQUIRE(!pending.empty());
      cur = pending.back();
      pending.pop_back();
      const std::size_t m = nodes[cur].list.size();
      k = 0, kmax = std::min<std::size_t>(m, 8), best = 0, best_cost = -1, classified = 0;
      front.clear(), back.clear();
      CHECK(sv["node"] == cur);
      CHECK(sv["m"] == Rational(static_cast<long>(m)));
      GeoItem& n = g.take(GeoKind::node2);
      check_node(n, cur);
      CHECK(n.life.empty());
    } else if (line == "choose") {
      const auto& list = nodes[cur].list;
      REQUIRE(k < kmax);
      const std::size_t pos = k * list.size() / kmax;
      const Frag& c = frags[list[pos]];
      std::int64_t s = 0, f = 0, b = 0;
      for (std::int32_t i : list) {
        const Rational sa = E(p[c.seg], q[c.seg], frags[i].a), sb = E(p[c.seg], q[c.seg], frags[i].b);
        if ((sa == 0 && sb == 0) || frags[i].seg == c.seg) continue;
        if (sa >= 0 && sb >= 0) ++f;
        else if (sa <= 0 && sb <= 0) ++b;
        else ++s, ++f, ++b;
      }
      const std::int64_t cost = cost_of(s, f, b);
      if (best_cost < 0 || cost < best_cost) best = pos, best_cost = cost;
      CHECK(sv["cand"] == list[pos]);
      CHECK(sv["seg"] == c.seg);
      CHECK(sv["splits"] == Rational(s));
      CHECK(sv["front"] == Rational(f));
      CHECK(sv["back"] == Rational(b));
      CHECK(sv["cost"] == Rational(cost));
      CHECK(sv["best"] == list[best]);
      GeoItem& seg = g.take(GeoKind::segment2);
      check_segment(seg, c.a, c.b);
      CHECK(seg.label == "candidate");
      CHECK(seg.value == Rational(cost));
      ++k;
    } else if (line == "splitter") {
      CHECK(k == kmax);
      line_seg = frags[nodes[cur].list[best]].seg;
      nodes[cur].splitter = line_seg;
      CHECK(sv["node"] == cur);
      CHECK(sv["seg"] == line_seg);
      GeoItem& s = g.take(GeoKind::segment2);
      const auto ends = across(line_seg);
      check_segment(s, ends[0], ends[1]);
      CHECK(s.label == "splitter");
      CHECK(s.life == "keep");
    } else if (line == "on_line" || line == "front" || line == "back" || line == "split") {
      const auto& list = nodes[cur].list;
      REQUIRE(classified < list.size());
      const std::int32_t f = list[classified++];
      const Frag ab = frags[f];
      const Rational sa = E(p[line_seg], q[line_seg], ab.a), sb = E(p[line_seg], q[line_seg], ab.b);
      if (ab.seg == line_seg) CHECK((sa == 0 && sb == 0));  // a piece of the splitter's segment is on its line
      const char* want = (sa == 0 && sb == 0) || ab.seg == line_seg ? "on_line" : sa >= 0 && sb >= 0 ? "front" : sa <= 0 && sb <= 0 ? "back" : "split";
      CHECK(line == want);
      CHECK(sv["frag"] == f);
      CHECK(sv["seg"] == ab.seg);
      CHECK(sv["s_a"] == sa);
      CHECK(sv["s_b"] == sb);
      GeoItem& pa = g.take(GeoKind::point2);
      check_point(pa, ab.a);
      CHECK(pa.value == sa);
      GeoItem& pb = g.take(GeoKind::point2);
      check_point(pb, ab.b);
      CHECK(pb.value == sb);
      if (line == "split") {
        const V x = crossing(p[line_seg], q[line_seg], p[ab.seg], q[ab.seg]);
        const auto g_id = static_cast<std::int32_t>(frags.size());
        CHECK(sv["new"] == g_id);
        CHECK((sv["x.x"] == x.x && sv["x.y"] == x.y));
        GeoItem& s1 = g.take(GeoKind::segment2);
        check_segment(s1, ab.a, x);
        CHECK(s1.value == sa);
        GeoItem& s2 = g.take(GeoKind::segment2);
        check_segment(s2, x, ab.b);
        CHECK(s2.value == sb);
        GeoItem& px = g.take(GeoKind::point2);
        check_point(px, x);
        CHECK(px.label == "x");
        frags.push_back({ab.seg, x, ab.b});
        frags[f].b = x;
        (sa < 0 ? back : front).push_back(f);
        (sa < 0 ? front : back).push_back(g_id);
        ++splits;
      } else {
        GeoItem& s = g.take(GeoKind::segment2);
        check_segment(s, ab.a, ab.b);
        CHECK(s.value == sa + sb);
        (line == "on_line" ? nodes[cur].frags : line == "front" ? front : back).push_back(f);
      }
      if (classified == list.size()) {  // the children, as the next steps must announce them
        const std::int32_t depth = nodes[cur].depth + 1;
        for (auto* part : {&front, &back}) {
          if (part->empty()) continue;
          const auto c = static_cast<std::int32_t>(nodes.size());
          nodes.push_back(make_node(cur, depth, *part));
          (part == &front ? nodes[cur].front : nodes[cur].back) = c;
          children.push_back(c);
        }
        if (nodes[cur].back >= 0) pending.push_back(nodes[cur].back);
        if (nodes[cur].front >= 0) pending.push_back(nodes[cur].front);
      }
    } else if (line == "child") {
      REQUIRE(!children.empty());
      const std::int32_t c = children.front();
      children.pop_front();
      CHECK(sv["node"] == c);
      CHECK(sv["parent"] == cur);
      CHECK(sv["side"] == (nodes[cur].front == c ? 1 : -1));
      CHECK(sv["m"] == Rational(static_cast<long>(nodes[c].list.size())));
      GeoItem& n = g.take(GeoKind::node2);
      check_node(n, c);
      CHECK(n.life == "keep");
    } else if (line == "done") {
      CHECK((pending.empty() && children.empty()));
      std::int64_t depth = 0, leaves = 0;
      for (const Node& n : nodes) depth = std::max<std::int64_t>(depth, n.depth), leaves += n.front < 0 && n.back < 0;
      CHECK(sv["nodes"] == Rational(static_cast<long>(nodes.size())));
      CHECK(sv["fragments"] == Rational(static_cast<long>(frags.size())));
      CHECK(sv["splits"] == Rational(static_cast<long>(splits)));
      CHECK(sv["depth"] == Rational(depth));
      CHECK(sv["leaves"] == Rational(leaves));
    } else {
      FAIL("a step on an unexpected line " << line);
    }
  }
};

inline std::vector<spatial::Segment2<Rational>> exact_segments(const std::vector<bsp::Seg>& segs) {
  std::vector<spatial::Segment2<Rational>> out;
  for (const auto& s : segs) out.push_back({{num::to_rational(s[0]), num::to_rational(s[1])}, {num::to_rational(s[2]), num::to_rational(s[3])}});
  return out;
}

}  // namespace sw::testing::bsp_model
