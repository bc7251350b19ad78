// The surface at a hit: the point, a bound on its rounding error per coordinate, the geometric
// normal and the texture coordinates (u, v); and the origin of a ray leaving it, offset along the
// normal by that bound so that the new ray cannot hit the surface it leaves (pbrt's method: the
// computed point lies within the error box of the true one, and the offset clears the box).
// The point is re-derived from the surface rather than taken as o + t d, so that its error does
// not grow with the ray's length: a sphere's point is projected onto the sphere, a plane's onto
// the plane, a triangle's rebuilt from its barycentric weights, and a box face's coordinate is the
// face's, exactly. Semantics and the bounds: docs/tracer/renderer.md#offsets.
#pragma once
#include <cmath>
#include <limits>
#include "rays/sphere_uv.hpp"
#include "tracer/trace_scene.hpp"

namespace sw::tracer {

template <class Num> struct Surface {
  Vec3<Num> p;    // the hit point
  Vec3<Num> err;  // |p_k - exact_k| <= err_k
  Vec3<Num> n;    // the geometric normal, unit, on the front (outside) side
  Num u{}, v{};   // texture coordinates (docs/tracer/scene-format.md#textures)
};

// gamma_k = k u / (1 - k u), u the unit roundoff: the classic bound on k roundings.
template <class Num> constexpr Num gamma_bound(int k) {
  constexpr Num u = std::numeric_limits<Num>::epsilon() / 2;
  return k * u / (1 - k * u);
}

template <class Num> Vec3<Num> abs3(const Vec3<Num>& v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }
template <class Num> Vec3<Num> unit3(const Vec3<Num>& v) {
  const Num m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  const Vec3<Num> s{v.x / m, v.y / m, v.z / m};
  return (Num(1) / std::sqrt(dot(s, s))) * s;
}

// Preconditions: h.hit, and h from scene_hit on the same objects and ray.
template <class Num> Surface<Num> surface_at(const TraceObjects<Num>& s, const ray::Ray3<Num>& r, const Hit<Num>& h) {
  const Prim<Num>& o = s.objects[static_cast<std::size_t>(h.object)];
  Surface<Num> out;
  const Vec3<Num> q = r.o + h.t * r.d;
  switch (o.shape) {
    case Shape::sphere: {
      const Vec3<Num> f = q - o.a;
      const Num len = std::sqrt(dot(f, f));
      out.p = o.a + (o.radius / len) * f;
      out.err = gamma_bound<Num>(8) * (abs3(o.a) + Vec3<Num>{o.radius, o.radius, o.radius});
      NoProbe none;
      const ray::SphereUV<Num> uv = ray::sphere_uv<Num>(o.a, out.p, none);
      out.n = uv.normal, out.u = uv.u, out.v = uv.v;
      break;
    }
    case Shape::plane: {
      const Num nn = dot(o.b, o.b);
      out.p = q - (dot(o.b, Vec3<Num>(q - o.a)) / nn) * o.b;
      out.err = gamma_bound<Num>(10) * (abs3(out.p) + abs3(o.a));
      out.n = unit3(o.b);
      const int k = num::max_axis(o.b);  // u, v: the two other axes of the dominant one
      out.u = out.p[(k + 1) % 3], out.v = out.p[(k + 2) % 3];
      break;
    }
    case Shape::box: {
      // The face is the slab whose boundary the slab test stopped at: its quotient (bound - o_k)/d_k,
      // computed as ray-box computes it, equals t exactly (entering: the near bound; leaving: the far).
      int face = -1;
      bool high = false;
      for (int pass = 0; pass < 2 && face < 0; ++pass)
        for (int k = 0; k < 3 && face < 0; ++k) {
          if (r.d[k] == Num(0)) continue;
          const bool hi_side = (r.d[k] > Num(0)) == (pass == 1);  // pass 0: the near bound; pass 1: the far
          if (((hi_side ? o.b[k] : o.a[k]) - r.o[k]) / r.d[k] == h.t) face = k, high = hi_side;
        }
      if (face < 0) face = num::max_axis(r.d), high = r.d[face] < Num(0);  // unreachable when h came from ray-box
      out.p = q;
      for (int k = 0; k < 3; ++k) out.p[k] = std::min(std::max(q[k], o.a[k]), o.b[k]);
      out.p[face] = high ? o.b[face] : o.a[face];  // exact: the face's own coordinate
      out.err = gamma_bound<Num>(4) * (abs3(r.o) + abs3(Vec3<Num>(h.t * r.d)));
      out.err[face] = Num(0);
      out.n = Vec3<Num>{};
      out.n[face] = high ? Num(1) : Num(-1);
      const int a = (face + 1) % 3, b = (face + 2) % 3;
      auto along = [&](int k) { return o.b[k] > o.a[k] ? (out.p[k] - o.a[k]) / (o.b[k] - o.a[k]) : Num(0); };
      out.u = along(a), out.v = along(b);
      break;
    }
    case Shape::triangle:
    case Shape::mesh: {
      const Triangle3<Num>& v =
          o.shape == Shape::triangle ? o.v : s.meshes[static_cast<std::size_t>(o.mesh)].tris[static_cast<std::size_t>(h.prim)];
      const Vec3<Num> p0 = h.b[0] * v[0], p1 = h.b[1] * v[1], p2 = h.b[2] * v[2];
      out.p = p0 + p1 + p2;
      out.err = gamma_bound<Num>(7) * (abs3(p0) + abs3(p1) + abs3(p2));
      out.n = unit3(cross(Vec3<Num>(v[1] - v[0]), Vec3<Num>(v[2] - v[0])));
      out.u = h.b[1], out.v = h.b[2];
      break;
    }
  }
  return out;
}

// The origin of a ray leaving surface s in direction w: p moved along the normal, to w's side, by
// the error box's extent along it, then each coordinate rounded one step further away (pbrt).
template <class Num> Vec3<Num> offset_origin(const Surface<Num>& s, const Vec3<Num>& w) {
  const Num d = dot(abs3(s.n), s.err);
  Vec3<Num> off = d * s.n;
  if (dot(w, s.n) < Num(0)) off = Num(-1) * off;
  Vec3<Num> o = s.p + off;
  for (int k = 0; k < 3; ++k) {
    if (off[k] > Num(0)) o[k] = std::nextafter(o[k], std::numeric_limits<Num>::infinity());
    else if (off[k] < Num(0)) o[k] = std::nextafter(o[k], -std::numeric_limits<Num>::infinity());
  }
  return o;
}

}  // namespace sw::tracer
