#include "tracer/passes.hpp"
#include <cmath>

namespace sw::tracer {

namespace {

// f(pixel index, the primary ray, its closest hit) for every pixel with a camera ray.
template <class F> void each_pixel(const TraceScene<double>& ts, F&& f) {
  NoProbe none;
  for (std::int64_t j = 0; j < ts.camera.height; ++j)
    for (std::int64_t i = 0; i < ts.camera.width; ++i) {
      const ray::CameraRay<double> cr = ray::camera_ray(ts.camera, i, j, none);
      if (!cr.valid) continue;
      const Hit<double> h = scene_hit(ts, cr.ray, false, 0.0, Leaving{}, none);
      f(static_cast<std::size_t>(j * ts.camera.width + i), cr.ray, h);
    }
}

}  // namespace

std::vector<int> object_id_pass(const TraceScene<double>& ts) {
  std::vector<int> ids(static_cast<std::size_t>(ts.camera.width * ts.camera.height), -1);
  each_pixel(ts, [&](std::size_t p, const ray::Ray3<double>&, const Hit<double>& h) {
    if (h.hit) ids[p] = h.object;
  });
  return ids;
}

ShadowPass shadow_pass(const TraceScene<double>& ts, std::size_t light) {
  ShadowPass out;
  const std::size_t n = static_cast<std::size_t>(ts.camera.width * ts.camera.height);
  out.lit.assign(n, 0), out.cosine.assign(n, 0.0);
  const lighting::Light<double>& li = ts.lights[light];
  NoProbe none;
  each_pixel(ts, [&](std::size_t p, const ray::Ray3<double>& r, const Hit<double>& h) {
    if (!h.hit) return;
    const Surface<double> sf = surface_at(ts, r, h);
    const Vec3<double> nf = dot(r.d, sf.n) < 0 ? sf.n : -1.0 * sf.n;
    const Vec3<double> to_light = towards(li, sf.p);
    if (to_light == Vec3<double>{}) return;
    out.cosine[p] = dot(nf, to_light) / std::sqrt(dot(to_light, to_light));
    if (lighting::sign_dot(nf, to_light) <= 0) return;
    const auto [sr, t_max] = shadow_ray(li, offset_origin(sf, to_light));
    const bool blocked = scene_hit(ts, sr, true, t_max, Leaving{h.object, h.prim}, none).hit;
    out.lit[p] = !blocked;
  });
  return out;
}

}  // namespace sw::tracer
