// kd-build: the structure of every build checked exactly (tests/spatial/kd_support.hpp): cells
// cut at one plane inside the parent, every triangle meeting a leaf's closed cell held by it
// (CGAL's exact triangle-box overlap), every point held by exactly one leaf with the points on a
// node's plane on one side; the hard inputs (identical points, one plane, zero-area triangles);
// the O(N log N) work counted; bad inputs and the trace budget.
#include <catch2/catch.hpp>
#include "kd_support.hpp"
#include "trace_io.hpp"

using namespace sw;
using namespace sw::testing::kd;

namespace {

const Algorithm& build_alg() { return find_algorithm("kd-build"); }

// Builds in every mode through the catalog and checks the structure; robust modes must be clean.
void check_mesh_all_modes(const Mesh& m, std::array<std::size_t, 2>& rounded_violations) {
  const Json in = mesh_json(m);
  for (Numeric n : {Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact}) {
    INFO(numeric_name(n) << ", " << m.size() << " triangles");
    Violations v;
    check_triangle_tree(read_tree(build_alg().open(in, n).run()), m, v);
    if (n == Numeric::filtered || n == Numeric::exact) {
      CHECK(v.cells == 0);
      CHECK(v.missing == 0);
      CHECK(v.extra == 0);
      CHECK(v.shape == 0);
    } else {
      rounded_violations[n == Numeric::f32 ? 0 : 1] += v.total();
    }
  }
}

std::vector<std::array<Q, 3>> exact_points(const Json& pts) {
  std::vector<std::array<Q, 3>> out;
  for (const Json& p : pts) out.push_back({parse_rational(p[0], "x"), parse_rational(p[1], "y"), p.size() > 2 ? parse_rational(p[2], "z") : Q(0)});
  return out;
}

void check_points_all_modes(const Json& pts, std::array<std::size_t, 2>& rounded_violations) {
  const Json in{{"points", pts}};
  const auto exact = exact_points(pts);
  for (Numeric n : {Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact}) {
    INFO(numeric_name(n) << ", " << pts.size() << " points of " << pts[0].size());
    Violations v;
    check_point_tree(read_tree(build_alg().open(in, n).run()), exact, v);
    if (n == Numeric::filtered || n == Numeric::exact) {
      CHECK(v.cells == 0);
      CHECK(v.held == 0);
      CHECK(v.planes == 0);
      CHECK(v.shape == 0);
    } else {
      rounded_violations[n == Numeric::f32 ? 0 : 1] += v.total();
    }
  }
}

Json random_points(std::mt19937_64& rng, int n, int dim, int bits, double dup) {
  Json pts = Json::array();
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < n; ++i) {
    if (i > 0 && u(rng) < dup) {  // a duplicate of an earlier point
      pts.push_back(pts[std::uniform_int_distribution<int>(0, i - 1)(rng)]);
      continue;
    }
    Json p = Json::array();
    for (int k = 0; k < dim; ++k) p.push_back(grid_coord(rng, -4, 4, bits));
    pts.push_back(p);
  }
  return pts;
}

}  // namespace

TEST_CASE("kd-build: random and grid meshes, every mode, the structure holds exactly", "[spatial][spatial-kd]") {
  std::array<std::size_t, 2> rounded{};
  for (int s = 0; s < 4; ++s) check_mesh_all_modes(kdspec::random_mesh_for(100 + s, 40 + 40 * s), rounded);
  check_mesh_all_modes(grid_mesh(6), rounded);                 // shared vertices and edges, all on z = 0
  check_mesh_all_modes(grid_mesh(5, 0.1, 0.3), rounded);       // 0.1 is not a dyadic: float rounds it
  WARN("kd-build meshes: structure violations float " << rounded[0] << ", double " << rounded[1]);
  // Rounded modes are counted, not asserted clean; but float must show its failures here (30-bit coordinates and
  // 0.1 do not fit 24 bits), or the checker would be blind to them.
  CHECK(rounded[0] > 0);
}

TEST_CASE("kd-build: zero-area triangles and triangles on one plane", "[spatial][spatial-kd]") {
  std::mt19937_64 rng(7);
  Mesh m = grid_mesh(4);
  // Zero-area triangles: a point, a segment along an axis, a segment across the grid.
  for (const auto& t : std::vector<std::array<std::array<double, 3>, 3>>{{{{1, 1, 0}, {1, 1, 0}, {1, 1, 0}}},
                                                                          {{{0, 2, 0}, {4, 2, 0}, {2, 2, 0}}},
                                                                          {{{0.5, 0.5, 0}, {3.5, 2.5, 0}, {2, 1.5, 0}}},
                                                                          {{{2, 2, -1}, {2, 2, 1}, {2, 2, 0}}}}) {
    const auto base = static_cast<std::int32_t>(m.v.size());
    for (const auto& p : t) m.v.push_back(p);
    m.f.push_back({base, base + 1, base + 2});
  }
  std::array<std::size_t, 2> rounded{};
  check_mesh_all_modes(m, rounded);
  // Overlapping random triangles, all on the plane y = 1/2.
  Mesh flat;
  for (int i = 0; i < 40; ++i) {
    for (int c = 0; c < 3; ++c) flat.v.push_back({grid_coord(rng, -2, 2, 4), 0.5, grid_coord(rng, -2, 2, 4)});
    flat.f.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  check_mesh_all_modes(flat, rounded);
  WARN("kd-build zero-area and coplanar: structure violations float " << rounded[0] << ", double " << rounded[1]);
}

TEST_CASE("kd-build: points in 2D and 3D, duplicates and grids, each held by one leaf", "[spatial][spatial-kd]") {
  std::mt19937_64 rng(11);
  std::array<std::size_t, 2> rounded{};
  for (int dim : {2, 3}) {
    check_points_all_modes(random_points(rng, 150, dim, 30, 0), rounded);
    check_points_all_modes(random_points(rng, 150, dim, 1, 0.3), rounded);  // many on one plane, 30% duplicates
  }
  WARN("kd-build points: structure violations float " << rounded[0] << ", double " << rounded[1]);
  CHECK(rounded[0] > 0);  // 30-bit coordinates do not fit float: the checker must see it
}

TEST_CASE("kd-build: 10^4 identical points stop at once, and with one more point the depth stays bounded", "[spatial][spatial-kd]") {
  for (int dim : {2, 3}) {
    Json pts = Json::array();
    for (int i = 0; i < 10000; ++i) pts.push_back(dim == 2 ? Json{0.25, -3} : Json{0.25, -3, 7});
    for (Numeric n : {Numeric::f64, Numeric::exact}) {
      const Json r = build_alg().open({{"points", pts}}, n).run();
      CHECK(r["nodes"] == 1);
      CHECK(r["depth"] == 0);
      CHECK(r["tree"][0]["prims"].size() == 10000);
    }
    pts.push_back(dim == 2 ? Json{1, 1} : Json{1, 1, 1});
    const Json r = build_alg().open({{"points", pts}}, Numeric::filtered).run();
    CHECK(r["depth"].get<int>() <= kd_max_depth(10001));
    Violations v;
    check_point_tree(read_tree(r), exact_points(pts), v);
    CHECK(v.total() == 0);
  }
}

TEST_CASE("kd-build: the work is O(N log N): events swept and split per N log2 N stays flat", "[spatial][spatial-kd]") {
  // The events are sorted once (at the root); below it every node touches each of its events a
  // bounded number of times, so the work per N log2 N must not grow with N.
  std::vector<double> ratio;
  for (std::size_t n : {1000u, 4000u, 16000u}) {
    const Mesh m = kdspec::random_mesh_for(500 + n, n);
    const KdTree<double, 3> t = mesh_tree(mesh_tris<double>(m));
    ratio.push_back(static_cast<double>(t.events_touched) / (static_cast<double>(n) * std::log2(static_cast<double>(n))));
    INFO("n " << n << " events touched " << t.events_touched << " depth " << t.depth << " nodes " << t.nodes.size());
    CHECK(t.depth <= static_cast<std::size_t>(kd_max_depth(n)));
  }
  INFO("events per N log2 N: " << ratio[0] << ", " << ratio[1] << ", " << ratio[2]);
  CHECK(ratio[2] < 1.5 * ratio[0]);
  CHECK(ratio[2] < 40);
}

TEST_CASE("kd-build: bad input is one line, and an input beyond the work budget is refused", "[spatial][spatial-kd]") {
  const Algorithm& a = build_alg();
  check_refused(a, {R"({"points":[]})", R"({"points":[[1,2,3,4]]})", R"({"points":[[1,2],[1,2,3]]})", R"({"points":[[1,"nan"]]})",
                    R"({"points":[[1,"inf"]]})", R"({"points":[[1,2]],"k":1})", R"({"triangles":[[[0,0,0],[1,0,0]]]})",
                    R"({"points":[[1,2]],"triangles":[]})", R"({"points":[[1e300,2]]})", "[1,2]"});
  Json pts = Json::array();
  std::mt19937_64 rng(3);
  for (int i = 0; i < 50000; ++i) pts.push_back({grid_coord(rng, 0, 1, 20), grid_coord(rng, 0, 1, 20)});
  const Json big{{"points", pts}};
  // About 4.8 million estimated steps: over the default work budget (docs/cli.md), within a raised one.
  CHECK_THROWS_WITH(a.open(big, Numeric::f64).check_budget(Budget{}), Catch::Contains("steps, more than the budget of 4000000 (--max-steps raises it)"));
  CHECK_NOTHROW(a.open(big, Numeric::f64).check_budget(Budget{5'000'000}));
  CHECK(a.open(big, Numeric::f64).run()["leaves"].get<int>() > 1000);
}
