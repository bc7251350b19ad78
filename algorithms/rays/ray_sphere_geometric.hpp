// The implementor's-guide geometric ray-sphere test: compare the origin with the sphere (inside /
// outside), project the centre onto the ray (closest approach), reject by the squared distance of
// the line from the centre, then step back by the half chord. The direction is not normalised,
// so tca and the half chord carry a factor |d| that the final division by a = d.d removes.
#pragma once
#include <array>
#include <string_view>
#include "core/probe.hpp"
#include "rays/ray_common.hpp"
#include "rays/sphere_hit.hpp"

namespace sw::ray {

struct RaySphereGeometric {
  static constexpr std::string_view id = "ray-sphere-geometric";
  static constexpr std::string_view summary = "Ray-sphere, implementor's guide: closest approach, inside/outside, half chord";
#define SW_LINES_RAY_SPHERE_GEOMETRIC(X) \
  X(oc, "L <- c - o; L2 <- L . L; a <- d . d") \
  X(inside, "inside <- L2 < r^2; on <- L2 = r^2") \
  X(tca, "tca <- L . d                                -- |d| times the closest-approach distance") \
  X(behind, "if not inside and tca <= 0: miss            -- the sphere is behind (or only touches the origin)") \
  X(dist, "m2 <- L2 - tca^2 / a                        -- squared distance from c to the line") \
  X(reject, "if m2 > r^2: miss") \
  X(chord, "h2 <- a (r^2 - m2)                          -- |d|^2 times the squared half chord") \
  X(root, "t <- (tca - sqrt(h2)) / a if outside, else (tca + sqrt(h2)) / a") \
  X(hit, "hit at o + t d")
  SW_LISTING("Geometric ray-sphere", SW_LINES_RAY_SPHERE_GEOMETRIC)
#undef SW_LINES_RAY_SPHERE_GEOMETRIC
  // The algorithm itself, callable as RaySphereGeometric{}(...): ray_sphere_geometric below.
  template <NumberType Num, StepProbe Probe>
  SphereHit<Num> operator()(const Ray3<Num>& r, const Vec3<Num>& c, const Num& radius, Probe& probe) const;
};

template <NumberType Num, StepProbe Probe = NoProbe>
[[gnu::always_inline]] inline SphereHit<Num> ray_sphere_geometric(const Ray3<Num>& r, const Vec3<Num>& c, const Num& radius,
                                                                  Probe& probe) {
  using L = RaySphereGeometric;
  SphereHit<Num> out;
  const Vec3<Num> l = c - r.o;
  const Num l2 = dot(l, l), a = dot(r.d, r.d), r2 = radius * radius;
  if constexpr (Probe::on)
    record_sphere_scene(probe.step(L::oc, StepKind::init).num("L2", l2).num("a", a).num("r2", r2), r, c, radius);
  const bool inside = l2<r2, outside = l2> r2;
  if constexpr (Probe::on) probe.step(L::inside, StepKind::decide).idx("inside", inside).idx("on", !inside && !outside);
  const Num tca = dot(l, r.d);
  if constexpr (Probe::on)
    probe.step(L::tca, StepKind::decide).num("tca", tca).point(Vec3<Num>(r.o + (tca / a) * r.d)).label("closest").keep();
  if (!inside && !(tca > Num(0))) {
    if constexpr (Probe::on) probe.step(L::behind, StepKind::miss);
    return out;
  }
  const Num m2 = l2 - tca * tca / a;
  if constexpr (Probe::on)  // the line's closest approach to c, coloured by whether it is within r
    probe.step(L::dist, StepKind::decide)
        .num("m2", m2)
        .segment(c, Vec3<Num>(r.o + (tca / a) * r.d))
        .label("r^2 - m2")
        .value(r2 - m2)
        .keep();
  if (m2 > r2) {
    if constexpr (Probe::on) probe.step(L::reject, StepKind::miss);
    return out;
  }
  const Num h2 = a * (r2 - m2);
  if constexpr (Probe::on) probe.step(L::chord, StepKind::decide).num("h2", h2);
  // Near root when the origin is outside; the far root when inside or on the sphere (there the
  // near root is <= 0).
  const num::Rooted<Num> n = add_root(tca, outside ? -1 : 1, h2);
  out.t = n.value / a;
  out.t_exact = n.exact;
  out.hit = true;
  if constexpr (Probe::on) probe.step(L::root, StepKind::hit).num("t", out.t).point(Vec3<Num>(r.o + out.t * r.d)).label("hit");
  return out;
}

template <NumberType Num, StepProbe Probe>
[[gnu::always_inline]] inline SphereHit<Num> RaySphereGeometric::operator()(const Ray3<Num>& r, const Vec3<Num>& c,
                                                                            const Num& radius, Probe& probe) const {
  return ray_sphere_geometric<Num>(r, c, radius, probe);
}

}  // namespace sw::ray
