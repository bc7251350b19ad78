// The scene reader's parts: typed readers, textures, materials, lights and sampling
// (docs/tracer/scene-format.md). Every failure is one InputError line naming the JSON path.
#include <filesystem>
#include <fstream>
#include "lighting/models.hpp"
#include "tracer/scene_read.hpp"

namespace sw::tracer::detail {

constexpr double kValueBound = 1e6;     // colours, scales, amplitudes
constexpr double kExponentBound = 1e4;  // shininess and spot exponents, as in `shade`

std::string at(const std::string& what, const char* key) { return what + "." + key; }

Real real_of(const Rational& q) { return {q, q.get_d()}; }
Real3 real3_of(const Vec3<Rational>& q) { return {q, {q.x.get_d(), q.y.get_d(), q.z.get_d()}}; }

Real real(const Json& j, const std::string& what, double lo, double hi, bool open_lo) {
  const Rational q = parse_rational(j, what);
  if (open_lo ? q <= Rational(lo) : q < Rational(lo))
    throw InputError(what + ": must be " + (open_lo ? "> " : ">= ") + num::to_text(lo) + ", got " + q.get_str());
  if (q > Rational(hi)) throw InputError(what + ": must be <= " + num::to_text(hi) + ", got " + q.get_str());
  return real_of(q);
}
Real real_or(const Json& obj, const char* key, const std::string& what, double lo, double hi, Real dflt, bool open_lo) {
  return obj.contains(key) ? real(obj[key], at(what, key), lo, hi, open_lo) : dflt;
}

Real3 point(const Json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3) throw InputError(what + ": expected an array of 3 numbers");
  Vec3<Rational> p;
  for (int k = 0; k < 3; ++k) {
    p[k] = parse_rational(j[k], at(what, k));
    check_bound(p[k], kCoordBound, at(what, k));
  }
  return real3_of(p);
}
Real3 nonzero(const Json& j, const std::string& what) {
  Real3 v = point(j, what);
  if (sgn(v.q.x) == 0 && sgn(v.q.y) == 0 && sgn(v.q.z) == 0) throw InputError(what + ": zero-length direction");
  return v;
}
Real3 colour(const Json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3) throw InputError(what + ": expected a colour [r, g, b]");
  Vec3<Rational> c;
  for (int k = 0; k < 3; ++k) c[k] = real(j[k], at(what, k), 0, kValueBound).q;
  return real3_of(c);
}
Real3 colour_or(const Json& obj, const char* key, const std::string& what, const Real3& dflt) {
  return obj.contains(key) ? colour(obj[key], at(what, key)) : dflt;
}
static Real3 grey(Rational g) { return real3_of({g, g, g}); }

std::uint32_t seed_or(const Json& obj, const char* key, const std::string& what) {
  return obj.contains(key) ? static_cast<std::uint32_t>(parse_integer(obj[key], at(what, key), 0, 0xffffffffLL)) : 0;
}

std::string text(const Json& j, const std::string& what) {
  if (!j.is_string()) throw InputError(what + ": expected a string, got " + std::string(j.type_name()));
  std::string s = j.get<std::string>();
  if (s.size() > 4096) throw InputError(what + ": longer than 4096 bytes");
  if (s.find('\0') != std::string::npos) throw InputError(what + ": contains a NUL character");
  return s;
}

std::string resolve(const std::string& file, const std::string& what, const SceneOptions& opt) {
  if (file.empty()) throw InputError(what + ": empty file name");
  const std::filesystem::path p(file);
  if (p.is_absolute()) throw InputError(what + ": '" + one_line(file, 200) + "' is absolute; paths are relative to the scene file");
  const std::string path = (std::filesystem::path(opt.base_dir) / p).lexically_normal().string();
  if (opt.load_files) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw InputError(what + ": '" + one_line(file, 200) + "' is missing or not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(what + ": '" + one_line(file, 200) + "' cannot be read");
  }
  return path;
}

void check_name(const std::string& name, const std::string& what) {
  bool ok = !name.empty() && name.size() <= 64;
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.');
  if (!ok) throw InputError(what + ": the name '" + one_line(name, 80) + "' must be 1 to 64 letters, digits, '-', '_' or '.'");
}

namespace {

// A PNG's width and height from its IHDR chunk (the first, by the PNG specification).
void read_png_size(Texture& t, const std::string& what) {
  std::ifstream in(t.path, std::ios::binary);
  unsigned char h[24] = {};
  in.read(reinterpret_cast<char*>(h), sizeof h);
  static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (in.gcount() != 24 || !std::equal(sig, sig + 8, h) || std::string(h + 12, h + 16) != "IHDR")
    throw InputError(what + ": '" + one_line(t.file, 200) + "' is not a PNG file");
  auto be32 = [&](int o) { return (std::int64_t{h[o]} << 24) | (h[o + 1] << 16) | (h[o + 2] << 8) | h[o + 3]; };
  t.image_width = be32(16), t.image_height = be32(20);
  if (t.image_width < 1 || t.image_height < 1 || t.image_width > kMaxImageSide || t.image_height > kMaxImageSide)
    throw InputError(what + ": the image is " + std::to_string(t.image_width) + "x" + std::to_string(t.image_height) + ", sides must be in [1, 16384]");
  if (t.image_width * t.image_height > kMaxImageTexels)
    throw InputError(what + ": the image is " + std::to_string(t.image_width) + "x" + std::to_string(t.image_height) + ", more than 2^24 texels (4096x4096)");
}

Texture parse_texture(const Json& j, const std::string& what, const SceneOptions& opt) {
  Texture t;
  const std::string type = text(require(j, "type", what), at(what, "type"));
  const Real one = real_of(1);
  if (type == "checker") {
    only_keys_optional(j, {"type"}, {"scale", "colours"}, what);
    t.kind = TextureKind::checker;
    t.scale = real_or(j, "scale", what, 0, kValueBound, real_of(8), true);
    t.colours = {grey(1), grey(0)};
  } else if (type == "marble" || type == "wood") {
    only_keys_optional(j, {"type"}, {"scale", "colours", "seed"}, what);
    t.kind = type == "marble" ? TextureKind::marble : TextureKind::wood;
    t.scale = real_or(j, "scale", what, 0, kValueBound, one, true);
    t.seed = seed_or(j, "seed", what);
    t.colours = type == "marble" ? std::array{grey(Rational(9, 10)), grey(Rational(1, 5))}
                                 : std::array{real3_of({Rational(3, 5), Rational(2, 5), Rational(1, 5)}), real3_of({Rational(3, 10), Rational(1, 5), Rational(1, 10)})};
  } else if (type == "image") {
    only_keys(j, {"type", "file"}, what);
    t.kind = TextureKind::image;
    t.file = text(j["file"], at(what, "file"));
    t.path = resolve(t.file, at(what, "file"), opt);
    if (opt.load_files) read_png_size(t, at(what, "file"));
    return t;
  } else {
    throw InputError(at(what, "type") + ": unknown texture type '" + one_line(type, 60) + "' (checker, image, marble, wood)");
  }
  if (j.contains("colours")) {
    const Json& c = j["colours"];
    if (!c.is_array() || c.size() != 2) throw InputError(at(what, "colours") + ": expected two colours [[r,g,b], [r,g,b]]");
    t.colours = {colour(c[0], at(at(what, "colours"), 0)), colour(c[1], at(at(what, "colours"), 1))};
  }
  return t;
}

template <class E> E model_by_name(const Json& j, const std::string& what, int count) {
  const std::string name = text(j, what);
  std::string known;
  for (int k = 0; k < count; ++k) {
    if (lighting::model_name(E(k)) == name) return E(k);
    known += (k ? ", " : "") + std::string(lighting::model_name(E(k)));
  }
  throw InputError(what + ": unknown model '" + one_line(name, 60) + "' (" + known + ")");
}

Material parse_material(const Json& j, const std::string& what, const std::vector<Texture>& textures) {
  only_keys_optional(j, {}, {"diffuse_model", "specular_model", "emission", "ambient", "diffuse", "specular", "shininess", "minnaert_k", "sigma",
                             "m", "toon", "fresnel", "ior", "kr", "kt", "texture", "bump"}, what);
  Material m;
  auto& s = m.shading;
  s.diffuse = j.contains("diffuse_model") ? model_by_name<lighting::DiffuseModel>(j["diffuse_model"], at(what, "diffuse_model"), lighting::kDiffuseModels)
                                          : lighting::DiffuseModel::lambert;
  s.specular = j.contains("specular_model") ? model_by_name<lighting::SpecularModel>(j["specular_model"], at(what, "specular_model"), lighting::kSpecularModels)
                                            : lighting::SpecularModel::none;
  s.emission = colour_or(j, "emission", what, grey(0)).q;
  s.ka = colour_or(j, "ambient", what, grey(Rational(1, 5))).q;
  s.kd = colour_or(j, "diffuse", what, grey(Rational(4, 5))).q;
  s.ks = colour_or(j, "specular", what, grey(0)).q;
  auto& p = s.params;
  p.shininess = real_or(j, "shininess", what, 0, kExponentBound, real_of(0)).q;
  p.minnaert_k = real_or(j, "minnaert_k", what, 0, 1, real_of(1)).q;
  p.sigma = real_or(j, "sigma", what, 0, 1, real_of(0)).q;
  p.m = real_or(j, "m", what, 0, kValueBound, real_of(Rational(3, 10)), true).q;
  if (j.contains("toon")) p.toon = real(j["toon"], at(what, "toon"), 0, 1).q;
  if (j.contains("fresnel")) {
    const std::string f = text(j["fresnel"], at(what, "fresnel"));
    if (f == "exact") p.fresnel = lighting::Fresnel::exact;
    else if (f == "schlick") p.fresnel = lighting::Fresnel::schlick;
    else throw InputError(at(what, "fresnel") + ": expected \"exact\" or \"schlick\"");
  }
  m.ior = real_or(j, "ior", what, 1, 100, real_of(Rational(3, 2)));
  p.ior = m.ior.q;
  m.kr = real_or(j, "kr", what, 0, 1, real_of(0));
  m.kt = real_or(j, "kt", what, 0, 1, real_of(0));
  if (m.kr.q + m.kt.q > 1)  // exactly: JSON 0.1 + 0.9 is above 1, as the doubles are
    throw InputError(what + ": kr + kt = " + Rational(m.kr.q + m.kt.q).get_str() + " exceeds 1 (numbers are exact: write \"1/10\" for a tenth)");
  if (j.contains("texture")) {
    const std::string name = text(j["texture"], at(what, "texture"));
    for (std::size_t i = 0; i < textures.size() && m.texture < 0; ++i)
      if (textures[i].name == name) m.texture = static_cast<int>(i);
    if (m.texture < 0) throw InputError(at(what, "texture") + ": unknown texture '" + one_line(name, 60) + "'");
  }
  if (j.contains("bump")) {
    const Json& b = j["bump"];
    const std::string bw = at(what, "bump");
    only_keys_optional(b, {"amplitude", "scale"}, {"seed"}, bw);
    m.bump.on = true;
    m.bump.amplitude = real(b["amplitude"], at(bw, "amplitude"), 0, kValueBound, true);
    m.bump.scale = real(b["scale"], at(bw, "scale"), 0, kValueBound, true);
    m.bump.seed = seed_or(b, "seed", bw);
  }
  return m;
}

lighting::Light<Rational> parse_light(const Json& j, const std::string& what) {
  lighting::Light<Rational> l;
  const std::string type = text(require(j, "type", what), at(what, "type"));
  const std::initializer_list<const char*> colours{"type", "colour", "ambient", "diffuse", "specular"};
  if (type == "point") {
    only_keys_optional(j, {"position"}, {"type", "attenuation", "colour", "ambient", "diffuse", "specular"}, what);
    l.type = lighting::LightType::point;
    l.where = point(j["position"], at(what, "position")).q;
  } else if (type == "directional") {
    only_keys_optional(j, {"direction"}, colours, what);
    l.type = lighting::LightType::directional;
    l.where = nonzero(j["direction"], at(what, "direction")).q;
  } else if (type == "spot") {
    only_keys_optional(j, {"position", "spot_direction", "cutoff"}, {"type", "exponent", "attenuation", "colour", "ambient", "diffuse", "specular"}, what);
    l.type = lighting::LightType::spot;
    l.where = point(j["position"], at(what, "position")).q;
    l.spot_dir = nonzero(j["spot_direction"], at(what, "spot_direction")).q;
    const Rational c = parse_rational(j["cutoff"], at(what, "cutoff"));
    if (c != 180 && (sgn(c) < 0 || c > 90)) throw InputError(at(what, "cutoff") + ": degrees in [0, 90], or 180 (no cone), got " + c.get_str());
    l.cone.all = c == 180, l.cone.degrees = c;
    if (const auto c2 = lighting::rational_cos2(c); c2 && !l.cone.all) l.cone.cos2_exact = true, l.cone.cos2 = *c2;
    l.cone.exponent = real_or(j, "exponent", what, 0, kExponentBound, real_of(0)).q;
  } else {
    throw InputError(at(what, "type") + ": unknown light type '" + one_line(type, 60) + "' (point, directional, spot)");
  }
  if (j.contains("attenuation")) {
    const Json& a = j["attenuation"];
    const std::string aw = at(what, "attenuation");
    if (!a.is_array() || a.size() != 3) throw InputError(aw + ": expected [constant, linear, quadratic]");
    l.k0 = real(a[0], at(aw, 0), 0, kValueBound).q, l.k1 = real(a[1], at(aw, 1), 0, kValueBound).q, l.k2 = real(a[2], at(aw, 2), 0, kValueBound).q;
    if (sgn(l.k0) == 0 && sgn(l.k1) == 0 && sgn(l.k2) == 0) throw InputError(aw + ": all three factors are 0");
  }
  const Real3 c = colour_or(j, "colour", what, grey(1));
  l.ambient = colour_or(j, "ambient", what, grey(0)).q;
  l.diffuse = colour_or(j, "diffuse", what, c).q;
  l.specular = colour_or(j, "specular", what, c).q;
  return l;
}

}  // namespace

std::vector<Texture> parse_textures(const Json& j, const std::string& what, const SceneOptions& opt) {
  if (!j.is_object()) throw InputError(what + ": expected an object of named textures");
  if (j.size() > kMaxTextures) throw InputError(what + ": " + std::to_string(j.size()) + " textures, more than the bound 256");
  std::vector<Texture> out;
  for (auto it = j.begin(); it != j.end(); ++it) {
    check_name(it.key(), what);
    const std::string w = at(what, it.key().c_str());
    if (!it.value().is_object()) throw InputError(w + ": expected an object");
    out.push_back(parse_texture(it.value(), w, opt));
    out.back().name = it.key();
  }
  return out;
}

std::vector<Material> parse_materials(const Json& j, const std::string& what, const std::vector<Texture>& textures) {
  if (!j.is_object() || j.empty()) throw InputError(what + ": expected a non-empty object of named materials");
  if (j.size() > kMaxMaterials) throw InputError(what + ": " + std::to_string(j.size()) + " materials, more than the bound 1024");
  std::vector<Material> out;
  for (auto it = j.begin(); it != j.end(); ++it) {
    check_name(it.key(), what);
    const std::string w = at(what, it.key().c_str());
    if (!it.value().is_object()) throw InputError(w + ": expected an object");
    out.push_back(parse_material(it.value(), w, textures));
    out.back().name = it.key();
  }
  return out;
}

std::vector<lighting::Light<Rational>> parse_lights(const Json& j, const std::string& what) {
  if (!j.is_array()) throw InputError(what + ": expected an array of lights");
  if (j.size() > kMaxLights) throw InputError(what + ": " + std::to_string(j.size()) + " lights, more than the bound 8");
  std::vector<lighting::Light<Rational>> out;
  for (std::size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_object()) throw InputError(at(what, i) + ": expected an object");
    out.push_back(parse_light(j[i], at(what, i)));
  }
  return out;
}

Sampling parse_sampling(const Json& j, const std::string& what) {
  Sampling s;
  const std::string type = text(require(j, "type", what), at(what, "type"));
  if (type == "one") {
    only_keys(j, {"type"}, what);
  } else if (type == "regular" || type == "jittered") {
    s.kind = type == "regular" ? SamplingKind::regular : SamplingKind::jittered;
    if (s.kind == SamplingKind::regular) only_keys(j, {"type", "n"}, what);
    else only_keys_optional(j, {"type", "n"}, {"seed"}, what);
    s.n = parse_integer(j["n"], at(what, "n"), 1, kMaxSamplesPerAxis);
    s.seed = seed_or(j, "seed", what);
  } else if (type == "adaptive") {
    only_keys(j, {"type", "threshold", "max_n"}, what);
    s.kind = SamplingKind::adaptive;
    s.threshold = real(j["threshold"], at(what, "threshold"), 0, 1, true);
    s.n = parse_integer(j["max_n"], at(what, "max_n"), 2, kMaxSamplesPerAxis);
  } else {
    throw InputError(at(what, "type") + ": unknown sampling '" + one_line(type, 60) + "' (one, regular, jittered, adaptive)");
  }
  return s;
}

}  // namespace sw::tracer::detail
