#include "tracer/pov_export.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace sw::tracer {

namespace {

using Vd = Vec3<double>;  // POV-Ray takes doubles

Vd d3(const Real3& r) { return {r.d[0], r.d[1], r.d[2]}; }
// The double nearest q (get_d truncates).
double nearest(const Rational& q) {
  const double d = q.get_d();
  double best = d;
  for (const double c : {std::nextafter(d, -1e308), std::nextafter(d, 1e308)})
    if (abs(Rational(c) - q) < abs(Rational(best) - q)) best = c;
  return best;
}
Vd dq(const Vec3<Rational>& v) { return {nearest(v.x), nearest(v.y), nearest(v.z)}; }

// Doubles round-trip through %.17g; POV-Ray reads them with strtod.
std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}
std::string vec(const Vd& v) { return "<" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ">"; }
Vd unit(const Vd& v) { return (1 / std::sqrt(dot(v, v))) * v; }
bool grey(const Vd& c) { return c.x == c.y && c.y == c.z; }

std::string mat_path(const Material& m) { return "scene.materials." + m.name; }

// The camera: POV-Ray's perspective ray through pixel (i, j) is direction + x right + y up with
// x = (i + 1/2)/W - 1/2 and y = 1/2 - (j + 1/2)/H (pixel centres, measured with 3.7.0.10), which is
// camera-ray's view-plane point when right and up span the window.
void camera(std::ostream& o, const Camera& c, std::int64_t w, std::int64_t h) {
  if (c.projection != ray::Projection::perspective)
    throw InputError(
        "scene.camera.projection: " + std::string(c.projection == ray::Projection::fisheye ? "fisheye" : "cylindrical") +
        " has no one-to-one POV-Ray camera (export-pov takes perspective)");
  const Vd vpn = d3(c.vpn), vup = d3(c.vup);
  const Vd n = unit(vpn), u = unit(cross(vup, n)), v = cross(n, u);
  Vd dir = -c.dist.d * n, right, up;
  if (c.has_window) {
    const double u0 = c.window[0].d, u1 = c.window[1].d, v0 = c.window[2].d, v1 = c.window[3].d;
    dir = dir + (0.5 * (u0 + u1)) * u + (0.5 * (v0 + v1)) * v;
    right = (u1 - u0) * u, up = (v1 - v0) * v;
  } else {
    const double hh = c.dist.d * std::tan(c.fov.d * (3.14159265358979323846 / 360)), hw = hh * double(w) / double(h);
    right = (2 * hw) * u, up = (2 * hh) * v;
  }
  o << "camera { perspective location " << vec(d3(c.eye)) << " direction " << vec(dir) << " right " << vec(right) << " up "
    << vec(up) << " }\n";
}

// A point far beyond every finite object and the eye, towards a directional light: POV-Ray's
// parallel light needs a position, and casts shadows only from objects nearer than it.
Vd far_point(const Scene& s, const Vd& towards) {
  Vd lo = d3(s.camera.eye), hi = lo;
  auto grow = [&](const Vd& p) {
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  };
  for (const Object& ob : s.objects) {
    if (ob.kind == Shape::sphere)
      grow(d3(ob.a) - Vd{ob.radius.d, ob.radius.d, ob.radius.d}), grow(d3(ob.a) + Vd{ob.radius.d, ob.radius.d, ob.radius.d});
    else if (ob.kind == Shape::box) grow(d3(ob.a)), grow(d3(ob.b));
    else if (ob.kind == Shape::triangle) grow(d3(ob.v[0])), grow(d3(ob.v[1])), grow(d3(ob.v[2]));
    else if (ob.kind == Shape::plane) grow(d3(ob.a));
  }
  const Vd mid = 0.5 * (lo + hi), span = hi - lo;
  return mid + (1e3 * std::max(1.0, std::sqrt(dot(span, span)))) * unit(towards);
}

// One light as in the image (shadow = false) or as the shadow mask's plain white point light.
void light(std::ostream& o, const Scene& s, std::size_t i, bool image, std::vector<std::string>& approx) {
  const lighting::Light<Rational>& li = s.lights[i];
  const std::string at = "scene.lights[" + std::to_string(i) + "]";
  Vd colour = image ? dq(li.diffuse) : Vd{1, 1, 1};
  std::string extra;
  if (li.type == lighting::LightType::directional) {
    const Vd to = dq(li.where);
    o << "light_source { " << vec(far_point(s, to)) << " color rgb " << vec(colour) << " parallel point_at "
      << vec(far_point(s, to) - to) << " }\n";
    return;
  }
  if (image) {
    const double k0 = nearest(li.k0), k1 = nearest(li.k1), k2 = nearest(li.k2);
    // POV's fade is 2 / (1 + (d / fade_distance)^fade_power): 1/(k0 + k2 d^2) is it times 1/(2 k0)
    // with power 2 and distance sqrt(k0/k2); 1/(k0 + k1 d) with power 1 and distance k0/k1.
    if (k0 == 0) throw InputError(at + ".attenuation: k0 = 0 has no POV-Ray fade (2 / (1 + (d/fd)^p) is finite at d = 0)");
    if (k1 != 0 || k2 != 0) {
      if (k1 != 0 && k2 != 0) approx.push_back(at + ".attenuation: k1 and k2 both > 0: POV fades with k2 only (fade_power 2)");
      const bool square = k2 != 0;
      colour = (1 / (2 * k0)) * colour;
      extra = " fade_distance " + num(square ? std::sqrt(k0 / k2) : k0 / k1) + " fade_power " + (square ? "2" : "1");
    }
    if (li.type == lighting::LightType::spot && !li.cone.all) {
      // POV's cone: cos^tightness inside radius, a cubic blend out to falloff: radius just below falloff.
      const double cut = nearest(li.cone.degrees);
      extra += " spotlight point_at " + vec(dq(li.where) + dq(li.spot_dir)) + " radius " + num(cut * (1 - 1e-9)) + " falloff " +
               num(cut) + " tightness " + num(nearest(li.cone.exponent));
    }
    if (li.ambient != Vec3<Rational>{})
      approx.push_back(at + ".ambient: added to POV's ambient_light, without attenuation or cone");
    if (li.specular != li.diffuse) approx.push_back(at + ".specular: POV lights have one colour; the diffuse colour is used");
  }
  o << "light_source { " << vec(dq(li.where)) << " color rgb " << vec(colour) << extra << " }\n";
}

// The checker on an axis-aligned plane: ours is floor(u s) + floor(v s) over the two other axes;
// POV's checker is solid (unit cubes), so scaled by 1/s it adds floor(c s) of the plane's own axis,
// which picks the colour order. Returns the pigment.
std::string checker(const Scene& s, const Material& m, std::size_t obj_index) {
  const Texture& t = s.textures[static_cast<std::size_t>(m.texture)];
  const std::string at = "scene.objects[" + std::to_string(obj_index) + "].material";
  const Object& ob = s.objects[obj_index];
  const Vd nrm = d3(ob.b);
  const int axes = (nrm.x != 0) + (nrm.y != 0) + (nrm.z != 0);
  if (ob.kind != Shape::plane || axes != 1)
    throw InputError(at + ": a checker maps to POV-Ray's solid checker only on an axis-aligned plane, not on a " +
                     std::string(kind_name(ob.kind)));
  const int k = nrm.x != 0 ? 0 : nrm.y != 0 ? 1 : 2;
  const double sc = t.scale.d;
  const bool odd = static_cast<std::int64_t>(std::floor(ob.a.d[static_cast<std::size_t>(k)] * sc)) & 1;
  const Vd c0 = d3(t.colours[odd ? 1 : 0]), c1 = d3(t.colours[odd ? 0 : 1]);
  return "pigment { checker color rgb " + vec(c0) + ", color rgb " + vec(c1) + " scale " + num(1 / sc) + " }";
}

// One object's material in the image: pigment kd, POV's ambient and emission are multiplied by the
// pigment, so they are written as ka / kd and e / kd per channel.
std::string material(const Scene& s, std::size_t obj_index, std::vector<std::string>& approx) {
  const Material& m = s.materials[static_cast<std::size_t>(s.objects[obj_index].material)];
  const lighting::Material<Rational>& sh = m.shading;
  const std::string at = mat_path(m);
  if (sh.diffuse != lighting::DiffuseModel::lambert)
    throw InputError(at + ".diffuse_model: only lambert maps to POV-Ray's diffuse");
  if (sh.params.toon) throw InputError(at + ".toon: no POV-Ray equivalent");
  if (m.bump.on) throw InputError(at + ".bump: our noise bump map has no POV-Ray equivalent");
  std::string pigment, ambient = "1", emission = "0";
  if (m.texture >= 0) {
    const Texture& t = s.textures[static_cast<std::size_t>(m.texture)];
    if (t.kind != TextureKind::checker)
      throw InputError(at + ".texture: " + std::string(kind_name(t.kind)) + " textures have no POV-Ray equivalent");
    pigment = checker(s, m, obj_index);
  } else {
    const Vd kd = dq(sh.kd), ka = dq(sh.ka), ke = dq(sh.emission);
    Vd a, e;
    for (int k = 0; k < 3; ++k) {
      a[k] = kd[k] > 0 ? ka[k] / kd[k] : 0, e[k] = kd[k] > 0 ? ke[k] / kd[k] : 0;
      if (kd[k] == 0 && (ka[k] != 0 || ke[k] != 0))
        approx.push_back(at + ": ambient or emission where diffuse is 0 is lost (POV multiplies them by the pigment)");
    }
    pigment = "pigment { rgbt <" + num(kd.x) + ", " + num(kd.y) + ", " + num(kd.z) + ", " + num(m.kt.d) + "> }";
    ambient = "rgb " + vec(a), emission = "rgb " + vec(e);
  }
  std::string spec;
  const Vd ks = dq(sh.ks);
  const double s_mean = (ks.x + ks.y + ks.z) / 3, shin = nearest(sh.params.shininess);
  if (sh.specular == lighting::SpecularModel::phong) spec = " phong " + num(s_mean) + " phong_size " + num(shin);
  else if (sh.specular == lighting::SpecularModel::blinn_phong) {
    if (shin == 0) throw InputError(at + ".shininess: blinn-phong with shininess 0 has no POV-Ray roughness");
    spec = " specular " + num(s_mean) + " roughness " + num(1 / shin);
  } else if (sh.specular != lighting::SpecularModel::none)
    throw InputError(at + ".specular_model: only phong and blinn-phong map to POV-Ray (phong, specular)");
  if (!spec.empty() && !grey(ks)) approx.push_back(at + ".specular: a coloured ks is written as its mean");
  std::string refl, interior;
  const double kr = m.kr.d, kt = m.kt.d;
  if (kt > 0) {
    refl = " reflection { " + num(kr) + ", " + num(kr + kt) + " fresnel on }";
    interior = " interior { ior " + num(m.ior.d) + " }";
    approx.push_back(at + ".kt: POV transmits kt (ours kt (1 - F)) and lets light through to shadows (ours blocks it)");
  } else if (kr > 0) {
    refl = " reflection { " + num(kr) + " }";
  }
  return "material { texture { " + pigment + " finish { ambient " + ambient + " emission " + emission + " diffuse 1" + spec +
         refl + " } }" + interior + " }";
}

void shape(std::ostream& o, const Scene& s, std::size_t k, const std::string& look) {
  const Object& ob = s.objects[k];
  switch (ob.kind) {
    case Shape::sphere: o << "sphere { " << vec(d3(ob.a)) << ", " << num(ob.radius.d); break;
    case Shape::plane: {
      const Vd n = d3(ob.b);  // POV's plane: unit(n) . p = distance
      o << "plane { " << vec(n) << ", " << num(dot(n, d3(ob.a)) / std::sqrt(dot(n, n)));
      break;
    }
    case Shape::box: o << "box { " << vec(d3(ob.a)) << ", " << vec(d3(ob.b)); break;
    case Shape::triangle: o << "triangle { " << vec(d3(ob.v[0])) << ", " << vec(d3(ob.v[1])) << ", " << vec(d3(ob.v[2])); break;
    case Shape::mesh: {
      const MeshFile& mf = s.meshes[static_cast<std::size_t>(ob.mesh)];
      if (!mf.mesh) throw InputError("scene.objects[" + std::to_string(k) + "].file: the mesh was not loaded");
      const spatial::Mesh& m = *mf.mesh;
      const Vd tr = d3(ob.translate);
      o << "mesh2 {\n vertex_vectors { " << m.v.size();
      for (const auto& x : m.v)
        o << ",\n  " << vec(Vd{ob.scale.d * x[0], ob.scale.d * x[1], ob.scale.d * x[2]} + tr);  // as trace_scene places them
      o << " }\n face_indices { " << m.size();
      for (std::size_t i = 0; i < m.size(); ++i) o << ",\n  <" << m.f[i][0] << ", " << m.f[i][1] << ", " << m.f[i][2] << ">";
      o << " }\n";
      break;
    }
  }
  o << " " << look << " }\n";
}

}  // namespace

std::array<std::uint8_t, 3> pov_id_colour(int id) {
  const int x = id + 1;
  return {static_cast<std::uint8_t>(17 * ((x >> 8) & 15)), static_cast<std::uint8_t>(17 * ((x >> 4) & 15)),
          static_cast<std::uint8_t>(17 * (x & 15))};
}

int pov_id_of(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  int x = 0;
  for (const int c : {int(r), int(g), int(b)}) {
    const int d = (c + 8) / 17;
    if (std::abs(c - 17 * d) > 4) return -2;
    x = 16 * x + d;
  }
  return x - 1;
}

PovScene export_pov(const Scene& s, const PovOptions& opt) {
  PovScene out;
  std::ostringstream o;
  const std::int64_t w = opt.width > 0 ? opt.width : s.camera.width, h = opt.height > 0 ? opt.height : s.camera.height;
  if (opt.mode == PovMode::ids && s.objects.size() > std::size_t(kMaxPovIds))
    throw InputError("scene.objects: ids mode takes at most " + std::to_string(kMaxPovIds) + " objects, got " +
                     std::to_string(s.objects.size()));
  if (opt.mode == PovMode::shadow && opt.light >= s.lights.size())
    throw InputError("--light: the scene has no light " + std::to_string(opt.light) + " (it has " +
                     std::to_string(s.lights.size()) + ", counted from 0)");
  static constexpr const char* kModes[] = {"image", "ids", "shadow"};
  o << "// stepwise scene export-pov, mode " << kModes[static_cast<int>(opt.mode)] << ", for " << w << "x" << h
    << " (docs/tracer/povray.md)\n"
    << "// render: povray +W" << w << " +H" << h << " -A +WT1 -D +FN File_Gamma=1.0 +I<this file> +O<png>\n#version 3.7;\n";
  const bool image = opt.mode == PovMode::image;
  Vd amb = image ? d3(s.ambient) : Vd{};
  if (image)
    for (const auto& li : s.lights) amb = amb + dq(li.ambient);
  o << "global_settings { assumed_gamma 1.0 ambient_light rgb " << (opt.mode == PovMode::ids ? "1" : vec(amb))
    << " max_trace_level " << (image ? s.max_depth : 1) << " adc_bailout 0 }\n";
  o << "background { rgb " << (image ? vec(d3(s.background)) : "0") << " }\n";
  camera(o, s.camera, w, h);
  if (image)
    for (std::size_t i = 0; i < s.lights.size(); ++i) light(o, s, i, true, out.approximations);
  else if (opt.mode == PovMode::shadow) light(o, s, opt.light, false, out.approximations);
  for (std::size_t k = 0; k < s.objects.size(); ++k) {
    std::string look;
    if (opt.mode == PovMode::ids) {
      const auto c = pov_id_colour(static_cast<int>(k));
      look = "pigment { rgb <" + num(c[0] / 255.0) + ", " + num(c[1] / 255.0) + ", " + num(c[2] / 255.0) +
             "> } finish { ambient 1 diffuse 0 }";
    } else if (opt.mode == PovMode::shadow) {
      look = "pigment { rgb 1 } finish { ambient 0 diffuse 1 }";
    } else {
      look = material(s, k, out.approximations);
    }
    shape(o, s, k, look);
  }
  std::sort(out.approximations.begin(), out.approximations.end());
  out.approximations.erase(std::unique(out.approximations.begin(), out.approximations.end()), out.approximations.end());
  out.text = o.str();
  return out;
}

std::vector<std::string> povray_args(const std::string& pov, const std::string& png, std::int64_t width, std::int64_t height) {
  return {"povray", "+I" + pov, "+O" + png,       "+W" + std::to_string(width),     "+H" + std::to_string(height), "-A", "+WT1",
          "-D",     "+FN",      "File_Gamma=1.0", "+L/usr/share/povray-3.7/include"};
}

}  // namespace sw::tracer
