// quadtree-build's and octree-build's steps: every variable and geometry item of every exact step
// against the build stated recursively here (depth first, child 0 first; mid = (lo + hi) / 2; a
// point goes to the child of the halves it is >= mid on; a triangle to every child whose closed
// cell oracle::triangle_meets_box (CGAL) says it meets; a node splits iff it holds more than
// capacity items below max_depth).
#include <catch2/catch.hpp>
#include <random>
#include "spatial/octree_build.hpp"
#include "spatial/quadtree_build.hpp"
#include "spatial_oracle.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;

namespace {

// One expected step: its line, its variables, and its geometry (kind, values, kept or not).
struct Want {
  std::string line;
  std::vector<std::pair<std::string, Rational>> vars;
  std::vector<std::tuple<GeoKind, std::vector<Rational>, bool>> geo;
};

template <int D> using P = spatial::VecN<Rational, D>;

template <int D> std::vector<Rational> node_values(long id, long parent, const P<D>& lo, const P<D>& hi) {
  std::vector<Rational> v{Rational(id), Rational(parent)};
  for (int a = 0; a < D; ++a) v.push_back(lo[a]);
  for (int a = 0; a < D; ++a) v.push_back(hi[a]);
  return v;
}

// The expected steps of a build over points (D = 2, 3) or triangles (D = 3, tris non-empty).
template <int D> struct Expect {
  const std::vector<P<D>>& pts;
  const std::vector<oracle::Triangle3>& tris;
  std::size_t cap;
  int max_depth;
  bool octree;
  std::vector<Want> steps;
  long nodes = 1, deepest = 0, refs = 0;

  void node(long id, long parent, const P<D>& lo, const P<D>& hi, const std::vector<std::int32_t>& items, int depth, long pending) {
    const bool split = items.size() > cap && depth < max_depth;
    steps.push_back({"visit", {{"node", id}, {"count", static_cast<long>(items.size())}, {"depth", depth}, {"split", Rational(split ? 1 : 0)}}, {{D == 2 ? GeoKind::node2 : GeoKind::node3, node_values<D>(id, parent, lo, hi), false}}});
    if (!split) {
      deepest = std::max<long>(deepest, depth);
      return;
    }
    P<D> mid;
    for (int a = 0; a < D; ++a) mid[a] = (lo[a] + hi[a]) / 2;
    const long first = nodes;
    constexpr int K = 1 << D;
    nodes += K;
    Want s{"split", {{"node", id}}, {}};
    for (int a = 0; a < D; ++a) s.vars.push_back({std::string("mid_") + "xyz"[a], mid[a]});
    std::array<P<D>, K> clo, chi;
    for (int c = 0; c < K; ++c) {
      for (int a = 0; a < D; ++a) clo[c][a] = c >> a & 1 ? mid[a] : lo[a], chi[c][a] = c >> a & 1 ? hi[a] : mid[a];
      s.geo.push_back({D == 2 ? GeoKind::node2 : GeoKind::node3, node_values<D>(first + c, id, clo[c], chi[c]), true});
    }
    steps.push_back(s);
    std::array<std::vector<std::int32_t>, K> child;
    refs -= static_cast<long>(items.size());
    for (std::int32_t i : items) {
      if (tris.empty()) {
        int c = 0;
        for (int a = 0; a < D; ++a) c |= (pts[i][a] >= mid[a]) << a;
        child[c].push_back(i), ++refs;
        std::vector<Rational> pv;
        for (int a = 0; a < D; ++a) pv.push_back(pts[i][a]);
        steps.push_back({octree ? "place_point" : "place", {{"point", i}, {"child", first + c}}, {{D == 2 ? GeoKind::point2 : GeoKind::point3, pv, false}}});
      } else if constexpr (D == 3) {
        long mask = 0;
        for (int c = 0; c < K; ++c)
          if (oracle::triangle_meets_box(tris[i], clo[c], chi[c])) child[c].push_back(i), mask |= 1 << c, ++refs;
        std::vector<Rational> tv;
        for (const auto& v : tris[i]) tv.insert(tv.end(), {v.x, v.y, v.z});
        steps.push_back({"place_triangle", {{"triangle", i}, {"children", mask}}, {{GeoKind::triangle3, tv, false}}});
      }
    }
    Want push{"push", {{"stack", pending + K}}, {}};
    if (octree) push.vars.push_back({"refs", refs});
    steps.push_back(push);
    for (int c = 0; c < K; ++c) node(first + c, id, clo[c], chi[c], child[c], depth + 1, pending + K - 1 - c);
  }
  void run() {
    P<D> lo, hi;
    const std::size_t n = tris.empty() ? pts.size() : tris.size();
    bool any = false;
    auto grow = [&](const auto& p) {
      for (int a = 0; a < D; ++a) lo[a] = any ? std::min(lo[a], p[a]) : p[a], hi[a] = any ? std::max(hi[a], p[a]) : p[a];
      any = true;
    };
    if constexpr (D == 3)
      for (const auto& t : tris)
        for (const auto& v : t) grow(v);
    for (const auto& p : pts) grow(p);
    std::vector<std::int32_t> all(n);
    for (std::size_t i = 0; i < n; ++i) all[i] = static_cast<std::int32_t>(i);
    refs = static_cast<long>(n);
    Want root{"root", {{octree ? "items" : "points", static_cast<long>(n)}}, {{D == 2 ? GeoKind::node2 : GeoKind::node3, node_values<D>(0, -1, lo, hi), true}}};
    for (const auto& p : pts) {  // the input, kept for the views
      std::vector<Rational> v;
      for (int a = 0; a < D; ++a) v.push_back(p[a]);
      root.geo.push_back({D == 2 ? GeoKind::point2 : GeoKind::point3, v, true});
    }
    for (const auto& t : tris) root.geo.push_back({GeoKind::triangle3, {t[0].x, t[0].y, t[0].z, t[1].x, t[1].y, t[1].z, t[2].x, t[2].y, t[2].z}, true});
    steps.push_back(root);
    node(0, -1, lo, hi, all, 0, 0);
    Want done{"done", {{"nodes", nodes}, {"depth", deepest}}, {}};
    if (octree) done.vars.push_back({"budget_stops", 0});
    steps.push_back(done);
  }
};

template <class L> void compare(const Recorder<Rational>& rec, const std::vector<Want>& want) {
  REQUIRE(rec.size() == want.size());
  for (std::size_t s = 0; s < rec.size(); ++s) {
    const std::string_view line = L::lines[rec.at(s).line - 1].name;
    INFO("step " << s << " line " << line);
    REQUIRE(line == want[s].line);
    StepValues sv = values_of(rec, s);
    StepGeometry g = geometry_of(rec, s);
    for (const auto& [name, value] : want[s].vars) CHECK(sv[name] == value);
    for (const auto& [kind, values, keep] : want[s].geo) {
      GeoItem& item = g.take(kind);
      CHECK(item.values == values);
      CHECK(item.life == (keep ? "keep" : ""));
    }
    require_all_checked(sv, s);
    require_all_geometry_checked(g, s);
  }
}

}  // namespace

TEST_CASE("quadtree-build steps: every recorded value against the recursive statement", "[spatial][spatial-pt]") {
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<long> c(0, 16);
  for (int set = 0; set < 12; ++set) {
    std::vector<P<2>> pts;
    const std::size_t n = 3 + static_cast<std::size_t>(set) * 3;
    for (std::size_t i = 0; i < n; ++i) pts.push_back({ratio(c(rng), set % 2 ? 1 : 4), ratio(c(rng), 2)});  // on split lines often
    if (set == 11) pts.assign(9, P<2>{ratio(1, 3), 2});                                                    // duplicates
    const std::size_t cap = 1 + static_cast<std::size_t>(set % 3);
    const int depth = 2 + set % 4;
    INFO("set " << set);
    Recorder<Rational> rec;
    (void)spatial::quadtree_build<Rational>(pts, cap, depth, rec);
    const std::vector<oracle::Triangle3> none;
    Expect<2> e{pts, none, cap, depth, false, {}};
    e.run();
    compare<spatial::QuadtreeBuild>(rec, e.steps);
  }
}

TEST_CASE("octree-build steps over points and triangles: every recorded value", "[spatial][spatial-pt]") {
  std::mt19937_64 rng(98);
  std::uniform_int_distribution<long> c(0, 8);
  for (int set = 0; set < 10; ++set) {
    const bool with_tris = set % 2 == 1;
    spatial::OctreeItems<Rational> items;
    std::vector<P<3>> pts;
    std::vector<oracle::Triangle3> tris;
    for (int i = 0; i < 4 + set * 2; ++i) {
      if (with_tris) {
        oracle::Triangle3 t;
        for (auto& v : t) v = {ratio(c(rng), 1), ratio(c(rng), 2), ratio(c(rng), 1)};
        if (i % 5 == 4) t[2] = t[1];  // zero area
        tris.push_back(t);
      } else {
        pts.push_back({ratio(c(rng), 1), ratio(c(rng), 2), ratio(c(rng), 4)});
      }
    }
    items.points = pts;
    items.triangles.assign(tris.begin(), tris.end());
    const std::size_t cap = 1 + static_cast<std::size_t>(set % 3);
    const int depth = 2 + set % 2;
    INFO("set " << set);
    Recorder<Rational> rec;
    (void)spatial::octree_build<Rational>(items, cap, depth, std::size_t{1} << 22, rec);
    Expect<3> e{pts, tris, cap, depth, true, {}};
    e.run();
    compare<spatial::OctreeBuild>(rec, e.steps);
  }
}
