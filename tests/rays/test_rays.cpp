// The ray family: the corpus and random cases against the exact oracle (expected outcomes come
// from oracle/rays_oracle at test time), watertightness on a tessellated grid, exact step replay,
// bad input, and `check` on exact traces.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <sys/wait.h>
#include "catalog.hpp"
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
using V3 = Vec3<Rational>;

namespace {

const std::map<std::string, std::vector<std::string>> kAlgs = {
    {"triangle", {"ray-triangle-barycentric", "ray-triangle-mt", "ray-triangle-watertight"}},
    {"sphere", {"ray-sphere-geometric", "ray-sphere-quadratic", "ray-sphere-stable"}},
    {"box", {"ray-box"}},
    {"plane", {"ray-plane"}}};

std::vector<Json> read_jsonl(const std::string& name) {
  std::ifstream f(std::string(SW_SOURCE_DIR) + "/tests/cases/rays/" + name);
  REQUIRE(f.good());
  std::vector<Json> out;
  for (std::string line; std::getline(f, line);)
    if (!line.empty()) out.push_back(Json::parse(line));
  return out;
}

Rational q(const Json& v) { return parse_rational(v, "value"); }

// Results agree: hit, and every reported number as an exact rational.
bool same_result(const Json& got, const Json& want) {
  if (got.at("hit") != want.at("hit")) return false;
  for (const char* k : {"t", "t_near", "t_far"})
    if (want.contains(k) && (!got.contains(k) || q(got[k]) != q(want[k]))) return false;
  if (want.contains("b"))
    for (int i = 0; i < 3; ++i)
      if (q(got["b"][i]) != q(want["b"][i])) return false;
  if (want.contains("attr") != got.contains("attr")) return false;
  if (want.contains("attr"))
    for (std::size_t k = 0; k < want["attr"].size(); ++k)
      if (q(got["attr"][k]) != q(want["attr"][k])) return false;
  return true;
}

V3 sub(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Rational dotq(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 crossq(const V3& a, const V3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
const V3 kAxis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

struct Parsed {
  V3 o, d;
  std::array<V3, 3> v;
  Rational r;
};
Parsed parse(const Json& in, const std::string& prim) {
  Parsed p;
  p.o = parse_point3(in["ray"], "o");
  p.d = parse_point3(in["ray"], "d");
  const Json& g = in[prim];
  if (prim == "triangle")
    for (int i = 0; i < 3; ++i) p.v[i] = {q(g[i][0]), q(g[i][1]), q(g[i][2])};
  if (prim == "sphere") p.v[0] = parse_point3(g, "c"), p.r = q(g["r"]);
  if (prim == "box") p.v[0] = parse_point3(g, "min"), p.v[1] = parse_point3(g, "max");
  if (prim == "plane") p.v[0] = parse_point3(g, "p"), p.v[1] = parse_point3(g, "n");
  return p;
}

// |x - y| <= 2^-200 max(|y|, 1): for values that went through a 300-bit square root.
bool close(const Rational& x, const Rational& y) {
  Rational scale = abs(y) > 1 ? Rational(abs(y)) : Rational(1);
  Rational tol = scale;
  mpq_div_2exp(tol.get_mpq_t(), tol.get_mpq_t(), 200);
  return abs(Rational(x - y)) <= tol;
}

}  // namespace

TEST_CASE("rays: every corpus case: exact and filtered equal the oracle and float and double stay finite", "[rays]") {
  int cases = 0;
  for (const Json& c : read_jsonl("corpus.jsonl")) {
    const std::string prim = c["primitive"];
    for (const std::string& id : kAlgs.at(prim)) {
      const Algorithm& alg = find_algorithm(id);
      INFO(c["name"].get<std::string>() << " " << id);
      const Json want = alg.oracle(c["input"]);
      const Json exact = alg.run(c["input"], Numeric::exact);
      CHECK(same_result(exact, want));
      const Json filtered = alg.run(c["input"], Numeric::filtered);
      CHECK(filtered["hit"] == want["hit"]);
      if (filtered["fallback"].get<bool>()) CHECK(same_result(filtered, want));
      for (Numeric n : {Numeric::f32, Numeric::f64}) {
        const Json r = alg.run(c["input"], n);
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
    return find_algorithm(kAlgs.at(c["primitive"])[0]).oracle(c["input"])["hit"].get<bool>();
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
  const Json attr = find_algorithm("ray-triangle-watertight").run(by_name.at("attr-uv-normal")["input"], Numeric::exact);
  CHECK(q(attr["attr"][0]) == Rational(1, 4));
  CHECK(q(attr["attr"][1]) == Rational(1, 2));
  CHECK(q(attr["attr"][2]) == Rational(1, 6));
  CHECK_FALSE(find_algorithm("ray-triangle-mt").run(by_name.at("attr-miss")["input"], Numeric::exact).contains("attr"));
  // The stable sphere survives the far small sphere in double; the quadratic does not have to.
  const Json far = by_name.at("far-1e8")["input"];
  CHECK(find_algorithm("ray-sphere-stable").run(far, Numeric::f64)["hit"].get<bool>());
  // The box never produces NaN on zero / -0 components with the origin on a slab plane.
  for (const char* name : {"box-axis-zero-on-slab", "box-neg-zero"})
    for (Numeric n : {Numeric::f32, Numeric::f64}) {
      const Json r = find_algorithm("ray-box").run(by_name.at(name)["input"], n);
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
        CHECK_THROWS_AS(find_algorithm(id).validate(c["input"], n), InputError);
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
  constexpr int kFiltered = 100000, kExact = 100000;
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
TEST_CASE("rays: exact step replay, every variable", "[rays]") {
  std::vector<std::pair<std::string, Json>> inputs;
  for (const Json& c : read_jsonl("corpus.jsonl")) inputs.push_back({c["primitive"], c["input"]});
  for (const char* prim : {"triangle", "sphere", "box", "plane"}) {
    for (const Json& j : rays::random_inputs(prim, 60, 99)) inputs.push_back({prim, j});
    const auto hard = rays::hard_inputs(prim, 5);
    for (std::size_t i = 0; i < hard.size(); i += hard.size() / 40 + 1) inputs.push_back({prim, hard[i]});
  }
  std::size_t checked = 0;
  for (const auto& [prim, in] : inputs) {
    const Parsed p = parse(in, prim);
    const V3 f = sub(p.o, p.v[0]);
    for (const std::string& id : kAlgs.at(prim)) {
      const Recorded rec = find_algorithm(id).record(in, Numeric::exact);
      const auto& tr = dynamic_cast<const Recorder<Rational>&>(*rec.trace);
      INFO(id << " " << in.dump());
      // Integer state the expected values depend on, read as the steps go.
      std::map<std::string, std::int64_t> ints;
      Rational tn, tf;
      bool bounded = false;
      for (std::size_t s = 0; s < tr.size(); ++s) {
        const StepRecord& st = tr.at(s);
        for (auto vi = st.var_begin; vi < st.var_end; ++vi) {
          const VarRecord& var = tr.var_at(vi);
          const std::string name = var.name;
          if (var.is_int) {
            ints[name] = tr.int_value(var.slot);
            continue;
          }
          const Rational got = tr.num_value(var.slot);
          std::optional<Rational> want;
          bool approx = false;  // went through a rounded square root
          if (prim == "triangle") {
            const V3 e1 = sub(p.v[1], p.v[0]), e2 = sub(p.v[2], p.v[0]), so = sub(p.o, p.v[0]);
            const V3 a = sub(p.v[0], p.o), b = sub(p.v[1], p.o), c = sub(p.v[2], p.o);
            const Rational w0 = oracle::triple(p.d, b, c), w1 = oracle::triple(p.d, c, a), w2 = oracle::triple(p.d, a, b);
            if (id == "ray-triangle-watertight") {
              const int kx = int(ints["kx"]), ky = int(ints["ky"]), kz = int(ints["kz"]);
              const Rational adz = abs(p.d[kz]);
              auto sheared = [&](const V3& v, int k) { return Rational(v[k] - p.d[k] / p.d[kz] * v[kz]); };
              const std::map<std::string, Rational> m = {
                  {"Sx", p.d[kx] / p.d[kz]}, {"Sy", p.d[ky] / p.d[kz]}, {"Sz", 1 / p.d[kz]},
                  {"Ax", sheared(a, kx)}, {"Ay", sheared(a, ky)}, {"Bx", sheared(b, kx)}, {"By", sheared(b, ky)},
                  {"Cx", sheared(c, kx)}, {"Cy", sheared(c, ky)},
                  // The shear frame (kx, ky, kz) is an even permutation when d_kz > 0 and odd
                  // otherwise, so the 2D edge functions are -(triple products) / |d_kz|.
                  {"U", -w0 / adz}, {"V", -w1 / adz}, {"W", -w2 / adz}, {"det", -(w0 + w1 + w2) / adz},
                  {"T", -oracle::triple(e1, e2, a) / adz}};
              if (m.count(name)) want = m.at(name);
            } else if (id == "ray-triangle-mt") {
              const Rational det = oracle::triple(e1, p.d, e2);
              const std::map<std::string, Rational> m = {{"det", det}};
              if (m.count(name)) want = m.at(name);
              if (sgn(det) != 0) {
                if (name == "u") want = oracle::triple(so, p.d, e2) / det;
                if (name == "v") want = oracle::triple(p.d, so, e1) / det;
                if (name == "t") want = oracle::triple(e2, so, e1) / det;
              }
            } else {
              const V3 n = crossq(e1, e2);
              const Rational den = oracle::triple(p.d, e1, e2);
              if (name == "nx") want = oracle::triple(kAxis[0], e1, e2);
              if (name == "ny") want = oracle::triple(kAxis[1], e1, e2);
              if (name == "nz") want = oracle::triple(kAxis[2], e1, e2);
              if (name == "den") want = den;
              if (name == "t") want = dotq(n, a) / den;
              if (name == "beta") want = w1 / (w0 + w1 + w2);
              if (name == "gamma") want = w2 / (w0 + w1 + w2);
            }
            if (name == "b0") want = w0 / (w0 + w1 + w2);
            if (name == "b1") want = w1 / (w0 + w1 + w2);
            if (name == "b2") want = w2 / (w0 + w1 + w2);
            if (name == "t" && !want) want = oracle::ray_triangle(p.o, p.d, p.v).t;
          } else if (prim == "sphere") {
            const Rational a = dotq(p.d, p.d), r2 = p.r * p.r, fxd2 = dotq(crossq(f, p.d), crossq(f, p.d));
            const Rational cc = dotq(f, f) - r2, hb = dotq(f, p.d);
            const std::map<std::string, Rational> m = {
                {"L2", dotq(f, f)}, {"a", a}, {"r2", r2}, {"tca", -hb}, {"m2", fxd2 / a}, {"h2", a * r2 - fxd2},
                {"b", 2 * hb}, {"c", cc}, {"b'", hb}, {"lx", f.x - hb / a * p.d.x}, {"ly", f.y - hb / a * p.d.y},
                {"lz", f.z - hb / a * p.d.z}};
            if (m.count(name)) want = m.at(name);
            if (name == "D") want = id == "ray-sphere-quadratic" ? Rational(4 * (a * r2 - fxd2)) : Rational(a * r2 - fxd2);
            // Roots: they must satisfy Vieta's formulas with the other recorded root (checked below).
            if (name == "t0" || name == "t1" || name == "n0" || name == "n1" || name == "near" || name == "far" || name == "q") approx = true;
            if (name == "t") {
              const auto o = oracle::ray_sphere(p.o, p.d, p.v[0], p.r);
              REQUIRE(o.hit);
              want = o.t;
              approx = !o.t_exact;  // rational t: exact equality
            }
          } else if (prim == "box") {
            const int k = int(ints["k"]);
            if (sgn(p.d[k]) != 0) {
              Rational t1 = (p.v[0][k] - p.o[k]) / p.d[k], t2 = (p.v[1][k] - p.o[k]) / p.d[k];
              if (t1 > t2) std::swap(t1, t2);
              if (name == "t1") want = t1;
              if (name == "t2") {
                want = t2;
                tn = bounded ? std::max(tn, t1) : t1, tf = bounded ? std::min(tf, t2) : t2, bounded = true;
              }
            }
            if (name == "t_near") want = tn;
            if (name == "t_far") want = tf;
            if (name == "t") want = oracle::ray_box(p.o, p.d, p.v[0], p.v[1]).t;
          } else {
            const Rational den = dotq(p.v[1], p.d);
            if (name == "den") want = den;
            if (name == "num") want = dotq(p.v[1], sub(p.v[0], p.o));
            if (name == "t") want = dotq(p.v[1], sub(p.v[0], p.o)) / den;
          }
          if (approx && name != "t") {
            ++checked;
            continue;  // checked as pairs after the loop
          }
          INFO("variable " << name << " at step " << s);
          REQUIRE(want.has_value());  // every recorded number has an independent expectation
          if (approx) CHECK(num::round_bits(got, oracle::kSphereTBits) == *want);
          else CHECK(got == *want);
          ++checked;
        }
      }
      // Sphere roots recorded as pairs: Vieta (t0 t1 = c/a, t0 + t1 = -b/a) on the exact inputs, and
      // the quadratic's numerators n = 2a t.
      if (prim == "sphere") {
        std::map<std::string, Rational> v;
        for (std::size_t s = 0; s < tr.size(); ++s)
          for (auto vi = tr.at(s).var_begin; vi < tr.at(s).var_end; ++vi)
            if (!tr.var_at(vi).is_int) v[tr.var_at(vi).name] = tr.num_value(tr.var_at(vi).slot);
        const Rational a = dotq(p.d, p.d), cc = dotq(f, f) - p.r * p.r, hb = dotq(f, p.d);
        for (auto [x, y] : {std::pair{"t0", "t1"}, std::pair{"near", "far"}})
          if (v.count(x)) {
            CHECK(close(v[x] * v[y], cc / a));
            CHECK(close(v[x] + v[y], -2 * hb / a));
          }
        if (v.count("n0")) {  // n0 n1 = b^2 - D = 4 a cc, n0 + n1 = -2b
          CHECK(close(v["n0"] * v["n1"], 4 * a * cc));
          CHECK(close(v["n0"] + v["n1"], -4 * hb));
        }
        if (v.count("q")) CHECK(close((v["q"] + hb) * (v["q"] + hb), Rational(a * p.r * p.r - dotq(crossq(f, p.d), crossq(f, p.d)))));
      }
    }
  }
  CHECK(checked > 2000);
}

TEST_CASE("rays: stepwise check accepts exact traces and rejects a tampered one", "[rays]") {
  for (const Json& c : read_jsonl("corpus.jsonl"))
    for (const std::string& id : kAlgs.at(c["primitive"])) {
      std::stringstream ss;
      write_trace(find_algorithm(id), Numeric::exact, c["input"], ss);
      const CheckReport rep = check_trace(ss, false);
      INFO(id << " " << c["name"].get<std::string>() << ": " << rep.message);
      CHECK(rep.status == 0);
    }
  std::stringstream ss;
  const Json in = Json::parse(R"({"ray":{"o":[0,0,5],"d":[0,0,-1]},"sphere":{"c":[0,0,0],"r":1}})");
  write_trace(find_algorithm("ray-sphere-stable"), Numeric::exact, in, ss);
  std::string text = ss.str();
  const auto pos = text.find("\"t\":\"4\"");
  REQUIRE(pos != std::string::npos);
  text.replace(pos, 7, "\"t\":\"5\"");
  std::stringstream bad(text);
  CHECK(check_trace(bad, false).status == 1);
}

TEST_CASE("rays: camera rays, pixel centres and projections", "[rays]") {
  const Algorithm& cam = find_algorithm("camera-ray");
  auto run = [&](const char* proj, int fov, int i, int j, int w, int h, Numeric n = Numeric::f64) {
    Json in = Json::parse(R"({"camera":{"eye":[1,2,3],"vpn":[0,0,2],"vup":[0,5,0],"d":2,"fov":90},"pixel":[0,0],"size":[1,1]})");
    in["projection"] = proj;
    in["camera"]["fov"] = fov;
    in["pixel"] = {i, j};
    in["size"] = {w, h};
    return cam.run(in, n);
  };
  for (const char* proj : {"perspective", "fisheye", "cylindrical"}) {
    // The centre pixel of an odd image looks straight along -n.
    const Json r = run(proj, 90, 2, 1, 5, 3);
    INFO(proj << " " << r.dump());
    REQUIRE(r["valid"].get<bool>());
    CHECK(std::fabs(r["d"][0].get<double>()) < 1e-15);
    CHECK(std::fabs(r["d"][1].get<double>()) < 1e-15);
    CHECK(r["d"][2].get<double>() < 0);
    CHECK(r["o"] == Json::array({1.0, 2.0, 3.0}));
  }
  // Perspective, 90 degrees, 2 x 2 image at d = 2: pixel (0, 0) is the upper-left quarter's centre,
  // at screen (-1/2, +1/2) of the half sizes hh = hw = 2 tan(45) = 2: P1 - P0 = (-1, 1, -2).
  const Json p = run("perspective", 90, 0, 0, 2, 2);
  CHECK(std::fabs(p["d"][0].get<double>() + 1) < 1e-14);
  CHECK(std::fabs(p["d"][1].get<double>() - 1) < 1e-14);
  CHECK(std::fabs(p["d"][2].get<double>() + 2) < 1e-14);
  // Fisheye: a corner of a square image lies outside the image circle.
  CHECK_FALSE(run("fisheye", 180, 0, 0, 8, 8)["valid"].get<bool>());
  CHECK(run("fisheye", 180, 4, 4, 8, 8)["valid"].get<bool>());
  // Float stays within a few float ulps of the 300-bit reference on the bench sets.
  for (const BenchRow& row : cam.bench(Numeric::f32, 1, "")) CHECK(row.max_error < 64);
  // Bad input: exact mode, pixel outside, vup parallel to vpn, unknown projection.
  CHECK_THROWS_AS(parse_numeric_for(cam, "exact"), InputError);
  Json bad = Json::parse(R"({"camera":{"eye":[1,2,3],"vpn":[0,0,2],"vup":[0,0,1],"d":2,"fov":90},"pixel":[0,0],"size":[1,1],"projection":"perspective"})");
  CHECK_THROWS_AS(cam.validate(bad, Numeric::f64), InputError);
  bad["camera"]["vup"] = {0, 1, 0};
  bad["pixel"] = {1, 0};
  CHECK_THROWS_AS(cam.validate(bad, Numeric::f64), InputError);
  bad["pixel"] = {0, 0};
  bad["projection"] = "orthographic";
  CHECK_THROWS_AS(cam.validate(bad, Numeric::f64), InputError);
}

TEST_CASE("rays: sphere inverse mapping, the seam and the poles", "[rays]") {
  const Algorithm& uv = find_algorithm("sphere-uv");
  auto run = [&](double x, double y, double z) {
    return uv.run(Json{{"sphere", {{"c", {0, 0, 0}}, {"r", 1}}}, {"point", {x, y, z}}}, Numeric::f64);
  };
  const double pi = 3.14159265358979323846;
  const Json seam = run(-0.6, 0, 0.8);  // on the seam: atan2(+0, -0.6) = +pi, so u = 1
  CHECK(seam["lon"].get<double>() == pi);
  CHECK(seam["u"].get<double>() == 1.0);
  CHECK(run(-0.6, -1e-300, 0.8)["u"].get<double>() < 1e-15);  // just below the seam: u near 0
  const Json north = run(0, 0, 3);  // pole: lon = atan2(0, 0) = 0, u = 1/2, v = 1
  CHECK(north["u"].get<double>() == 0.5);
  CHECK(north["v"].get<double>() == 1.0);
  CHECK(north["lat"].get<double>() == pi / 2);
  const Json east = run(0, 2, 0);
  CHECK(std::fabs(east["u"].get<double>() - 0.75) < 1e-15);
  CHECK(east["v"].get<double>() == 0.5);
  CHECK(east["normal"] == Json::array({0.0, 1.0, 0.0}));
  CHECK_THROWS_AS(uv.validate(Json::parse(R"({"sphere":{"c":[1,1,1],"r":1},"point":[1,1,1]})"), Numeric::f64), InputError);
  for (const BenchRow& row : uv.bench(Numeric::f64, 1, "")) CHECK(row.max_error < 16);
}
