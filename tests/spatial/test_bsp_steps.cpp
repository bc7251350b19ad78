// bsp-build's and bsp-painter's exact steps replayed: every recorded value and geometry item of
// every step against the build's model (bsp_model.hpp) and the painter's far-node-near rule.
#include <catch2/catch.hpp>
#include "bsp_model.hpp"
#include "spatial/bsp_painter.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::bsp_model;

namespace {
void replay_build(const std::vector<bsp::Seg>& segs) {
  Recorder<Rational> t;
  const auto tree = spatial::bsp_build<Rational>(exact_segments(segs), 1 << 18, t);
  BuildModel model(segs);
  std::size_t done = 0;
  for (std::size_t s = 0; s < t.size(); ++s) {
    const std::string_view line = spatial::BspBuild::lines[t.at(s).line - 1].name;
    INFO("step " << s << " line " << line);
    CHECK(t.at(s).scope == 0);
    check_step(t, s, [&](StepValues& sv, StepGeometry& g) { model.step(line, sv, g); });
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
      check_step(t, s, [&](StepValues& sv, StepGeometry& g) { build.step(line, sv, g); });
      continue;
    }
    const std::string_view line = L::lines[st.line - 1].name;
    INFO("step " << s << " line " << line);
    check_step(t, s, [&](StepValues& sv, StepGeometry& g) {
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
