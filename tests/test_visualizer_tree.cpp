// The tree view's diagram and marks, from a trace written here by hand: nodes appear at the step
// that records them, leaves take consecutive slots with each parent over its children, and the
// current node, its path to the root and a "stack" list variable are what the view marks.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <random>
#include <set>
#include "headless/headless.hpp"
#include "panels/tree_view.hpp"

using namespace sw;
using namespace sw::vis;

namespace {

// A build of the tree 0 -> (1, 2), 2 -> (3, 4), then a traversal step on node 3 with the stack [1].
std::shared_ptr<const TraceModel> hand_trace() {
  auto r = std::make_unique<Recorder<double>>();
  const Vec2<double> lo{0, 0}, hi{1, 1};
  r->step(1, StepKind::init).node(0, -1, lo, hi).keep();
  r->step(1, StepKind::advance).node(1, 0, lo, hi).keep().node(2, 0, lo, hi).keep();
  r->step(1, StepKind::advance).node(3, 2, lo, hi).keep().node(4, 2, lo, hi).keep();
  const std::int64_t stack[] = {1};
  r->step(1, StepKind::visit).ilist("stack", stack).node(3, 2, lo, hi);
  Recorded rec{std::move(r), Json::object()};
  return std::make_shared<TraceModel>(catalog().front().open(Json::parse(catalog().front().example), Numeric::f64), std::move(rec));
}

}  // namespace

TEST_CASE("tree view: the diagram's layout from a trace's node items", "[visualizer][tree-view]") {
  const auto m = hand_trace();
  const TreeDiagram d = build_tree_diagram(*m);
  REQUIRE(d.nodes.size() == 5);
  CHECK(d.depth == 2);
  CHECK(d.width == 3);  // leaves 1, 3, 4
  const auto at = [&](std::int64_t id) -> const TreeDiagram::Node& { return d.nodes[*d.find(id)]; };
  CHECK(at(1).x == 0);
  CHECK(at(3).x == 1);
  CHECK(at(4).x == 2);
  CHECK(at(2).x == 1.5f);   // over its children
  CHECK(at(0).x == 0.75f);  // over 1 and 2
  CHECK(at(3).y == 2);
  CHECK(at(3).first_step == 2);
  CHECK(d.nodes[*d.find(3)].parent == std::int32_t(*d.find(2)));
}

TEST_CASE("tree view: built so far, the current node, its path and the stack", "[visualizer][tree-view]") {
  const auto m = hand_trace();
  const TreeDiagram d = build_tree_diagram(*m);
  const TreeMarks early = tree_marks(*m, d, 1);
  CHECK(early.built == 3);
  REQUIRE(early.current.size() == 2);  // the step's own nodes, 1 and 2
  const TreeMarks late = tree_marks(*m, d, 3);
  CHECK(late.built == 5);
  REQUIRE(late.current.size() == 1);
  CHECK(d.nodes[late.current[0]].id == 3);
  REQUIRE(late.stack.size() == 1);
  CHECK(d.nodes[late.stack[0]].id == 1);
  std::vector<std::int64_t> path;
  for (std::size_t i : late.path) path.push_back(d.nodes[i].id);
  CHECK(path == std::vector<std::int64_t>{3, 2, 0});
}

TEST_CASE("tree view: a query shows the whole tree its nested build records, and marks the nodes it visits", "[visualizer][tree-view]") {
  for (const char* id : {"kd-traverse", "bvh-traverse"}) {
    INFO(id);
    const Algorithm& alg = find_algorithm(id);
    const Json input = Json::parse(alg.example);
    Recorded rec = alg.open(input, Numeric::exact).record();
    const TraceView& t = *rec.trace;
    // The nodes the nested build creates (scope 1), counted here from the trace itself.
    std::set<std::int64_t> built, visited;
    std::size_t first_visit = t.size();
    for (std::size_t s = 0; s < t.size(); ++s)
      for (std::uint32_t g = t.at(s).geo_begin; g < t.at(s).geo_end; ++g) {
        const GeoRecord& geo = t.geo_at(g);
        if (geo.kind != GeoKind::node3) continue;
        const auto node = static_cast<std::int64_t>(t.geo_double(geo, 0));
        (t.at(s).scope == 0 ? visited : built).insert(node);
        if (t.at(s).scope == 0) first_visit = std::min(first_visit, s);
      }
    REQUIRE(built.size() > visited.size());
    REQUIRE(first_visit < t.size());
    auto m = std::make_shared<TraceModel>(alg.open(input, Numeric::exact), std::move(rec));
    const TreeDiagram d = build_tree_diagram(*m);
    CHECK(d.nodes.size() == built.size());
    for (std::int64_t v : visited) CHECK(d.find(v));
    const TreeMarks k = tree_marks(*m, d, first_visit);
    REQUIRE(!k.current.empty());
    CHECK(visited.count(d.nodes[k.current[0]].id));
    CHECK(k.built == d.nodes.size());
  }
}
TEST_CASE("tree view: 10^4 nodes fit the canvas and draw headless (past 65536 vertices in one list)", "[visualizer][tree-view][render]") {
  std::mt19937_64 rng(20261125);
  std::uniform_real_distribution<double> u(-100, 100);
  Json pts = Json::array();
  for (int i = 0; i < 12000; ++i) pts.push_back({u(rng), u(rng)});
  HeadlessHost host(1280, 800);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_algorithm(find_algorithm("kd-build"), Json{{"points", pts}}, Numeric::f64));
  REQUIRE(session.set_view(View::tree));
  session.set_step(session.model(0)->last());
  host.render();
  const auto* tc = dynamic_cast<const TreeCanvas*>(app.canvas(0));
  REQUIRE(tc);
  const TreeDiagram& d = tc->diagram();
  REQUIRE(d.nodes.size() > 10000);
  const auto r = tc->canvas_rect();
  std::size_t inside = 0;
  for (std::size_t i = 0; i < d.nodes.size(); ++i)
    if (const auto c = tc->node_centre(i)) inside += (*c)[0] >= r[0] && (*c)[0] <= r[2] && (*c)[1] >= r[1] && (*c)[1] <= r[3];
  CHECK(inside == d.nodes.size());  // fitted: every node is drawn, within the canvas
}

TEST_CASE("trace model: a nested call's kept items end with the call, the caller's own last", "[visualizer][tree-view]") {
  const Algorithm& alg = find_algorithm("kd-traverse");
  const Json input = Json::parse(alg.example);
  const Run run = alg.open(input, Numeric::exact);
  auto m = std::make_shared<TraceModel>(run, run.record());
  const TraceView& t = m->trace();
  std::size_t first_own = 0;  // the build's steps come first, then the traversal's own "build" step
  while (first_own < t.size() && t.at(first_own).scope != 0) ++first_own;
  REQUIRE(first_own > 0);
  REQUIRE(first_own < t.size());
  const std::size_t last_build = first_own - 1;
  auto count = [&](std::size_t step, GeoKind kind, bool nested) {
    std::size_t n = 0;
    for (std::uint32_t g : m->visible_items(step)) {
      std::size_t s = 0;
      while (t.at(s).geo_end <= g) ++s;
      n += t.geo_at(g).kind == kind && (t.at(s).scope != 0) == nested;
    }
    return n;
  };
  CHECK(count(last_build, GeoKind::node3, true) > 1);  // the build shows its nodes as it goes
  CHECK(count(first_own, GeoKind::node3, true) == 0);  // gone once it returns
  CHECK(count(t.size() - 1, GeoKind::node3, true) == 0);
  const std::size_t tris = input.at("triangles").size();
  CHECK(count(first_own, GeoKind::triangle3, false) == tris);  // what the traversal keeps itself stays
  CHECK(count(t.size() - 1, GeoKind::triangle3, false) == tris);
}
#endif
