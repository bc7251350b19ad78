#include "shadows/projective_shadow_input.hpp"
#include "shadows/shadow_volume_input.hpp"

namespace sw::shadowspec {

namespace {

using V3 = Vec3<Rational>;
using V4 = pipe::Vec4<Rational>;

bool flat(tracer::ObjectKind k) { return k == tracer::ObjectKind::plane || k == tracer::ObjectKind::triangle; }

// Whether GL covers sample (i, j) (rows bottom up) with occluder t's shadow polygon: t cut to the
// slab, squashed by S, through the eye's matrix, clipped, divided and fanned, then triangle-edge's
// rule, all exact.
bool covers_sample(const ProjectiveInput& in, const std::array<V4, 3>& t, std::int64_t i, std::int64_t j) {
  const RasterScene& s = *in.seen->scene;
  const pipe::Mat4<Rational> S = shadow::shadow_matrix(in.plane, in.light), M = pipe::raster_matrix(s.camera);
  const V4 w_row{S[3][0], S[3][1], S[3][2], S[3][3]};
  const auto K = shadow::clip_half_spaces<Rational>({t[0], t[1], t[2]}, {in.plane, w_row});
  const pipe::Viewport<Rational> vp = pipe::raster_viewport(s.camera);
  NoProbe none;
  for (std::size_t k = 1; k + 1 < K.size(); ++k) {
    const std::array<V4, 3> c{pipe::apply(M, pipe::apply(S, K[0])), pipe::apply(M, pipe::apply(S, K[k])), pipe::apply(M, pipe::apply(S, K[k + 1]))};
    const pipe::ClippedPolygon<Rational> C = pipe::clip_volume(c, none);
    const auto w = pipe::window_corners(vp, C);
    for (int q = 1; q + 1 < C.k; ++q)
      for (const Pixel& p : pipe::covered_samples<Rational>({w[0], w[std::size_t(q)], w[std::size_t(q + 1)]}, s.width, s.height))
        if (p.x == i && p.y == j) return true;
  }
  return false;
}

}  // namespace

ReceiverPlane receiver_plane(const RasterScene& s, std::size_t light, std::int64_t receiver) {
  ReceiverPlane r;
  if (receiver >= 0) {
    if (receiver >= std::int64_t(s.objects.size()))
      throw InputError("receiver: " + std::to_string(receiver) + " is outside [0, " + std::to_string(s.objects.size() - 1) + "], the scene's objects");
    r.receiver = std::int32_t(receiver);
    if (!flat(s.objects[std::size_t(r.receiver)].kind))
      throw InputError("receiver: object " + std::to_string(r.receiver) + " is a " + std::string(tracer::kind_name(s.objects[std::size_t(r.receiver)].kind)) +
                       "; a receiver is a plane or a triangle");
  } else {
    r.receiver = -1;
    for (std::size_t k = 0; k < s.objects.size() && r.receiver < 0; ++k)
      if (flat(s.objects[k].kind)) r.receiver = std::int32_t(k);
    if (r.receiver < 0) throw InputError("receiver: the scene has no plane or triangle to receive a projective shadow");
  }
  r.light = homogeneous_light(s, light);
  // The plane from the receiver's first triangle (corner 0 is a point; a corner at infinity a direction).
  const auto& t = s.tris[std::size_t(s.objects[std::size_t(r.receiver)].first)].x;
  auto dir = [&](int k) {
    const pipe::Vec4<Rational>& x = t[std::size_t(k)];
    return x.w == 0 ? V3{x.x, x.y, x.z} : V3{x.x - t[0].x, x.y - t[0].y, x.z - t[0].z};
  };
  const V3 n = cross(dir(1), dir(2));
  r.plane = {n.x, n.y, n.z, Rational(-dot(n, V3{t[0].x, t[0].y, t[0].z}))};
  const Rational side = shadow::dot4(r.plane, r.light);
  if (side == 0) throw InputError("receiver: the light lies in the receiver's plane, which then takes no projective shadow");
  if (side < 0) r.plane = {-r.plane.x, -r.plane.y, -r.plane.z, -r.plane.w};
  return r;
}

std::shared_ptr<const ProjectiveInput> projective_input(std::shared_ptr<const MapInput> seen, const ReceiverPlane& r, const shadow::ProjectiveParams<Rational>& p) {
  auto in = std::make_shared<ProjectiveInput>();
  in->seen = std::move(seen), in->receiver = r.receiver, in->plane = r.plane, in->light = r.light, in->params = p;
  return in;
}

ProjectiveInputRef parse_projective_input(const Json& j) {
  if (!j.is_object()) throw InputError("input: expected an object with a scene and a light");
  only_keys_optional(j, {"scene"}, {"size", "stacks", "light", "receiver", "depth", "offset", "stencil"}, "input");
  LightScene ls = parse_light_scene(j);
  shadow::ProjectiveParams<Rational> p;
  if (j.contains("depth")) {
    const Json& d = j["depth"];
    if (!d.is_string() || (d != "less" && d != "lequal")) throw InputError("input.depth: expected \"less\" or \"lequal\"");
    p.lequal = d == "lequal";
  }
  if (j.contains("offset")) {
    const Json& o = j["offset"];
    if (!o.is_array() || o.size() != 2) throw InputError("input.offset: expected [factor, units]");
    p.factor = parse_rational(o[0], "input.offset[0]"), p.units = parse_rational(o[1], "input.offset[1]");
    for (const Rational* v : {&p.factor, &p.units})
      if (num::abs(*v) > 1000) throw InputError("input.offset: " + v->get_str() + " is outside [-1000, 1000]");
  }
  if (j.contains("stencil")) {
    if (!j["stencil"].is_boolean()) throw InputError("input.stencil: expected true or false");
    p.stencil = j["stencil"].get<bool>();
  }
  const std::int64_t receiver = j.contains("receiver") ? parse_integer(j["receiver"], "input.receiver", 0, 1 << 20) : -1;
  ReceiverPlane r;
  try {
    r = receiver_plane(*ls.scene, ls.light, receiver);
  } catch (const InputError& e) {
    throw InputError("input." + std::string(e.what()));
  }
  return {projective_input(seen_input(std::move(ls.scene), ls.light), r, p)};
}

ProjectivePixels projective_verdicts(const ProjectiveInput& in, const std::vector<char>& bottom_up) {
  const MapInput& m = *in.seen;
  const std::int64_t w = m.scene->width, h = m.scene->height;
  ProjectivePixels o{w, h, std::vector<int>(std::size_t(w * h), -1), std::vector<int>(std::size_t(w * h), -1)};
  for (std::size_t k = 0; k < m.points.size(); ++k) {
    const std::size_t px = m.points[k].pixel;
    const std::int64_t i = std::int64_t(px) % w, j = std::int64_t(px) / w;
    const bool dark = bottom_up[std::size_t((h - 1 - j) * w + i)] != 0;
    o.shadowed[px] = dark;
    if (m.points[k].object != in.receiver) continue;
    const bool reach = m.reaches[k];
    o.visible[px] = reach;
    if (!m.faces[k]) continue;
    o.missing += !reach && !dark, o.spurious += reach && dark;
  }
  return o;
}

ProjectivePixels projected(const ProjectiveInput& in, Numeric n) {
  const RasterScene& s = *in.seen->scene;
  return pipespec::in_mode(n, "projective-shadow", nullptr, [&]<class Num>(std::type_identity<Num>) {
    NoProbe none;
    return projective_pixels(in, shadow::projective_shadow(pipespec::camera_in<Num>(s.camera), pipespec::triangles_in<Num>(s.tris), in.receiver,
                                                           v4_in<Num>(in.plane), v4_in<Num>(in.light), params_in<Num>(in.params), none));
  });
}

ProjectivePixels projective_oracle(const ProjectiveInput& in) {
  const MapInput& m = *in.seen;
  const RasterScene& s = *m.scene;
  const pipe::RasterCamera<Rational>& cam = s.camera;
  std::vector<std::array<V4, 3>> occluders;
  for (const auto& t : s.tris) {
    const bool in_plane = shadow::dot4(in.plane, t.x[0]) == 0 && shadow::dot4(in.plane, t.x[1]) == 0 && shadow::dot4(in.plane, t.x[2]) == 0;
    if (t.object != in.receiver && !in_plane) occluders.push_back(t.x);
  }
  // The receiver plane's slope in the window (constant: window depth is affine on a plane).
  const auto& t0 = s.tris[std::size_t(s.objects[std::size_t(in.receiver)].first)].x;
  const V3 Y{t0[0].x, t0[0].y, t0[0].z};
  auto dir = [&](int k) { return t0[std::size_t(k)].w == 0 ? V3{t0[std::size_t(k)].x, t0[std::size_t(k)].y, t0[std::size_t(k)].z} : V3(V3{t0[std::size_t(k)].x, t0[std::size_t(k)].y, t0[std::size_t(k)].z} - Y); };
  const Rational slope = in.params.factor == 0 ? Rational(0) : window_slope(pipe::raster_matrix(cam), cam, Y, dir(1), dir(2));
  const Rational o = in.params.factor * slope + in.params.units / Rational(1 << 24);
  std::vector<char> mask(std::size_t(s.width * s.height), 0);
  std::int64_t ties = 0;
  for (const SeenPoint& p : m.points) {
    const std::int64_t i = std::int64_t(p.pixel) % s.width, j = std::int64_t(p.pixel) / s.width;
    const bool on_receiver = p.object == in.receiver;
    if (in.params.stencil && !on_receiver) continue;
    const ray::Ray3<Rational> r = pipespec::pixel_ray(cam, i, j);
    const Rational den = shadow::dot4(in.plane, V4{r.d.x, r.d.y, r.d.z, Rational(0)});
    if (den == 0) continue;  // the ray runs along the plane
    const Rational tq = -shadow::dot4(in.plane, V4{r.o.x, r.o.y, r.o.z, Rational(1)}) / den;
    if (tq < 0) continue;  // the plane lies behind the near plane here
    const V3 Q = r.o + V3(tq * r.d);  // on the receiver, the seen point itself (tq = p.t)
    const Rational D = window_depth(cam, p.t), d = std::clamp(Rational(window_depth(cam, tq) + o), Rational(0), Rational(1));
    if (!(in.params.lequal ? d <= D : d < D)) continue;
    const V4 X{Q.x, Q.y, Q.z, Rational(1)};
    const std::int64_t jb = s.height - 1 - j;  // GL's row
    std::vector<const std::array<V4, 3>*> touching;
    bool covered = false;
    for (const auto& t : occluders) {
      const Meeting m = segment_meets(t, in.light, X);
      if (m.inside) {
        covered = true;
        break;
      }
      if (m.touching) touching.push_back(&t);
    }
    // Q on a shadow polygon's edge (an occluder's edge seen from the light): GL's tie rule decides,
    // on the polygon's exact window triangles.
    for (std::size_t k = 0; !covered && k < touching.size(); ++k) covered = covers_sample(in, *touching[k], i, jb);
    mask[std::size_t(jb * s.width + i)] = covered;
    ties += !touching.empty();
  }
  ProjectivePixels out = projective_verdicts(in, mask);
  out.edge_ties = ties;
  return out;
}

Json projective_json(const ProjectivePixels& p) {
  return Json{{"width", p.width}, {"height", p.height}, {"shadowed", p.shadowed}, {"visible", p.visible}, {"missing", p.missing}, {"spurious", p.spurious}};
}

std::size_t projective_steps(const ProjectiveInput& in) {
  const RasterScene& s = *in.seen->scene;
  NoProbe none;
  const auto img = pipe::scene_raster<double>(pipespec::camera_in<double>(s.camera), pipespec::triangles_in<double>(s.tris), none);
  const auto pr = shadow::projective_shadow<double>(pipespec::camera_in<double>(s.camera), pipespec::triangles_in<double>(s.tris), in.receiver,
                                                    v4_in<double>(in.plane), v4_in<double>(in.light), params_in<double>(in.params), none);
  const double tris = double(s.tris.size()), window = double(img.drawn.size() + s.tris.size()), pixels = double(s.width * s.height);
  // The eye pass (scene-raster's count), a step a triangle, a shadow triangle's clip and offset, three a fragment.
  const double steps = 8 + tris * 126 + 3 * window + 3 * (2 * double(img.buffer.fragments) + pixels) + tris + 3 * tris * 64 + 3 * double(pr.fragments);
  return static_cast<std::size_t>(steps);
}

std::vector<BenchSet<ProjectiveInputRef>> projective_sets() {
  BenchSet<ProjectiveInputRef> set{"receivers", {}};
  // The floor under spots and a point light: the depth tie lost (GL_LESS), kept (GL_LEQUAL), offset.
  for (const char* scene : {"scenes/spot-lit.json", "scenes/glass-spheres.json", "scenes/eye-in-shadow.json"})
    for (const Json& test : {Json{{"depth", "less"}}, Json{{"depth", "lequal"}}, Json{{"depth", "less"}, {"offset", {-1, -1}}}}) {
      Json j{{"scene", scene}, {"size", {24, 18}}, {"stacks", 4}};
      j.update(test);
      set.inputs.push_back(parse_projective_input(j));
    }
  return {set};
}

}  // namespace sw::shadowspec
