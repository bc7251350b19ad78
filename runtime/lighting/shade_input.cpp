// Parsing and validating the scene of `shade` and `gouraud-vs-phong` (shade_input.hpp).
#include "lighting/shade_input.hpp"
#include "rays/ray_input.hpp"

namespace sw::lighting {
namespace {

constexpr double kValueBound = 1e6;   // colours, attenuation factors
constexpr double kExponentBound = 1e4;

// [x, y, z], each |c| <= 1e15: the ray family's point.
Vec3<Rational> vec3(const Json& j, const std::string& what) { return rays::point3(j, what); }
Vec3<Rational> nonzero(const Json& j, const std::string& what) {
  const Vec3<Rational> v = vec3(j, what);
  if (sgn(v.x) == 0 && sgn(v.y) == 0 && sgn(v.z) == 0) throw InputError(what + ": zero-length vector");
  return v;
}
Vec3<Rational> colour(const Json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3) throw InputError(what + ": expected a colour [r, g, b]");
  Vec3<Rational> c;
  for (int k = 0; k < 3; ++k) {
    const std::string w = what + "[" + std::to_string(k) + "]";
    c[k] = parse_rational(j[k], w);
    if (sgn(c[k]) < 0 || c[k] > Rational(kValueBound)) throw InputError(w + ": a colour component must be in [0, 1e6]");
  }
  return c;
}
Vec3<Rational> colour_or(const Json& obj, const char* key, const std::string& what, Vec3<Rational> dflt) {
  return obj.contains(key) ? colour(obj[key], what + "." + key) : dflt;
}
Rational in_range(const Json& j, const std::string& what, double hi) {
  const Rational v = parse_rational(j, what);
  if (sgn(v) < 0) throw InputError(what + ": must be >= 0, got " + v.get_str());
  if (v > Rational(hi)) throw InputError(what + ": must be <= " + Rational(hi).get_str());
  return v;
}

template <class E> E model_by_name(const Json& j, const std::string& what, int count) {
  if (!j.is_string()) throw InputError(what + ": expected a model name");
  const std::string name = j.get<std::string>();
  std::string known;
  for (int k = 0; k < count; ++k) {
    if (model_name(E(k)) == name) return E(k);
    known += (k ? ", " : "") + std::string(model_name(E(k)));
  }
  throw InputError(what + ": unknown model '" + name + "' (" + known + ")");
}

Light<Rational> parse_light(const Json& j, const std::string& what) {
  if (!j.is_object()) throw InputError(what + ": expected an object");
  Light<Rational> l;
  const std::string type = j.contains("type") ? (j["type"].is_string() ? j["type"].get<std::string>() : "?") : "point";
  if (type == "point") {
    only_keys_optional(j, {"position"}, {"type", "attenuation", "colour", "ambient", "diffuse", "specular"}, what);
    l.type = LightType::point;
  } else if (type == "directional") {
    only_keys_optional(j, {"direction"}, {"type", "colour", "ambient", "diffuse", "specular"}, what);
    l.type = LightType::directional;
  } else if (type == "spot") {
    only_keys_optional(j, {"position", "spot_direction", "cutoff"}, {"type", "exponent", "attenuation", "colour", "ambient", "diffuse", "specular"},
                       what);
    l.type = LightType::spot;
  } else {
    throw InputError(what + ".type: unknown light type (point, directional, spot)");
  }
  if (l.type == LightType::directional) l.where = nonzero(j["direction"], what + ".direction");
  else l.where = vec3(j["position"], what + ".position");
  if (j.contains("attenuation")) {
    const Json& a = j["attenuation"];
    if (!a.is_array() || a.size() != 3) throw InputError(what + ".attenuation: expected [constant, linear, quadratic]");
    l.k0 = in_range(a[0], what + ".attenuation[0]", kValueBound);
    l.k1 = in_range(a[1], what + ".attenuation[1]", kValueBound);
    l.k2 = in_range(a[2], what + ".attenuation[2]", kValueBound);
    if (sgn(l.k0) == 0 && sgn(l.k1) == 0 && sgn(l.k2) == 0) throw InputError(what + ".attenuation: all three factors are 0");
  }
  if (l.type == LightType::spot) {
    l.spot_dir = nonzero(j["spot_direction"], what + ".spot_direction");
    const Rational c = parse_rational(j["cutoff"], what + ".cutoff");
    if (c != 180 && (sgn(c) < 0 || c > 90)) throw InputError(what + ".cutoff: degrees in [0, 90], or 180 (no cone), got " + c.get_str());
    l.cone.all = c == 180;
    l.cone.degrees = c;
    if (!l.cone.all) {
      const auto c2 = rational_cos2(c);
      l.cone.cos2_exact = c2.has_value();
      if (c2) l.cone.cos2 = *c2;
    }
    if (j.contains("exponent")) l.cone.exponent = in_range(j["exponent"], what + ".exponent", kExponentBound);
  }
  const Vec3<Rational> white{1, 1, 1}, black{0, 0, 0};
  const Vec3<Rational> c = colour_or(j, "colour", what, white);
  l.ambient = colour_or(j, "ambient", what, black);
  l.diffuse = colour_or(j, "diffuse", what, c);
  l.specular = colour_or(j, "specular", what, c);
  return l;
}

}  // namespace

void parse_scene_rest(const Json& j, const std::string& what, ShadeScene<Rational>& s) {
  const bool has_eye = j.contains("eye"), has_dir = j.contains("eye_direction");
  if (has_eye == has_dir) throw InputError(what + ": give exactly one of eye (a point) and eye_direction (an eye at infinity)");
  s.eye_at_infinity = has_dir;
  s.eye = has_dir ? nonzero(j["eye_direction"], what + ".eye_direction") : vec3(j["eye"], what + ".eye");
  s.scene_ambient = colour_or(j, "ambient", what, {Rational(1, 5), Rational(1, 5), Rational(1, 5)});
  s.convention = Convention::gl;
  if (j.contains("convention")) {
    const Json& c = j["convention"];
    const std::string v = c.is_string() ? c.get<std::string>() : "";
    if (v == "models") s.convention = Convention::models;
    else if (v != "gl") throw InputError(what + ".convention: expected \"gl\" or \"models\"");
  }
  const Json& ls = require(j, "lights", what);
  if (!ls.is_array()) throw InputError(what + ".lights: expected an array of lights");
  if (ls.size() > kMaxLights) throw InputError(what + ".lights: at most 8 lights (OpenGL's guaranteed number)");
  for (std::size_t i = 0; i < ls.size(); ++i) s.lights.push_back(parse_light(ls[i], what + ".lights[" + std::to_string(i) + "]"));
  if (j.contains("blocked")) {  // the lights a ray tracer's shadow rays found occluded
    const Json& b = j["blocked"];
    if (!b.is_array()) throw InputError(what + ".blocked: expected an array of light indices");
    for (std::size_t k = 0; k < b.size(); ++k) {
      const std::int64_t i = parse_integer(b[k], what + ".blocked[" + std::to_string(k) + "]", 0, std::int64_t(ls.size()) - 1);
      s.blocked |= 1u << i;
    }
  }
  const Json& m = require(j, "material", what);
  const std::string mw = what + ".material";
  if (!m.is_object()) throw InputError(mw + ": expected an object");
  only_keys_optional(m, {}, {"emission", "ambient", "diffuse", "specular", "shininess", "diffuse_model", "specular_model", "minnaert_k", "sigma", "m", "ior", "fresnel", "toon"}, mw);
  Material<Rational>& mat = s.material;
  mat.emission = colour_or(m, "emission", mw, {0, 0, 0});
  mat.ka = colour_or(m, "ambient", mw, {Rational(1, 5), Rational(1, 5), Rational(1, 5)});
  mat.kd = colour_or(m, "diffuse", mw, {Rational(4, 5), Rational(4, 5), Rational(4, 5)});
  mat.ks = colour_or(m, "specular", mw, {0, 0, 0});
  auto& q = mat.params;
  q.shininess = m.contains("shininess") ? in_range(m["shininess"], mw + ".shininess", kExponentBound) : Rational(0);
  const bool model_keys = m.contains("diffuse_model") || m.contains("specular_model") || m.contains("minnaert_k") || m.contains("sigma") ||
                          m.contains("m") || m.contains("ior") || m.contains("fresnel") || m.contains("toon");
  if (model_keys && s.convention == Convention::gl) throw InputError(mw + ": model fields need \"convention\": \"models\"");
  if (m.contains("diffuse_model")) mat.diffuse = model_by_name<DiffuseModel>(m["diffuse_model"], mw + ".diffuse_model", kDiffuseModels);
  if (m.contains("specular_model")) mat.specular = model_by_name<SpecularModel>(m["specular_model"], mw + ".specular_model", kSpecularModels);
  if (m.contains("minnaert_k")) q.minnaert_k = in_range(m["minnaert_k"], mw + ".minnaert_k", 1);
  if (m.contains("sigma")) q.sigma = in_range(m["sigma"], mw + ".sigma", 1);
  if (m.contains("m")) {
    q.m = in_range(m["m"], mw + ".m", kValueBound);
    if (sgn(q.m) == 0) throw InputError(mw + ".m: must be > 0");
  }
  if (m.contains("ior")) {
    q.ior = in_range(m["ior"], mw + ".ior", kValueBound);
    if (sgn(q.ior) == 0) throw InputError(mw + ".ior: must be > 0");
  }
  if (m.contains("toon")) q.toon = in_range(m["toon"], mw + ".toon", 1);
  if (m.contains("fresnel")) {
    const std::string f = m["fresnel"].is_string() ? m["fresnel"].get<std::string>() : "";
    if (f == "exact") q.fresnel = Fresnel::exact;
    else if (f == "schlick") q.fresnel = Fresnel::schlick;
    else throw InputError(mw + ".fresnel: expected \"exact\" or \"schlick\"");
  }
}

ShadeScene<Rational> parse_scene(const Json& j, const std::string& what) {
  if (!j.is_object()) throw InputError(what + ": expected an object");
  only_keys_optional(j, {"p", "n", "lights", "material"}, {"eye", "eye_direction", "ambient", "convention", "blocked"}, what);
  ShadeScene<Rational> s;
  s.p = vec3(j["p"], what + ".p");
  s.n = nonzero(j["n"], what + ".n");
  parse_scene_rest(j, what, s);
  if (!s.eye_at_infinity && s.eye == s.p) throw InputError(what + ".eye: equals p (no direction to the eye)");
  return s;
}

}  // namespace sw::lighting
