// Möller-Trumbore (1997): solve o + t d = (1-u-v) v0 + u v1 + v v2 by Cramer's rule with scalar
// triple products, testing u and v as soon as each is known. No epsilon: det = 0 (ray parallel to
// the plane, or in it) is the only rejection of that kind, so the semantics stay defined.
#pragma once
#include "rays/ray_triangle_watertight.hpp"

namespace sw::ray {

struct RayTriangleMT {
  static constexpr std::string_view id = "ray-triangle-mt";
  static constexpr std::string_view summary = "Ray-triangle, Moller-Trumbore: Cramer's rule with triple products";
#define SW_LINES_RAY_TRIANGLE_M_T(X) \
  X(edges, "e1 <- v1 - v0; e2 <- v2 - v0") \
  X(pvec, "p <- d x e2") \
  X(det, "det <- e1 . p; if det = 0: miss                 -- parallel to the plane (or in it)") \
  X(inv, "inv <- 1 / det") \
  X(tvec, "s <- o - v0") \
  X(u, "u <- (s . p) inv; if u < 0 or u > 1: miss") \
  X(qvec, "q <- s x e1") \
  X(v, "v <- (d . q) inv; if v < 0 or u + v > 1: miss") \
  X(t, "t <- (e2 . q) inv; if t <= 0: miss") \
  X(hit, "hit: b <- (1 - u - v, u, v)")
  SW_LISTING("Moller-Trumbore", SW_LINES_RAY_TRIANGLE_M_T)
#undef SW_LINES_RAY_TRIANGLE_M_T
  // The algorithm itself, callable as RayTriangleMT{}(...): ray_triangle_mt below.
  template <NumberType Num, StepProbe Probe>
  TriangleHit<Num> operator()(const Ray3<Num>& r, const std::array<Vec3<Num>, 3>& v, Probe& probe) const;
};

template <NumberType Num, StepProbe Probe = NoProbe>
[[gnu::always_inline]] inline TriangleHit<Num> ray_triangle_mt(const Ray3<Num>& r, const std::array<Vec3<Num>, 3>& vtx,
                                                               Probe& probe) {
  using L = RayTriangleMT;
  TriangleHit<Num> out;
  const Vec3<Num> e1 = vtx[1] - vtx[0], e2 = vtx[2] - vtx[0];
  if constexpr (Probe::on) record_triangle_scene(probe.step(L::edges, StepKind::init), r, vtx);
  const Vec3<Num> p = cross(r.d, e2);
  const Num det = dot(e1, p);
  if constexpr (Probe::on) probe.step(L::det, StepKind::decide).num("det", det);
  if (det == Num(0)) {
    if constexpr (Probe::on) probe.step(L::det, StepKind::miss);
    return out;
  }
  const Num inv = Num(1) / det;
  const Vec3<Num> s = r.o - vtx[0];
  const Num u = dot(s, p) * inv;
  if constexpr (Probe::on)
    probe.step(L::u, StepKind::decide).num("u", u).segment(vtx[2], vtx[0]).label("u").value(u);  // u = 0 on the edge opposite v1
  if (u < Num(0) || u > Num(1)) {
    if constexpr (Probe::on) probe.step(L::u, StepKind::miss);
    return out;
  }
  const Vec3<Num> q = cross(s, e1);
  const Num v = dot(r.d, q) * inv;
  if constexpr (Probe::on)
    probe.step(L::v, StepKind::decide)
        .num("v", v)
        .segment(vtx[0], vtx[1])
        .label("v")
        .value(v)
        .segment(vtx[1], vtx[2])
        .label("1 - u - v")
        .value(Num(1) - (u + v));
  if (v < Num(0) || u + v > Num(1)) {
    if constexpr (Probe::on) probe.step(L::v, StepKind::miss);
    return out;
  }
  const Num t = dot(e2, q) * inv;
  if constexpr (Probe::on) probe.step(L::t, StepKind::decide).num("t", t);
  if (!(t > Num(0))) {
    if constexpr (Probe::on) probe.step(L::t, StepKind::miss);
    return out;
  }
  out.hit = true;
  out.t = t;
  out.b = {Num(1) - u - v, u, v};
  if constexpr (Probe::on) probe.step(L::hit, StepKind::hit).num("b0", out.b[0]).point(Vec3<Num>(r.o + t * r.d)).label("hit");
  return out;
}

template <NumberType Num, StepProbe Probe>
[[gnu::always_inline]] inline TriangleHit<Num> RayTriangleMT::operator()(const Ray3<Num>& r, const std::array<Vec3<Num>, 3>& v,
                                                                         Probe& probe) const {
  return ray_triangle_mt<Num>(r, v, probe);
}

}  // namespace sw::ray
