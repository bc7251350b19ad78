// The step replay of kd-build on small exact inputs: every recorded value and geometry item
// against a closed form stated independently: the SAH cost of every candidate plane by counting
// (N_L: lo <= p, N_R: hi >= p; flat points on one side), the first least per axis, the children's
// primitive sets by the closed-cell rule, the node items.
#include <catch2/catch.hpp>
#include "kd_steps.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::kd;

namespace {

// The expected node: its cell and primitives, stated from its parent's by the closed-cell rule.
template <int D> struct WantNode {
  Box<Q, D> cell;
  std::int64_t parent = -1;
  int depth = 0;
  std::vector<std::int32_t> prims;
};

template <int D> Q half_area(const Box<Q, D>& b) { return b.half_area(); }

// The build's replay over primitives' bounds b (points: flats go to one side).
template <int D> void check_build(const std::vector<Box<Q, D>>& b, bool points) {
  using L = KdBuild;
  Recorder<Q> t;
  const KdTree<Q, D> tree = kd_build<Q, D>(b, points, t);
  const std::size_t n = b.size();
  std::vector<WantNode<D>> want(1);
  want[0].cell = b[0];
  for (const auto& x : b) want[0].cell.grow(x);
  for (std::size_t i = 0; i < n; ++i) want[0].prims.push_back(static_cast<std::int32_t>(i));
  std::vector<std::int64_t> order{0};  // pending nodes, the last taken first
  std::int64_t cur = -1;
  // The current node's chosen split (first least over axes) and its leaf cost.
  struct Choice {
    bool found = false;
    int axis = 0;
    Q p, cost;
    std::size_t nl = 0, nr = 0;
    bool flat_left = true;
  } best;
  Q leaf_cost;
  std::size_t leaves = 0, max_depth = 0;
  auto counts = [&](const WantNode<D>& w, int k, const Q& p, int side) {  // side 0 flats left, 1 right, 2 both
    std::size_t nl = 0, nr = 0;
    for (std::int32_t i : w.prims) {
      const Q &lo = b[i].lo[k], &hi = b[i].hi[k];
      if (lo == hi && lo == p) nl += side != 1, nr += side != 0;
      else nl += lo <= p, nr += p <= hi;
    }
    return std::pair{nl, nr};
  };
  auto cost = [&](const Box<Q, D>& c, int k, const Q& p, std::size_t nl, std::size_t nr) -> Q {
    Box<Q, D> l = c, r = c;
    l.hi[k] = p, r.lo[k] = p;
    const Q lam = nl == 0 || nr == 0 ? Q(4) : Q(5);
    return lam * (Q(kKdTraverseCost) * half_area<D>(c) + Q(kKdIntersectCost) * (half_area<D>(l) * Q(nl) + half_area<D>(r) * Q(nr)));
  };
  for_each_step<L>(t, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
    if (line == "events") {
      std::size_t e = 0;
      for (int k = 0; k < D; ++k)
        for (const auto& x : b) e += x.lo[k] == x.hi[k] ? 1 : 2;
      CHECK(sv["events"] == Q(e));
    } else if (line == "sort") {
    } else if (line == "root") {
      CHECK(sv["node"] == 0);
      GeoItem& item = g.take(D == 2 ? GeoKind::node2 : GeoKind::node3);
      CHECK(item.values == node_values<D>(0, -1, want[0].cell));
      CHECK(item.life == "keep");
      for (const auto& x : b) {  // the input points, kept for the views
        if (!points) break;
        GeoItem& p = g.take(D == 2 ? GeoKind::point2 : GeoKind::point3);
        for (int k = 0; k < D; ++k) CHECK(p.values[static_cast<std::size_t>(k)] == x.lo[k]);
        CHECK(p.life == "keep");
      }
    } else if (line == "pop") {
      REQUIRE(!order.empty());
      cur = order.back();
      order.pop_back();
      const WantNode<D>& w = want[cur];
      CHECK(sv["node"] == Q(cur));
      CHECK(sv["n"] == Q(w.prims.size()));
      CHECK(sv["depth"] == w.depth);
      CHECK(sv["A"] == half_area<D>(w.cell));
      CHECK(g.take(D == 2 ? GeoKind::node2 : GeoKind::node3).values == node_values<D>(cur, w.parent, w.cell));
      best = Choice{};
      leaf_cost = Q(5 * kKdIntersectCost) * Q(w.prims.size()) * half_area<D>(w.cell);
    } else if (line == "best") {
      const WantNode<D>& w = want[cur];
      const int k = static_cast<int>(sv["axis"].get_num().get_si());
      // Candidates: the distinct bounds strictly inside the cell, in order; flats left, then right.
      std::vector<Q> ps;
      for (std::int32_t i : w.prims)
        for (const Q& p : {b[i].lo[k], b[i].hi[k]})
          if (w.cell.lo[k] < p && p < w.cell.hi[k]) ps.push_back(p);
      std::sort(ps.begin(), ps.end());
      ps.erase(std::unique(ps.begin(), ps.end()), ps.end());
      Choice axis_best;
      for (const Q& p : ps)
        for (int side : points ? std::vector<int>{0, 1} : std::vector<int>{2}) {
          const auto [nl, nr] = counts(w, k, p, side);
          const Q c = cost(w.cell, k, p, nl, nr);
          if (!axis_best.found || c < axis_best.cost) axis_best = {true, k, p, c, nl, nr, side != 1};
          if (!best.found || c < best.cost) best = {true, k, p, c, nl, nr, side != 1};
        }
      CHECK(sv["found"] == Q(axis_best.found));
      if (axis_best.found) {
        CHECK(sv["p"] == axis_best.p);
        CHECK(sv["cost"] == axis_best.cost);
        CHECK(sv["n_left"] == Q(axis_best.nl));
        CHECK(sv["n_right"] == Q(axis_best.nr));
        Box<Q, D> face = w.cell;
        face.lo[k] = face.hi[k] = axis_best.p;
        GeoItem& item = g.take(D == 2 ? GeoKind::segment2 : GeoKind::box3);
        std::vector<Q> v = flat_values<D>(face.lo);
        for (const Q& x : flat_values<D>(face.hi)) v.push_back(x);
        CHECK(item.values == v);
        CHECK(item.label == "cost");
        CHECK(item.value == std::optional<Q>(axis_best.cost));
      }
    } else if (line == "leaf") {
      const WantNode<D>& w = want[cur];
      CHECK(sv["node"] == Q(cur));
      CHECK(sv["n"] == Q(w.prims.size()));
      CHECK(sv["leaf_cost"] == leaf_cost);
      CHECK(sv["found"] == Q(best.found));
      CHECK((!best.found || !(best.cost < leaf_cost) || w.depth >= kd_max_depth(n) || w.prims.size() <= 1));
      GeoItem& item = g.take(D == 2 ? GeoKind::node2 : GeoKind::node3);
      CHECK(item.values == node_values<D>(cur, w.parent, w.cell));
      CHECK(item.life == "keep");
      CHECK(tree.nodes[cur].prims == w.prims);
      ++leaves, max_depth = std::max<std::size_t>(max_depth, w.depth);
    } else if (line == "classify") {
      REQUIRE(best.found);
      CHECK(best.cost < leaf_cost);
      CHECK(sv["axis"] == best.axis);
      CHECK(sv["p"] == best.p);
      CHECK(sv["cost"] == best.cost);
      CHECK(sv["leaf_cost"] == leaf_cost);
      CHECK(sv["n_left"] == Q(best.nl));
      CHECK(sv["n_right"] == Q(best.nr));
      CHECK(sv["flat_left"] == Q(best.flat_left));
    } else if (line == "split") {
      // The children's primitives: left if lo <= p, right if hi >= p; flat at p: the chosen side.
      const WantNode<D> w = want[cur];
      WantNode<D> l, r;
      const int k = best.axis;
      for (std::int32_t i : w.prims) {
        const Q &lo = b[i].lo[k], &hi = b[i].hi[k];
        const bool flat_here = lo == hi && lo == best.p;
        if (flat_here ? (!points || best.flat_left) : lo <= best.p) l.prims.push_back(i);
        if (flat_here ? (!points || !best.flat_left) : best.p <= hi) r.prims.push_back(i);
      }
      CHECK(l.prims.size() == best.nl);
      CHECK(r.prims.size() == best.nr);
      auto events0 = [&](const WantNode<D>& c) {
        std::size_t e = 0;
        for (std::int32_t i : c.prims) e += b[i].lo[0] == b[i].hi[0] ? 1 : 2;
        return e;
      };
      CHECK(sv["events_left"] == Q(events0(l)));
      CHECK(sv["events_right"] == Q(events0(r)));
      l.cell = r.cell = w.cell;
      l.cell.hi[k] = best.p, r.cell.lo[k] = best.p;
      l.parent = r.parent = cur, l.depth = r.depth = w.depth + 1;
      std::sort(l.prims.begin(), l.prims.end()), std::sort(r.prims.begin(), r.prims.end());
      want.push_back(l), want.push_back(r);
    } else if (line == "children") {
      const auto lid = static_cast<std::int64_t>(want.size() - 2);
      CHECK(sv["left"] == Q(lid));
      CHECK(sv["right"] == Q(lid + 1));
      for (std::int64_t c : {lid, lid + 1}) {
        GeoItem& item = g.take(D == 2 ? GeoKind::node2 : GeoKind::node3);
        CHECK(item.values == node_values<D>(c, cur, want[c].cell));
        CHECK(item.life == "keep");
      }
      order.push_back(lid + 1), order.push_back(lid);
    } else if (line == "done") {
      CHECK(order.empty());
      CHECK(sv["nodes"] == Q(want.size()));
      CHECK(sv["leaves"] == Q(leaves));
      CHECK(sv["depth"] == Q(max_depth));
    } else {
      FAIL("a step on an unexpected line");
    }
  });
  CHECK(tree.nodes.size() == want.size());
}

}  // namespace

TEST_CASE("kd-build steps: every value of an exact build matches its closed form (2D and 3D points, triangles)", "[spatial][spatial-kd][replay]") {
  std::mt19937_64 rng(41);
  for (int c = 0; c < 12; ++c) {
    INFO("case " << c);
    std::vector<Box<Q, 2>> p2;
    for (int i = 0; i < 6 + c; ++i) p2.push_back(Box<Q, 2>::at({qc(rng, 0, 12), qc(rng, 0, 12)}));
    check_build<2>(p2, true);
    std::vector<Box<Q, 3>> p3;
    for (int i = 0; i < 6 + c; ++i) p3.push_back(Box<Q, 3>::at({qc(rng, 0, 8), qc(rng, 0, 8), qc(rng, 0, 8)}));
    check_build<3>(p3, true);
    std::vector<Box<Q, 3>> tris;
    for (int i = 0; i < 8 + 2 * c; ++i) {
      std::array<Vec3<Q>, 3> tri;
      const Vec3<Q> o{qc(rng, 0, 20), qc(rng, 0, 20), qc(rng, 0, 20)};
      for (auto& v : tri) v = {o.x + qc(rng, 0, 3), o.y + qc(rng, 0, 3), c % 3 ? o.z + qc(rng, 0, 3) : Q(0)};  // a third of the cases flat in z
      tris.push_back(triangle_bounds(tri));
    }
    check_build<3>(tris, false);
  }
  check_build<2>(std::vector<Box<Q, 2>>(5, Box<Q, 2>::at({1, 2})), true);  // identical points: one leaf
}

