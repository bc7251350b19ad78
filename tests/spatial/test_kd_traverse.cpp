// kd-traverse against the brute-force exact closest hit (closest_hit_oracle): random meshes and
// rays, and the hard cases: rays lying in the tree's split planes (with +0 and -0 components),
// origins on split planes, rays through the shared edges and vertices of a grid mesh, zero-area
// triangles, all triangles on one plane. Filtered and exact: 0 wrong; float and double counted.
#include <catch2/catch.hpp>
#include "kd_support.hpp"

using namespace sw;
using namespace sw::testing::kd;

namespace {

struct Tally {
  std::size_t rays = 0;
  std::array<std::size_t, 4> wrong{};  // float, double, filtered, exact
};

// Every mode against the oracle; robust modes must agree (hit, prim, and exactly t and b).
void shoot(Scene& sc, const RayIn& r, Tally& tally) {
  const HitOutput want = closest_hit_oracle(sc.mesh, r);
  ++tally.rays;
  const Numeric modes[] = {Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  for (int m = 0; m < 4; ++m) {
    const HitOutput got = sc.run(modes[m], r);
    const bool ok = got == want;
    tally.wrong[m] += !ok;
    if (m >= 2) {
      INFO(numeric_name(modes[m]) << " ray o " << r.o[0] << "," << r.o[1] << "," << r.o[2] << " d " << r.d[0] << "," << r.d[1] << "," << r.d[2]
                                  << ": got " << hit_json(got).dump() << " want " << hit_json(want).dump());
      CHECK(ok);
      if (m == 3 && want.hit) CHECK((got.exact && want.exact && got.exact->t == want.exact->t && got.exact->b == want.exact->b));
    }
  }
}

void report(const char* what, const Tally& t, const Scene& sc) {
  WARN(what << ": " << t.rays << " rays; wrong float " << t.wrong[0] << ", double " << t.wrong[1] << ", filtered " << t.wrong[2] << ", exact "
            << t.wrong[3] << " (filtered fell back to exact " << sc.fallbacks << " times)");
  CHECK(t.wrong[2] == 0);
  CHECK(t.wrong[3] == 0);
  CHECK(t.wrong[0] <= t.rays);
}

RayIn toward(std::mt19937_64& rng, const std::array<double, 3>& target, double dist) {
  RayIn r;
  for (int k = 0; k < 3; ++k) r.o[k] = target[k] + grid_coord(rng, -dist, dist, 10), r.d[k] = target[k] - r.o[k];
  if (r.d[0] == 0 && r.d[1] == 0 && r.d[2] == 0) r.d[2] = 1;
  return r;
}

// Rays lying in each split plane (d_k = +0 or -0, o_k = p), and rays starting on it.
void plane_rays(Scene& sc, std::mt19937_64& rng, Tally& t, std::size_t per_plane, double lo, double hi) {
  for (const auto& [k, p] : split_planes<3>(sc.kq)) {
    for (std::size_t i = 0; i < per_plane; ++i) {
      std::array<double, 3> target;
      for (int a = 0; a < 3; ++a) target[a] = grid_coord(rng, lo, hi, 4);
      target[k] = p.get_d();
      RayIn r = toward(rng, target, 2);
      r.o[k] = p.get_d(), r.d[k] = i % 2 ? -0.0 : 0.0;  // in the plane
      if (r.d[0] == 0 && r.d[1] == 0 && r.d[2] == 0) r.d[(k + 1) % 3] = 1;
      shoot(sc, r, t);
      RayIn s = toward(rng, target, 2);  // from the plane, out of it
      s.o[k] = p.get_d();
      if (s.d[k] == 0) s.d[k] = 1;
      shoot(sc, s, t);
    }
  }
}

}  // namespace

TEST_CASE("kd-traverse: random meshes and rays against the exact closest hit", "[spatial][spatial-kd]") {
  std::mt19937_64 rng(21);
  Tally t;
  Scene* last = nullptr;
  std::vector<std::unique_ptr<Scene>> scenes;
  for (std::size_t n : {60u, 200u}) {
    scenes.push_back(std::make_unique<Scene>(kdspec::random_mesh_for(300 + n, n)));
    Scene& sc = *scenes.back();
    last = &sc;
    for (int i = 0; i < 150; ++i) {
      const auto& v = sc.mesh.v[std::uniform_int_distribution<std::size_t>(0, sc.mesh.v.size() - 1)(rng)];
      std::array<double, 3> target = v;
      if (i % 3) for (double& x : target) x += grid_coord(rng, -0.05, 0.05, 12);  // near a vertex; a third through one
      shoot(sc, toward(rng, target, 3), t);
    }
    plane_rays(sc, rng, t, 1, -1, 1);
  }
  report("random meshes", t, *last);
}

TEST_CASE("kd-traverse: a grid mesh's shared edges and vertices, split planes, -0 and zero-area triangles", "[spatial][spatial-kd]") {
  std::mt19937_64 rng(22);
  Mesh m = grid_mesh(8);
  // Zero-area triangles over the grid (never hit, but held and tested), and a second layer on z = 1
  // so that hits compete in t.
  for (const auto& t : std::vector<std::array<std::array<double, 3>, 3>>{{{{2, 2, 0}, {2, 2, 0}, {2, 2, 0}}}, {{{0, 4, 0}, {8, 4, 0}, {4, 4, 0}}}}) {
    const auto base = static_cast<std::int32_t>(m.v.size());
    for (const auto& p : t) m.v.push_back(p);
    m.f.push_back({base, base + 1, base + 2});
  }
  const Mesh top = grid_mesh(2, 4, 1);
  for (const auto& f : top.f) {
    const auto base = static_cast<std::int32_t>(m.v.size());
    for (int c = 0; c < 3; ++c) m.v.push_back(top.v[f[c]]);
    m.f.push_back({base, base + 1, base + 2});
  }
  Scene sc(std::move(m));
  Tally t;
  for (int j = 0; j <= 8; ++j)
    for (int i = 0; i <= 8; ++i) {
      // Through the vertex (i, j), the middle of the edges from it, and the cell's diagonal.
      for (const std::array<double, 3> target : {std::array<double, 3>{double(i), double(j), 0}, {i + 0.5, double(j), 0}, {double(i), j + 0.5, 0}, {i + 0.25, j + 0.25, 0}})
        shoot(sc, toward(rng, target, 4), t);
      // Straight down (two zero components, one of them -0) and along the plane z = 0.
      shoot(sc, RayIn{{double(i), double(j), 3}, {-0.0, 0.0, -1}}, t);
      shoot(sc, RayIn{{double(i), -1, 0}, {-0.0, 1, 0}}, t);
    }
  plane_rays(sc, rng, t, 2, 0, 8);
  report("grid mesh", t, sc);
}

TEST_CASE("kd-traverse: the catalog run matches the oracle in every robust mode, and its result members", "[spatial][spatial-kd]") {
  const Algorithm& a = find_algorithm("kd-traverse");
  std::mt19937_64 rng(23);
  const Mesh m = grid_mesh(4);
  for (int i = 0; i < 12; ++i) {
    RayIn r = toward(rng, {grid_coord(rng, 0, 4, 1), grid_coord(rng, 0, 4, 1), 0}, 3);
    if (i % 4 == 0) r.d[0] = -0.0, r.o[0] = 2;
    Json in = mesh_json(m);
    in["ray"] = ray_json(r);
    const Json want = a.open(in).oracle();
    for (Numeric n : {Numeric::filtered, Numeric::exact}) {
      const Json got = a.open(in, n).run();
      INFO(in["ray"].dump() << " " << numeric_name(n) << " got " << got.dump() << " want " << want.dump());
      CHECK(got["hit"] == want["hit"]);
      if (want["hit"]) CHECK(got["prim"] == want["prim"]);
      if (n == Numeric::exact) CHECK(got["t"] == want["t"]);
      CHECK(got["nodes_visited"].get<int>() >= 1);
    }
  }
  for (const char* bad : {R"({"triangles":[[[0,0,0],[1,0,0],[0,1,0]]],"ray":{"o":[0,0,1],"d":[0,0,0]}})", R"({"triangles":[[[0,0,0],[1,0,0],[0,1,0]]]})",
                          R"({"triangles":[[[0,0,0],[1,0,0],[0,1,"nan"]]],"ray":{"o":[0,0,1],"d":[0,0,-1]}})"}) {
    INFO(bad);
    CHECK_THROWS_AS((void)a.open(Json::parse(bad), Numeric::exact), InputError);
  }
}
