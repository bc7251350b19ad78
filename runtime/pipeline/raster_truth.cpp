#include "pipeline/raster_truth.hpp"
#include "platform.hpp"
#include <algorithm>
#include <optional>
#include <thread>
#include "tracer/parallel.hpp"

namespace sw::pipespec {

namespace {

using Tri = std::array<Vec3<Rational>, 3>;

template <class Num> ray::Ray3<Num> ray_in(const ray::Ray3<Rational>& r) { return {to_num<Num>(r.o), to_num<Num>(r.d)}; }

// The prim a hit names, as the results name it (named_prim).
template <class Num> std::int32_t hit_prim(const RasterScene& s, const tracer::Hit<Num>& h) {
  switch (s.objects[static_cast<std::size_t>(h.object)].kind) {
    case tracer::ObjectKind::plane: return -1;
    case tracer::ObjectKind::triangle: return 0;
    default: return h.prim;
  }
}

template <class Num> bool inside_triangle(const RasterScene& s, const tracer::Hit<Num>& h) {
  if (s.objects[static_cast<std::size_t>(h.object)].kind == tracer::ObjectKind::plane) return true;
  return Num(0) < h.b[0] && Num(0) < h.b[1] && Num(0) < h.b[2];  // intervals throw Uncertain when they cannot tell
}

// Whether GL covers the sample whose ray meets triangle v at Y, with barycentric weights b: inside
// when every weight is > 0; on the edge opposite corner j (b_j = 0), when triangle-edge's rule
// gives it that edge: after the triangle is made counter-clockwise on the screen (y up), an edge
// whose image runs down, or right along a row. The image's direction at Y is the derivative of
// (x/w, y/w) along the edge, from M Y and M E (E the edge's direction, w = 0).
bool covers(const RasterScene& s, const pipe::Mat4<Rational>& M, const Tri& v, const std::array<Rational, 3>& b, const Vec3<Rational>& Y) {
  if (b[0] > 0 && b[1] > 0 && b[2] > 0) return true;
  const Vec3<Rational> N = cross(Vec3<Rational>(v[1] - v[0]), Vec3<Rational>(v[2] - v[0]));
  // Front-facing (the viewer on the normal's side) is counter-clockwise on the screen; an
  // orthographic viewer lies toward +n.
  const bool ccw = dot(N, s.camera.orthographic ? s.camera.n : Vec3<Rational>(s.camera.eye - v[0])) > 0;
  const pipe::Vec4<Rational> cy = pipe::apply(M, pipe::Vec4<Rational>{Y.x, Y.y, Y.z, Rational(1)});
  for (int j = 0; j < 3; ++j) {
    if (b[j] != 0) continue;
    Vec3<Rational> E = v[(j + 2) % 3] - v[(j + 1) % 3];
    if (!ccw) E = Rational(-1) * E;
    const pipe::Vec4<Rational> ce = pipe::apply(M, pipe::Vec4<Rational>{E.x, E.y, E.z, Rational(0)});
    const Rational dx = ce.x * cy.w - cy.x * ce.w, dy = ce.y * cy.w - cy.y * ce.w;
    if (!(dy < 0 || (dy == 0 && dx > 0))) return false;
  }
  return true;
}

// GL's answer where the closest hit lies on a boundary: every triangle and plane the ray meets,
// kept where it covers the sample; the least t, then the first drawn (object, then prim).
std::optional<std::array<std::int32_t, 2>> covering_hit(const RasterScene& s, const pipe::Mat4<Rational>& M, const ray::Ray3<Rational>& r,
                                                        Rational* t_best) {
  std::optional<std::array<std::int32_t, 2>> best;
  NoProbe none;
  auto offer = [&](const Rational& t, std::int32_t k, std::int32_t prim) {
    if (!best || t < *t_best) best = std::array<std::int32_t, 2>{k, prim}, *t_best = t;  // in drawing order: equal t keeps the first
  };
  auto triangle = [&](const Tri& v, std::int32_t k, std::int32_t prim) {
    const auto h = ray::ray_triangle_watertight<Rational>(r, v, none);
    if (h.hit && covers(s, M, v, h.b, Vec3<Rational>(r.o + Vec3<Rational>(h.t * r.d)))) offer(h.t, k, prim);
  };
  for (std::size_t k = 0; k < s.traced.objects.size(); ++k) {
    const tracer::Prim<Rational>& o = s.traced.objects[k];
    const std::int32_t id = std::int32_t(k);
    if (o.shape == tracer::Shape::plane) {
      const auto h = ray::ray_plane<Rational>(r, o.a, o.b, none);
      if (h.hit) offer(h.t, id, -1);
    } else if (o.shape == tracer::Shape::triangle) {
      triangle(o.v, id, 0);
    } else {
      const auto& tris = s.traced.meshes[static_cast<std::size_t>(o.mesh)].tris;
      for (std::size_t i = 0; i < tris.size(); ++i) triangle(tris[i], id, std::int32_t(i));
    }
  }
  return best;
}

// The exact t at which the ray meets the named surface (it does).
Rational exact_t(const RasterScene& s, const ray::Ray3<Rational>& r, std::int32_t object, std::int32_t prim) {
  const tracer::Prim<Rational>& o = s.traced.objects[static_cast<std::size_t>(object)];
  NoProbe none;
  if (o.shape == tracer::Shape::plane) return ray::ray_plane<Rational>(r, o.a, o.b, none).t;
  const Tri& v = o.shape == tracer::Shape::triangle ? o.v : s.traced.meshes[static_cast<std::size_t>(o.mesh)].tris[static_cast<std::size_t>(prim)];
  return ray::ray_triangle_watertight<Rational>(r, v, none).t;
}

PixelTruth pixel_truth(const RasterScene& s, const pipe::Mat4<Rational>& M, std::int64_t i, std::int64_t j, bool* exact) {
  const ray::Ray3<Rational> r = pixel_ray(s.camera, i, j);
  PixelTruth p;
  NoProbe none;
  auto depth_at = [&](const Rational& t) {  // eye depth near + t d; window depth 1 - near/(eye depth)
    p.t = t;
    if (s.camera.orthographic) return Rational(t / (s.camera.far - s.camera.near)).get_d();  // the ray starts on the near plane
    const Rational e = s.camera.near + t * s.camera.dist;
    return Rational(1 - s.camera.near / e).get_d();
  };
  *exact = false;
  try {
    const tracer::Hit<Interval> h = tracer::scene_hit(s.traced_iv, ray_in<Interval>(r), false, Interval(0), tracer::Leaving{}, none);
    if (!h.hit) return p;
    if (inside_triangle(s, h)) {
      p.object = p.ray_object = h.object, p.prim = p.ray_prim = hit_prim(s, h);
      p.depth = depth_at(exact_t(s, r, p.object, h.prim));
      return p;
    }
  } catch (const Uncertain&) {
  }
  *exact = true;
  const tracer::Hit<Rational> h = tracer::scene_hit(s.traced, r, false, Rational(0), tracer::Leaving{}, none);
  if (!h.hit) return p;
  p.ray_object = h.object, p.ray_prim = hit_prim(s, h);
  if (inside_triangle(s, h)) {
    p.object = p.ray_object, p.prim = p.ray_prim, p.depth = depth_at(h.t);
    return p;
  }
  p.boundary = true;
  Rational t;
  if (const auto g = covering_hit(s, M, r, &t)) p.object = (*g)[0], p.prim = (*g)[1], p.depth = depth_at(t);
  return p;
}

}  // namespace

RasterTruth raster_truth(const RasterScene& s, unsigned threads) {
  RasterTruth out{s.width, s.height, std::vector<PixelTruth>(static_cast<std::size_t>(s.width * s.height)), 0};
  const pipe::Mat4<Rational> M = pipe::raster_matrix(s.camera);
  std::vector<std::int64_t> exact_rows(static_cast<std::size_t>(s.height), 0);
  if (threads == 0) threads = worker_threads();
  tracer::parallel_rows(s.height, threads, {}, [&](std::int64_t j) {
    for (std::int64_t i = 0; i < s.width; ++i) {
      bool exact = false;
      out.px[static_cast<std::size_t>(j * s.width + i)] = pixel_truth(s, M, i, j, &exact);
      exact_rows[static_cast<std::size_t>(j)] += exact;
    }
  });
  for (std::int64_t n : exact_rows) out.exact_rays += n;
  return out;
}

Identity identity(const RasterTruth& truth, const RasterPixels& raster) {
  Identity id;
  for (std::size_t k = 0; k < truth.px.size(); ++k) {
    const PixelTruth& p = truth.px[k];
    const std::int32_t o = raster.objects[k], q = raster.prims[k];
    ++id.pixels;
    const bool differ = o != p.ray_object || q != p.ray_prim, wrong = o != p.object || q != p.prim;
    id.differ += differ, id.wrong += wrong, id.ties += differ && !wrong, id.wrong_inside += wrong && !p.boundary;
    id.holes += o < 0 && p.object >= 0;
    id.objects_differ += o != p.ray_object, id.objects_wrong += o != p.object;
  }
  return id;
}

}  // namespace sw::pipespec
