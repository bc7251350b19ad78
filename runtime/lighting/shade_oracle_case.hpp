// A scene as the independent oracle takes it (oracle/lighting_shade_oracle.hpp), for shade_spec.cpp, the
// tests and the GL peer (each links sw_oracle).
#pragma once
#include "lighting/shade.hpp"
#include "lighting_shade_oracle.hpp"

namespace sw::lighting {

inline sw::oracle::ShadeCase oracle_case(const ShadeScene<Rational>& s) {
  sw::oracle::ShadeCase c;
  auto rgb = [](const Vec3<Rational>& v) { return sw::oracle::Rgb{v.x, v.y, v.z}; };
  c.p = s.p, c.n = s.n, c.eye = s.eye, c.eye_at_infinity = s.eye_at_infinity;
  c.scene_ambient = rgb(s.scene_ambient), c.emission = rgb(s.material.emission);
  c.ka = rgb(s.material.ka), c.kd = rgb(s.material.kd), c.ks = rgb(s.material.ks);
  c.shininess = s.material.params.shininess;
  for (std::size_t i = 0; i < s.lights.size(); ++i) {
    const Light<Rational>& l = s.lights[i];
    sw::oracle::ShadeLight o;
    o.blocked = (s.blocked >> i) & 1u;
    o.type = l.type == LightType::point ? sw::oracle::ShadeLight::Type::point
             : l.type == LightType::spot ? sw::oracle::ShadeLight::Type::spot : sw::oracle::ShadeLight::Type::directional;
    o.where = l.where, o.spot_dir = l.spot_dir, o.cutoff = l.cone.degrees, o.exponent = l.cone.exponent;
    o.k0 = l.k0, o.k1 = l.k1, o.k2 = l.k2;
    o.ambient = rgb(l.ambient), o.diffuse = rgb(l.diffuse), o.specular = rgb(l.specular);
    c.lights.push_back(o);
  }
  return c;
}

}  // namespace sw::lighting
