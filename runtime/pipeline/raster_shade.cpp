#include "pipeline/raster_shade.hpp"
#include "platform.hpp"
#include <algorithm>
#include <cmath>
#include <thread>
#include "rays/sphere_uv.hpp"
#include "tracer/parallel.hpp"
#include "tracer/render.hpp"

namespace sw::pipespec {

std::string_view shading_name(Shading s) { return s == Shading::gouraud ? "gouraud" : "phong"; }

namespace {

using V3 = Vec3<double>;
V3 unit(const V3& a) { return (1.0 / std::sqrt(dot(a, a))) * a; }

// What one pixel's colour needs of the scene, converted once.
struct Shader {
  const RasterScene& s;
  tracer::TraceScene<double> ts;
  V3 eye, u, v, n;
  double dist;

  explicit Shader(const RasterScene& rs) : s(rs), ts(tracer::trace_scene(*rs.scene, rs.width, rs.height)) {
    const auto& c = rs.camera;
    eye = to_double3(c.eye), u = to_double3(c.u), v = to_double3(c.v), n = to_double3(c.n), dist = c.dist.get_d();
  }

  V3 direction(std::int64_t i, std::int64_t j) const {  // the tracer's ray through the pixel's centre
    const auto& w = s.camera.window;
    const double wu = w[0].get_d() + (double(i) + 0.5) * (w[1].get_d() - w[0].get_d()) / double(s.width);
    const double wv = w[3].get_d() - (double(j) + 0.5) * (w[3].get_d() - w[2].get_d()) / double(s.height);
    return (-dist) * n + wu * u + wv * v;
  }

  // Texture coordinates as the tracer's surfaces define them (tracer/surface.hpp).
  std::array<double, 2> uv(std::int32_t object, const V3& p, const V3& face, const std::array<double, 3>& b) const {
    const tracer::Prim<double>& o = ts.objects[static_cast<std::size_t>(object)];
    switch (o.shape) {
      case tracer::Shape::sphere: {
        NoProbe none;
        const auto m = ray::sphere_uv<double>(o.a, p, none);
        return {m.u, m.v};
      }
      case tracer::Shape::plane: {
        const int k = num::max_axis(o.b);
        return {p[(k + 1) % 3], p[(k + 2) % 3]};
      }
      case tracer::Shape::box: {
        const int k = num::max_axis(face), a = (k + 1) % 3, c = (k + 2) % 3;
        auto along = [&](int x) { return o.b[x] > o.a[x] ? (p[x] - o.a[x]) / (o.b[x] - o.a[x]) : 0.0; };
        return {along(a), along(c)};
      }
      default: return {b[1], b[2]};
    }
  }

  // The local lighting at p with the normal nf facing the eye.
  V3 light(lighting::ShadeScene<double>& sc, std::int32_t object, const V3& p, const V3& nf, const std::array<double, 2>& tc) const {
    const tracer::TraceMaterial<double>& m = ts.materials[static_cast<std::size_t>(ts.objects[static_cast<std::size_t>(object)].material)];
    sc.material = m.shading;
    if (m.texture >= 0) {
      const V3 c = tracer::texture_colour(ts.textures[static_cast<std::size_t>(m.texture)], tc[0], tc[1], p);
      sc.material.kd = c, sc.material.ka = c;
    }
    sc.p = p, sc.n = m.bump.on ? tracer::bumped(m.bump, nf, p) : nf;
    NoProbe none;
    return lighting::shade(sc, none).rgb;
  }

  // With shadows, a light adds nothing where the point's own face, turned toward the eye, turns away
  // from it: the surface shadows itself there (exact visibility's "facing away"), though an
  // interpolated normal may still face the light. Bits set in sc.blocked.
  static void own_face(lighting::ShadeScene<double>& sc, const V3& p, const V3& face) {
    for (std::size_t i = 0; i < sc.lights.size() && i < 32; ++i) {
      const auto& l = sc.lights[i];
      const V3 toward = l.type == lighting::LightType::directional ? l.where : V3(l.where - p);
      if (!(dot(face, toward) > 0)) sc.blocked |= 1u << i;
    }
  }

  V3 pixel(lighting::ShadeScene<double>& sc, std::int64_t i, std::int64_t j, std::int32_t object, std::int32_t prim, Shading mode, bool shadows) const {
    const V3 d = direction(i, j);
    const RasterObject& ro = s.objects[static_cast<std::size_t>(object)];
    if (ro.kind == tracer::ObjectKind::plane) {
      const tracer::Prim<double>& o = ts.objects[static_cast<std::size_t>(object)];
      const V3 p = eye + (dot(o.b, V3(o.a - eye)) / dot(o.b, d)) * d;
      const V3 nu = unit(o.b), toward_eye = dot(d, nu) > 0 ? -1.0 * nu : nu;
      if (shadows) own_face(sc, p, toward_eye);
      return light(sc, object, p, toward_eye, uv(object, p, nu, {}));
    }
    const std::size_t t = static_cast<std::size_t>(ro.first + std::max(prim, 0));
    const auto& tri = s.tris[t];
    const std::array<V3, 3> x{V3{tri.x[0].x.get_d(), tri.x[0].y.get_d(), tri.x[0].z.get_d()}, V3{tri.x[1].x.get_d(), tri.x[1].y.get_d(), tri.x[1].z.get_d()},
                              V3{tri.x[2].x.get_d(), tri.x[2].y.get_d(), tri.x[2].z.get_d()}};
    const V3 g = cross(V3(x[1] - x[0]), V3(x[2] - x[0]));
    const V3 p = eye + (dot(g, V3(x[0] - eye)) / dot(g, d)) * d;
    // Barycentric weights of p by signed areas, clamped: rounding may put a covered sample a hair outside.
    std::array<double, 3> b;
    for (int k = 0; k < 3; ++k) b[k] = std::max(0.0, dot(cross(V3(x[(k + 1) % 3] - p), V3(x[(k + 2) % 3] - p)), g));
    const double sum = b[0] + b[1] + b[2];
    for (double& w : b) w = sum > 0 ? w / sum : 1.0 / 3;
    const double facing = dot(d, g) > 0 ? -1.0 : 1.0;  // two-sided: the normals turn toward the eye
    if (shadows) own_face(sc, p, facing * g);
    const auto& ns = s.normals[t];
    if (mode == Shading::phong) {
      const V3 nf = unit(facing * V3(b[0] * ns[0] + b[1] * ns[1] + b[2] * ns[2]));
      return light(sc, object, p, nf, uv(object, p, g, b));
    }
    V3 c{};
    static constexpr std::array<std::array<double, 3>, 3> corner{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (int k = 0; k < 3; ++k) c = c + b[k] * light(sc, object, x[k], facing * ns[k], uv(object, x[k], g, corner[k]));
    return c;
  }
};

}  // namespace

std::vector<Vec3<double>> shade_pixels(const RasterScene& s, const RasterPixels& px, Shading mode, const std::vector<std::uint32_t>* blocked) {
  const Shader sh(s);
  std::vector<V3> out(px.objects.size(), sh.ts.background);
  const unsigned threads = worker_threads();
  tracer::parallel_rows(px.height, threads, {}, [&](std::int64_t j) {
    lighting::ShadeScene<double> sc;
    sc.eye = sh.eye, sc.scene_ambient = sh.ts.ambient, sc.lights = sh.ts.lights, sc.convention = lighting::Convention::models;
    for (std::int64_t i = 0; i < px.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j * px.width + i);
      sc.blocked = blocked ? (*blocked)[k] : 0;
      if (px.objects[k] >= 0) out[k] = sh.pixel(sc, i, j, px.objects[k], px.prims[k], mode, blocked != nullptr);
    }
  });
  return out;
}

std::vector<std::uint8_t> depth_grey(const RasterPixels& px) {
  std::vector<double> e(px.depth.size(), -1);
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t k = 0; k < e.size(); ++k)
    if (px.objects[k] >= 0 && px.depth[k] < 1) e[k] = -std::log1p(-px.depth[k]), lo = std::min(lo, e[k]), hi = std::max(hi, e[k]);
  std::vector<std::uint8_t> out(e.size(), 255);
  for (std::size_t k = 0; k < e.size(); ++k)
    if (e[k] >= 0) out[k] = static_cast<std::uint8_t>(std::lround(hi > lo ? 235 * (e[k] - lo) / (hi - lo) : 0));
  return out;
}

}  // namespace sw::pipespec
