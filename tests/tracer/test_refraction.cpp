// Refraction (algorithms/tracer/refraction.hpp) and caustics (photon_trace.hpp, photon_map.hpp):
//  - the TIR decision equals an exact rational evaluation of sin^2 of the refracted angle >= 1 on
//    near-critical rays, where a plain double evaluation errs on some;
//  - the guide's test misses TIR where the exact one finds it (a hand-derived angle);
//  - Snell's law and Fresnel at normal incidence, from the formulas by hand;
//  - a glass ball over a floor focuses the photons below it;
//  - the photon tree gathers exactly what a scan of every photon gathers.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include "scale.hpp"
#include "tracer/photon_trace.hpp"
#include "tracer/render.hpp"

using namespace sw;

namespace {

// sin^2 of the refracted angle >= 1, from the doubles as rationals: (n1/n2)^2 (1 - cos^2).
bool exact_tir(const Vec3<double>& d, const Vec3<double>& n, double n1, double n2) {
  auto q = [](double x) { return Rational(x); };
  const Rational dn = q(d.x) * q(n.x) + q(d.y) * q(n.y) + q(d.z) * q(n.z);
  const Rational dd = q(d.x) * q(d.x) + q(d.y) * q(d.y) + q(d.z) * q(d.z), nn = q(n.x) * q(n.x) + q(n.y) * q(n.y) + q(n.z) * q(n.z);
  const Rational cos2 = dn * dn / (dd * nn), eta = q(n1) / q(n2);
  return eta * eta * (1 - cos2) >= 1;
}

}  // namespace

TEST_CASE("refract decides total internal reflection exactly, where doubles err", "[tracer][refract]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(-1e-15, 1e-15);
  NoProbe none;
  int naive_wrong = 0, tir = 0, cases = 0;
  for (double n1 : {1.5, 1.3333333333333333, 2.4, 1.01})
    for (int k = 0; k < 2000; ++k) {
      // A ray leaving the dense medium near the critical angle: sin(theta_i) ~ n2/n1.
      const double s = (1.0 / n1) * (1 + jitter(rng)), c = std::sqrt(1 - s * s);
      const Vec3<double> n{0.0, 0.0, 1.0 + jitter(rng)}, d{s, jitter(rng), -c};
      const bool want = exact_tir(d, n, n1, 1.0);
      const auto t = tracer::refract(d, n, n1, 1.0, lighting::Fresnel::exact, none);
      REQUIRE(t.tir == want);
      const double cd = -dot(d, n) / std::sqrt(dot(d, d) * dot(n, n));
      naive_wrong += ((n1 * n1) * (1 - cd * cd) >= 1) != want;
      tir += want, ++cases;
    }
  CHECK(tir > 0);
  CHECK(tir < cases);
  CHECK(naive_wrong > 0);  // the plain double formula decides some of these wrongly
}

TEST_CASE("the guide's refraction test misses total internal reflection", "[tracer][refract]") {
  // Leaving glass (n1/n2 = 1.5) at cos = 0.7: sin_t = 1.5 sqrt(1 - 0.49) = 1.07 (TIR); the guide's
  // 1.5 sqrt(1 - 0.7) = 0.82 (none).
  NoProbe none;
  const double c = 0.7, s = std::sqrt(1 - c * c);
  const auto t = tracer::refract(Vec3<double>{s, 0, -c}, Vec3<double>{0, 0, 1}, 1.5, 1.0, lighting::Fresnel::exact, none);
  CHECK(t.tir);
  CHECK_FALSE(t.guide_tir);
  CHECK(t.fresnel == 1.0);
}

TEST_CASE("refract follows Snell's law and Fresnel's normal incidence", "[tracer][refract]") {
  NoProbe none;
  // Entering glass at 45 degrees: sin_t = sin(45)/1.5.
  const double r = std::sqrt(0.5);
  const auto t = tracer::refract(Vec3<double>{r, 0, -r}, Vec3<double>{0, 0, 1}, 1.0, 1.5, lighting::Fresnel::exact, none);
  REQUIRE_FALSE(t.tir);
  CHECK(t.dir.x == Approx(r / 1.5).margin(1e-14));
  CHECK(t.dir.z == Approx(-std::sqrt(1 - 0.5 / 2.25)).margin(1e-14));
  // Head on: F = ((1.5 - 1)/(1.5 + 1))^2 = 0.04, the transmitted ray straight through.
  const auto h = tracer::refract(Vec3<double>{0, 0, -2}, Vec3<double>{0, 0, 1}, 1.0, 1.5, lighting::Fresnel::exact, none);
  CHECK(h.fresnel == Approx(0.04).margin(1e-12));
  CHECK(h.dir.z == Approx(-1.0).margin(1e-15));
}

TEST_CASE("a glass ball focuses caustic photons on the floor below it", "[tracer][caustics]") {
  // A ball lens of index 1.5 and radius 1 has its focus 1.5 from its centre for parallel light: a
  // light 8 above the ball's top concentrates the photons through it near the floor below it.
  const Json j = {{"camera", {{"eye", {0, 3, 8}}, {"vpn", {0, 0.2, 1}}, {"vup", {0, 1, 0}}, {"d", 1}, {"fov", 40}, {"resolution", {32, 24}}}},
                  {"materials", {{"floor", {{"diffuse", {0.8, 0.8, 0.8}}}}, {"glass", {{"diffuse", {0, 0, 0}}, {"kt", 1}, {"ior", 1.5}}}}},
                  {"lights", {{{"type", "point"}, {"position", {0, 11, 0}}}}},
                  {"objects", {{{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "floor"}},
                               {{"type", "sphere"}, {"center", {0, 2, 0}}, {"radius", 1}, {"material", "glass"}}}},
                  {"photons", {{"count", 20000}, {"radius", 0.1}}}};
  tracer::SceneOptions opt;
  const tracer::Scene s = tracer::parse_scene(j, opt);
  const tracer::TraceScene<double> ts = tracer::trace_scene(s, 32, 24);
  tracer::PhotonMap map;
  std::uint64_t rays = 0;
  tracer::trace_photons(ts, 0, 0, 20000, 20000, 0, map.at, map.power, rays);
  REQUIRE(map.at.size() > 10000);  // every photon is aimed at the ball; most pass through to the floor
  tracer::index_photons(map);
  map.gather = 64, map.radius = 0.1;
  // Unblocked, the light gives the floor irradiance I cos / att = 1 (att = 1): below the ball the
  // focused photons give several times that; 3 away, outside the ball's shadow, none.
  CHECK(tracer::caustic_irradiance(map, {0, 0, 0}).x > 3);
  CHECK(tracer::caustic_irradiance(map, {3, 0, 0}).x == 0);
}

TEST_CASE("refraction: exactly at the critical angle is total internal reflection", "[tracer][refraction]") {
  // Leaving glass of index 5/4 into air: sin(critical) = 4/5. The ray (4, -3, 0) meets the normal
  // (0, 1, 0) at sin = 4/5 exactly (every input a double, exactly), so n1^2 sin^2 = n2^2: the exact
  // sign of the TIR polynomial is 0, and the ray is reflected.
  NoProbe none;
  const auto at = tracer::refract(Vec3<double>{4, -3, 0}, Vec3<double>{0, 1, 0}, 1.25, 1.0, lighting::Fresnel::exact, none);
  CHECK(at.tir);
  // A hair inside the cone (sin just below 4/5) is transmitted, bent by eta = n1/n2 = 5/4 away from the normal.
  const auto inside = tracer::refract(Vec3<double>{3.99, -3, 0}, Vec3<double>{0, 1, 0}, 1.25, 1.0, lighting::Fresnel::exact, none);
  REQUIRE_FALSE(inside.tir);
  const double sin_i = 3.99 / std::sqrt(3.99 * 3.99 + 9), sin_t = inside.dir.x / std::sqrt(dot(inside.dir, inside.dir));
  CHECK(sin_t == Approx(1.25 * sin_i).epsilon(1e-12));  // Snell: n1 sin(i) = n2 sin(t)
}

TEST_CASE("caustic irradiance: the photons within a closed radius over the disc's area", "[tracer][caustics]") {
  // Jensen's estimate E = sum(power) / (pi r^2): photons of power 1 at distances 1/2 and exactly
  // the radius 1 from the point, and one at 2 (outside). With room for all (gather 64) r is the
  // radius: E = 2 / pi. With gather 1, r is the nearest photon's distance: E = 1 / (pi / 4).
  tracer::PhotonMap map;
  map.at = {{0.5, 0, 0}, {0, 1, 0}, {0, 0, 2}};
  map.power.assign(3, Vec3<double>{1, 1, 1});
  tracer::index_photons(map);
  map.radius = 1;
  map.gather = 64;
  const double pi = std::acos(-1.0);
  CHECK(tracer::caustic_irradiance(map, {0, 0, 0}).x == Approx(2 / pi).epsilon(1e-15));
  map.gather = 1;
  CHECK(tracer::caustic_irradiance(map, {0, 0, 0}).y == Approx(4 / pi).epsilon(1e-15));
  // Farther than the radius from every photon: nothing.
  map.gather = 64;
  CHECK(tracer::caustic_irradiance(map, {0, -5, 0}).z == 0);
}

TEST_CASE("caustic irradiance: the photon tree gathers what a scan of every photon gathers, bit for bit", "[tracer][caustics]") {
  // Photons on a lattice (many equal distances, so the (d2, id) tie rule decides which are taken),
  // duplicates at one point (a leaf that cannot split) and a random cloud; queries on and off them.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  tracer::PhotonMap map;
  for (int x = 0; x < 12; ++x)
    for (int z = 0; z < 12; ++z) map.at.push_back({x / 8.0, 0, z / 8.0});
  for (int k = 0; k < 40; ++k) map.at.push_back({0.5, 0, 0.5});
  for (int k = 0; k < 3000; ++k) map.at.push_back({u(rng), u(rng) / 4, u(rng)});
  for (std::size_t i = 0; i < map.at.size(); ++i) map.power.push_back({1.0 + i % 7, 0.5, 1.0 / (1 + i % 3)});
  tracer::index_photons(map);
  const std::size_t queries = sw::testing::cases(600u);
  std::size_t nonzero = 0;
  for (const std::int64_t gather : {1, 8, 64}) {
    map.gather = gather;
    map.radius = gather == 8 ? 0.25 : 0.125;
    for (std::size_t q = 0; q < queries; ++q) {
      const Vec3<double> p = q % 3 == 0 ? map.at[q % map.at.size()] : Vec3<double>{u(rng), u(rng) / 4, u(rng)};
      // The scan: every photon within the radius by (d2, id), the first `gather`, summed in that order.
      std::vector<std::pair<double, std::size_t>> near;
      for (std::size_t i = 0; i < map.at.size(); ++i) {
        const Vec3<double> d = map.at[i] - p;
        const double d2 = d.x * d.x + d.y * d.y + d.z * d.z;
        if (d2 <= map.radius * map.radius) near.push_back({d2, i});
      }
      std::sort(near.begin(), near.end());
      if (near.size() > static_cast<std::size_t>(gather)) near.resize(static_cast<std::size_t>(gather));
      Vec3<double> sum{};
      for (const auto& [d2, i] : near) sum = sum + map.power[i];
      const double r2 = near.size() == static_cast<std::size_t>(gather) && near.back().first > 0 ? near.back().first
                                                                                                    : map.radius * map.radius;
      const Vec3<double> want = near.empty() ? Vec3<double>{} : (1 / (3.141592653589793 * r2)) * sum;
      const Vec3<double> got = tracer::caustic_irradiance(map, p);
      INFO("gather " << gather << " query " << q);
      REQUIRE(got.x == want.x);
      REQUIRE(got.y == want.y);
      REQUIRE(got.z == want.z);
      nonzero += !near.empty();
    }
  }
  CHECK(nonzero > queries);  // most queries gathered something
  CHECK(map.tree.leaves > map.at.size() / 8 / 2);
}
