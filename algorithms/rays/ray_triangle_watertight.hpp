// Watertight ray-triangle test (Woop, Benthin and Wald 2013): translate to the ray origin, permute
// so the ray's largest component is z, shear the ray onto +z, then take the three 2D edge
// functions. The edge functions of a shared edge are computed from the same two sheared points by
// the same expression in both triangles, so a ray can never slip between them.
#pragma once
#include <array>
#include <string_view>
#include <type_traits>
#include "core/probe.hpp"
#include "rays/ray_common.hpp"

namespace sw::ray {

template <class Num> struct TriangleHit {
  bool hit = false;
  Num t{};
  std::array<Num, 3> b{};  // barycentric weights of v0, v1, v2
};

struct RayTriangleWatertight {
  static constexpr std::string_view id = "ray-triangle-watertight";
  static constexpr std::string_view summary = "Ray-triangle, watertight (Woop-Benthin-Wald 2013): shear to +z, 2D edge functions";
#define SW_LINES_RAY_TRIANGLE_WATERTIGHT(X) \
  X(axes, "kz <- axis of max |d|; kx, ky the next two; swap kx, ky if d_kz < 0   -- keeps the winding") \
  X(shear, "Sx <- d_kx / d_kz; Sy <- d_ky / d_kz; Sz <- 1 / d_kz") \
  X(translate, "A, B, C <- v0 - o, v1 - o, v2 - o") \
  X(project, "P' <- (P_kx - Sx P_kz, P_ky - Sy P_kz) for P in A, B, C   -- the ray is now the +z axis") \
  X(edges, "U <- Cx By - Cy Bx; V <- Ax Cy - Ay Cx; W <- Bx Ay - By Ax") \
  X(retry, "if U, V or W = 0 in float: redo the edge functions in double") \
  X(sides, "if some of U, V, W < 0 and some > 0: miss              -- the axis passes outside an edge") \
  X(det, "det <- U + V + W; if det = 0: miss                      -- the ray is parallel to the plane") \
  X(depth, "T <- U Sz A_kz + V Sz B_kz + W Sz C_kz") \
  X(sign, "if T = 0 or sign(T) != sign(det): miss                 -- t = T/det must be > 0") \
  X(hit, "hit: r <- 1 / det; t <- T r; b <- (U r, V r, W r)")
  SW_LISTING("Watertight ray-triangle", SW_LINES_RAY_TRIANGLE_WATERTIGHT)
#undef SW_LINES_RAY_TRIANGLE_WATERTIGHT
  // The algorithm itself, callable as RayTriangleWatertight{}(...): ray_triangle_watertight below.
  template <NumberType Num, StepProbe Probe>
  TriangleHit<Num> operator()(const Ray3<Num>& r, const std::array<Vec3<Num>, 3>& v, Probe& probe) const;
};

template <NumberType Num, StepProbe Probe = NoProbe>
[[gnu::always_inline]] inline TriangleHit<Num> ray_triangle_watertight(const Ray3<Num>& r, const std::array<Vec3<Num>, 3>& v,
                                                                       Probe& probe) {
  using L = RayTriangleWatertight;
  TriangleHit<Num> out;
  const int kz = num::max_axis(r.d);
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (r.d[kz] < Num(0)) std::swap(kx, ky);
  if constexpr (Probe::on)
    record_triangle_scene(probe.step(L::axes, StepKind::init).idx("kx", kx).idx("ky", ky).idx("kz", kz), r, v);
  const Num sx = r.d[kx] / r.d[kz], sy = r.d[ky] / r.d[kz], sz = Num(1) / r.d[kz];
  if constexpr (Probe::on) probe.step(L::shear, StepKind::init).num("Sx", sx).num("Sy", sy).num("Sz", sz);
  const Vec3<Num> a = v[0] - r.o, b = v[1] - r.o, c = v[2] - r.o;
  if constexpr (Probe::on)
    probe.step(L::translate, StepKind::init)
        .segment(r.o, v[0])
        .label("A")
        .segment(r.o, v[1])
        .label("B")
        .segment(r.o, v[2])
        .label("C");
  const Num ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
  const Num bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
  const Num cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];
  if constexpr (Probe::on)
    probe.step(L::project, StepKind::init).num("Ax", ax).num("Ay", ay).num("Bx", bx).num("By", by).num("Cx", cx).num("Cy", cy);
  Num u = cx * by - cy * bx, w_v = ax * cy - ay * cx, w = bx * ay - by * ax;
  // U, V, W are the edge functions of the edges opposite v0, v1, v2: their signs colour those edges.
  auto record_edges = [&](auto line) {
    if constexpr (Probe::on)
      probe.step(line, StepKind::decide)
          .num("U", u)
          .num("V", w_v)
          .num("W", w)
          .segment(v[1], v[2])
          .label("U")
          .value(u)
          .segment(v[2], v[0])
          .label("V")
          .value(w_v)
          .segment(v[0], v[1])
          .label("W")
          .value(w);
  };
  record_edges(L::edges);
  if constexpr (std::is_same_v<Num, float>) {
    if (u == 0.0f || w_v == 0.0f || w == 0.0f) {
      // Float edge functions of exactly zero are retried with double products of the same
      // float operands (as the paper does), so an edge is decided consistently.
      const double cxy = double(cx) * double(by), cyx = double(cy) * double(bx);
      const double axy = double(ax) * double(cy), ayx = double(ay) * double(cx);
      const double bxy = double(bx) * double(ay), byx = double(by) * double(ax);
      u = float(cxy - cyx), w_v = float(axy - ayx), w = float(bxy - byx);
      record_edges(L::retry);
    }
  }
  const int su = num::sign(u), sv = num::sign(w_v), sw = num::sign(w);
  if ((su < 0 || sv < 0 || sw < 0) && (su > 0 || sv > 0 || sw > 0)) {
    if constexpr (Probe::on) probe.step(L::sides, StepKind::miss);
    return out;
  }
  const Num det = u + w_v + w;
  if constexpr (Probe::on) probe.step(L::det, StepKind::decide).num("det", det);
  const int det_sign = num::sign(det);
  if (det_sign == 0) {
    if constexpr (Probe::on) probe.step(L::det, StepKind::miss);
    return out;
  }
  const Num t_num = u * (sz * a[kz]) + w_v * (sz * b[kz]) + w * (sz * c[kz]);
  if constexpr (Probe::on) probe.step(L::depth, StepKind::decide).num("T", t_num);
  if (num::sign(t_num) != det_sign) {  // T = 0 included: det != 0 here
    if constexpr (Probe::on) probe.step(L::sign, StepKind::miss);
    return out;
  }
  // One division, as in the paper: the reciprocal scales t and the three weights.
  const Num inv_det = Num(1) / det;
  out.hit = true;
  out.t = t_num * inv_det;
  out.b = {u * inv_det, w_v * inv_det, w * inv_det};
  if constexpr (Probe::on) {
    const Vec3<Num> p = r.o + out.t * r.d;
    probe.step(L::hit, StepKind::hit)
        .num("t", out.t)
        .num("b0", out.b[0])
        .num("b1", out.b[1])
        .num("b2", out.b[2])
        .point(p)
        .label("hit");
  }
  return out;
}

template <NumberType Num, StepProbe Probe>
[[gnu::always_inline]] inline TriangleHit<Num> RayTriangleWatertight::operator()(const Ray3<Num>& r,
                                                                                 const std::array<Vec3<Num>, 3>& v,
                                                                                 Probe& probe) const {
  return ray_triangle_watertight<Num>(r, v, probe);
}

}  // namespace sw::ray
