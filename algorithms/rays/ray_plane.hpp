// Ray-plane: the plane n . (x - p) = 0 meets o + t d at t = n . (p - o) / (n . d). A zero
// denominator (the ray parallel to the plane, including a ray lying in it) is a defined miss.
#pragma once
#include <array>
#include <string_view>
#include "core/probe.hpp"
#include "rays/ray_common.hpp"

namespace sw::ray {

template <class Num> struct PlaneHit {
  bool hit = false;
  Num t{};
};

struct RayPlane {
  static constexpr std::string_view id = "ray-plane";
  static constexpr std::string_view summary = "Ray-plane: t = n.(p - o) / n.d; parallel is a defined miss";
#define SW_LINES_RAY_PLANE(X) \
  X(denom, "den <- n . d") \
  X(parallel, "if den = 0: miss                             -- parallel, or lying in the plane") \
  X(num, "num <- n . (p - o)") \
  X(behind, "if num = 0 or sign(num) != sign(den): miss   -- t = num / den <= 0: behind, or o on the plane") \
  X(hit, "hit: t <- num / den; the point o + t d")
  SW_LISTING("Ray-plane", SW_LINES_RAY_PLANE)
#undef SW_LINES_RAY_PLANE
  // The algorithm itself, callable as RayPlane{}(...): ray_plane below.
  template <NumberType Num, StepProbe Probe>
  PlaneHit<Num> operator()(const Ray3<Num>& r, const Vec3<Num>& p, const Vec3<Num>& n, Probe& probe) const;
};

template <NumberType Num, StepProbe Probe = NoProbe>
[[gnu::always_inline]] inline PlaneHit<Num> ray_plane(const Ray3<Num>& r, const Vec3<Num>& p, const Vec3<Num>& n, Probe& probe) {
  using L = RayPlane;
  PlaneHit<Num> out;
  const Num den = dot(n, r.d);
  if constexpr (Probe::on) probe.step(L::denom, StepKind::decide).num("den", den).ray(r.o, r.d).keep().plane(p, n).keep();
  const int den_sign = num::sign(den);
  if (den_sign == 0) {
    if constexpr (Probe::on) probe.step(L::parallel, StepKind::miss);
    return out;
  }
  // Deciding t's sign from num and den keeps the decision a polynomial sign (docs/rays/accuracy.md).
  const Num num = dot(n, Vec3<Num>(p - r.o));
  if constexpr (Probe::on) probe.step(L::num, StepKind::decide).num("num", num);
  if (num::sign(num) != den_sign) {  // num = 0 included: den_sign != 0
    if constexpr (Probe::on) probe.step(L::behind, StepKind::miss);
    return out;
  }
  out.hit = true, out.t = num / den;
  if constexpr (Probe::on) probe.step(L::hit, StepKind::hit).num("t", out.t).point(Vec3<Num>(r.o + out.t * r.d)).label("hit");
  return out;
}

template <NumberType Num, StepProbe Probe>
[[gnu::always_inline]] inline PlaneHit<Num> RayPlane::operator()(const Ray3<Num>& r, const Vec3<Num>& p, const Vec3<Num>& n,
                                                                 Probe& probe) const {
  return ray_plane<Num>(r, p, n, probe);
}

}  // namespace sw::ray
