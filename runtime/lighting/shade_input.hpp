// The input of `shade` and `gouraud-vs-phong` (shade_spec.cpp): the scene in exact rationals, parsed and
// validated (every failure one InputError line), and converted to a number type. The JSON shape
// and the defaults (OpenGL's): docs/lighting/shade.md.
#pragma once
#include <string>
#include "input.hpp"
#include "lighting/shade.hpp"

namespace sw::lighting {

// A scene from JSON: {"p", "n", "eye" | "eye_direction", "ambient"?, "convention"?, "lights": [...],
// "material": {...}}. At most kMaxLights lights (OpenGL's guaranteed 8).
ShadeScene<Rational> parse_scene(const Json& j, const std::string& what);
// The part of a scene without p and n (gouraud-vs-phong gives them per vertex).
void parse_scene_rest(const Json& j, const std::string& what, ShadeScene<Rational>& s);
inline constexpr std::size_t kMaxLights = 8;

template <class Num> SpotCone<Num> convert_cone(const SpotCone<Rational>& c) {
  SpotCone<Num> o;
  o.all = c.all;
  o.degrees = num::from_rational<Num>(c.degrees);
  o.exponent = num::from_rational<Num>(c.exponent);
  o.cos2_exact = c.cos2_exact;
  if constexpr (std::is_same_v<Num, Rational>) {
    o.cos = num::cos(Rational(c.degrees * num::pi<Rational>() / 180));
    o.cos2 = c.cos2_exact ? c.cos2 : Rational(o.cos * o.cos);
  } else if constexpr (std::is_floating_point_v<Num>) {
    o.cos = num::cos(Num(o.degrees * Num(3.14159265358979323846 / 180)));
    o.cos2 = Num(o.cos * o.cos);
  }
  return o;
}

template <class Num> Vec3<Num> to_num3(const Vec3<Rational>& v) { return to_num<Num>(v); }

template <class Num> ShadeScene<Num> convert_scene(const ShadeScene<Rational>& s) {
  ShadeScene<Num> o;
  o.p = to_num3<Num>(s.p), o.n = to_num3<Num>(s.n), o.eye = to_num3<Num>(s.eye);
  o.eye_at_infinity = s.eye_at_infinity;
  o.scene_ambient = to_num3<Num>(s.scene_ambient);
  o.convention = s.convention;
  o.blocked = s.blocked;
  const Material<Rational>& m = s.material;
  o.material.emission = to_num3<Num>(m.emission), o.material.ka = to_num3<Num>(m.ka);
  o.material.kd = to_num3<Num>(m.kd), o.material.ks = to_num3<Num>(m.ks);
  o.material.diffuse = m.diffuse, o.material.specular = m.specular;
  auto& q = o.material.params;
  q.minnaert_k = num::from_rational<Num>(m.params.minnaert_k), q.sigma = num::from_rational<Num>(m.params.sigma);
  if (m.params.toon) q.toon = num::from_rational<Num>(*m.params.toon);
  q.shininess = num::from_rational<Num>(m.params.shininess), q.m = num::from_rational<Num>(m.params.m);
  q.ior = num::from_rational<Num>(m.params.ior), q.fresnel = m.params.fresnel;
  for (const Light<Rational>& l : s.lights) {
    Light<Num> x;
    x.type = l.type, x.where = to_num3<Num>(l.where), x.spot_dir = to_num3<Num>(l.spot_dir), x.cone = convert_cone<Num>(l.cone);
    x.k0 = num::from_rational<Num>(l.k0), x.k1 = num::from_rational<Num>(l.k1), x.k2 = num::from_rational<Num>(l.k2);
    x.ambient = to_num3<Num>(l.ambient), x.diffuse = to_num3<Num>(l.diffuse), x.specular = to_num3<Num>(l.specular);
    o.lights.push_back(x);
  }
  return o;
}

}  // namespace sw::lighting
