// gouraud-vs-phong in reference mode against independent statements: the pixels are the fill
// oracle's covered samples (oracle/fill_oracle), each Gouraud colour is the fill oracle's linear
// interpolation of the MPFR oracle's vertex colours, and each Phong colour is the MPFR oracle's
// shade at the linearly interpolated position and normal (oracle/lighting_shade_oracle).
#include <catch2/catch.hpp>
#include "catalog.hpp"
#include "fill_oracle.hpp"
#include "lighting/gouraud_vs_phong.hpp"
#include "lighting/shade_input.hpp"
#include "lighting/shade_oracle_case.hpp"

using namespace sw;
using namespace sw::lighting;

TEST_CASE("gouraud-vs-phong: pixels, Gouraud and Phong colours against the fill and MPFR oracles", "[lighting][shade]") {
  const Algorithm& alg = find_algorithm("gouraud-vs-phong");
  Json in = Json::parse(alg.example);
  for (int variant = 0; variant < 2; ++variant) {
    if (variant == 1) {  // a sliver with vertices off the grid, an eye at infinity and a spot
      in["vertices"][0]["xy"] = {"1/3", "1/2"}, in["vertices"][1]["xy"] = {"29/2", "5/4"}, in["vertices"][2]["xy"] = {"7/3", "9/2"};
      in.erase("eye");
      in["eye_direction"] = {0, 0, 1};
      in["lights"].push_back(Json::parse(R"({"type":"spot","position":[0,0,3],"spot_direction":[0,0,-1],"cutoff":30,"exponent":5})"));
    }
    INFO("variant " << variant);
    ShadedTriangle<Rational> t;
    for (int k = 0; k < 3; ++k) {
      const Json& v = in["vertices"][k];
      for (int a = 0; a < 2; ++a) t.xy[k][a] = parse_rational(v["xy"][a], "xy");
      for (int a = 0; a < 3; ++a) t.p[k][a] = parse_rational(v["p"][a], "p"), t.n[k][a] = parse_rational(v["n"][a], "n");
    }
    parse_scene_rest(in, "input", t.scene);
    NoProbe none;
    const auto r = gouraud_vs_phong<Rational>(t, none);
    const auto samples = oracle::triangle_samples(t.xy);
    REQUIRE(r.pixels.size() == samples.size());
    REQUIRE(samples.size() > 10);
    auto at = [&](const Vec3<Rational>& p, const Vec3<Rational>& n) {
      ShadeScene<Rational> s = t.scene;
      s.p = p, s.n = n;
      return oracle::shade_gl(oracle_case(s)).rgb;
    };
    std::array<oracle::Rgb, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = at(t.p[k], t.n[k]);
    const Rational tol = Rational(1) / Rational(mpz_class(1) << 200);
    Rational worst = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const Pixel s = samples[i];
      const auto& g = r.pixels[i];
      CHECK(g.px == s);
      REQUIRE(g.defined);
      Vec3<Rational> p, n;
      for (int a = 0; a < 3; ++a) {
        p[a] = oracle::linear_at(t.xy, {t.p[0][a], t.p[1][a], t.p[2][a]}, s);
        n[a] = oracle::linear_at(t.xy, {t.n[0][a], t.n[1][a], t.n[2][a]}, s);
      }
      const auto phong = at(p, n);
      for (int a = 0; a < 3; ++a) {
        const Rational gouraud = oracle::linear_at(t.xy, {c[0][a], c[1][a], c[2][a]}, s);
        CHECK(abs(Rational(g.gouraud[a] - gouraud)) <= tol);
        CHECK(abs(Rational(g.phong[a] - phong[std::size_t(a)])) <= tol);
        worst = std::max(worst, Rational(abs(Rational(phong[std::size_t(a)] - gouraud))));
      }
    }
    CHECK(abs(Rational(r.max_diff - worst)) <= tol);
    if (variant == 0) CHECK(worst > Rational(1, 2));  // the highlight Gouraud misses (docs/lighting/shade.md)
  }
}
