// shade: hand-computed exact cases, reference mode against the independent MPFR oracle (random and
// hard scenes), the float failures on the hard set by group, and bad input (one-line InputError;
// the CLI exits 2 and writes no file). Semantics: docs/lighting/shade.md.
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include "catalog.hpp"
#include "cli_harness.hpp"
#include "lighting/shade_common.hpp"
#include "lighting/shade_input.hpp"
#include "lighting/shade_oracle_case.hpp"

using namespace sw;
using namespace sw::lighting;

namespace {

Shaded<Rational> exact_shade(const std::string& json) {
  NoProbe none;
  return shade<Rational>(convert_scene<Rational>(parse_scene(Json::parse(json), "input")), none);
}
Rational q(std::int64_t a, std::int64_t b = 1) { return Rational(a) / Rational(b); }

}  // namespace

TEST_CASE("shade: hand-computed GL cases, exact", "[lighting][shade]") {
  SECTION("a point light straight above, local eye above: n.l = n.h = 1") {
    // att = 1/(1 + 1/2 * 2 + 1/4 * 4) = 1/3; colour = ambient 1/5 * 1/2 + 1/3 (1/10 * 1/2 + 1 * 3/5 + 1 * 1/4)
    const auto s = exact_shade(R"({"p":[0,0,0],"n":[0,0,7],"eye":[0,0,5],"ambient":["0.2","0.2","0.2"],
      "lights":[{"position":[0,0,2],"attenuation":[1,"0.5","0.25"],"ambient":["0.1","0.1","0.1"],"diffuse":[1,1,1],"specular":[1,1,1]}],
      "material":{"ambient":["0.5","0.5","0.5"],"diffuse":["0.6","0.6","0.6"],"specular":["0.25","0.25","0.25"],"shininess":7}})");
    REQUIRE(s.lights.size() == 1);
    CHECK(s.lights[0].lit);
    CHECK(s.lights[0].attenuation == q(1, 3));
    CHECK(s.lights[0].diffuse == 1);
    CHECK(s.lights[0].specular == 1);
    const Rational expect = q(1, 10) + q(1, 3) * (q(1, 20) + q(3, 5) + q(1, 4));
    CHECK(s.rgb.x == expect);
    CHECK(s.rgb.z == expect);
  }
  SECTION("a spot exactly on its 60 degree cut-off is inside: spot = (1/2)^2") {
    // D = P - light = (1, 1, 0), S = (1, 0, 1): D.S / (|D||S|) = 1/2 = cos 60.
    const auto s = exact_shade(R"({"p":[0,0,0],"n":[-1,-1,0],"eye":[-3,-3,1],"ambient":[0,0,0],
      "lights":[{"type":"spot","position":[-1,-1,0],"spot_direction":[1,0,1],"cutoff":60,"exponent":2}],
      "material":{"ambient":[0,0,0],"diffuse":[1,1,1]}})");
    CHECK(s.lights[0].inside);
    CHECK(s.lights[0].spot == q(1, 4));
    CHECK(abs(Rational(s.lights[0].diffuse - 1)) < Rational(1e-80));  // n = l = -D/|D|, |D| = sqrt 2 at 300 bits
    CHECK(abs(Rational(s.rgb.y - q(1, 4))) < Rational(1e-80));
  }
  SECTION("just outside the cut-off: nothing") {
    const auto s = exact_shade(R"({"p":[0,0,0],"n":[-1,-1,0],"eye":[-3,-3,1],"ambient":[0,0,0],
      "lights":[{"type":"spot","position":[-1,"-1000001/1000000",0],"spot_direction":[1,0,1],"cutoff":60,"exponent":2}],
      "material":{"ambient":[0,0,0],"diffuse":[1,1,1]}})");
    CHECK_FALSE(s.lights[0].inside);
    CHECK(s.rgb.x == 0);
  }
  SECTION("a spot turned away: P behind it (D.S < 0) is outside any cone up to 90 degrees") {
    // D = P - light = (0, 0, -2), S = (0, 0, 1): D.S = -2 < 0. Turned towards P it lights it fully.
    const std::string away = R"({"p":[0,0,0],"n":[0,0,1],"eye":[0,0,5],"ambient":[0,0,0],
      "lights":[{"type":"spot","position":[0,0,2],"spot_direction":[0,0,1],"cutoff":80,"exponent":0}],
      "material":{"ambient":[0,0,0],"diffuse":[1,1,1]}})";
    const auto s = exact_shade(away);
    CHECK_FALSE(s.lights[0].inside);
    CHECK(s.rgb.x == 0);
    std::string towards = away;
    towards.replace(towards.find("[0,0,1],\"cutoff\""), 7, "[0,0,-1]");
    const auto t = exact_shade(towards);
    CHECK(t.lights[0].inside);
    CHECK(t.rgb.x == 1);  // n = l = (0, 0, 1), spot^0 = 1, no attenuation
  }
  SECTION("grazing light (n.l = 0) and a light behind: no diffuse, no specular; ambient of the light stays") {
    const auto s = exact_shade(R"({"p":[0,0,0],"n":[0,0,1],"eye":[0,0,1],"ambient":[0,0,0],
      "lights":[{"position":[4,0,0],"ambient":["0.5","0.5","0.5"]},{"position":[0,0,-1]}],
      "material":{"ambient":[1,1,1],"diffuse":[1,1,1],"specular":[1,1,1],"shininess":0}})");
    CHECK_FALSE(s.lights[0].lit);
    CHECK_FALSE(s.lights[1].lit);
    CHECK(s.rgb.x == q(1, 2));
  }
  SECTION("a light at the shading point adds nothing, not even its ambient part") {
    const auto s = exact_shade(R"({"p":[1,2,3],"n":[0,0,1],"eye":[0,0,9],"ambient":[0,0,0],
      "lights":[{"position":[1,2,3],"ambient":[1,1,1]}],"material":{"ambient":[1,1,1]}})");
    CHECK(s.lights[0].at_point);
    CHECK(s.rgb.x == 0);
  }
  SECTION("infinite viewer: h = l + (0, 0, 1); n.h = cos 22.5 degrees squared to s = 2") {
    // n = z, l = x (grazing: unlit) is 0; take l = (0, 1, 1)/sqrt 2 directional: n.l = 1/sqrt 2,
    // h = (0, 1/sqrt 2, 1 + 1/sqrt 2), (n.h)^2 / |h|^2 = (1 + 1/sqrt 2)^2 / (2 + sqrt 2) = (2 + sqrt 2)/4.
    const auto s = exact_shade(R"({"p":[5,5,5],"n":[0,0,1],"eye_direction":[0,0,1],"ambient":[0,0,0],
      "lights":[{"type":"directional","direction":[0,3,3]}],
      "material":{"ambient":[0,0,0],"diffuse":[0,0,0],"specular":[1,1,1],"shininess":2}})");
    const double expect = (2 + std::sqrt(2.0)) / 4;
    CHECK(std::fabs(s.lights[0].specular.get_d() - expect) < 1e-15);
    CHECK(s.lights[0].attenuation == 1);
  }
}

TEST_CASE("shade: reference mode equals the independent MPFR oracle", "[lighting][shade]") {
  auto scenes = shade_random_scenes(150, 3);
  std::vector<std::string> groups;
  for (auto& s : shade_hard_scenes(&groups)) scenes.push_back(std::move(s));
  NoProbe none;
  const Rational tol = Rational(1) / Rational(mpz_class(1) << 200);
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const auto ref = shade<Rational>(convert_scene<Rational>(scenes[i]), none);
    const auto orc = oracle::shade_gl(oracle_case(scenes[i]));
    INFO("scene " << i << ": " << scene_json(scenes[i]).dump());
    REQUIRE(ref.lights.size() == orc.lights.size());
    for (std::size_t k = 0; k < ref.lights.size(); ++k) {
      CHECK(ref.lights[k].at_point == orc.lights[k].at_point);
      CHECK(ref.lights[k].lit == orc.lights[k].lit);
      CHECK(ref.lights[k].inside == orc.lights[k].inside);
    }
    for (int c = 0; c < 3; ++c) CHECK(abs(Rational(ref.rgb[c] - orc.rgb[std::size_t(c)])) <= tol);
  }
}

TEST_CASE("shade: float and double on the hard set, decision failures by group", "[lighting][shade]") {
  std::vector<std::string> groups;
  const auto scenes = shade_hard_scenes(&groups);
  NoProbe none;
  std::map<std::string, int> flt, dbl;
  std::map<std::string, double> flt_err, dbl_err;
  int on_cutoff_inside = 0, on_cutoff = 0;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const auto ref = shade_output(shade<Rational>(convert_scene<Rational>(scenes[i]), none));
    const auto f = shade_output(shade<float>(convert_scene<float>(scenes[i]), none));
    const auto d = shade_output(shade<double>(convert_scene<double>(scenes[i]), none));
    if (!(f == ref)) ++flt[groups[i]];
    if (!(d == ref)) ++dbl[groups[i]];
    flt_err[groups[i]] = std::max(flt_err[groups[i]], shade_error(f, ref));
    dbl_err[groups[i]] = std::max(dbl_err[groups[i]], shade_error(d, ref));
    if (groups[i] == "spot on its cut-off") ++on_cutoff, on_cutoff_inside += ref.flags[0][2];
  }
  std::string report;
  for (const auto& [g, n] : flt) report += g + ": float " + std::to_string(n) + "; ";
  for (const auto& [g, n] : dbl) report += g + ": double " + std::to_string(n) + "; ";
  for (const auto& [g, e] : flt_err) report += g + ": float error " + std::to_string(e) + " ulp; ";
  for (const auto& [g, e] : dbl_err) report += g + ": double error " + std::to_string(e) + " ulp; ";
  INFO(report);
  // The reference puts every on-cut-off point inside (closed cone), exactly.
  CHECK(on_cutoff_inside == on_cutoff);
  // n.l and n.e are decided exactly on the mode's input, so the failures are: the cone (a rounded
  // cos), grazing lights whose input rounds onto the plane (3 + 2^-k is 3 in float for k > 22, in
  // double for k > 51), and subnormal or 1e-40 vectors that are 0 in float.
  for (const auto& [g, n] : flt) CHECK((g == "spot on its cut-off" || g == "grazing light" || g.rfind("subnormal", 0) == 0));
  for (const auto& [g, n] : dbl) CHECK((g == "spot on its cut-off" || g == "grazing light"));
  CHECK(dbl["grazing light"] == 3);
  CHECK(flt["grazing light"] == 10);
  // Rounding cos(cut-off) decides some boundary points wrongly in each: the counts are in the docs.
  CHECK(flt["spot on its cut-off"] > 0);
  CHECK(dbl["spot on its cut-off"] > 0);
  // Prescaled normalisation: huge, tiny and (in double) subnormal vectors stay within a few ulps of
  // the reference; shininess 16 multiplies n.h's relative error by 16, hence 32.
  for (const char* g : {"non-unit normal", "non-unit directions"}) {
    CHECK(flt_err[g] <= 32);
    CHECK(dbl_err[g] <= 32);
  }
  for (const char* g : {"subnormal in float (normal)", "subnormal in float (directions)"}) {
    CHECK(dbl_err[g] <= 32);
    CHECK(flt_err[g] > 1e6);  // the input itself is 0 or loses its bits in float
  }
}

TEST_CASE("shade: bad input is one InputError line", "[lighting][shade]") {
  const Algorithm& alg = find_algorithm("shade");
  const Algorithm* a = &alg;
  const Json good = Json::parse(a->example);
  auto bad = [&](const char* pointer, Json value) {
    Json j = good;
    j[Json::json_pointer(pointer)] = std::move(value);
    return j;
  };
  const std::vector<std::pair<std::string, Json>> cases{
      {"zero normal", bad("/n", {0, 0, 0})},
      {"zero light direction", bad("/lights/2/direction", {0, 0, 0})},
      {"zero spot direction", bad("/lights/1/spot_direction", {0, 0, 0})},
      {"negative exponent", bad("/lights/1/exponent", -1)},
      {"negative shininess", bad("/material/shininess", -2)},
      {"unknown light type", bad("/lights/0/type", "area")},
      {"unknown model", [&] { Json j = bad("/material/diffuse_model", "phong-ish"); j["convention"] = "models"; return j; }()},
      {"model in gl convention", bad("/material/diffuse_model", "lambert")},
      {"NaN", bad("/p/0", "nan")},
      {"Inf", bad("/n/2", "inf")},
      {"colour of 2", bad("/material/diffuse", {1, 1})},
      {"colour of 4", bad("/lights/0/colour", {1, 1, 1, 1})},
      {"negative colour", bad("/ambient", {0, -1, 0})},
      {"cut-off 91", bad("/lights/1/cutoff", 91)},
      {"cut-off -1", bad("/lights/1/cutoff", -1)},
      {"cut-off 179", bad("/lights/1/cutoff", 179)},
      {"negative attenuation", bad("/lights/0/attenuation", {1, -0.1, 0})},
      {"zero attenuation", bad("/lights/0/attenuation", {0, 0, 0})},
      {"eye at p", bad("/eye", {0, 0, 0})},
      {"unknown field", bad("/lights/0/cutoff", 30)},
      {"nine lights", [&] { Json j = good; for (int k = 0; k < 6; ++k) j["lights"].push_back(good["lights"][0]); return j; }()},
  };
  for (const auto& [why, j] : cases) {
    INFO(why);
    for (Numeric n : {Numeric::f32, Numeric::f64, Numeric::reference}) CHECK_THROWS_AS((void)(*a).open(j, n), InputError);
    try {
      (void)(*a).open(j, Numeric::f64);
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find('\n') == std::string::npos);
    }
  }
  CHECK_NOTHROW((void)(*a).open(good, Numeric::reference));
  // The CLI: exit 2, one line, and no partial trace file.
  const auto out = sw::testing::scratch("shade-bad-input") / "t.jsonl";
  const std::string cmd = std::string("\"") + SW_STEPWISE_EXE + "\" trace shade --numeric float --input '" + bad("/n", {0, 0, 0}).dump() +
                          "' --out " + out.string() + " 2>/dev/null";
  const int rc = std::system(cmd.c_str());
  CHECK(WIFEXITED(rc));
  CHECK(WEXITSTATUS(rc) == 2);
  CHECK_FALSE(std::filesystem::exists(out));
}
