// shade's output, error and seeded scenes (shade_common.hpp).
#include "lighting/shade_common.hpp"
#include <cmath>
#include <random>
#include "lighting/shade_input.hpp"

namespace sw::lighting {

std::vector<Param> shade_params() {
  return {{"/material/shininess", "shininess", 0, 128, true, "the highlight exponent (GL's range is 0 to 128)"},
          {"/material/minnaert_k", "k", 0, 1, false, "Minnaert's darkening exponent: 1 is Lambert"},
          {"/material/sigma", "sigma", 0, 1, false, "Oren-Nayar's slope spread in radians: 0 is Lambert"},
          {"/material/m", "m", 0.001, 1, true, "the RMS slope of the microfacets"},
          {"/material/ior", "ior", 1, 3, false, "the index of refraction in the Fresnel term"},
          {"/material/toon", "toon", 0, 1, false, "the diffuse value at which the toon band switches"},
          {"/lights/0/cutoff", "light 0 cut-off", 0, 90, false, "the first light's spot cut-off in degrees"},
          {"/lights/0/exponent", "light 0 exponent", 0, 128, false, "the first light's spot exponent"}};
}

Json shade_json(const ShadeOutput& o) {
  auto clamp = [](double x) { return x < 0 ? 0.0 : x > 1 ? 1.0 : x; };
  Json lights = Json::array();
  for (std::size_t i = 0; i < o.flags.size(); ++i) {
    const auto& t = o.terms[i];
    lights.push_back({{"at_point", o.flags[i][0]}, {"lit", o.flags[i][1]}, {"inside", o.flags[i][2]}, {"attenuation", t[0]}, {"spot", t[1]},
                      {"diffuse", t[2]}, {"specular", t[3]}, {"rgb", {t[4], t[5], t[6]}}});
  }
  return Json{{"rgb", {o.rgb[0], o.rgb[1], o.rgb[2]}},
              {"clamped", {clamp(o.rgb[0]), clamp(o.rgb[1]), clamp(o.rgb[2])}},
              {"ambient", {o.ambient[0], o.ambient[1], o.ambient[2]}},
              {"facing", o.facing},
              {"lights", lights}};
}

double shade_error(const ShadeOutput& got, const ShadeOutput& ref) {
  if (!ref.ref) return 0;
  double worst = 0;
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(got.rgb[k])) return INFINITY;
    worst = std::max(worst, std::fabs(Rational(num::to_rational(got.rgb[k]) - (*ref.ref)[std::size_t(k)]).get_d()));
  }
  return std::ldexp(worst, got.bits);
}

namespace {

Rational f(double x) { return num::to_rational(double(float(x))); }

class Maker {
 public:
  explicit Maker(std::uint64_t seed) : rng_(seed) {}
  double u(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  Vec3<Rational> vec(double lo, double hi) { return {f(u(lo, hi)), f(u(lo, hi)), f(u(lo, hi))}; }
  Vec3<Rational> colour() { return vec(0, 1); }
  Vec3<Rational> nonzero(double r) {
    for (;;) {
      const Vec3<Rational> v = vec(-r, r);
      if (sgn(dot(v, v)) > 0) return v;
    }
  }

 private:
  std::mt19937_64 rng_;
};

}  // namespace

std::vector<ShadeScene<Rational>> shade_random_scenes(std::size_t count, std::uint64_t seed) {
  Maker m(seed);
  std::vector<ShadeScene<Rational>> out;
  for (std::size_t i = 0; i < count; ++i) {
    ShadeScene<Rational> s;
    s.p = m.vec(-4, 4);
    s.n = m.nonzero(1.5);
    s.eye_at_infinity = m.pick(2);
    s.eye = s.eye_at_infinity ? Vec3<Rational>{0, 0, 1} : Vec3<Rational>{0, 0, 0};
    if (!s.eye_at_infinity && s.p == s.eye) s.p.z = 1;
    s.scene_ambient = Rational(1, 2) * m.colour();
    auto& mat = s.material;
    mat.emission = m.pick(4) ? Vec3<Rational>{0, 0, 0} : Rational(1, 4) * m.colour();
    mat.ka = m.colour(), mat.kd = m.colour(), mat.ks = m.colour();
    mat.params.shininess = m.pick(8) ? f(m.u(0, 128)) : Rational(m.pick(3) * 4);
    const int lights = 1 + m.pick(3);
    for (int k = 0; k < lights; ++k) {
      Light<Rational> l;
      const int type = m.pick(3);
      l.type = type == 0 ? LightType::point : type == 1 ? LightType::directional : LightType::spot;
      l.ambient = Rational(1, 4) * m.colour(), l.diffuse = Rational(1, 2) * m.colour(), l.specular = Rational(1, 2) * m.colour();
      if (l.type == LightType::directional) {
        l.where = m.nonzero(2);
      } else {
        l.where = m.vec(-6, 6);
        if (m.pick(3)) l.k0 = f(m.u(0.2, 2)), l.k1 = f(m.u(0, 0.5)), l.k2 = f(m.u(0, 0.2));
      }
      if (l.type == LightType::spot) {
        // Aimed near the point, so that about half the cases fall inside the cone.
        l.spot_dir = Vec3<Rational>(s.p - l.where) + m.vec(-2, 2);
        if (sgn(dot(l.spot_dir, l.spot_dir)) == 0) l.spot_dir = {0, 0, -1};
        const int c = m.pick(8);
        l.cone.all = c == 0;
        l.cone.degrees = c == 0 ? Rational(180) : c == 1 ? Rational(90) : c == 2 ? Rational(45) : f(m.u(5, 89));
        if (!l.cone.all) {
          const auto c2 = rational_cos2(l.cone.degrees);
          l.cone.cos2_exact = c2.has_value();
          if (c2) l.cone.cos2 = *c2;
        }
        l.cone.exponent = m.pick(4) ? f(m.u(0, 40)) : Rational(m.pick(3));
      }
      s.lights.push_back(l);
    }
    out.push_back(s);
  }
  return out;
}

namespace {

// One spot exactly on its cut-off: D (light -> point) and S with (D.S)^2 = cos^2(c) |D|^2 |S|^2,
// both scaled, then an axis permutation and sign flips (dot products unchanged).
ShadeScene<Rational> on_cutoff(const Rational& deg, Vec3<Rational> D, Vec3<Rational> S, const Rational& scale, int perm, int flips) {
  auto move = [&](Vec3<Rational> v) {
    const int a = perm % 3, b = (a + 1 + perm / 3) % 3, c = 3 - a - b;
    Vec3<Rational> w{v[a], v[b], v[c]};
    for (int k = 0; k < 3; ++k)
      if (flips >> k & 1) w[k] = Rational(-w[k]);
    return w;
  };
  D = move(D), S = move(S);
  ShadeScene<Rational> s;
  s.p = {Rational(1, 2), Rational(-1, 4), 1};
  s.n = Rational(-1) * D;  // faces the light
  s.eye = s.p + Rational(3) * s.n;
  Light<Rational> l;
  l.type = LightType::spot;
  l.where = s.p - scale * D;
  l.spot_dir = scale * S;
  l.cone.all = false, l.cone.degrees = deg, l.cone.exponent = 3;
  l.cone.cos2_exact = true, l.cone.cos2 = *rational_cos2(deg);
  l.diffuse = l.specular = {1, 1, 1};
  s.lights.push_back(l);
  s.material.ka = {Rational(1, 5), Rational(1, 5), Rational(1, 5)}, s.material.kd = {Rational(4, 5), Rational(3, 5), Rational(2, 5)};
  s.material.ks = {Rational(1, 2), Rational(1, 2), Rational(1, 2)}, s.material.params.shininess = 10;
  return s;
}

ShadeScene<Rational> simple(const Vec3<Rational>& n, const Vec3<Rational>& light, const Vec3<Rational>& eye) {
  ShadeScene<Rational> s;
  s.p = {0, 0, 0}, s.n = n, s.eye = eye;
  Light<Rational> l;
  l.where = light;
  l.k1 = Rational(1, 10);
  l.ambient = {Rational(1, 10), Rational(1, 10), Rational(1, 10)}, l.diffuse = l.specular = {1, 1, 1};
  s.lights.push_back(l);
  s.scene_ambient = {Rational(1, 5), Rational(1, 5), Rational(1, 5)};
  s.material.ka = {Rational(1, 5), Rational(1, 5), Rational(1, 5)}, s.material.kd = {Rational(4, 5), Rational(3, 5), Rational(2, 5)};
  s.material.ks = {Rational(1, 2), Rational(1, 2), Rational(1, 2)}, s.material.params.shininess = 16;
  return s;
}

}  // namespace

std::vector<ShadeScene<Rational>> shade_hard_scenes(std::vector<std::string>* groups) {
  std::vector<ShadeScene<Rational>> out;
  auto add = [&](ShadeScene<Rational> s, const char* g) {
    out.push_back(std::move(s));
    if (groups) groups->push_back(g);
  };
  struct Cone {
    int deg;
    Vec3<Rational> D, S;
  };
  const Cone cones[] = {{30, {1, 1, 0}, {2, 1, 1}}, {45, {1, 0, 0}, {1, 1, 0}}, {60, {1, 1, 0}, {1, 0, 1}}, {90, {1, 0, 0}, {0, 1, 0}}, {0, {2, 0, 0}, {3, 0, 0}}};
  const Rational scales[] = {1, Rational(1, 1024), 1024, Rational(3, 7), num::to_rational(1e-20), num::to_rational(1e12)};
  for (const Cone& c : cones)
    for (const Rational& sc : scales)
      for (int perm = 0; perm < 6; ++perm) add(on_cutoff(c.deg, c.D, c.S, sc, perm, perm * 3 % 8), "spot on its cut-off");
  // Grazing light: n.l = 0 exactly, and n.l of one part in 2^k.
  for (int k = 0; k <= 60; k += 4) {
    const Rational tiny = k == 0 ? Rational(0) : Rational(1) / Rational(mpz_class(1) << k);
    add(simple({0, 0, 1}, {5, 1, tiny}, {0, 1, 4}), "grazing light");
    add(simple({1, 1, 1}, {Rational(3 + tiny), -2, -1}, {1, 2, 3}), "grazing light");
    add(simple({0, 0, 1}, {1, 2, 4}, {4, -1, tiny}), "grazing eye");
  }
  // A light at the shading point, alone and beside another.
  add(simple({0, 0, 1}, {0, 0, 0}, {0, 0, 3}), "light at the point");
  {
    ShadeScene<Rational> s = simple({1, 2, 3}, {0, 0, 0}, {1, 1, 1});
    Light<Rational> l2;
    l2.where = {2, 2, 2}, l2.diffuse = l2.specular = {1, 1, 1};
    s.lights.push_back(l2);
    add(s, "light at the point");
  }
  // Non-unit vectors: huge, tiny and subnormal normals, light directions and eye directions.
  const double sizes[] = {1e-300, 4e-310, 1e-40, 1e-20, 1e15, 1e14};  // 1e15: the input bound
  for (double sz : sizes) {
    const Rational z = num::to_rational(sz);
    add(simple({0, Rational(z / 2), z}, {1, 2, 3}, {0, 1, 5}), sz < 1e-37 ? "subnormal in float (normal)" : "non-unit normal");
    ShadeScene<Rational> s = simple({1, 1, 2}, {0, 0, 0}, {0, 0, 0});
    s.eye_at_infinity = true, s.eye = {Rational(z / 3), Rational(z * 2 / 3), z};
    s.lights[0].type = LightType::directional, s.lights[0].where = {Rational(z * 3 / 5), Rational(z / 5), z};
    add(s, sz < 1e-37 ? "subnormal in float (directions)" : "non-unit directions");
  }
  return out;
}

Json scene_json(const ShadeScene<Rational>& s) {
  auto v = [](const Vec3<Rational>& x) { return Json::array({x.x.get_str(), x.y.get_str(), x.z.get_str()}); };
  Json j{{"p", v(s.p)}, {"n", v(s.n)}, {"ambient", v(s.scene_ambient)}};
  j[s.eye_at_infinity ? "eye_direction" : "eye"] = v(s.eye);
  if (s.convention == Convention::models) j["convention"] = "models";
  Json lights = Json::array();
  for (const auto& l : s.lights) {
    Json o{{"ambient", v(l.ambient)}, {"diffuse", v(l.diffuse)}, {"specular", v(l.specular)}};
    if (l.type == LightType::directional) {
      o["type"] = "directional", o["direction"] = v(l.where);
    } else {
      o["type"] = l.type == LightType::spot ? "spot" : "point";
      o["position"] = v(l.where);
      o["attenuation"] = Json::array({l.k0.get_str(), l.k1.get_str(), l.k2.get_str()});
    }
    if (l.type == LightType::spot) {
      o["spot_direction"] = v(l.spot_dir);
      o["cutoff"] = l.cone.degrees.get_str();
      o["exponent"] = l.cone.exponent.get_str();
    }
    lights.push_back(o);
  }
  j["lights"] = lights;
  const auto& m = s.material;
  j["material"] = {{"emission", v(m.emission)}, {"ambient", v(m.ka)}, {"diffuse", v(m.kd)}, {"specular", v(m.ks)}, {"shininess", m.params.shininess.get_str()}};
  return j;
}

}  // namespace sw::lighting
