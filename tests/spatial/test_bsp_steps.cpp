// bsp-build's and bsp-painter's exact steps replayed: every recorded value and geometry item of
// every step against a model written from the semantics (docs/spatial/bsp.md): orientations
// E(p, q, r), the cost 3 splits + |front - back| from its definition, cuts as line-line crossings
// by Cramer's rule, boxes as minima and maxima, and the painter's far-node-near rule.
#include <catch2/catch.hpp>
#include <deque>
#include "spatial/bsp_painter.hpp"
#include "spatial/bsp_run.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;

namespace {

using V = Vec2<Rational>;
Rational E(const V& p, const V& q, const V& r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); }
// Where the lines p0 p1 and q0 q1 cross (not parallel), by Cramer's rule.
V crossing(const V& p0, const V& p1, const V& q0, const V& q1) {
  const Rational a1 = p1.y - p0.y, b1 = p0.x - p1.x, c1 = a1 * p0.x + b1 * p0.y;
  const Rational a2 = q1.y - q0.y, b2 = q0.x - q1.x, c2 = a2 * q0.x + b2 * q0.y;
  const Rational det = a1 * b2 - a2 * b1;
  return {(c1 * b2 - c2 * b1) / det, (a1 * c2 - a2 * c1) / det};
}
void check_values(GeoItem& g, const std::vector<Rational>& want) { CHECK(g.values == want); }
void check_point(GeoItem& g, const V& p) { check_values(g, {p.x, p.y}); }
void check_segment(GeoItem& g, const V& a, const V& b) { check_values(g, {a.x, a.y, b.x, b.y}); }

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

std::vector<spatial::Segment2<Rational>> exact_segments(const std::vector<bsp::Seg>& segs) {
  std::vector<spatial::Segment2<Rational>> out;
  for (const auto& s : segs) out.push_back({{num::to_rational(s[0]), num::to_rational(s[1])}, {num::to_rational(s[2]), num::to_rational(s[3])}});
  return out;
}

template <class F> void for_each(const Recorder<Rational>& t, std::size_t s, F&& f) {
  StepValues sv = values_of(t, s);
  StepGeometry g = geometry_of(t, s);
  f(sv, g);
  require_all_checked(sv, s);
  require_all_geometry_checked(g, s);
}

void replay_build(const std::vector<bsp::Seg>& segs) {
  Recorder<Rational> t;
  const auto tree = spatial::bsp_build<Rational>(exact_segments(segs), 1 << 18, t);
  BuildModel model(segs);
  std::size_t done = 0;
  for (std::size_t s = 0; s < t.size(); ++s) {
    const std::string_view line = spatial::BspBuild::lines[t.at(s).line - 1].name;
    INFO("step " << s << " line " << line);
    CHECK(t.at(s).scope == 0);
    for_each(t, s, [&](StepValues& sv, StepGeometry& g) { model.step(line, sv, g); });
    done += line == "done";
  }
  CHECK(done == 1);
  CHECK(std::string_view(spatial::BspBuild::lines[t.at(t.size() - 1).line - 1].name) == "done");
  // The model's fragments are the build's, and the oracle finds they cover the segments.
  REQUIRE(model.frags.size() == tree.frags.size());
  std::vector<oracle::FragmentQ> fq;
  for (std::size_t f = 0; f < tree.frags.size(); ++f) {
    CHECK(model.frags[f].a == tree.frags[f].a);
    CHECK(model.frags[f].b == tree.frags[f].b);
    fq.push_back({tree.frags[f].seg, tree.frags[f].a, tree.frags[f].b});
  }
  CHECK(oracle::fragments_cover(bsp::segments_of(segs), fq).empty());
}

void replay_painter(const std::vector<bsp::Seg>& segs, const std::array<double, 2>& eye_d) {
  using L = spatial::BspPainter;
  const V eye{num::to_rational(eye_d[0]), num::to_rational(eye_d[1])};
  Recorder<Rational> t;
  const auto out = spatial::bsp_painter<Rational>(exact_segments(segs), eye, 1 << 18, t);
  BuildModel build(segs);
  std::vector<std::int32_t> stack;  // tasks: v >= 0 visit v, v < 0 draw -v - 1
  std::deque<std::int32_t> drawing;
  std::int32_t drawing_node = -1, pushed_near = -1, pushed_far = -1;
  std::vector<std::int32_t> order;
  for (std::size_t s = 0; s < t.size(); ++s) {
    const auto& st = t.at(s);
    if (st.scope != 0) {
      CHECK(t.scope_id(st.scope) == spatial::BspBuild::id);
      const std::string_view line = spatial::BspBuild::lines[st.line - 1].name;
      INFO("nested step " << s << " line " << line);
      for_each(t, s, [&](StepValues& sv, StepGeometry& g) { build.step(line, sv, g); });
      continue;
    }
    const std::string_view line = L::lines[st.line - 1].name;
    INFO("step " << s << " line " << line);
    for_each(t, s, [&](StepValues& sv, StepGeometry& g) {
      if (line == "build") {
        CHECK(s == 0);
        CHECK(sv["n"] == Rational(static_cast<long>(segs.size())));
        GeoItem& e = g.take(GeoKind::point2);
        check_point(e, eye);
        CHECK(e.label == "eye");
        CHECK(e.life == "keep");
        for (std::size_t i = 0; i < segs.size(); ++i) {  // the input, kept by the painter (the build's items end with it)
          GeoItem& sg = g.take(GeoKind::segment2);
          check_segment(sg, build.p[i], build.q[i]);
          CHECK(sg.label == "seg");
          CHECK(sg.value == Rational(static_cast<long>(i)));
          CHECK(sg.life == "keep");
        }
      } else if (line == "root") {
        stack.push_back(0);
        CHECK(sv["node"] == 0);
        CHECK(sv["stack"] == 1);
      } else if (line == "visit") {
        REQUIRE(drawing.empty());
        REQUIRE(!stack.empty());
        const std::int32_t id = stack.back();
        stack.pop_back();
        REQUIRE(id >= 0);
        const Node& n = build.nodes[id];
        const Rational side = E(build.p[n.splitter], build.q[n.splitter], eye);
        CHECK(sv["node"] == id);
        CHECK(sv["seg"] == n.splitter);
        CHECK(sv["s"] == side);
        CHECK(sv["in_front"] == (side >= 0 ? 1 : 0));
        build.check_node(g.take(GeoKind::node2), id);
        GeoItem& l = g.take(GeoKind::segment2);
        const auto ends = build.across(n.splitter);
        check_segment(l, ends[0], ends[1]);
        CHECK(l.label == "splitter");
        CHECK(l.value == side);
        const std::int32_t near = side >= 0 ? n.front : n.back, far = side >= 0 ? n.back : n.front;
        if (near >= 0) stack.push_back(near);
        stack.push_back(-id - 1);
        if (far >= 0) stack.push_back(far);
        pushed_near = near, pushed_far = far;
      } else if (line == "push") {
        CHECK((sv["near"] == pushed_near && sv["far"] == pushed_far));
        CHECK(sv["stack"] == Rational(static_cast<long>(stack.size())));
      } else if (line == "plot") {
        if (drawing.empty()) {
          REQUIRE(!stack.empty());
          REQUIRE(stack.back() < 0);
          drawing_node = -stack.back() - 1;
          stack.pop_back();
          drawing.assign(build.nodes[drawing_node].frags.begin(), build.nodes[drawing_node].frags.end());
          REQUIRE(!drawing.empty());
        }
        const std::int32_t f = drawing.front();
        drawing.pop_front();
        order.push_back(f);
        CHECK(sv["node"] == drawing_node);
        CHECK(sv["frag"] == f);
        CHECK(sv["seg"] == build.frags[f].seg);
        CHECK(sv["k"] == Rational(static_cast<long>(order.size()) - 1));
        GeoItem& seg = g.take(GeoKind::segment2);
        check_segment(seg, build.frags[f].a, build.frags[f].b);
        CHECK(seg.label == "k");
        CHECK(seg.value == Rational(static_cast<long>(order.size()) - 1));
        CHECK(seg.life == "keep");
      } else if (line == "done") {
        CHECK((stack.empty() && drawing.empty()));
        CHECK(sv["painted"] == Rational(static_cast<long>(order.size())));
      } else {
        FAIL("a step on an unexpected line");
      }
    });
  }
  CHECK(order == out.order);
  std::vector<oracle::FragmentQ> fq;
  for (const auto& f : out.tree.frags) fq.push_back({f.seg, f.a, f.b});
  const auto check = oracle::painter_order(eye, fq, out.order);
  INFO(check.first);
  CHECK(check.violations == 0);
}

std::vector<std::pair<std::vector<bsp::Seg>, std::array<double, 2>>> replay_inputs() {
  std::vector<std::pair<std::vector<bsp::Seg>, std::array<double, 2>>> out;
  const std::vector<bsp::Seg> example{{0, 0, 8, 8}, {8, 0, 0, 8}, {-2, 3, 10, 3}, {2, 10, 6, 10}, {10, 10, 12, 12}, {1, -3, 7, -3}};
  for (std::array<double, 2> eye : {std::array<double, 2>{3, -6}, {20, 10}, {-2, -2}, {4, 4}}) out.emplace_back(example, eye);
  out.emplace_back(std::vector<bsp::Seg>{{0, 0, 1, 1}, {2, 2, 3, 3}, {1, 1, 2, 2}, {3, 3, 0, 0}, {0.5, 0.5, 2.5, 2.5}, {0, 1, 3, 4}}, std::array<double, 2>{5, 0});
  out.emplace_back(std::vector<bsp::Seg>{{0, 0, 4, 0}, {4, 0, 4, 4}, {4, 4, 0, 4}, {0, 4, 0, 0}, {0, 0, 4, 4}, {4, 0, 0, 4}, {2, 0, 2, 4}, {2, 2, 6, 2}}, std::array<double, 2>{1, 3});
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> e(-40, 40);
  for (int k = 0; k < 16; ++k) {
    auto segs = bsp::random_segments(rng, 5 + static_cast<std::size_t>(k % 8), k % 3 != 0, 4);
    out.emplace_back(segs, std::array<double, 2>{e(rng) / 4.0, e(rng) / 4.0});
  }
  // A set of 20 (more than the 8 candidates: the spread candidate positions).
  out.emplace_back(bsp::random_segments(rng, 20, true, 4), std::array<double, 2>{1.25, -60});
  return out;
}

}  // namespace

TEST_CASE("bsp steps: every value a bsp-build step records matches the model from the semantics", "[spatial][spatial-bsp][replay]") {
  for (const auto& [segs, eye] : replay_inputs()) {
    INFO(bsp::input_json(segs).dump());
    replay_build(segs);
  }
}

TEST_CASE("bsp steps: every value a bsp-painter step records, its nested build's included, matches the model", "[spatial][spatial-bsp][replay]") {
  for (const auto& [segs, eye] : replay_inputs()) {
    INFO(bsp::input_json(segs, eye).dump());
    replay_painter(segs, eye);
  }
}
