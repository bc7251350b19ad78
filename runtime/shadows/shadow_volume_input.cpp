#include "shadows/shadow_volume_input.hpp"
#include <map>

namespace sw::shadowspec {

using V4 = pipe::Vec4<Rational>;

shadow::VolumeMesh<Rational> volume_mesh(const RasterScene& s) {
  shadow::VolumeMesh<Rational> mesh;
  std::map<std::array<Rational, 4>, std::int32_t> index;
  for (const auto& t : s.tris) {
    std::array<std::int32_t, 3> k{};
    for (int c = 0; c < 3; ++c) {
      const V4& x = t.x[std::size_t(c)];
      const auto [it, fresh] = index.try_emplace({x.x, x.y, x.z, x.w}, std::int32_t(mesh.corners.size()));
      if (fresh) mesh.corners.push_back(x);
      k[std::size_t(c)] = it->second;
    }
    const tracer::ObjectKind kind = s.objects[std::size_t(t.object)].kind;
    mesh.tris.push_back(k);
    mesh.closed.push_back(kind == tracer::ObjectKind::sphere || kind == tracer::ObjectKind::box);
  }
  return mesh;
}

pipe::Vec4<Rational> homogeneous_light(const RasterScene& s, std::size_t light) {
  const lighting::Light<Rational>& li = s.scene->lights.at(light);
  return {li.where.x, li.where.y, li.where.z, Rational(li.type == lighting::LightType::directional ? 0 : 1)};
}

std::shared_ptr<const VolumeInput> volume_input(std::shared_ptr<const MapInput> seen, bool zfail) {
  auto in = std::make_shared<VolumeInput>();
  in->mesh = volume_mesh(*seen->scene);
  in->light = homogeneous_light(*seen->scene, seen->light);
  in->seen = std::move(seen), in->zfail = zfail;
  return in;
}

VolumeInputRef parse_volume_input(const Json& j) {
  if (!j.is_object()) throw InputError("input: expected an object with a scene and a light");
  only_keys_optional(j, {"scene"}, {"size", "stacks", "light", "method"}, "input");
  LightScene ls = parse_light_scene(j);
  bool zfail = true;
  if (j.contains("method")) {
    const Json& m = j["method"];
    if (!m.is_string() || (m != "zfail" && m != "zpass")) throw InputError("input.method: expected \"zfail\" or \"zpass\"");
    zfail = m == "zfail";
  }
  return {volume_input(seen_input(std::move(ls.scene), ls.light), zfail)};
}

VolumePixels volume_pixels(const VolumeInput& in, std::vector<std::int64_t> zpass_top, std::vector<std::int64_t> zfail_top) {
  const MapInput& m = *in.seen;
  const std::size_t n = std::size_t(m.scene->width * m.scene->height);
  VolumePixels o{m.scene->width, m.scene->height, std::vector<int>(n, -1), std::vector<int>(n, -1), std::vector<std::int64_t>(n, 0), std::vector<std::int64_t>(n, 0)};
  for (std::size_t k = 0; k < m.points.size(); ++k) {
    const std::size_t px = m.points[k].pixel;
    const bool reach = m.reaches[k], pass_lit = zpass_top[px] == 0, fail_lit = zfail_top[px] == 0;
    o.zpass[px] = zpass_top[px], o.zfail[px] = zfail_top[px];
    o.lit[px] = in.zfail ? fail_lit : pass_lit, o.visible[px] = reach;
    if (!m.faces[k]) {
      ++o.away;
      continue;
    }
    o.wrong_pass += pass_lit != reach, o.wrong_fail += fail_lit != reach;
  }
  return o;
}

VolumePixels stenciled(const VolumeInput& in, Numeric n, bool* fell_back) {
  const RasterScene& s = *in.seen->scene;
  return pipespec::in_mode(n, "shadow-volume", fell_back, [&]<class Num>(std::type_identity<Num>) {
    NoProbe none;
    return stencil_pixels(in, shadow::shadow_volume(pipespec::camera_in<Num>(s.camera), pipespec::triangles_in<Num>(s.tris), mesh_in<Num>(in.mesh),
                                                    v4_in<Num>(in.light), in.zfail, none));
  });
}

VolumePixels volume_oracle(const VolumeInput& in) {
  const MapInput& m = *in.seen;
  const RasterScene& s = *m.scene;
  std::vector<std::array<V4, 3>> casters;
  for (std::size_t t = 0; t < s.tris.size(); ++t) {
    const auto& x = s.tris[t].x;
    const int side = exact_sign_of([&]<class Num>(std::type_identity<Num>) { return shadow::det4(v4_in<Num>(in.light), v4_in<Num>(x[0]), v4_in<Num>(x[1]), v4_in<Num>(x[2])); });
    if (side == 0 || (side < 0 && in.mesh.closed[t])) continue;
    casters.push_back({x[0], x[1], x[2]});
  }
  auto holding = [&](const V4& X, const V4& R) {
    std::int64_t n = 0;
    for (const auto& c : casters) n += segment_crosses(c, in.light, X, R);
    return n;
  };
  const std::size_t n = std::size_t(s.width * s.height);
  std::vector<std::int64_t> zpass(n, 0), zfail(n, 0);
  for (const SeenPoint& p : m.points) {
    const ray::Ray3<Rational> r = pipespec::pixel_ray(s.camera, std::int64_t(p.pixel) % s.width, std::int64_t(p.pixel) / s.width);
    const V4 R{r.d.x, r.d.y, r.d.z, Rational(0)};
    const std::int64_t at_p = holding(V4{p.p.x, p.p.y, p.p.z, Rational(1)}, R);
    zfail[p.pixel] = at_p;
    zpass[p.pixel] = at_p - holding(V4{r.o.x, r.o.y, r.o.z, Rational(1)}, R);
  }
  VolumePixels o = volume_pixels(in, std::move(zpass), std::move(zfail));
  o.casters = std::int64_t(casters.size());
  return o;
}

// The silhouette, faces and fragments are the rasterizer's work, not the answer (the steps
// edges, sides and done record them): the result holds what the oracle states.
Json volume_json(const VolumePixels& p) {
  return Json{{"width", p.width}, {"height", p.height}, {"lit", p.lit}, {"visible", p.visible}, {"zpass", p.zpass}, {"zfail", p.zfail},
              {"wrong_pass", p.wrong_pass}, {"wrong_fail", p.wrong_fail}, {"away", p.away}, {"casters", p.casters}};
}

std::size_t volume_steps(const VolumeInput& in) {
  const RasterScene& s = *in.seen->scene;
  NoProbe none;
  const auto img = pipe::scene_raster<double>(pipespec::camera_in<double>(s.camera), pipespec::triangles_in<double>(s.tris), none);
  const auto vol = shadow::shadow_volume<double>(pipespec::camera_in<double>(s.camera), pipespec::triangles_in<double>(s.tris), mesh_in<double>(in.mesh),
                                                 v4_in<double>(in.light), in.zfail, none);
  const double tris = double(s.tris.size()), window = double(img.drawn.size() + s.tris.size()), pixels = double(s.width * s.height);
  // The eye pass (scene-raster's count), two steps a triangle, a face's clip and fan, three a fragment.
  const double steps = 8 + tris * 126 + 3 * window + 3 * (2 * double(img.buffer.fragments) + pixels) + 2 * tris + double(vol.faces) * 120 +
                       2 * double(vol.fragments);
  return static_cast<std::size_t>(steps);
}

std::vector<BenchSet<VolumeInputRef>> volume_sets() {
  BenchSet<VolumeInputRef> set{"lights", {}};
  // A spot, point lights and a directional light, by z-fail and by z-pass.
  for (const char* scene : {"scenes/spot-lit.json", "scenes/glass-spheres.json", "scenes/cornell-box.json"})
    for (int light = 0; light < 2; ++light)
      for (const char* method : {"zfail", "zpass"}) {
        try {
          set.inputs.push_back(parse_volume_input(Json{{"scene", scene}, {"size", {24, 18}}, {"stacks", 4}, {"light", light}, {"method", method}}));
        } catch (const InputError&) {  // the scene has one light only
        }
      }
  return {set};
}

}  // namespace sw::shadowspec
