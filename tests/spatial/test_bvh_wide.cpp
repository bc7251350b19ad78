// bvh-traverse's wide fast path (spatial/bvh_wide.hpp) against the walk with ray-box: every box
// answer of every group, and the whole answer of every query (hit, prim, t and b bit for bit, the
// counts of nodes and triangles), on random meshes, a grid mesh's shared edges and vertices,
// axis-parallel rays with -0 components and origins on box faces, 10^3 identical triangles (the
// deepest trees), and any-hit queries.
#include <catch2/catch.hpp>
#include <cstring>
#include "spatial/bvh_cases.hpp"
#include "spatial/bvh_wide.hpp"

using namespace sw;
using spatial::Mesh;
using spatial::RayIn;

namespace {

using Tris = std::vector<std::array<Vec3<double>, 3>>;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

Tris tris_of(const Mesh& m) {
  Tris t;
  for (std::size_t i = 0; i < m.size(); ++i) t.push_back(m.triangle<double>(i));
  return t;
}

ray::Ray3<double> ray_of(const RayIn& r) { return {{r.o[0], r.o[1], r.o[2]}, {r.d[0], r.d[1], r.d[2]}}; }

// The box answers ray_box gives, field by field ("" when they are the same bits).
std::string box_difference(const ray::BoxHit<double>& a, const ray::BoxHit<double>& b) {
  if (a.hit != b.hit) return "hit";
  if (!same_bits(a.t_near, b.t_near)) return "t_near";
  if (!same_bits(a.t_far, b.t_far)) return "t_far";
  if (!same_bits(a.t, b.t)) return "t";
  return "";
}

// Every inner node's children through WideBoxes, parents before children (as a walk asks), against
// ray_box one box at a time. Returns the boxes compared.
std::size_t check_every_box(const spatial::Bvh<double>& bvh, const spatial::BvhWide& w, const ray::Ray3<double>& r) {
  NoProbe none;
  spatial::WideBoxes wide(bvh, w, r);
  spatial::RayBoxes<double> one{bvh, r};
  std::size_t compared = 0;
  auto compare = [&](std::int32_t n) {
    const auto a = wide.children(n, none), b = one.children(n, none);
    for (int c = 0; c < 2; ++c) {
      INFO("node " << n << " child " << c);
      CHECK(box_difference(a[c], b[c]) == "");
      ++compared;
    }
  };
  for (std::size_t n = 0; n < bvh.nodes.size(); ++n) {
    const auto& nd = bvh.nodes[n];
    if (nd.left < 0 || nd.depth % 2 != 0) continue;
    compare(static_cast<std::int32_t>(n));
    for (const std::int32_t c : {nd.left, nd.right})
      if (bvh.nodes[c].left >= 0) compare(c);
  }
  return compared;
}

// The whole answer of the query both ways ("" when the same).
std::string query_difference(const spatial::Bvh<double>& bvh, const spatial::BvhWide& w, const Tris& tris, const ray::Ray3<double>& r,
                             const spatial::BvhQuery<double>& q) {
  NoProbe none;
  const auto a = spatial::bvh_query(w, bvh, tris, r, q), b = spatial::bvh_query<double>(bvh, tris, r, q, none);
  if (a.hit != b.hit || a.prim != b.prim) return "hit or prim";
  if (!same_bits(a.t, b.t)) return "t";
  for (int k = 0; k < 3; ++k)
    if (!same_bits(a.b[k], b.b[k])) return "b";
  if (a.nodes_visited != b.nodes_visited) return "nodes visited";
  if (a.prim_tests != b.prim_tests) return "triangles tested";
  return "";
}

struct Counts {
  std::size_t boxes = 0, queries = 0, hits = 0;
};

void check_mesh(const Mesh& m, const std::vector<RayIn>& rays, Counts& counts) {
  const Tris tris = tris_of(m);
  NoProbe none;
  const spatial::Bvh<double> bvh = spatial::bvh_build<double>(tris, none);
  const spatial::BvhWide w = spatial::bvh_widen(bvh);
  for (const RayIn& in : rays) {
    const auto r = ray_of(in);
    counts.boxes += check_every_box(bvh, w, r);
    spatial::BvhQuery<double> closest, any;
    any.any = true, any.t_max = 2;
    for (const auto& q : {closest, any}) {
      INFO("ray o " << in.o[0] << " " << in.o[1] << " " << in.o[2] << " d " << in.d[0] << " " << in.d[1] << " " << in.d[2] << " any " << q.any);
      CHECK(query_difference(bvh, w, tris, r, q) == "");
      ++counts.queries;
    }
    counts.hits += spatial::bvh_query(w, bvh, tris, r, closest).hit;
  }
}

}  // namespace

TEST_CASE("bvh-traverse wide: random meshes, every box and every answer as the walk with ray-box", "[spatial][spatial-bvh]") {
  std::mt19937_64 rng(20261207);
  Counts counts;
  for (const std::size_t n : {std::size_t{1}, std::size_t{7}, std::size_t{60}, std::size_t{2000}}) {
    const Mesh m = spatial::cases::random_mesh(rng, n, 0.2);
    std::vector<RayIn> rays;
    for (int i = 0; i < 60; ++i) rays.push_back(spatial::cases::random_ray(rng));
    check_mesh(m, rays, counts);
  }
  CHECK(counts.queries == 480);
  CHECK(counts.hits > 60);      // the rays do meet the meshes
  CHECK(counts.boxes > 20000);  // and the groups hold many boxes
}

TEST_CASE("bvh-traverse wide: a grid mesh's shared edges and vertices, axis-parallel rays, -0 and origins on faces", "[spatial][spatial-bvh]") {
  std::mt19937_64 rng(20261208);
  Counts counts;
  for (const bool flat : {false, true}) {
    const Mesh g = spatial::cases::grid_mesh(16, 16, flat, 9);
    std::vector<RayIn> rays;
    for (int i = 0; i < 90; ++i) rays.push_back(spatial::cases::grid_ray(g, 16, 16, rng, i % 3));
    // Axis-parallel rays (+0 and -0 components) from the grid's vertices, edges and box faces.
    for (int i = 0; i <= 16; i += 4)
      for (const double zero : {0.0, -0.0}) {
        rays.push_back({{double(i), 3.0, 5.0}, {zero, zero, -1.0}});
        rays.push_back({{double(i), 0.5, 0.0}, {zero, 1.0, zero}});
        rays.push_back({{0.0, double(i), 1.0}, {1.0, zero, zero}});   // origin on the root box's face
        rays.push_back({{16.0, double(i), -1.0}, {-1.0, zero, zero}});  // on the opposite face, its corner edge
      }
    check_mesh(g, rays, counts);
  }
  CHECK(counts.queries == 2 * 2 * (90 + 5 * 2 * 4));
  CHECK(counts.hits > 150);
}

TEST_CASE("bvh-traverse wide: 10^3 identical triangles (median splits to the deepest tree)", "[spatial][spatial-bvh]") {
  Mesh m;
  for (int i = 0; i < 1000; ++i) {
    const auto b = static_cast<std::int32_t>(m.v.size());
    m.v.push_back({0, 0, 0}), m.v.push_back({1, 0, 0}), m.v.push_back({0, 1, 0});
    m.f.push_back({b, b + 1, b + 2});
  }
  std::mt19937_64 rng(5);
  std::vector<RayIn> rays{{{0.25, 0.25, 1}, {0, 0, -1}}, {{0, 0, 1}, {0, 0, -1}}, {{0.5, 0.5, 1}, {-0.0, 0.0, -1}}};
  for (int i = 0; i < 20; ++i) rays.push_back(spatial::cases::random_ray(rng));
  Counts counts;
  check_mesh(m, rays, counts);
  CHECK(counts.hits >= 3);
  NoProbe none;
  const Tris tris = tris_of(m);
  const auto bvh = spatial::bvh_build<double>(tris, none);
  const auto h = spatial::bvh_query(spatial::bvh_widen(bvh), bvh, tris, ray_of(rays[0]), {});
  CHECK(h.hit);
  CHECK(h.prim == 0);  // the lowest id of the equal hits
}
