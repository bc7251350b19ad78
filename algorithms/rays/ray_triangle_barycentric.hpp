// The implementor's-guide test: intersect the triangle's plane, then find the hit point's
// barycentric coordinates from the precomputed edge vectors e1, e2 in the 2D projection that
// drops the normal's largest axis (that projection keeps the triangle non-degenerate).
#pragma once
#include "rays/ray_triangle_watertight.hpp"

namespace sw::ray {

struct RayTriangleBarycentric {
  static constexpr std::string_view id = "ray-triangle-barycentric";
  static constexpr std::string_view summary = "Ray-triangle, implementor's guide: plane hit, then barycentrics from e1, e2";
#define SW_LINES_RAY_TRIANGLE_BARYCENTRIC(X) \
  X(edges, "e1 <- v1 - v0; e2 <- v2 - v0                  -- precomputed per triangle") \
  X(normal, "n <- e1 x e2") \
  X(denom, "den <- n . d; if den = 0: miss                 -- parallel to the plane (or in it)") \
  X(t, "t <- n . (v0 - o) / den; if t <= 0: miss") \
  X(point, "P <- o + t d") \
  X(drop, "k <- axis of max |n|; (i, j) the other two     -- project along k") \
  X(solve, "w <- P - v0; beta <- (w_i e2_j - w_j e2_i) / n_k'; gamma <- (e1_i w_j - e1_j w_i) / n_k'") \
  X(inside, "if beta < 0 or gamma < 0 or beta + gamma > 1: miss") \
  X(hit, "hit: b <- (1 - beta - gamma, beta, gamma)")
  SW_LISTING("Implementor's-guide ray-triangle", SW_LINES_RAY_TRIANGLE_BARYCENTRIC)
#undef SW_LINES_RAY_TRIANGLE_BARYCENTRIC
  // The algorithm itself, callable as RayTriangleBarycentric{}(...): ray_triangle_barycentric below.
  template <NumberType Num, StepProbe Probe>
  TriangleHit<Num> operator()(const Ray3<Num>& r, const std::array<Vec3<Num>, 3>& v, Probe& probe) const;
};

template <NumberType Num, StepProbe Probe = NoProbe>
[[gnu::always_inline]] inline TriangleHit<Num> ray_triangle_barycentric(const Ray3<Num>& r, const std::array<Vec3<Num>, 3>& vtx,
                                                                        Probe& probe) {
  using L = RayTriangleBarycentric;
  TriangleHit<Num> out;
  const Vec3<Num> e1 = vtx[1] - vtx[0], e2 = vtx[2] - vtx[0];
  const Vec3<Num> n = cross(e1, e2);
  if constexpr (Probe::on)
    record_triangle_scene(probe.step(L::normal, StepKind::init).num("nx", n.x).num("ny", n.y).num("nz", n.z), r, vtx);
  const Num den = dot(n, r.d);
  if constexpr (Probe::on) probe.step(L::denom, StepKind::decide).num("den", den);
  if (den == Num(0)) {
    if constexpr (Probe::on) probe.step(L::denom, StepKind::miss);
    return out;
  }
  const Num t = dot(n, Vec3<Num>(vtx[0] - r.o)) / den;
  if constexpr (Probe::on) probe.step(L::t, StepKind::decide).num("t", t);
  if (!(t > Num(0))) {
    if constexpr (Probe::on) probe.step(L::t, StepKind::miss);
    return out;
  }
  const Vec3<Num> p = r.o + t * r.d;
  if constexpr (Probe::on) probe.step(L::point, StepKind::advance).point(p).label("p").keep();
  const int k = num::max_axis(n), i = (k + 1) % 3, j = (k + 2) % 3;
  if constexpr (Probe::on) probe.step(L::drop, StepKind::decide).idx("k", k);
  const Vec3<Num> w = p - vtx[0];
  const Num nk = e1[i] * e2[j] - e1[j] * e2[i];  // = n_k, nonzero as |n_k| is max and n != 0
  const Num beta = (w[i] * e2[j] - w[j] * e2[i]) / nk;
  const Num gamma = (e1[i] * w[j] - e1[j] * w[i]) / nk;
  // Each weight is an edge test: b_i = 0 on the edge opposite v_i, so its sign colours that edge.
  if constexpr (Probe::on)
    probe.step(L::solve, StepKind::decide)
        .num("beta", beta)
        .num("gamma", gamma)
        .segment(vtx[2], vtx[0])
        .label("beta")
        .value(beta)
        .segment(vtx[0], vtx[1])
        .label("gamma")
        .value(gamma)
        .segment(vtx[1], vtx[2])
        .label("1 - beta - gamma")
        .value(Num(1) - (beta + gamma));
  if (beta < Num(0) || gamma < Num(0) || beta + gamma > Num(1)) {
    if constexpr (Probe::on) probe.step(L::inside, StepKind::miss);
    return out;
  }
  out.hit = true;
  out.t = t;
  out.b = {Num(1) - beta - gamma, beta, gamma};
  if constexpr (Probe::on) probe.step(L::hit, StepKind::hit).num("b0", out.b[0]).point(p).label("hit");
  return out;
}

template <NumberType Num, StepProbe Probe>
[[gnu::always_inline]] inline TriangleHit<Num> RayTriangleBarycentric::operator()(const Ray3<Num>& r,
                                                                                  const std::array<Vec3<Num>, 3>& v,
                                                                                  Probe& probe) const {
  return ray_triangle_barycentric<Num>(r, v, probe);
}

}  // namespace sw::ray
