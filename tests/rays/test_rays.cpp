// The ray family: the corpus and random cases against the exact oracle (expected outcomes come
// from oracle/rays_oracle at test time), watertightness on a tessellated grid, bad input, and the
// filter's budget.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <sys/wait.h>
#include "catalog.hpp"
#include "scale.hpp"
#include "ray_test_support.hpp"
#include "rays/cases.hpp"
#include "rays_oracle.hpp"
#include "trace_io.hpp"
#include "rays/ray_box.hpp"
#include "rays/ray_plane.hpp"
#include "rays/ray_sphere_geometric.hpp"
#include "rays/ray_sphere_quadratic.hpp"
#include "rays/ray_sphere_stable.hpp"
#include "rays/ray_triangle_barycentric.hpp"
#include "rays/ray_triangle_mt.hpp"
#include "rays/ray_triangle_watertight.hpp"

using namespace sw;
using namespace sw::testing::rays;

TEST_CASE("rays: every corpus case: exact and filtered equal the oracle and float and double stay finite", "[rays]") {
  int cases = 0;
  for (const Json& c : read_jsonl("corpus.jsonl")) {
    const std::string prim = c["primitive"];
    for (const std::string& id : kAlgs.at(prim)) {
      const Algorithm& alg = find_algorithm(id);
      INFO(c["name"].get<std::string>() << " " << id);
      const Json want = alg.open(c["input"]).oracle();
      const Json exact = alg.open(c["input"], Numeric::exact).run();
      CHECK(same_result(exact, want));
      const Json filtered = alg.open(c["input"], Numeric::filtered).run();
      CHECK(filtered["hit"] == want["hit"]);
      if (filtered["fallback"].get<bool>()) CHECK(same_result(filtered, want));
      for (Numeric n : {Numeric::f32, Numeric::f64}) {
        const Json r = alg.open(c["input"], n).run();
        if (r["hit"].get<bool>()) CHECK(std::isfinite(r["t"].get<double>()));
      }
      ++cases;
    }
  }
  CHECK(cases > 50);
}

TEST_CASE("rays: the named corpus outcomes", "[rays]") {
  // Spot checks that the corpus says what its notes claim, as decided by the oracle.
  std::map<std::string, Json> by_name;
  for (const Json& c : read_jsonl("corpus.jsonl")) by_name[c["name"]] = c;
  auto oracle_hit = [&](const char* name) {
    const Json& c = by_name.at(name);
    return find_algorithm(kAlgs.at(c["primitive"])[0]).open(c["input"]).oracle()["hit"].get<bool>();
  };
  CHECK(oracle_hit("crack-a"));
  CHECK(oracle_hit("crack-b"));
  CHECK_FALSE(oracle_hit("pbrt-sliver"));
  CHECK_FALSE(oracle_hit("in-plane"));
  CHECK_FALSE(oracle_hit("origin-on-triangle"));
  CHECK(oracle_hit("grazing-sphere"));
  CHECK_FALSE(oracle_hit("just-miss-sphere"));
  CHECK(oracle_hit("just-hit-sphere"));
  CHECK(oracle_hit("far-1e8"));
  CHECK_FALSE(oracle_hit("origin-on-surface-out"));
  CHECK_FALSE(oracle_hit("origin-on-surface-tangent"));
  CHECK(oracle_hit("box-axis-zero-on-slab"));
  CHECK(oracle_hit("box-neg-zero"));
  CHECK_FALSE(oracle_hit("plane-parallel"));
  CHECK_FALSE(oracle_hit("plane-in"));
  CHECK(oracle_hit("plane-nearly-parallel"));
  // Interpolated attributes at b = (1/4, 1/4, 1/2): uv = (1/4, 1/2), normal = (1/6, 1/3 + 0.15, 1/3 + 0.25 + 0.2).
  const Json attr = find_algorithm("ray-triangle-watertight").open(by_name.at("attr-uv-normal")["input"], Numeric::exact).run();
  CHECK(q(attr["attr"][0]) == Rational(1, 4));
  CHECK(q(attr["attr"][1]) == Rational(1, 2));
  CHECK(q(attr["attr"][2]) == Rational(1, 6));
  CHECK_FALSE(find_algorithm("ray-triangle-mt").open(by_name.at("attr-miss")["input"], Numeric::exact).run().contains("attr"));
  // The stable sphere survives the far small sphere in double; the quadratic does not have to.
  const Json far = by_name.at("far-1e8")["input"];
  CHECK(find_algorithm("ray-sphere-stable").open(far, Numeric::f64).run()["hit"].get<bool>());
  // The box never produces NaN on zero / -0 components with the origin on a slab plane.
  for (const char* name : {"box-axis-zero-on-slab", "box-neg-zero"})
    for (Numeric n : {Numeric::f32, Numeric::f64}) {
      const Json r = find_algorithm("ray-box").open(by_name.at(name)["input"], n).run();
      REQUIRE(r["hit"].get<bool>());
      CHECK(std::isfinite(r["t_near"].get<double>()));
      CHECK(std::isfinite(r["t_far"].get<double>()));
    }
}

TEST_CASE("rays: bad input is an InputError (exit 2 from the CLI)", "[rays]") {
  for (const Json& c : read_jsonl("bad_inputs.jsonl"))
    for (const std::string& id : kAlgs.at(c["primitive"]))
      for (Numeric n : {Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact}) {
        INFO(c["why"].get<std::string>() << " " << id);
        CHECK_THROWS_AS((void)find_algorithm(id).open(c["input"], n), InputError);
      }
  const std::string cmd = std::string(SW_STEPWISE_EXE) +
                          " trace ray-sphere-stable --input '{\"ray\":{\"o\":[0,0,0],\"d\":[0,0,0]},\"sphere\":{\"c\":[0,0,5],\"r\":1}}'"
                          " >/dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  CHECK(WEXITSTATUS(status) == 2);
}

TEST_CASE("rays: tessellated grid, rays through every shared edge and vertex", "[rays]") {
  const rays::Grid g = rays::make_grid(16, 7);
  const std::vector<rays::FRay> shots = rays::grid_rays(g, 4, 8);
  int misses_wt[2] = {0, 0}, misses_mt[2] = {0, 0}, misses_bary[2] = {0, 0};
  for (const rays::FRay& r : shots) {
    // The triangles of the 3 x 3 cells around the aim point; the exact ray must hit one of them.
    std::vector<int> tris;
    for (int cj = std::max(r.cj - 1, 0); cj <= std::min(r.cj + 1, g.n - 1); ++cj)
      for (int ci = std::max(r.ci - 1, 0); ci <= std::min(r.ci + 1, g.n - 1); ++ci) tris.push_back(2 * (cj * g.n + ci)), tris.push_back(2 * (cj * g.n + ci) + 1);
    const V3 o{r.o[0], r.o[1], r.o[2]}, d{r.d[0], r.d[1], r.d[2]};
    bool oracle_hit = false;
    for (int t : tris) {
      const auto tri = g.triangle(t);
      std::array<V3, 3> v;
      for (int i = 0; i < 3; ++i) v[i] = {tri[i][0], tri[i][1], tri[i][2]};
      oracle_hit = oracle_hit || oracle::ray_triangle(o, d, v).hit;
    }
    REQUIRE(oracle_hit);
    auto count = [&](auto t0) {
      using Num = typename decltype(t0)::type;
      const ray::Ray3<Num> ray{{Num(r.o[0]), Num(r.o[1]), Num(r.o[2])}, {Num(r.d[0]), Num(r.d[1]), Num(r.d[2])}};
      bool wt = false, mt = false, bary = false;
      NoProbe none;
      for (int t : tris) {
        const auto tri = g.triangle(t);
        std::array<Vec3<Num>, 3> v;
        for (int i = 0; i < 3; ++i) v[i] = {Num(tri[i][0]), Num(tri[i][1]), Num(tri[i][2])};
        wt = wt || ray::ray_triangle_watertight<Num>(ray, v, none).hit;
        mt = mt || ray::ray_triangle_mt<Num>(ray, v, none).hit;
        bary = bary || ray::ray_triangle_barycentric<Num>(ray, v, none).hit;
      }
      const int k = std::is_same_v<Num, float> ? 0 : 1;
      misses_wt[k] += !wt, misses_mt[k] += !mt, misses_bary[k] += !bary;
    };
    count(std::type_identity<float>{});
    count(std::type_identity<double>{});
  }
  WARN("grid: " << shots.size() << " rays; misses float/double: watertight " << misses_wt[0] << "/" << misses_wt[1]
                << ", Moller-Trumbore " << misses_mt[0] << "/" << misses_mt[1] << ", barycentric " << misses_bary[0] << "/"
                << misses_bary[1]);
  CHECK(misses_wt[0] == 0);
  CHECK(misses_wt[1] == 0);
}

// Random float cases: the filtered variant (exact fallback included) and the exact variant equal
// the oracle's hit; exact also its t (and b).
TEST_CASE("rays: seeded random cases against the oracle", "[rays]") {
  constexpr int kFiltered = sw::testing::cases(100000), kExact = kFiltered;
  std::mt19937_64 rng(42);
  auto u = [&](double lo, double hi) { return float(std::uniform_real_distribution<double>(lo, hi)(rng)); };
  auto fv = [&](double lo, double hi) { return std::array<float, 3>{u(lo, hi), u(lo, hi), u(lo, hi)}; };
  auto rq = [](const std::array<float, 3>& a) { return V3{a[0], a[1], a[2]}; };
  NoProbe none;
  int fallbacks = 0;
  for (int k = 0; k < kFiltered; ++k) {
    const auto o = fv(-3, 3), d = fv(-1, 1), a = fv(-1, 1), b = fv(-1, 1), c = fv(-1, 1);
    if (d == std::array<float, 3>{0, 0, 0}) continue;
    const float r = u(0.1, 1.5);
    const V3 oq = rq(o), dq = rq(d);
    const bool exact_too = k < kExact;
    // The filtered chain of runtime/rays.cpp: Mag, then Interval, then exact. MagChecked runs too:
    // it throws logic_error if a decision exceeds Mag's index budget or a product nears underflow.
    auto run = [&](auto&& alg, const oracle::RayResult& want, auto&& exact_check) {
      try {
        (void)run_filter_stage<MagChecked>([&] { return alg(std::type_identity<MagChecked>{}); });
      } catch (const Uncertain&) {
      }
      const bool hit = [&] {
        try {
          return run_filter_stage<Mag>([&] { return alg(std::type_identity<Mag>{}).hit; });
        } catch (const Uncertain&) {
          ++fallbacks;
          try {
            return alg(std::type_identity<Interval>{}).hit;
          } catch (const Uncertain&) {
            return alg(std::type_identity<Rational>{}).hit;
          }
        }
      }();
      REQUIRE(hit == want.hit);
      if (exact_too) {
        const auto h = alg(std::type_identity<Rational>{});
        REQUIRE(h.hit == want.hit);
        if (h.hit) exact_check(h);
      }
    };
    // triangle
    {
      const std::array<V3, 3> vq{rq(a), rq(b), rq(c)};
      const auto want = oracle::ray_triangle(oq, dq, vq);
      auto check_tri = [&](const auto& h) {
        REQUIRE(h.t == want.t);
        REQUIRE(h.b == want.b);
      };
      auto with = [&](auto fn) {
        return [&, fn](auto t) {
          using Num = typename decltype(t)::type;
          const ray::Ray3<Num> ray{{Num(o[0]), Num(o[1]), Num(o[2])}, {Num(d[0]), Num(d[1]), Num(d[2])}};
          const std::array<Vec3<Num>, 3> v{Vec3<Num>{Num(a[0]), Num(a[1]), Num(a[2])}, Vec3<Num>{Num(b[0]), Num(b[1]), Num(b[2])},
                                           Vec3<Num>{Num(c[0]), Num(c[1]), Num(c[2])}};
          return fn(ray, v, t);
        };
      };
      run(with([&](const auto& ray, const auto& v, auto t) { return ray::ray_triangle_watertight<typename decltype(t)::type>(ray, v, none); }), want, check_tri);
      run(with([&](const auto& ray, const auto& v, auto t) { return ray::ray_triangle_mt<typename decltype(t)::type>(ray, v, none); }), want, check_tri);
      run(with([&](const auto& ray, const auto& v, auto t) { return ray::ray_triangle_barycentric<typename decltype(t)::type>(ray, v, none); }), want, check_tri);
    }
    // sphere (centre a, radius r), box (a sorted against b), plane (p = a, n = b)
    {
      const auto want = oracle::ray_sphere(oq, dq, rq(a), Rational(r));
      auto check_sph = [&](const auto& h) { REQUIRE((h.t_exact ? h.t : num::round_bits(h.t, oracle::kSphereTBits)) == want.t); };
      auto with = [&](auto fn) {
        return [&, fn](auto t) {
          using Num = typename decltype(t)::type;
          const ray::Ray3<Num> ray{{Num(o[0]), Num(o[1]), Num(o[2])}, {Num(d[0]), Num(d[1]), Num(d[2])}};
          return fn(ray, Vec3<Num>{Num(a[0]), Num(a[1]), Num(a[2])}, Num(r), t);
        };
      };
      run(with([&](const auto& ray, const auto& cc, const auto& rr, auto t) { return ray::ray_sphere_geometric<typename decltype(t)::type>(ray, cc, rr, none); }), want, check_sph);
      run(with([&](const auto& ray, const auto& cc, const auto& rr, auto t) { return ray::ray_sphere_quadratic<typename decltype(t)::type>(ray, cc, rr, none); }), want, check_sph);
      run(with([&](const auto& ray, const auto& cc, const auto& rr, auto t) { return ray::ray_sphere_stable<typename decltype(t)::type>(ray, cc, rr, none); }), want, check_sph);
    }
    {
      std::array<float, 3> lo, hi;
      for (int i = 0; i < 3; ++i) lo[i] = std::min(a[i], b[i]), hi[i] = std::max(a[i], b[i]);
      const auto want = oracle::ray_box(oq, dq, rq(lo), rq(hi));
      run([&](auto t) {
            using Num = typename decltype(t)::type;
            const ray::Ray3<Num> ray{{Num(o[0]), Num(o[1]), Num(o[2])}, {Num(d[0]), Num(d[1]), Num(d[2])}};
            return ray::ray_box<Num>(ray, {Num(lo[0]), Num(lo[1]), Num(lo[2])}, {Num(hi[0]), Num(hi[1]), Num(hi[2])}, none);
          },
          want, [&](const auto& h) { REQUIRE((h.t == want.t && h.t_near == want.t_near && h.t_far == want.t_far)); });
      if (b != std::array<float, 3>{0, 0, 0}) {
        const auto wp = oracle::ray_plane(oq, dq, rq(a), rq(b));
        run([&](auto t) {
              using Num = typename decltype(t)::type;
              const ray::Ray3<Num> ray{{Num(o[0]), Num(o[1]), Num(o[2])}, {Num(d[0]), Num(d[1]), Num(d[2])}};
              return ray::ray_plane<Num>(ray, {Num(a[0]), Num(a[1]), Num(a[2])}, {Num(b[0]), Num(b[1]), Num(b[2])}, none);
            },
            wp, [&](const auto& h) { REQUIRE(h.t == wp.t); });
      }
    }
  }
  WARN("random: " << kFiltered << " cases per primitive (filtered), " << kExact << " exact; filtered fallbacks " << fallbacks);
}

// Mag's own preconditions, checked by MagChecked on every ray variant: no decision exceeds the
// index budget and no product comes near underflow, on the hard sets, the corpus, and the hard
// sets scaled towards both ends of Mag's input range (2^-90 and 2^90). A violation throws
// logic_error, which fails the test.
TEST_CASE("rays: Mag's index budget and underflow margin hold on hard and scaled inputs", "[rays]") {
  using M = MagChecked;
  std::vector<std::pair<std::string, Json>> inputs;
  for (const Json& c : read_jsonl("corpus.jsonl")) inputs.push_back({c["primitive"], c["input"]});
  for (const char* prim : {"triangle", "sphere", "box", "plane"})
    for (const Json& j : rays::hard_inputs(prim, 7)) inputs.push_back({prim, j});
  std::size_t runs = 0;
  for (const double scale : {1.0, 0x1p-90, 0x1p90}) {
    for (const auto& [prim, in] : inputs) {
      const Parsed p = parse(in, prim);
      const auto m = [&](const Rational& x) { return M(x.get_d() * scale); };
      const auto mv = [&](const V3& v) { return Vec3<M>{m(v.x), m(v.y), m(v.z)}; };
      // The direction is not scaled: it keeps the same rays.
      const ray::Ray3<M> ray{mv(p.o), {M(p.d.x.get_d()), M(p.d.y.get_d()), M(p.d.z.get_d())}};
      NoProbe none;
      auto go = [&](auto&& alg) {
        try {
          (void)run_filter_stage<M>(alg);
        } catch (const Uncertain&) {
        }
        ++runs;
      };
      if (prim == "triangle") {
        const std::array<Vec3<M>, 3> v{mv(p.v[0]), mv(p.v[1]), mv(p.v[2])};
        go([&] { return ray::ray_triangle_watertight<M>(ray, v, none).hit; });
        go([&] { return ray::ray_triangle_mt<M>(ray, v, none).hit; });
        go([&] { return ray::ray_triangle_barycentric<M>(ray, v, none).hit; });
      } else if (prim == "sphere") {
        go([&] { return ray::ray_sphere_geometric<M>(ray, mv(p.v[0]), m(p.r), none).hit; });
        go([&] { return ray::ray_sphere_quadratic<M>(ray, mv(p.v[0]), m(p.r), none).hit; });
        go([&] { return ray::ray_sphere_stable<M>(ray, mv(p.v[0]), m(p.r), none).hit; });
      } else if (prim == "box") {
        go([&] { return ray::ray_box<M>(ray, mv(p.v[0]), mv(p.v[1]), none).hit; });
      } else {
        go([&] { return ray::ray_plane<M>(ray, mv(p.v[0]), {M(p.v[1].x.get_d()), M(p.v[1].y.get_d()), M(p.v[1].z.get_d())}, none).hit; });
      }
    }
  }
  CHECK(runs > 3 * 10000);
}

// Replays exact traces: every recorded number is compared with a value computed here from the
// input by independent formulas (oracle triple products, Lagrange's identity, Vieta).
