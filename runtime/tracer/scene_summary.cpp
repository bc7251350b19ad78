// What `stepwise scene check` prints about a valid scene: as JSON and as text.
#include <sstream>
#include "tracer/scene.hpp"

namespace sw::tracer {
namespace {

std::string_view projection_name(ray::Projection p) {
  switch (p) {
    case ray::Projection::perspective: return "perspective";
    case ray::Projection::fisheye: return "fisheye";
    case ray::Projection::cylindrical: return "cylindrical";
  }
  return "?";
}
std::string_view light_name(lighting::LightType t) {
  switch (t) {
    case lighting::LightType::point: return "point";
    case lighting::LightType::directional: return "directional";
    case lighting::LightType::spot: return "spot";
  }
  return "?";
}
Json vec(const Real3& v) { return Json::array({v.d[0], v.d[1], v.d[2]}); }

}  // namespace

Json scene_summary(const Scene& s) {
  const Camera& c = s.camera;
  Json cam = {{"projection", projection_name(c.projection)}, {"eye", vec(c.eye)}, {"vpn", vec(c.vpn)}, {"vup", vec(c.vup)}, {"d", c.dist.d}};
  if (c.has_window) cam["window"] = Json::array({c.window[0].d, c.window[1].d, c.window[2].d, c.window[3].d});
  else cam["fov"] = c.fov.d;
  Json objects = Json::object(), lights = Json::object(), mirrors = Json::array(), transparent = Json::array(), textures = Json::object();
  for (std::string_view k : {"sphere", "plane", "box", "triangle", "mesh"}) objects[std::string(k)] = 0;
  for (std::string_view k : {"point", "directional", "spot"}) lights[std::string(k)] = 0;
  std::size_t triangles = s.mesh_triangles;
  for (const Object& o : s.objects) {
    objects[std::string(kind_name(o.kind))] = objects[std::string(kind_name(o.kind))].get<int>() + 1;
    triangles += o.kind == ObjectKind::triangle;
  }
  for (const auto& l : s.lights) lights[std::string(light_name(l.type))] = lights[std::string(light_name(l.type))].get<int>() + 1;
  for (const Material& m : s.materials) {
    if (sgn(m.kr.q) > 0) mirrors.push_back(m.name);
    if (sgn(m.kt.q) > 0) transparent.push_back(m.name);
  }
  for (const Texture& t : s.textures) textures[t.name] = kind_name(t.kind);
  Json sampling = {{"type", kind_name(s.sampling.kind)}, {"samples_per_pixel", s.sampling.samples()}};
  if (s.sampling.kind == SamplingKind::adaptive) sampling["threshold"] = s.sampling.threshold.d;
  if (s.sampling.kind == SamplingKind::jittered) sampling["seed"] = s.sampling.seed;
  return {{"valid", true},
          {"camera", cam},
          {"resolution", Json::array({c.width, c.height})},
          {"objects", objects},
          {"object_count", s.objects.size()},
          {"triangles", triangles},
          {"mesh_files", s.meshes.size()},
          {"lights", lights},
          {"materials", s.materials.size()},
          {"mirror_materials", mirrors},
          {"transparent_materials", transparent},
          {"textures", textures},
          {"max_depth", s.max_depth},
          {"sampling", sampling},
          {"rays_per_pixel", s.rays_per_pixel},
          {"photons", {{"count", s.photons.count}, {"gather", s.photons.gather}, {"radius", sgn(s.photons.radius.q) > 0 ? Json(s.photons.radius.d) : Json("derived")}}},
          {"background", vec(s.background)}};
}

std::string scene_summary_text(const Scene& s) {
  const Json j = scene_summary(s);
  std::ostringstream o;
  auto counts = [](const Json& m) {
    std::string out;
    for (auto it = m.begin(); it != m.end(); ++it)
      if (it.value().get<int>() > 0) out += (out.empty() ? "" : ", ") + std::to_string(it.value().get<int>()) + " " + it.key();
    return out.empty() ? std::string("none") : out;
  };
  auto names = [](const Json& a) {
    std::string out;
    for (const Json& n : a) out += (out.empty() ? "" : ", ") + n.get<std::string>();
    return out.empty() ? std::string("none") : out;
  };
  const Json& cam = j["camera"];
  o << "scene: valid" << (s.description.empty() ? "" : " (" + s.description + ")") << '\n';
  o << "camera: " << cam["projection"].get<std::string>() << ", eye " << cam["eye"].dump() << ", vpn " << cam["vpn"].dump() << ", vup "
    << cam["vup"].dump() << ", d " << cam["d"].dump() << (s.camera.has_window ? ", window " + cam["window"].dump() : ", fov " + cam["fov"].dump())
    << '\n';
  o << "resolution: " << s.camera.width << "x" << s.camera.height << '\n';
  o << "objects: " << s.objects.size() << " (" << counts(j["objects"]) << ")\n";
  o << "triangles: " << j["triangles"].get<std::size_t>() << " (" << s.meshes.size() << " mesh files)\n";
  o << "lights: " << s.lights.size() << " (" << counts(j["lights"]) << ")\n";
  o << "materials: " << s.materials.size() << "; mirror (kr > 0): " << names(j["mirror_materials"]) << "; transparent (kt > 0): "
    << names(j["transparent_materials"]) << '\n';
  std::string tex;
  for (const Texture& t : s.textures) tex += (tex.empty() ? "" : ", ") + t.name + " (" + std::string(kind_name(t.kind)) + ")";
  o << "textures: " << (tex.empty() ? "none" : tex) << '\n';
  o << "max depth: " << s.max_depth << '\n';
  o << "sampling: " << kind_name(s.sampling.kind) << ", up to " << s.sampling.samples() << " primary rays per pixel; budget " << s.rays_per_pixel
    << " rays per pixel\n";
  o << "photons: " << s.photons.count << ", gathering " << s.photons.gather << " within "
    << (sgn(s.photons.radius.q) > 0 ? std::to_string(s.photons.radius.d) : std::string("1/50 of the objects' diagonal")) << '\n';
  return o.str();
}

}  // namespace sw::tracer
