// The step replay of kd-nearest on small exact inputs: each cell's squared distance from its
// clamped gap, the stack, the prune test against the largest held, each point's d2, and the held
// set kept here as a sorted list (not a heap); the nested build repeats a standalone build's steps.
#include <catch2/catch.hpp>
#include <set>
#include "kd_steps.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::kd;

namespace {

// The squared distance from q to the closed box: the per-axis gap max(lo - q, 0, q - hi), squared.
template <int D> Q box_d2(const Box<Q, D>& b, const VecN<Q, D>& q) {
  Q s(0);
  for (int k = 0; k < D; ++k) {
    const Q below = b.lo[k] - q[k], above = q[k] - b.hi[k], gap = std::max(std::max(below, Q(0)), above);
    s += gap * gap;
  }
  return s;
}

template <int D> void replay_nearest(const std::vector<VecN<Q, D>>& pts, const VecN<Q, D>& q, std::size_t k) {
  using L = KdNearest;
  std::vector<Box<Q, D>> bb;
  for (const auto& p : pts) bb.push_back(Box<Q, D>::at(p));
  Recorder<Q> built;
  const KdTree<Q, D> tree = kd_build<Q, D>(bb, true, built);
  Recorder<Q> t;
  const KdNearestResult<Q> res = kd_nearest<Q, D>(pts, q, k, t);
  // The answer from the definition: all points by (d2, id), the first k.
  std::set<std::pair<Q, std::int32_t>> all;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    Q d2(0);
    for (int a = 0; a < D; ++a) d2 += (pts[i][a] - q[a]) * (pts[i][a] - q[a]);
    all.insert({d2, static_cast<std::int32_t>(i)});
  }
  std::vector<std::pair<Q, std::int32_t>> want(all.begin(), std::next(all.begin(), static_cast<std::ptrdiff_t>(k)));
  REQUIRE(res.ids.size() == k);
  for (std::size_t i = 0; i < k; ++i) CHECK((res.ids[i] == want[i].second && res.d2[i] == want[i].first));

  std::vector<std::pair<std::int32_t, Q>> stack;  // (node, d2 of its cell)
  std::set<std::pair<Q, std::int32_t>> held;      // sorted by (d2, id): the largest is the last
  std::int32_t node = -1;
  std::size_t leaf_pos = 0, nested = 0;
  std::pair<Q, std::int32_t> tested;
  bool should_take = false;  // the point just measured goes in the held set: a take step must follow
  for_each_step<L>(t, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
    if (line != "take") CHECK_FALSE(should_take);
    if (line == "build") {
      CHECK(nested == built.size());
      CHECK(sv["nodes"] == Q(tree.nodes.size()));
      CHECK(sv["depth"] == Q(tree.depth));
      GeoItem& qi = g.take(D == 2 ? GeoKind::point2 : GeoKind::point3);
      CHECK(qi.values == flat_values<D>(q));
      CHECK(qi.label == "q");
      for (const auto& p : pts) CHECK(g.take(D == 2 ? GeoKind::point2 : GeoKind::point3).values == flat_values<D>(p));
    } else if (line == "push") {
      stack = {{0, box_d2<D>(tree.nodes[0].cell, q)}};
      CHECK(sv["node"] == 0);
      CHECK(sv["d2_cell"] == stack[0].second);
    } else if (line == "pop") {
      REQUIRE(!stack.empty());
      const auto [n, d2] = stack.back();
      stack.pop_back();
      node = n, leaf_pos = 0;
      CHECK(sv["node"] == n);
      CHECK(sv["d2_cell"] == d2);
      CHECK(sv["stack.size"] == Q(stack.size()));
      for (std::size_t i = 0; i < stack.size(); ++i) CHECK(sv["stack[" + std::to_string(i) + "]"] == stack[i].first);
      CHECK(g.take(D == 2 ? GeoKind::node2 : GeoKind::node3).values == node_values<D>(n, tree.nodes[n].parent, tree.nodes[n].cell));
    } else if (line == "prune") {
      REQUIRE(held.size() == k);
      const Q worst = std::prev(held.end())->first, d2 = box_d2<D>(tree.nodes[node].cell, q);
      CHECK(sv["worst"] == worst);
      CHECK(sv["skip"] == Q(worst < d2));
    } else if (line == "children") {
      const auto& nd = tree.nodes[node];
      REQUIRE(nd.left >= 0);
      const std::int32_t near = q[nd.axis] <= nd.split ? nd.left : nd.right, far = near == nd.left ? nd.right : nd.left;
      const Q dn = box_d2<D>(tree.nodes[near].cell, q), df = box_d2<D>(tree.nodes[far].cell, q);
      CHECK(sv["near"] == near);
      CHECK(sv["far"] == far);
      CHECK(sv["d2_near"] == dn);
      CHECK(sv["d2_far"] == df);
      stack.push_back({far, df}), stack.push_back({near, dn});
    } else if (line == "point") {
      const auto& nd = tree.nodes[node];
      REQUIRE(nd.left < 0);
      REQUIRE(leaf_pos < nd.prims.size());
      const std::int32_t i = nd.prims[leaf_pos++];
      const auto it = std::find_if(all.begin(), all.end(), [&](const auto& e) { return e.second == i; });
      tested = *it;
      should_take = held.size() < k || tested < *std::prev(held.end());
      CHECK(sv["i"] == i);
      CHECK(sv["d2"] == it->first);
      const GeoKind pk = D == 2 ? GeoKind::point2 : GeoKind::point3;
      CHECK(g.take(pk).values == flat_values<D>(pts[i]));
      GeoItem& seg = g.take(D == 2 ? GeoKind::segment2 : GeoKind::segment3);
      std::vector<Q> v = flat_values<D>(pts[i]);
      for (const Q& x : flat_values<D>(q)) v.push_back(x);
      CHECK(seg.values == v);
      CHECK(seg.value == std::optional<Q>(it->first));
    } else if (line == "take") {
      CHECK(should_take);
      should_take = false;
      held.insert(tested);
      if (held.size() > k) held.erase(std::prev(held.end()));
      CHECK(sv["i"] == tested.second);
      CHECK(sv["held"] == Q(held.size()));
      CHECK(sv["worst"] == std::prev(held.end())->first);
    } else if (line == "done") {
      CHECK(stack.empty());
      CHECK(sv["held"] == Q(held.size()));
      CHECK(std::vector<std::pair<Q, std::int32_t>>(held.begin(), held.end()) == want);
      for (const auto& [d2, i] : held) {
        GeoItem& p = g.take(D == 2 ? GeoKind::point2 : GeoKind::point3);
        CHECK(p.values == flat_values<D>(pts[i]));
        CHECK(p.label == "nearest");
        CHECK(p.life == "keep");
      }
    } else {
      FAIL("a step on an unexpected line");
    }
  }, [&](std::size_t s) {
    REQUIRE(nested < built.size());
    CHECK(t.scope_id(t.at(s).scope) == KdBuild::id);
    CHECK(values_of(t, s).v == values_of(built, nested).v);
    CHECK(t.at(s).line == built.at(nested).line);
    ++nested;
  });
}

}  // namespace

TEST_CASE("kd-nearest steps: every value of an exact search matches its closed form (2D and 3D, ties, duplicates)", "[spatial][spatial-kd][replay]") {
  std::mt19937_64 rng(7);
  for (int c = 0; c < 24; ++c) {
    INFO("case " << c);
    const std::size_t n = 6 + static_cast<std::size_t>(c) * 3;
    const std::size_t k = 1 + static_cast<std::size_t>(c) % 5;
    if (c % 2 == 0) {
      std::vector<Vec2<Q>> pts;
      for (std::size_t i = 0; i < n; ++i) pts.push_back({qc(rng, 0, 8), qc(rng, 0, 8)});  // a coarse grid: ties and duplicates
      const Vec2<Q> q{qc(rng, -2, 10), qc(rng, -2, 10)};
      replay_nearest<2>(pts, q, k);
    } else {
      std::vector<Vec3<Q>> pts;
      for (std::size_t i = 0; i < n; ++i) pts.push_back({qc(rng, 0, 12), qc(rng, 0, 12), qc(rng, 0, 12)});
      const Vec3<Q> q{qc(rng, -2, 14), qc(rng, -2, 14), qc(rng, -2, 14)};
      replay_nearest<3>(pts, q, k);
    }
  }
}
