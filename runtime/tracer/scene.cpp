// The scene reader: the top level, the camera and the objects (docs/tracer/scene-format.md).
// Files are read only after the whole JSON has been checked, so a bad key never costs a mesh load.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include "tracer/scene_read.hpp"

namespace sw::tracer {
using namespace detail;

std::string_view kind_name(ObjectKind k) {
  static constexpr std::string_view names[] = {"sphere", "plane", "box", "triangle", "mesh"};
  return names[static_cast<int>(k)];
}
std::string_view kind_name(TextureKind k) {
  static constexpr std::string_view names[] = {"checker", "image", "marble", "wood"};
  return names[static_cast<int>(k)];
}
std::string_view kind_name(SamplingKind k) {
  static constexpr std::string_view names[] = {"one", "regular", "jittered", "adaptive"};
  return names[static_cast<int>(k)];
}

namespace {

bool is_zero(const Vec3<Rational>& v) { return sgn(v.x) == 0 && sgn(v.y) == 0 && sgn(v.z) == 0; }

Camera parse_camera(const Json& j, const std::string& what) {
  only_keys_optional(j, {"eye", "vpn", "vup", "d", "resolution"}, {"projection", "fov", "window"}, what);
  Camera c;
  c.eye = point(j["eye"], at(what, "eye"));
  c.vpn = nonzero(j["vpn"], at(what, "vpn"));
  c.vup = nonzero(j["vup"], at(what, "vup"));
  // Decided exactly: the frame u = VUP x VPN exists iff the cross product of the rationals is not 0.
  if (is_zero(cross(c.vup.q, c.vpn.q))) throw InputError(at(what, "vup") + ": parallel to vpn (their cross product is exactly 0)");
  c.dist = real(j["d"], at(what, "d"), 0, kCoordBound, true);
  if (j.contains("projection")) {
    const std::string p = text(j["projection"], at(what, "projection"));
    if (p == "perspective") c.projection = ray::Projection::perspective;
    else if (p == "fisheye") c.projection = ray::Projection::fisheye;
    else if (p == "cylindrical") c.projection = ray::Projection::cylindrical;
    else throw InputError(at(what, "projection") + ": unknown projection '" + one_line(p, 60) + "' (perspective, fisheye, cylindrical)");
  }
  if (j.contains("fov") == j.contains("window")) throw InputError(what + ": give exactly one of \"fov\" (degrees) and \"window\" [umin, umax, vmin, vmax]");
  if (j.contains("fov")) {
    const double max_fov = c.projection == ray::Projection::fisheye ? 360 : 179;
    c.fov = real(j["fov"], at(what, "fov"), 0, max_fov, true);
  } else {
    const std::string ww = at(what, "window");
    if (c.projection != ray::Projection::perspective) throw InputError(ww + ": a window needs the perspective projection");
    const Json& w = j["window"];
    if (!w.is_array() || w.size() != 4) throw InputError(ww + ": expected [umin, umax, vmin, vmax]");
    c.has_window = true;
    for (std::size_t k = 0; k < 4; ++k) c.window[k] = real(w[k], at(ww, k), -kCoordBound, kCoordBound);
    if (c.window[0].q >= c.window[1].q) throw InputError(ww + ": umin must be < umax");
    if (c.window[2].q >= c.window[3].q) throw InputError(ww + ": vmin must be < vmax");
  }
  const Json& r = j["resolution"];
  const std::string rw = at(what, "resolution");
  if (!r.is_array() || r.size() != 2) throw InputError(rw + ": expected [width, height]");
  c.width = parse_integer(r[0], at(rw, 0), 1, kMaxResolution);
  c.height = parse_integer(r[1], at(rw, 1), 1, kMaxResolution);
  return c;
}

int material_index(const Json& j, const std::string& what, const std::vector<Material>& ms) {
  const std::string name = text(require(j, "material", what), at(what, "material"));
  for (std::size_t i = 0; i < ms.size(); ++i)
    if (ms[i].name == name) return static_cast<int>(i);
  throw InputError(at(what, "material") + ": unknown material '" + one_line(name, 60) + "'");
}

Object parse_object(const Json& j, std::size_t index, const std::vector<Material>& ms, const SceneOptions& opt,
                    std::map<std::string, int>& mesh_ids, std::vector<MeshFile>& meshes) {
  const std::string what = at("scene.objects", index);
  if (!j.is_object()) throw InputError(what + ": expected an object");
  const std::string type = text(require(j, "type", what), at(what, "type"));
  Object o;
  if (type == "sphere") {
    only_keys(j, {"type", "material", "center", "radius"}, what);
    o.kind = ObjectKind::sphere;
    o.a = point(j["center"], at(what, "center"));
    o.radius = real(j["radius"], at(what, "radius"), 0, kCoordBound, true);
  } else if (type == "plane") {
    only_keys(j, {"type", "material", "point", "normal"}, what);
    o.kind = ObjectKind::plane;
    o.a = point(j["point"], at(what, "point"));
    o.b = nonzero(j["normal"], at(what, "normal"));
  } else if (type == "box") {
    only_keys(j, {"type", "material", "min", "max"}, what);
    o.kind = ObjectKind::box;
    o.a = point(j["min"], at(what, "min"));
    o.b = point(j["max"], at(what, "max"));
    for (int k = 0; k < 3; ++k)
      if (o.a.q[k] > o.b.q[k]) throw InputError(at(at(what, "max"), k) + ": below min[" + std::to_string(k) + "]");
  } else if (type == "triangle") {
    only_keys(j, {"type", "material", "vertices"}, what);
    o.kind = ObjectKind::triangle;
    const Json& v = j["vertices"];
    const std::string vw = at(what, "vertices");
    if (!v.is_array() || v.size() != 3) throw InputError(vw + ": expected three points [[x,y,z], [x,y,z], [x,y,z]]");
    for (std::size_t k = 0; k < 3; ++k) o.v[k] = point(v[k], at(vw, k));
    if (is_zero(cross(Vec3<Rational>(o.v[1].q - o.v[0].q), Vec3<Rational>(o.v[2].q - o.v[0].q))))
      throw InputError(vw + ": the vertices are collinear (zero area, exactly)");
  } else if (type == "mesh") {
    only_keys_optional(j, {"type", "material", "file"}, {"scale", "translate"}, what);
    o.kind = ObjectKind::mesh;
    const std::string file = text(j["file"], at(what, "file"));
    const std::string path = resolve(file, at(what, "file"), opt);
    auto [it, fresh] = mesh_ids.emplace(path, static_cast<int>(meshes.size()));
    if (fresh) meshes.push_back({file, path, nullptr, index});
    o.mesh = it->second;
    o.scale = real_or(j, "scale", what, 0, 1e6, real_of(1), true);
    o.translate = j.contains("translate") ? point(j["translate"], at(what, "translate")) : real3_of({0, 0, 0});
  } else {
    throw InputError(at(what, "type") + ": unknown object type '" + one_line(type, 60) + "' (sphere, plane, box, triangle, mesh)");
  }
  o.material = material_index(j, what, ms);
  return o;
}

// Reads each mesh file once, then checks every mesh object's triangles and extent.
void load_meshes(Scene& s) {
  for (MeshFile& m : s.meshes) {
    const std::string fw = "scene.objects[" + std::to_string(m.first_object) + "].file";
    try {
      m.mesh = std::make_shared<const spatial::Mesh>(spatial::read_mesh_file(m.path));
    } catch (const InputError& e) {
      throw InputError(fw + ": " + e.what());
    }
  }
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    const Object& o = s.objects[i];
    if (o.kind != ObjectKind::mesh) continue;
    const spatial::Mesh& m = *s.meshes[o.mesh].mesh;
    s.mesh_triangles += m.size();
    if (s.mesh_triangles > kMaxSceneTriangles)
      throw InputError("scene.objects[" + std::to_string(i) + "]: the scene's meshes exceed " + std::to_string(kMaxSceneTriangles) + " triangles");
    double reach = 0;
    for (const auto& v : m.v)
      for (int k = 0; k < 3; ++k) reach = std::max(reach, std::fabs(v[k]) * o.scale.d + std::fabs(o.translate.d[k]));
    if (!(reach <= kCoordBound)) throw InputError("scene.objects[" + std::to_string(i) + "]: the placed mesh reaches beyond 1e15");
  }
}

// {"count": 0..2^22 = 100000, "gather": 1..1024 = 64, "radius": (0, 1e15] (default: at render,
// 1/50 of the bounded objects' diagonal), "seed": = 0}
Photons parse_photons(const Json& j, const std::string& what) {
  if (!j.is_object()) throw InputError(what + ": expected an object");
  only_keys_optional(j, {}, {"count", "gather", "radius", "seed"}, what);
  Photons p;
  if (j.contains("count")) p.count = parse_integer(j["count"], at(what, "count"), 0, kMaxPhotons);
  if (j.contains("gather")) p.gather = parse_integer(j["gather"], at(what, "gather"), 1, 1024);
  if (j.contains("radius")) p.radius = real(j["radius"], at(what, "radius"), 0, kCoordBound, true);
  p.seed = seed_or(j, "seed", what);
  return p;
}

}  // namespace

Scene parse_scene(const Json& j, const SceneOptions& opt) {
  const std::string what = "scene";
  only_keys_optional(j, {"camera", "objects", "materials", "lights"},
                     {"description", "textures", "background", "ambient", "max_depth", "sampling", "rays_per_pixel", "photons"}, what);
  Scene s;
  if (j.contains("description")) s.description = text(j["description"], "scene.description");
  s.camera = parse_camera(j["camera"], "scene.camera");
  if (j.contains("textures")) s.textures = parse_textures(j["textures"], "scene.textures", opt);
  s.materials = parse_materials(j["materials"], "scene.materials", s.textures);
  s.lights = parse_lights(j["lights"], "scene.lights");
  const Json& objs = j["objects"];
  if (!objs.is_array() || objs.empty()) throw InputError("scene.objects: expected a non-empty array of objects");
  if (objs.size() > kMaxObjects) throw InputError("scene.objects: " + std::to_string(objs.size()) + " objects, more than the bound 65536");
  std::map<std::string, int> mesh_ids;
  for (std::size_t i = 0; i < objs.size(); ++i) s.objects.push_back(parse_object(objs[i], i, s.materials, opt, mesh_ids, s.meshes));
  s.background = colour_or(j, "background", what, real3_of({0, 0, 0}));
  s.ambient = colour_or(j, "ambient", what, real3_of({Rational(1, 5), Rational(1, 5), Rational(1, 5)}));
  if (j.contains("max_depth")) s.max_depth = parse_integer(j["max_depth"], "scene.max_depth", 1, kMaxDepth);
  if (j.contains("sampling")) s.sampling = parse_sampling(j["sampling"], "scene.sampling");
  if (j.contains("rays_per_pixel")) s.rays_per_pixel = parse_integer(j["rays_per_pixel"], "scene.rays_per_pixel", 1, kMaxRaysPerPixel);
  if (s.sampling.samples() > s.rays_per_pixel)
    throw InputError("scene.sampling: " + std::to_string(s.sampling.samples()) + " primary rays per pixel, more than rays_per_pixel " +
                     std::to_string(s.rays_per_pixel));
  if (j.contains("photons")) s.photons = parse_photons(j["photons"], "scene.photons");
  if (opt.load_files) load_meshes(s);
  return s;
}

Scene read_scene_file(const std::string& path) {
  std::ifstream in = open_input_file(path, "scene file");
  std::string text;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {  // bounded: stops past the readers' JSON bound
    text.append(buf, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxJsonBytes) break;
  }
  if (in.bad()) throw InputError(path + ": cannot read the scene file");
  const Json j = parse_json_text(text, path);
  SceneOptions opt;
  opt.base_dir = std::filesystem::path(path).parent_path().string();
  if (opt.base_dir.empty()) opt.base_dir = ".";
  return parse_scene(j, opt);
}

}  // namespace sw::tracer
