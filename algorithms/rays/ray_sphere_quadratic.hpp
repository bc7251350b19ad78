// The textbook quadratic: |o + t d - c|^2 = r^2 as a t^2 + b t + c = 0, both roots by the
// quadratic formula, the smaller positive one wins. Far small spheres lose everything to b^2 ~ 4ac.
#pragma once
#include <array>
#include <string_view>
#include "core/probe.hpp"
#include "rays/ray_common.hpp"
#include "rays/sphere_hit.hpp"

namespace sw::ray {

struct RaySphereQuadratic {
  static constexpr std::string_view id = "ray-sphere-quadratic";
  static constexpr std::string_view summary = "Ray-sphere, textbook quadratic formula";
#define SW_LINES_RAY_SPHERE_QUADRATIC(X) \
  X(coeffs, "f <- o - c; a <- d . d; b <- 2 f . d; cc <- f . f - r^2") \
  X(disc, "D <- b^2 - 4 a cc") \
  X(miss, "if D < 0: miss") \
  X(roots, "n0 <- -b - sqrt(D); n1 <- -b + sqrt(D)       -- the roots are t0 = n0 / 2a <= t1 = n1 / 2a") \
  X(near, "if n0 > 0: hit at t0                         -- 2a > 0, so t0 has n0's sign") \
  X(far, "if n1 > 0: hit at t1") \
  X(none, "miss                                         -- the sphere is behind")
  SW_LISTING("Quadratic ray-sphere", SW_LINES_RAY_SPHERE_QUADRATIC)
#undef SW_LINES_RAY_SPHERE_QUADRATIC
  // The algorithm itself, callable as RaySphereQuadratic{}(...): ray_sphere_quadratic below.
  template <NumberType Num, StepProbe Probe>
  SphereHit<Num> operator()(const Ray3<Num>& r, const Vec3<Num>& c, const Num& radius, Probe& probe) const;
};

template <NumberType Num, StepProbe Probe = NoProbe>
[[gnu::always_inline]] inline SphereHit<Num> ray_sphere_quadratic(const Ray3<Num>& r, const Vec3<Num>& c, const Num& radius,
                                                                  Probe& probe) {
  using L = RaySphereQuadratic;
  SphereHit<Num> out;
  const Vec3<Num> f = r.o - c;
  const Num a = dot(r.d, r.d), b = Num(2) * dot(f, r.d), cc = dot(f, f) - radius * radius;
  if constexpr (Probe::on)
    record_sphere_scene(probe.step(L::coeffs, StepKind::init).num("a", a).num("b", b).num("c", cc), r, c, radius);
  const Num disc = b * b - Num(4) * a * cc;
  if constexpr (Probe::on) {  // the closest approach t_c = -b / 2a, and c's distance to it coloured by D's sign
    const Vec3<Num> closest = r.o + (-b / (Num(2) * a)) * r.d;
    probe.step(L::disc, StepKind::decide)
        .num("D", disc)
        .point(closest)
        .label("t_c")
        .keep()
        .segment(c, closest)
        .label("D")
        .value(disc)
        .keep();
  }
  if (disc < Num(0)) {
    if constexpr (Probe::on) probe.step(L::miss, StepKind::miss);
    return out;
  }
  const Num two_a = Num(2) * a, nb = -b;
  const num::Rooted<Num> r0 = add_root(nb, -1, disc), r1 = add_root(nb, 1, disc);
  const Num n0 = r0.value, n1 = r1.value;
  if constexpr (Probe::on)
    probe.step(L::roots, StepKind::decide)
        .num("n0", n0)
        .num("n1", n1)
        .num("t0", n0 / two_a)
        .num("t1", n1 / two_a)
        .point(Vec3<Num>(r.o + (n0 / two_a) * r.d))
        .label("t0")
        .keep()
        .point(Vec3<Num>(r.o + (n1 / two_a) * r.d))
        .label("t1")
        .keep();
  // Branch-free from here (the outcome depends on the data); only the reported root is divided.
  const bool near_hit = n0 > Num(0), far_hit = n1 > Num(0);
  out = {bool(near_hit | far_hit), num::select(near_hit, n0, n1) / two_a, near_hit ? r0.exact : r1.exact};
  if constexpr (Probe::on) record_sphere_end<L>(probe, r, out.t, near_hit, far_hit);
  return out;
}

template <NumberType Num, StepProbe Probe>
[[gnu::always_inline]] inline SphereHit<Num> RaySphereQuadratic::operator()(const Ray3<Num>& r, const Vec3<Num>& c,
                                                                            const Num& radius, Probe& probe) const {
  return ray_sphere_quadratic<Num>(r, c, radius, probe);
}

}  // namespace sw::ray
