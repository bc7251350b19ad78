// Properties of the reflection models, checked numerically (double unless said):
//  - Helmholtz reciprocity of the BRDF f = term/(pi n.l): f(l, e) = f(e, l) within 1e-12 relative
//    (+ 1e-15 absolute) for lambert, minnaert, oren-nayar, beckmann, cook-torrance; phong, blinn-phong and gaussian are
//    not reciprocal (their term is symmetric, so f(l, e)/f(e, l) = n.e/n.l), nor is toon.
//  - White furnace: the directional albedo (1/pi) * integral over the hemisphere of term(l, e) dl,
//    by the midpoint rule on a 200 x 400 grid in (cos theta, phi); error estimate |Q(N) - Q(N/2)|/3
//    (Richardson, for a rule of order h^2); the midpoint rule is exact for Lambert (linear in
//    cos theta), which checks the rule itself. Cook-torrance stays <= 1 within the estimate;
//    minnaert (k < 1), beckmann without G and phong with n = 0 exceed 1 (documented in
//    docs/lighting/semantics.md), and the test requires that they do. Oren-Nayar has a closed form
//    (oren_nayar_albedo), which the quadrature must meet; it exceeds 1 towards a grazing eye when
//    sigma < 0.326.
//  - Limits: oren-nayar at sigma = 0 and minnaert at k = 1 equal lambert, and cook-torrance with
//    F = 1 and G = 1 equals beckmann, exactly, in float, double and reference.
//  - Blinn-Phong's (and Phong's) highlight is at the mirror direction: 1 there (reference within
//    2^-250), and smaller at every other eye sampled.
#include <catch2/catch.hpp>
#include <cmath>
#include "lighting_test_support.hpp"

using namespace sw;
using namespace sw::lighting;
using namespace sw::testing::lighting_models;

namespace {

ModelInput swapped(const ModelInput& in) {
  ModelInput s = in;
  std::swap(s.l, s.e);
  lighting_io::decide(s);
  return s;
}

struct Albedo {
  double q, estimate;
};
// (1/pi) * the integral of the model's term over the light's hemisphere, n = z, the eye at angle
// theta_e from n in the xz plane.
Albedo albedo(std::string_view id, const Json& params, double theta_e, int nu = 200) {
  Json j = params;
  j["n"] = Json::array({0, 0, 1}), j["l"] = Json::array({0, 0, 1}), j["e"] = Json::array({std::sin(theta_e), 0, std::cos(theta_e)});
  const ModelInput in = lighting_io::parse_model_input(id, j);
  const auto p = params_as<double>(in.p);
  const Vec3<double> n{0, 0, 1}, e{std::sin(theta_e), 0, std::cos(theta_e)};
  auto quad = [&](int nu_, int nphi) {
    double sum = 0;
    const double du = 1.0 / nu_, dphi = 2 * M_PI / nphi;
    for (int i = 0; i < nu_; ++i) {
      const double u = (i + 0.5) * du, s = std::sqrt(1 - u * u);
      for (int k = 0; k < nphi; ++k) {
        const double phi = (k + 0.5) * dphi;
        const Vec3<double> l{s * std::cos(phi), s * std::sin(phi), u};
        NoProbe none;
        sum += with_algo(id, [&]<class A>(std::type_identity<A>) -> double { return evaluate<A>(in.choice, n, l, e, p, none); });
      }
    }
    return sum * du * dphi / M_PI;
  };
  const double fine = quad(nu, 2 * nu), coarse = quad(nu / 2, nu);
  return {fine, std::fabs(fine - coarse) / 3};
}

}  // namespace

TEST_CASE("lighting: Helmholtz reciprocity holds where the model is reciprocal and fails as documented where not", "[lighting][properties]") {
  for (const char* id : kIds) {
    Gen gen(77 + std::string_view(id).size());
    const bool reciprocal = std::string_view(id) != "phong" && std::string_view(id) != "blinn-phong" && std::string_view(id) != "gaussian" &&
                            std::string_view(id) != "toon";
    int frames = 0, broken = 0;
    for (int k = 0; k < 300 && frames < 100; ++k) {
      const ModelInput in = lighting_io::parse_model_input(id, gen.input(id));
      if (!(in.signs.lit && in.signs.seen)) continue;
      const ModelInput sw = swapped(in);
      const auto o = oracle_of(id, in);
      const double nl = o.named.at("nl").get_d(), ne = o.named.at("ne").get_d();
      const double a = run_model<double>(id, in), b = run_model<double>(id, sw);
      const double f_le = a / nl, f_el = b / ne;  // pi f(l, e), pi f(e, l)
      if (std::string_view(id) == "toon" && (a == 0) == (b == 0)) continue;  // toon: only frames that cut differently tell
      ++frames;
      INFO(id << " " << lighting_io::to_json(in).dump() << " f(l,e) " << f_le << " f(e,l) " << f_el);
      if (reciprocal) {
        CHECK(std::fabs(f_le - f_el) <= 1e-12 * std::max(std::fabs(f_le), std::fabs(f_el)) + 1e-15);  // ior 1: F ~ 1e-33, not 0
      } else {
        if (std::fabs(f_le - f_el) > 0.1 * std::max(f_le, f_el)) ++broken;
        if (std::string_view(id) != "toon") CHECK(std::fabs(a - b) <= 1e-12 * std::max(a, 1e-300));  // the term itself is symmetric
      }
    }
    INFO(id << ": " << frames << " frames, " << broken << " clearly not reciprocal");
    CHECK(frames >= (std::string_view(id) == "toon" ? 5 : 50));
    if (!reciprocal) CHECK(broken > 0);
  }
}

TEST_CASE("lighting: white furnace, the directional albedo of the normalised models stays <= 1", "[lighting][properties][furnace]") {
  const double deg = M_PI / 180;
  // The rule itself: Lambert's albedo is 1 (the midpoint rule is exact for it).
  for (double t : {0.0, 60.0, 89.0}) {
    const Albedo a = albedo("lambert", Json::object(), t * deg);
    CHECK(std::fabs(a.q - 1) < 1e-12);
  }
  double worst_on = 0, worst_ct = 0;
  for (double t : {0.0, 45.0, 80.0, 89.0})
    for (const char* s : {"0", "1/2", "1"}) {
      const Albedo a = albedo("oren-nayar", Json{{"sigma", s}}, t * deg);
      INFO("oren-nayar sigma " << s << " theta_e " << t << ": " << a.q << " +- " << a.estimate);
      CHECK(a.q <= 1 + 2 * a.estimate + 1e-12);
      worst_on = std::max(worst_on, a.q);
    }
  for (double t : {0.0, 60.0, 85.0})
    for (const char* m : {"1/5", "1/2", "1"})
      for (const char* f : {"one", "exact"}) {
        const Albedo a = albedo("cook-torrance", Json{{"m", m}, {"ior", "3/2"}, {"fresnel", f}}, t * deg);
        INFO("cook-torrance m " << m << " F " << f << " theta_e " << t << ": " << a.q << " +- " << a.estimate);
        CHECK(a.q <= 1 + 2 * a.estimate + 1e-9);
        worst_ct = std::max(worst_ct, a.q);
      }
  // The nearest to 1 (F = 1, e = n, m = 1/5): 0.99983, 0.99994, 0.99997 at 200, 400, 800 intervals in
  // cos theta, rising towards about 0.99998 from below. The V-cavity G keeps it <= 1 for F <= 1
  // (docs/lighting/accuracy.md); the quadrature converges to a value under 1.
  const Albedo fine = albedo("cook-torrance", Json{{"m", "1/5"}, {"ior", "3/2"}, {"fresnel", "one"}}, 0, 800);
  INFO("cook-torrance m 1/5, F = 1, e = n, 800 x 1600: " << fine.q << " +- " << fine.estimate);
  CHECK(fine.q > worst_ct);
  CHECK(fine.q + 2 * fine.estimate < 1);
  INFO("worst albedo: oren-nayar " << worst_on << ", cook-torrance " << worst_ct);
  CHECK(worst_on > 0.5);
  CHECK(worst_ct > 0.5);
  // The documented violations: not normalised, and the quadrature shows it beyond its estimate.
  const Albedo mi = albedo("minnaert", Json{{"k", "1/2"}}, 80 * deg), be = albedo("beckmann", Json{{"m", "1/2"}}, 85 * deg),
               ph = albedo("phong", Json{{"shininess", 0}}, 0);
  INFO("minnaert k 1/2 at 80 degrees " << mi.q << ", beckmann m 1/2 at 85 degrees " << be.q << ", phong n 0 at 0 " << ph.q);
  CHECK(mi.q > 1 + 4 * mi.estimate);
  CHECK(std::fabs(mi.q - 2 / 1.5 / std::sqrt(std::cos(80 * deg))) < 1e-3);  // 2/(k+1) cos(theta_e)^(k-1)
  CHECK(be.q > 1 + 4 * be.estimate);
  CHECK(std::fabs(ph.q - 2) < 1e-3);  // (1/pi) * 2 pi * (1/2): the lobe r.e > 0 is half the hemisphere... at e = n it is all of it
}

// Oren-Nayar's directional albedo in closed form (the term is algebraic in the cosines): with the
// eye at theta_e and mu = cos(theta_l), rho = A + (2B/pi) sin(theta_e) I(cos theta_e), where
// I(c) = int_0^1 mu sin(theta_l) / max(mu, c) dmu = (1 - (1 - c^2)^(3/2))/(3c) + pi/4 - (c sqrt(1 - c^2) + asin c)/2
// (the phi integral of max(0, cos phi) is 2). As theta_e -> 90 degrees rho -> A + B/2.
long double oren_nayar_albedo(long double sigma, long double theta_e) {
  const long double s2 = sigma * sigma, A = 1 - 0.5L * s2 / (s2 + 0.33L), B = 0.45L * s2 / (s2 + 0.09L);
  const long double c = std::cos(theta_e), sc = std::sqrt(1 - c * c), pi = 3.14159265358979323846264338327950288L;
  const long double I = (1 - sc * sc * sc) / (3 * c) + pi / 4 - (c * sc + std::asin(c)) / 2;
  return A + 2 * B / pi * std::sin(theta_e) * I;
}

TEST_CASE("lighting: white furnace, Oren-Nayar's albedo in closed form, above 1 at grazing eyes when sigma < 0.326", "[lighting][properties][furnace]") {
  const double deg = M_PI / 180;
  double worst_gap = 0;
  for (double sigma : {0.1, 0.2, 0.5, 1.0})
    for (double t : {0.0, 30.0, 60.0, 80.0, 89.0}) {
      const Albedo a = albedo("oren-nayar", Json{{"sigma", sigma}}, t * deg);
      const double exact = double(oren_nayar_albedo(sigma, t * deg));
      INFO("sigma " << sigma << " theta_e " << t << ": quadrature " << a.q << " +- " << a.estimate << ", closed form " << exact);
      CHECK(std::fabs(a.q - exact) <= 1e-4);  // measured at most 5.6e-5 (at 89 degrees, sigma 1)
      worst_gap = std::max(worst_gap, std::fabs(a.q - exact));
    }
  INFO("largest |quadrature - closed form| " << worst_gap);
  CHECK(worst_gap > 0);  // the rule is not exact here (a kink at mu = cos theta_e): the comparison has teeth
  // The limit A + B/2 exceeds 1 exactly when 0.225 s2/(s2 + 0.09) > 0.5 s2/(s2 + 0.33), i.e. s2 < 0.02925/0.275.
  const double s_star = std::sqrt(0.02925 / 0.275);
  CHECK(s_star == Approx(0.32614).epsilon(1e-4));
  CHECK(oren_nayar_albedo(0.2, 89.9 * deg) > 1.014);
  CHECK(albedo("oren-nayar", Json{{"sigma", 0.2}}, 89 * deg).q > 1.01);
  for (double sigma : {0.33, 0.5, 1.0})
    for (int t = 0; t < 900; ++t) CHECK(oren_nayar_albedo(sigma, t * 0.1 * deg) < 1);
}

TEST_CASE("lighting: the limits, oren-nayar sigma 0 and minnaert k 1 are lambert, cook-torrance with F = G = 1 is beckmann", "[lighting][properties][limits]") {
  Gen gen(5);
  int lit = 0;
  for (int k = 0; k < 120; ++k) {
    Json j = gen.input("lambert");
    const ModelInput lam = lighting_io::parse_model_input("lambert", j);
    lit += lam.signs.lit && lam.signs.seen;
    Json jo = j, jm = j;
    jo["sigma"] = 0, jm["k"] = 1;
    const ModelInput on = lighting_io::parse_model_input("oren-nayar", jo), mi = lighting_io::parse_model_input("minnaert", jm);
    INFO(j.dump());
    CHECK(run_model<Q>("oren-nayar", on) == run_model<Q>("lambert", lam));
    CHECK(run_model<Q>("minnaert", mi) == run_model<Q>("lambert", lam));
    CHECK(run_model<double>("oren-nayar", on) == run_model<double>("lambert", lam));
    CHECK(run_model<double>("minnaert", mi) == run_model<double>("lambert", lam));
    CHECK(run_model<float>("oren-nayar", on) == run_model<float>("lambert", lam));
    CHECK(run_model<float>("minnaert", mi) == run_model<float>("lambert", lam));
    CHECK(close(oracle_of("oren-nayar", on).value, oracle_of("lambert", lam).value));  // the oracle's angle form too
    Json jb = j, jc = j;
    jb["m"] = "3/10", jc["m"] = "3/10", jc["ior"] = "3/2", jc["fresnel"] = "one", jc["shadowing"] = false;
    const ModelInput be = lighting_io::parse_model_input("beckmann", jb), ct = lighting_io::parse_model_input("cook-torrance", jc);
    CHECK(run_model<Q>("cook-torrance", ct) == run_model<Q>("beckmann", be));
    CHECK(run_model<double>("cook-torrance", ct) == run_model<double>("beckmann", be));
    CHECK(run_model<float>("cook-torrance", ct) == run_model<float>("beckmann", be));
    CHECK(close(oracle_of("cook-torrance", ct).value, oracle_of("beckmann", be).value));
  }
  CHECK(lit > 30);
}

TEST_CASE("lighting: the Blinn-Phong and Phong highlights sit at the mirror direction", "[lighting][properties]") {
  Gen gen(11);
  int frames = 0;
  for (int k = 0; k < 200 && frames < 40; ++k) {
    Json j = gen.input("blinn-phong");
    j["shininess"] = 50;
    const Vec3<Q> N = lighting_io::direction3(j, "n", "n"), L = lighting_io::direction3(j, "l", "l");
    const Q nl = dot(N, L);
    if (sgn(nl) <= 0) continue;
    const Vec3<Q> R = Q(2 * nl) * N - dot(N, N) * L;  // the mirror of L about N, unnormalised
    j["e"] = Gen::js(R);
    ++frames;
    INFO(j.dump());
    for (const char* id : {"blinn-phong", "phong"}) {
      const ModelInput at = lighting_io::parse_model_input(id, j);
      const Q top = run_model<Q>(id, at);
      CHECK(close(top, Q(1), 250, 250));
      CHECK(std::fabs(run_model<double>(id, at) - 1) < 1e-13);
      for (int s = 0; s < 25; ++s) {  // other eyes on the lit side
        Json js = j;
        js["e"] = Gen::js(Vec3<Q>(R + Q(1, 8) * gen.vec()));
        const ModelInput other = lighting_io::parse_model_input(id, js);
        if (!other.signs.seen || cross(other.e, R) == Vec3<Q>{}) continue;  // another eye, not the mirror direction
        CHECK(run_model<double>(id, other) < run_model<double>(id, at));
      }
    }
  }
  CHECK(frames >= 20);
}
