// shade, step by step in reference mode: every variable and geometry item of every step, against
// values worked out by hand (docs/lighting/shade.md) for a scene whose every quantity is rational:
// lights at distance 25 in the directions (24, 0, 7)/25 and (0, 24, 7)/25 from the point, the eye
// straight above, so that |h| = 8/5 and n.h = 4/5, and a light at the point.
#include <catch2/catch.hpp>
#include "lighting/shade_input.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::lighting;
using sw::testing::ratio;

namespace {

using V = Vec3<Rational>;
V v(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d = 1) { return {ratio(a, d), ratio(b, d), ratio(c, d)}; }

void vec_is(testing::StepValues& sv, const std::string& name, const V& x) {
  CHECK(sv[name + ".x"] == x.x);
  CHECK(sv[name + ".y"] == x.y);
  CHECK(sv[name + ".z"] == x.z);
}
void colour_is(testing::StepValues& sv, const std::string& name, const V& x) {
  CHECK(sv[name + ".r"] == x.x);
  CHECK(sv[name + ".g"] == x.y);
  CHECK(sv[name + ".b"] == x.z);
}
void geo_is(testing::StepGeometry& g, GeoKind kind, std::vector<Rational> values, const std::string& label, const std::string& life) {
  auto& item = g.take(kind);
  CHECK(item.values == values);
  CHECK(item.label == label);
  CHECK(item.life == life);
}

}  // namespace

TEST_CASE("shade steps: every recorded value in reference mode", "[lighting][shade]") {
  const Json in = Json::parse(R"({"p":[0,0,0],"n":[0,0,2],"eye":[0,0,5],"ambient":["1/5","1/5","1/5"],
    "lights":[{"position":[24,0,7],"attenuation":[1,"1/25",0]},
              {"type":"spot","position":[0,24,7],"spot_direction":[0,0,-1],"cutoff":90,"exponent":1},
              {"position":[0,0,0],"ambient":[1,1,1]}],
    "material":{"ambient":["1/2","1/2","1/2"],"diffuse":[1,"1/2","1/4"],"specular":["1/2","1/2","1/2"],"shininess":3}})");
  Recorder<Rational> t;
  const auto out = shade<Rational>(convert_scene<Rational>(parse_scene(in, "input")), t);
  using L = Shade;
  const V kd = v(4, 2, 1, 4), ks = v(1, 1, 1, 2), zero = v(0, 0, 0);
  const V ambient = v(1, 1, 1, 10);
  // Per light: what it adds = att spot (diff kd + spec ks); diff = 7/25, spec = (4/5)^3 = 64/125.
  const Rational diff = ratio(7, 25), spec = ratio(64, 125);
  auto adds = [&](const Rational& w) { return V(w * (diff * kd + spec * ks)); };
  const V add0 = adds(ratio(1, 2)), add1 = adds(ratio(7, 25));
  const V c1 = ambient + add0, c2 = c1 + add1;
  int light = -1;
  for (std::size_t s = 0; s < t.size(); ++s) {
    auto sv = testing::values_of(t, s);
    auto g = testing::geometry_of(t, s);
    const auto line = L::Line(t.at(s).line);
    INFO("step " << s << " line " << t.at(s).line << " light " << light);
    switch (line) {
      case L::normal:
        vec_is(sv, "N", v(0, 0, 2));
        vec_is(sv, "n", v(0, 0, 1));
        geo_is(g, GeoKind::point3, {0, 0, 0}, "P", "keep");
        geo_is(g, GeoKind::segment3, {0, 0, 0, 0, 0, 1}, "n", "keep");
        break;
      case L::view:
        vec_is(sv, "e", v(0, 0, 1));
        CHECK(sv["facing"] == 1);
        geo_is(g, GeoKind::segment3, {0, 0, 0, 0, 0, 1}, "e", "keep");
        geo_is(g, GeoKind::point3, {0, 0, 5}, "eye", "keep");
        break;
      case L::ambient: colour_is(sv, "c", ambient); break;
      case L::lights:
        ++light;
        CHECK(sv["i"] == light);
        CHECK(sv["type"] == (light == 1 ? 2 : 0));  // point, spot, point
        break;
      case L::to_light: {
        const V where = light == 0 ? v(24, 0, 7) : light == 1 ? v(0, 24, 7) : zero;
        vec_is(sv, "L", where);
        geo_is(g, GeoKind::point3, {where.x, where.y, where.z}, "light", "keep");
        geo_is(g, GeoKind::segment3, {0, 0, 0, where.x, where.y, where.z}, "L", "");
        break;
      }
      case L::at_point:
        CHECK(light == 2);
        CHECK(sv["i"] == 2);
        break;
      case L::facing:
        CHECK(sv["NL"] == 14);  // N.L = 2 * 7
        CHECK(sv["lit"] == 1);
        break;
      case L::unit:
        CHECK(sv["d"] == 25);
        vec_is(sv, "l", light == 0 ? v(24, 0, 7, 25) : v(0, 24, 7, 25));
        break;
      case L::atten: CHECK(sv["att"] == (light == 0 ? ratio(1, 2) : Rational(1))); break;
      case L::cone:
        REQUIRE(light == 1);
        CHECK(sv["DS"] == ratio(7, 24));    // D/24 = (0, -1, -7/24), S = (0, 0, -1)
        CHECK(sv["q"] == ratio(625, 576));  // |D/24|^2 |S|^2
        CHECK(sv["inside"] == 1);
        CHECK(sv["spot"] == ratio(7, 25));
        geo_is(g, GeoKind::ray3, {0, 24, 7, 0, 0, -1}, "S", "");
        break;
      case L::diffuse: CHECK(sv["diff"] == diff); break;
      case L::specular:
        vec_is(sv, "h", light == 0 ? v(24, 0, 32, 25) : v(0, 24, 32, 25));
        CHECK(sv["nh"] == ratio(4, 5));  // (32/25)/(8/5)
        CHECK(sv["spec"] == spec);
        break;
      case L::add:
        colour_is(sv, "light", light == 0 ? add0 : add1);
        colour_is(sv, "c", light == 0 ? c1 : c2);
        break;
      case L::done: colour_is(sv, "rgb", c2); break;
      default: FAIL("a step on no listing line"); break;
    }
    testing::require_all_checked(sv, s);
    testing::require_all_geometry_checked(g, s);
  }
  CHECK(light == 2);
  CHECK(out.rgb == c2);
  CHECK(out.lights[2].at_point);
}
