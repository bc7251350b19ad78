// The step replay of kd-traverse on small exact inputs: a traversal's [t0, t1] as the ray's
// interval in the node's cell (slabs), t_s at each plane, the stack, the hits from the rays oracle
// (CGAL); the nested build repeats a standalone build's steps value for value.
#include <catch2/catch.hpp>
#include "kd_steps.hpp"
#include "rays_oracle.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::kd;

TEST_CASE("kd-traverse steps: every value of an exact walk matches its closed form", "[spatial][spatial-kd][replay]") {
  using L = KdTraverse;
  std::mt19937_64 rng(42);
  Mesh m = grid_mesh(4);
  const Mesh top = grid_mesh(1, 4, 1);
  for (const auto& f : top.f) {
    const auto base = static_cast<std::int32_t>(m.v.size());
    for (int c = 0; c < 3; ++c) m.v.push_back({top.v[f[c]][0], top.v[f[c]][1], 0.5 + 0.25 * c});
    m.f.push_back({base, base + 1, base + 2});
  }
  const auto tris = mesh_tris<Q>(m);
  const KdTree<Q, 3> tree = mesh_tree(tris);
  std::vector<oracle::Triangle3> otris(tris.begin(), tris.end());
  // The standalone build's steps, which the nested ones must repeat.
  Recorder<Q> built;
  {
    std::vector<Box<Q, 3>> bb;
    for (const auto& tr : tris) bb.push_back(triangle_bounds(tr));
    (void)kd_build<Q, 3>(bb, false, built);
  }
  for (int c = 0; c < 40; ++c) {
    ray::Ray3<Q> r;
    for (int k = 0; k < 3; ++k) r.o[k] = qc(rng, -4, 12), r.d[k] = qc(rng, 0, 8) - r.o[k];
    r.o.z = qc(rng, 2, 8);
    if (c % 5 == 0) r.d.x = 0, r.o.x = 2;             // in a split plane (x = 2 is one of the grid's)
    if (c % 7 == 0) r.d = {Q(0), Q(0), Q(-1)};        // straight down
    if (r.d == Vec3<Q>{Q(0), Q(0), Q(0)}) r.d.z = -1;
    INFO("case " << c);
    Recorder<Q> t;
    const KdHit<Q> h = kd_traverse<Q>(tris, r, t);
    const oracle::ClosestHit want = oracle::closest_hit(r.o, r.d, otris);
    CHECK(h.hit == want.hit);
    if (want.hit) CHECK((h.prim == want.prim && h.t == want.r.t));
    // The ray's interval in a node's cell, from t >= 0 (slabs; d_k = 0: all or nothing).
    auto interval = [&](std::int32_t node) {
      Q t0(0), t1;
      bool bounded = false;
      for (int k = 0; k < 3; ++k) {
        if (r.d[k] == 0) continue;
        Q a = (tree.nodes[node].cell.lo[k] - r.o[k]) / r.d[k], b = (tree.nodes[node].cell.hi[k] - r.o[k]) / r.d[k];
        if (b < a) std::swap(a, b);
        t0 = std::max(t0, a), t1 = bounded ? std::min(t1, b) : b, bounded = true;
      }
      return std::pair{t0, t1};
    };
    std::vector<std::int32_t> stack;
    std::int32_t node = -1;
    Q t0, t1, best_t;
    bool best = false;
    std::int32_t best_prim = -1, leaf_pos = 0, tested = -1;
    std::size_t nested = 0;
    auto check_stack = [&](StepValues& sv, StepGeometry& g) {
      CHECK(sv["stack.size"] == Q(stack.size()));
      for (std::size_t i = 0; i < stack.size(); ++i) {
        CHECK(sv["stack[" + std::to_string(i) + "]"] == stack[i]);
        GeoItem& item = g.take(GeoKind::box3);
        const auto& cell = tree.nodes[stack[i]].cell;
        CHECK(item.values == std::vector<Q>{cell.lo.x, cell.lo.y, cell.lo.z, cell.hi.x, cell.hi.y, cell.hi.z});
        CHECK(item.label == "stack");
      }
    };
    auto check_node = [&](StepGeometry& g, std::int32_t id) { CHECK(g.take(GeoKind::node3).values == node_values<3>(id, tree.nodes[id].parent, tree.nodes[id].cell)); };
    for_each_step<L>(t, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
      if (line == "build") {
        CHECK(nested >= built.size());
        CHECK(sv["nodes"] == Q(tree.nodes.size()));
        CHECK(sv["depth"] == Q(tree.depth));
        CHECK(g.take(GeoKind::ray3).values == std::vector<Q>{r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z});
        for (const auto& tr : otris) {  // the mesh, kept for the views
          GeoItem& it = g.take(GeoKind::triangle3);
          std::vector<Q> v;
          for (const auto& c : tr) v.push_back(c.x), v.push_back(c.y), v.push_back(c.z);
          CHECK(it.values == v);
          CHECK(it.life == "keep");
        }
      } else if (line == "clip") {
        const oracle::RayResult box = oracle::ray_box(r.o, r.d, tree.nodes[0].cell.lo, tree.nodes[0].cell.hi);
        CHECK(sv["hit"] == Q(box.hit));
        if (box.hit) {
          const auto [a, b] = interval(0);
          CHECK(sv["t0"] == a);
          CHECK(sv["t1"] == b);
          t0 = a, t1 = b;
        }
      } else if (line == "push") {
        CHECK(sv["node"] == 0);
        CHECK(sv["t0"] == t0);
        CHECK(sv["t1"] == t1);
        stack = {0};
      } else if (line == "pop" || line == "descend") {
        if (line == "pop") node = stack.back(), stack.pop_back(), check_stack(sv, g);
        CHECK(sv["node"] == node);
        const auto [a, b] = interval(node);
        CHECK(sv["t0"] == a);
        CHECK(sv["t1"] == b);
        t0 = a, t1 = b;
        check_node(g, node);
        if (line == "pop") {
          GeoItem& seg = g.take(GeoKind::segment3);
          const Vec3<Q> p = r.o + a * r.d, q = r.o + b * r.d;
          CHECK(seg.values == std::vector<Q>{p.x, p.y, p.z, q.x, q.y, q.z});
        }
        leaf_pos = 0;
      } else if (line == "parallel") {
        const auto& nd = tree.nodes[node];
        CHECK(r.d[nd.axis] == 0);
        CHECK(sv["axis"] == nd.axis);
        CHECK(sv["p"] == nd.split);
        CHECK(sv["left"] == Q(r.o[nd.axis] <= nd.split));
        node = r.o[nd.axis] <= nd.split ? nd.left : nd.right;
      } else if (line == "cross") {
        const auto& nd = tree.nodes[node];
        const Q ts = (nd.split - r.o[nd.axis]) / r.d[nd.axis];
        CHECK(sv["axis"] == nd.axis);
        CHECK(sv["p"] == nd.split);
        CHECK(sv["t_s"] == ts);
        CHECK(sv["first"] == (r.d[nd.axis] > 0 ? nd.left : nd.right));
        CHECK(sv["second"] == (r.d[nd.axis] > 0 ? nd.right : nd.left));
      } else if (line == "one") {
        const auto& nd = tree.nodes[node];
        const Q ts = (nd.split - r.o[nd.axis]) / r.d[nd.axis];
        const std::int32_t first = r.d[nd.axis] > 0 ? nd.left : nd.right, second = first == nd.left ? nd.right : nd.left;
        CHECK(!(t0 < ts && ts < t1));
        node = t1 <= ts ? first : second;
        CHECK(sv["node"] == node);
      } else if (line == "both") {
        const auto& nd = tree.nodes[node];
        const Q ts = (nd.split - r.o[nd.axis]) / r.d[nd.axis];
        CHECK((t0 < ts && ts < t1));
        const std::int32_t first = r.d[nd.axis] > 0 ? nd.left : nd.right, second = first == nd.left ? nd.right : nd.left;
        stack.push_back(second);
        node = first;
        CHECK(sv["node"] == node);
        CHECK(sv["pushed"] == second);
        CHECK(sv["t1"] == ts);
        check_stack(sv, g);
      } else if (line == "test") {
        REQUIRE(tree.nodes[node].left < 0);
        tested = tree.nodes[node].prims.at(leaf_pos++);
        CHECK(sv["prim"] == tested);
      } else if (line == "keep") {
        const oracle::RayResult hit = oracle::ray_triangle(r.o, r.d, otris[tested]);
        REQUIRE(hit.hit);
        CHECK((!best || hit.t < best_t || (hit.t == best_t && tested < best_prim)));
        best = true, best_t = hit.t, best_prim = tested;
        CHECK(sv["prim"] == tested);
        CHECK(sv["t"] == hit.t);
        GeoItem& p = g.take(GeoKind::point3);
        const Vec3<Q> at = r.o + hit.t * r.d;
        CHECK(p.values == std::vector<Q>{at.x, at.y, at.z});
        CHECK(p.label == "best");
      } else if (line == "exit") {
        CHECK(leaf_pos == static_cast<std::int32_t>(tree.nodes[node].prims.size()));
        CHECK(best);
        CHECK(best_t <= t1);
        CHECK(sv["t_best"] == best_t);
        CHECK(sv["t1"] == t1);
      } else if (line == "done") {
        CHECK(sv["hit"] == Q(want.hit));
        if (want.hit) {
          CHECK(sv["prim"] == want.prim);
          CHECK(sv["t"] == want.r.t);
        }
      } else {
        FAIL("a step on an unexpected line");
      }
    }, [&](std::size_t s) {
      // The nested build repeats the standalone build's steps, value for value.
      if (nested < built.size() && t.scope_id(t.at(s).scope) == KdBuild::id) {
        const StepValues a = values_of(t, s), b = values_of(built, nested);
        CHECK(a.v == b.v);
        CHECK(t.at(s).line == built.at(nested).line);
        ++nested;
      }
    });
  }
}
