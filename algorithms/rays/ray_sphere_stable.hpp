// The stable ray-sphere test (Ray Tracing Gems ch. 7): the Hearn-Baker discriminant
// a (r^2 - |f - (f.d/a) d|^2), which measures the line's distance from the centre directly
// instead of subtracting two huge nearly equal squares, and the Press et al. root
// q = -(b' + sign(b') sqrt(D)), t = c/q and q/a, which never subtracts nearly equal numbers.
// Which of the two is nearer follows from the sign of b' alone.
#pragma once
#include <array>
#include <string_view>
#include "core/probe.hpp"
#include "rays/ray_common.hpp"
#include "rays/sphere_hit.hpp"

namespace sw::ray {

struct RaySphereStable {
  static constexpr std::string_view id = "ray-sphere-stable";
  static constexpr std::string_view summary = "Ray-sphere, stable: Hearn-Baker discriminant and the Press et al. root";
#define SW_LINES_RAY_SPHERE_STABLE(X) \
  X(coeffs, "f <- o - c; a <- d . d; b' <- f . d; cc <- f . f - r^2") \
  X(foot, "l <- f - (b' / a) d                          -- from the centre to the line's closest point") \
  X(disc, "D <- a (r^2 - l . l)                         -- Hearn-Baker: b'^2 - a cc without the cancellation") \
  X(miss, "if D < 0: miss") \
  X(q, "q <- -(b' + sign(b') sqrt(D))                -- sign(0) = +1; both terms have one sign") \
  X(degenerate, "if q = 0: miss                               -- tangent at the origin: both roots are 0") \
  X(order, "if b' >= 0: near <- q / a, far <- cc / q; else near <- cc / q, far <- q / a") \
  X(near, "if b' < 0 and cc > 0: hit at near            -- b' < 0 makes q > 0 (a > 0): near > 0 iff cc > 0") \
  X(far, "if b' < 0 or cc < 0: hit at far              -- b' >= 0 makes q < 0: far = cc / q > 0 iff cc < 0") \
  X(none, "miss")
  SW_LISTING("Stable ray-sphere", SW_LINES_RAY_SPHERE_STABLE)
#undef SW_LINES_RAY_SPHERE_STABLE
  // The algorithm itself, callable as RaySphereStable{}(...): ray_sphere_stable below.
  template <NumberType Num, StepProbe Probe>
  SphereHit<Num> operator()(const Ray3<Num>& r, const Vec3<Num>& c, const Num& radius, Probe& probe) const;
};

template <NumberType Num, StepProbe Probe = NoProbe>
[[gnu::always_inline]] inline SphereHit<Num> ray_sphere_stable(const Ray3<Num>& r, const Vec3<Num>& c, const Num& radius,
                                                               Probe& probe) {
  using L = RaySphereStable;
  SphereHit<Num> out;
  const Vec3<Num> f = r.o - c;
  const Num a = dot(r.d, r.d), bh = dot(f, r.d), r2 = radius * radius, cc = dot(f, f) - r2;
  if constexpr (Probe::on)
    record_sphere_scene(probe.step(L::coeffs, StepKind::init).num("a", a).num("b'", bh).num("c", cc), r, c, radius);
  const Vec3<Num> l = f - (bh / a) * r.d;
  if constexpr (Probe::on)  // the foot of the perpendicular from c, and whether the line is within r of c
    probe.step(L::foot, StepKind::advance)
        .num("lx", l.x)
        .num("ly", l.y)
        .num("lz", l.z)
        .point(Vec3<Num>(c + l))
        .label("foot")
        .keep()
        .segment(c, Vec3<Num>(c + l))
        .label("r^2 - |l|^2")
        .value(r2 - dot(l, l))
        .keep();
  const Num disc = a * (r2 - dot(l, l));
  if constexpr (Probe::on) probe.step(L::disc, StepKind::decide).num("D", disc);
  if (disc < Num(0)) {
    if constexpr (Probe::on) probe.step(L::miss, StepKind::miss);
    return out;
  }
  const bool b_neg = bh < Num(0);
  const num::Rooted<Num> root = num::root(disc);
  const Num s = root.value;
  out.t_exact = root.exact;
  const Num q = num::select(b_neg, s - bh, -bh - s);
  if constexpr (Probe::on) probe.step(L::q, StepKind::decide).num("q", q);
  if (q == Num(0)) {
    if constexpr (Probe::on) probe.step(L::degenerate, StepKind::miss);
    return out;
  }
  // The signs of the roots follow from b' and cc, so only the reported root is divided out, and
  // the rest is branch-free (the outcome depends on the data).
  const int cc_sign = num::sign(cc);
  const bool near_hit = b_neg & (cc_sign > 0), far_hit = b_neg | (cc_sign < 0), far_is_qa = b_neg & !near_hit;
  if constexpr (Probe::on) {
    const Num t_qa = q / a, t_cq = cc / q;
    const Num near = num::select(b_neg, t_cq, t_qa), far = num::select(b_neg, t_qa, t_cq);
    probe.step(L::order, StepKind::decide)
        .num("near", near)
        .num("far", far)
        .point(Vec3<Num>(r.o + near * r.d))
        .label("near")
        .keep()
        .point(Vec3<Num>(r.o + far * r.d))
        .label("far")
        .keep();
  }
  out.hit = far_hit;  // near_hit implies far_hit
  out.t = num::select(far_is_qa, q, cc) / num::select(far_is_qa, a, q);
  if constexpr (Probe::on) record_sphere_end<L>(probe, r, out.t, near_hit, far_hit);
  return out;
}

template <NumberType Num, StepProbe Probe>
[[gnu::always_inline]] inline SphereHit<Num> RaySphereStable::operator()(const Ray3<Num>& r, const Vec3<Num>& c,
                                                                         const Num& radius, Probe& probe) const {
  return ray_sphere_stable<Num>(r, c, radius, probe);
}

}  // namespace sw::ray
