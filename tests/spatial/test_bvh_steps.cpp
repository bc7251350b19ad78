// Step replays of bvh-build and bvh-traverse on small exact inputs: every recorded variable and
// geometry item against a model written from the semantics (docs/spatial/bvh.md): node sets,
// centroid boxes, bin counts, SAH costs by brute force over the splits; the traversal's entry t
// and hits from the oracle's slab and triangle tests (oracle/rays_oracle.hpp).
#include <catch2/catch.hpp>
#include <algorithm>
#include "spatial/bvh_run.hpp"
#include "spatial/bvh_traverse.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::bvh;

namespace {

using Q = Rational;
using V3 = Vec3<Q>;
struct QBox {
  V3 lo, hi;
};
QBox box_of(const std::vector<oracle::Triangle3>& t, const std::vector<std::int32_t>& ids) {
  QBox b{t[ids[0]][0], t[ids[0]][0]};
  for (std::int32_t i : ids)
    for (const V3& v : t[i])
      for (int k = 0; k < 3; ++k) b.lo[k] = std::min(b.lo[k], v[k]), b.hi[k] = std::max(b.hi[k], v[k]);
  return b;
}
Q half_area(const QBox& b) {
  const Q x = b.hi.x - b.lo.x, y = b.hi.y - b.lo.y, z = b.hi.z - b.lo.z;
  return x * y + y * z + z * x;
}
V3 centroid2(const oracle::Triangle3& t) {  // lo + hi of the triangle's box
  const QBox b = box_of({t}, {0});
  return V3{b.lo.x + b.hi.x, b.lo.y + b.hi.y, b.lo.z + b.hi.z};
}
std::vector<Q> values(const V3& a) { return {a.x, a.y, a.z}; }
void check_node(GeoItem& g, std::int64_t id, std::int64_t parent, const QBox& b, const char* life) {
  std::vector<Q> want{Q(id), Q(parent), b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z};
  CHECK(g.values == want);
  CHECK(g.life == life);
}
void check_vec(StepValues& sv, const std::string& name, const V3& v) {
  CHECK(sv[name + ".x"] == v.x);
  CHECK(sv[name + ".y"] == v.y);
  CHECK(sv[name + ".z"] == v.z);
}

// The build model: node sets and the stack, followed from the semantics.
struct BuildModel {
  explicit BuildModel(const std::vector<oracle::Triangle3>& tris) : t(tris) {}
  const std::vector<oracle::Triangle3>& t;
  std::vector<std::vector<std::int32_t>> set;
  std::vector<std::int64_t> parent, depth;
  std::vector<std::int32_t> stack{0};
  std::size_t leaves = 0, max_depth = 0;
  // The current node's state.
  std::int32_t node = -1;
  QBox c;
  int best_axis = -1, best_s = 0, last_axis = -1;
  Q best_cost;
  int bin(std::int32_t i, int k) const {
    const Q x = Q(16) * (centroid2(t[i])[k] - c.lo[k]) / (c.hi[k] - c.lo[k]);
    return static_cast<int>(std::clamp<std::int64_t>(num::floor_int(x), 0, 15));
  }
  std::vector<std::int32_t> side(int k, int s, bool left) const {
    std::vector<std::int32_t> out;
    for (std::int32_t i : set[node])
      if ((bin(i, k) < s) == left) out.push_back(i);
    return out;
  }
};

void replay_build(const Recorder<Rational>& rec, std::size_t from, std::size_t to, const std::vector<oracle::Triangle3>& t, const Json& result) {
  BuildModel m(t);
  std::vector<std::int32_t> all(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) all[i] = static_cast<std::int32_t>(i);
  m.set.push_back(all), m.parent.push_back(-1), m.depth.push_back(0);
  auto leaf = [&] { ++m.leaves; };
  for (std::size_t s = from; s < to; ++s) {
    const std::string_view line = spatial::BvhBuild::lines[rec.at(s).line - 1].name;
    INFO("build step " << s << " line " << line);
    StepValues sv = values_of(rec, s);
    StepGeometry g = geometry_of(rec, s);
    if (line == "bounds") {
      CHECK(sv["triangles"] == Q(t.size()));
      for (const auto& tri : t) {
        GeoItem& it = g.take(GeoKind::triangle3);
        std::vector<Q> want;
        for (const V3& v : tri) want.push_back(v.x), want.push_back(v.y), want.push_back(v.z);
        CHECK(it.values == want);
        CHECK(it.life == "keep");
      }
    } else if (line == "root") {
      CHECK(sv["node"] == 0);
      check_node(g.take(GeoKind::node3), 0, -1, box_of(t, all), "keep");
    } else if (line == "pop") {
      REQUIRE(!m.stack.empty());
      m.node = m.stack.back();
      m.stack.pop_back();
      const auto& ids = m.set[m.node];
      m.c = {centroid2(t[ids[0]]), centroid2(t[ids[0]])};
      for (std::int32_t i : ids)
        for (int k = 0; k < 3; ++k) m.c.lo[k] = std::min(m.c.lo[k], centroid2(t[i])[k]), m.c.hi[k] = std::max(m.c.hi[k], centroid2(t[i])[k]);
      m.best_axis = -1, m.last_axis = -1;
      m.max_depth = std::max<std::size_t>(m.max_depth, m.depth[m.node]);
      CHECK(sv["node"] == m.node);
      CHECK(sv["n"] == Q(ids.size()));
      CHECK(sv["depth"] == Q(m.depth[m.node]));
      check_vec(sv, "C_lo", m.c.lo);
      check_vec(sv, "C_hi", m.c.hi);
      check_node(g.take(GeoKind::node3), m.node, m.parent[m.node], box_of(t, ids), "");
    } else if (line == "one") {
      CHECK(sv["node"] == m.node);
      CHECK(m.set[m.node].size() == 1);
    } else if (line == "bins") {
      const int k = static_cast<int>(num::floor_int(sv["axis"]));
      CHECK(k > m.last_axis);
      for (int a = m.last_axis + 1; a < k; ++a) CHECK(!(m.c.lo[a] < m.c.hi[a]));  // skipped axes have no spread
      CHECK(m.c.lo[k] < m.c.hi[k]);
      m.last_axis = k;
      CHECK(sv["counts.size"] == 16);
      for (int b = 0; b < 16; ++b) {
        std::vector<std::int32_t> in_bin;
        for (std::int32_t i : m.set[m.node])
          if (m.bin(i, k) == b) in_bin.push_back(i);
        CHECK(sv["counts[" + std::to_string(b) + "]"] == Q(in_bin.size()));
        if (in_bin.empty()) continue;
        GeoItem& it = g.take(GeoKind::box3);
        const QBox bb = box_of(t, in_bin);
        std::vector<Q> want = values(bb.lo);
        for (const Q& x : values(bb.hi)) want.push_back(x);
        CHECK(it.values == want);
        CHECK(it.label == "bin");
      }
    } else if (line == "sweep") {
      const int k = static_cast<int>(num::floor_int(sv["axis"]));
      CHECK(k == m.last_axis);
      int best = 0;
      Q cost;
      for (int sp = 1; sp < 16; ++sp) {
        const auto l = m.side(k, sp, true), r = m.side(k, sp, false);
        if (l.empty() || r.empty()) continue;
        const Q c = half_area(box_of(t, l)) * Q(l.size()) + half_area(box_of(t, r)) * Q(r.size());
        if (best == 0 || c < cost) best = sp, cost = c;
      }
      CHECK(sv["s"] == best);
      CHECK(sv["cost"] == cost);
      if (m.best_axis < 0 || cost < m.best_cost) m.best_axis = k, m.best_s = best, m.best_cost = cost;
    } else if (line == "decide" || line == "median") {
      const auto& ids = m.set[m.node];
      const Q area = half_area(box_of(t, ids));
      bool is_leaf;
      std::vector<std::int32_t> left, right;
      int axis;
      if (line == "decide") {
        axis = m.best_axis;
        CHECK(m.depth[m.node] < 48);
        CHECK(sv["axis"] == axis);
        CHECK(sv["s"] == m.best_s);
        CHECK(sv["leaf_cost"] == Q(ids.size()) * area);
        CHECK(sv["split_cost"] == Q(2) * area + m.best_cost);
        is_leaf = ids.size() <= 8 && !(Q(2) * area + m.best_cost < Q(ids.size()) * area);
        left = m.side(axis, m.best_s, true), right = m.side(axis, m.best_s, false);
      } else {
        CHECK((m.best_axis < 0 || m.depth[m.node] >= 48));
        axis = 0;
        for (int k = 1; k < 3; ++k)
          if (m.c.hi[axis] - m.c.lo[axis] < m.c.hi[k] - m.c.lo[k]) axis = k;
        CHECK(sv["axis"] == axis);
        is_leaf = ids.size() <= 8;
        std::vector<std::int32_t> sorted = ids;
        std::stable_sort(sorted.begin(), sorted.end(), [&](std::int32_t a, std::int32_t b) { return centroid2(t[a])[axis] < centroid2(t[b])[axis]; });
        left.assign(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2));
        right.assign(sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
      }
      CHECK(sv["leaf"] == (is_leaf ? 1 : 0));
      if (!is_leaf) {  // the children, created next
        const auto l = static_cast<std::int32_t>(m.set.size());
        m.set.push_back(left), m.set.push_back(right);
        m.parent.push_back(m.node), m.parent.push_back(m.node);
        m.depth.push_back(m.depth[m.node] + 1), m.depth.push_back(m.depth[m.node] + 1);
        m.stack.push_back(l + 1), m.stack.push_back(l);
        m.best_axis = axis;
      }
    } else if (line == "leaf") {
      leaf();
      CHECK(sv["node"] == m.node);
      const auto& ids = m.set[m.node];
      CHECK(sv["prims.size"] == Q(ids.size()));
      for (std::size_t j = 0; j < ids.size(); ++j) CHECK(sv["prims[" + std::to_string(j) + "]"] == ids[j]);
    } else if (line == "split") {
      const auto l = static_cast<std::int32_t>(m.set.size()) - 2;
      CHECK(sv["node"] == m.node);
      CHECK(sv["axis"] == m.best_axis);
      CHECK(sv["left"] == l);
      CHECK(sv["right"] == l + 1);
      CHECK(sv["n_left"] == Q(m.set[l].size()));
      CHECK(sv["n_right"] == Q(m.set[l + 1].size()));
      check_node(g.take(GeoKind::node3), l, m.node, box_of(t, m.set[l]), "keep");
      check_node(g.take(GeoKind::node3), l + 1, m.node, box_of(t, m.set[l + 1]), "keep");
    } else if (line == "done") {
      CHECK(m.stack.empty());
      CHECK(sv["nodes"] == Q(m.set.size()));
      CHECK(sv["leaves"] == Q(m.leaves));
      CHECK(sv["depth"] == Q(m.max_depth));
      CHECK(result["nodes"].get<std::size_t>() == m.set.size());
    } else {
      FAIL("unexpected line " << line);
    }
    require_all_checked(sv, s);
    require_all_geometry_checked(g, s);
  }
}

std::vector<oracle::Triangle3> triangles_of(const Json& in) { return exact_tris(spatial::parse_mesh(in, "input")); }

}  // namespace

TEST_CASE("bvh-build: every step of exact traces against the model", "[spatial][spatial-bvh]") {
  const Algorithm& a = find_algorithm("bvh-build");
  std::mt19937_64 rng(20261127);
  std::vector<Json> inputs{Json::parse(a.example), mesh_json(spatial::cases::random_mesh(rng, 40, 0.3)), mesh_json(spatial::cases::grid_mesh(3, 3, false, 2))};
  Mesh same;
  same.v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  same.f.assign(20, {0, 1, 2});
  inputs.push_back(mesh_json(same));
  for (const Json& in : inputs) {
    const Recorded rec = a.open(in, Numeric::exact).record();
    const auto& t = dynamic_cast<const Recorder<Rational>&>(*rec.trace);
    replay_build(t, 0, t.size(), triangles_of(in), rec.result);
  }
}

TEST_CASE("bvh-traverse: every step of exact traces against the model", "[spatial][spatial-bvh]") {
  const Algorithm& a = find_algorithm("bvh-traverse");
  Json grid = mesh_json(spatial::cases::grid_mesh(3, 3, false, 4));
  std::vector<Json> inputs{Json::parse(a.example)};
  for (const Json& ray : {Json{{"o", {1.5, 1, 3}}, {"d", {0, -0.0, -1}}}, Json{{"o", {-1, 1.5, 0.25}}, {"d", {1, 0, 0}}}, Json{{"o", {9, 9, 9}}, {"d", {1, 1, 1}}}}) {
    Json in = grid;
    in["ray"] = ray;
    inputs.push_back(in);
    in["any"] = true, in["t_max"] = 2.5;
    inputs.push_back(in);
  }
  for (const Json& in : inputs) {
    INFO(in.dump());
    const Recorded rec = a.open(in, Numeric::exact).record();
    const auto& t = dynamic_cast<const Recorder<Rational>&>(*rec.trace);
    const auto tris = triangles_of(in);
    const spatial::RayIn ray = spatial::parse_ray(in["ray"], "ray");
    const V3 o = spatial::vec_from<Rational, 3>(ray.o), d = spatial::vec_from<Rational, 3>(ray.d);
    const bool any = in.value("any", false);
    const Q t_max = any ? num::to_rational(in["t_max"].get<double>()) : Q(0);
    // The tree, from bvh-build's own (replayed) run on the same triangles.
    Json b_in = in;
    b_in.erase("ray"), b_in.erase("any"), b_in.erase("t_max");
    const Json tree = find_algorithm("bvh-build").open(b_in, Numeric::exact).run();
    auto node_box = [&](std::int64_t n) {
      const Json& nd = tree["tree"][static_cast<std::size_t>(n)];
      QBox b;
      for (int k = 0; k < 3; ++k) b.lo[k] = parse_rational(nd["lo"][k], "lo"), b.hi[k] = parse_rational(nd["hi"][k], "hi");
      return b;
    };
    auto entry = [&](std::int64_t n) {
      const QBox b = node_box(n);
      return oracle::ray_box(o, d, b.lo, b.hi);
    };
    // The build's steps are bvh-build's: the nested scope, replayed as such.
    std::size_t s = 0;
    while (s < t.size() && t.at(s).scope != 0) ++s;
    REQUIRE(s > 0);
    replay_build(t, 0, s, tris, tree);
    struct E {
      std::int64_t node;
      Q t;
    };
    std::vector<E> stack;
    bool hit = false;
    std::int64_t best = -1, current = -1;
    Q t_best;
    std::vector<std::int64_t> pending_tests;  // the current leaf's triangles, in order
    auto check_stack = [&](StepValues& sv, StepGeometry& g) {
      CHECK(sv["stack"] == Q(stack.size()));
      for (const E& e : stack) {
        const QBox b = node_box(e.node);
        GeoItem& it = g.take(GeoKind::box3);
        std::vector<Q> want = values(b.lo);
        for (const Q& x : values(b.hi)) want.push_back(x);
        CHECK(it.values == want);
        CHECK(it.label == "stack");
      }
    };
    for (; s < t.size(); ++s) {
      if (t.at(s).scope != 0) continue;  // ray-box and ray-triangle-watertight: the ray family's replays
      const std::string_view line = spatial::BvhTraverse::lines[t.at(s).line - 1].name;
      INFO("traverse step " << s << " line " << line);
      StepValues sv = values_of(t, s);
      StepGeometry g = geometry_of(t, s);
      if (line == "build") {
        CHECK(sv["nodes"] == Q(tree["nodes"].get<std::int64_t>()));
        CHECK(sv["depth"] == Q(tree["depth"].get<std::int64_t>()));
        GeoItem& r = g.take(GeoKind::ray3);
        CHECK(r.values == std::vector<Q>{o.x, o.y, o.z, d.x, d.y, d.z});
        CHECK(r.life == "keep");
        for (const auto& tr : tris) {  // the mesh, kept for the views (the build's items end with it)
          GeoItem& it = g.take(GeoKind::triangle3);
          std::vector<Q> v;
          for (const auto& c : tr) v.push_back(c.x), v.push_back(c.y), v.push_back(c.z);
          CHECK(it.values == v);
          CHECK(it.life == "keep");
        }
      } else if (line == "root") {
        const auto e = entry(0);
        CHECK(sv["hit"] == (e.hit ? 1 : 0));
        if (e.hit) {
          CHECK(sv["t_entry"] == e.t_near);
          stack.push_back({0, e.t_near});
        }
      } else if (line == "prune" || line == "pop") {
        REQUIRE(!stack.empty());
        const E e = stack.back();
        stack.pop_back();
        const bool pruned = any ? !(e.t < t_max) : hit && t_best < e.t;
        CHECK(pruned == (line == "prune"));
        CHECK(sv["node"] == Q(e.node));
        CHECK(sv["t_entry"] == e.t);
        if (pruned) {
          CHECK(sv[any ? "t_max" : "t_best"] == (any ? t_max : t_best));
        } else {
          current = e.node;
          const Json& nd = tree["tree"][static_cast<std::size_t>(e.node)];
          check_node(g.take(GeoKind::node3), e.node, nd["parent"].get<std::int64_t>(), node_box(e.node), "");
          check_stack(sv, g);
          pending_tests.clear();
          if (nd.contains("prims"))
            for (const Json& p : nd["prims"]) pending_tests.push_back(p.get<std::int64_t>());
        }
      } else if (line == "test") {
        REQUIRE(!pending_tests.empty());
        const std::int64_t i = pending_tests.front();
        pending_tests.erase(pending_tests.begin());
        CHECK(sv["prim"] == Q(i));
      } else if (line == "keep" || line == "stop") {
        const std::int64_t i = num::floor_int(sv["prim"]);
        const oracle::RayResult h = oracle::ray_triangle(o, d, tris[static_cast<std::size_t>(i)]);
        REQUIRE(h.hit);
        CHECK(sv["t"] == h.t);
        if (line == "keep") CHECK((!hit || h.t < t_best || (h.t == t_best && i < best)));
        else CHECK((any && h.t < t_max));
        hit = true, best = i, t_best = h.t;
        GeoItem& p = g.take(GeoKind::point3);
        CHECK(p.values == values(V3{o.x + h.t * d.x, o.y + h.t * d.y, o.z + h.t * d.z}));
        CHECK(p.label == "best");
        if (line == "stop") stack.clear();
      } else if (line == "boxes") {
        const Json& nd = tree["tree"][static_cast<std::size_t>(current)];
        const std::int64_t l = nd["children"][0], r = nd["children"][1];
        const auto el = entry(l), er = entry(r);
        CHECK(sv["left"] == Q(l));
        CHECK(sv["right"] == Q(r));
        CHECK(sv["left_hit"] == (el.hit ? 1 : 0));
        CHECK(sv["right_hit"] == (er.hit ? 1 : 0));
        if (el.hit) CHECK(sv["t_left"] == el.t_near);
        if (er.hit) CHECK(sv["t_right"] == er.t_near);
        // The push that follows: the farther first; the left on top on a tie.
        std::vector<E> hits;
        if (el.hit) hits.push_back({l, el.t_near});
        if (er.hit) hits.push_back({r, er.t_near});
        if (hits.size() == 2 && !(er.t_near < el.t_near)) std::swap(hits[0], hits[1]);
        for (const E& e : hits) stack.push_back(e);
      } else if (line == "push") {
        CHECK(sv["next"] == Q(stack.back().node));
        check_stack(sv, g);
      } else if (line == "done") {
        CHECK(s + 1 == t.size());
        CHECK(sv["hit"] == (hit ? 1 : 0));
        if (hit) {
          CHECK(sv["prim"] == Q(best));
          CHECK(sv["t"] == t_best);
        }
        CHECK(rec.result["hit"] == hit);
        // And the oracle's answer.
        const oracle::ClosestHit want = oracle::closest_hit(o, d, tris);
        if (!any && want.hit) CHECK(best == want.prim);
        if (!any) CHECK(hit == want.hit);
        else CHECK(hit == (want.hit && want.r.t < t_max));
      } else {
        FAIL("unexpected line " << line);
      }
      require_all_checked(sv, s);
      require_all_geometry_checked(g, s);
    }
  }
}
