// The stable ray-sphere test (Ray Tracing Gems ch. 7): the Hearn-Baker discriminant
// a (r^2 - |f - (f.d/a) d|^2), which measures the line's distance from the centre directly
// instead of subtracting two huge nearly equal squares, and the Press et al. root
// q = -(b' + sign(b') sqrt(D)), t = c/q and q/a, which never subtracts nearly equal numbers.
// Which of the two is nearer follows from the sign of b' alone.
#pragma once
#include "ray/ray_sphere_geometric.hpp"

namespace sw::ray {

struct RaySphereStable {
  static constexpr std::string_view id = "ray-sphere-stable";
  static constexpr std::string_view summary = "Ray-sphere, stable: Hearn-Baker discriminant and the Press et al. root";
  enum Line : std::uint32_t { coeffs = 1, foot, disc, miss, q, degenerate, order, near, far, none };
  static constexpr std::array<std::string_view, 10> lines = {
      "f <- o - c; a <- d . d; b' <- f . d; cc <- f . f - r^2",
      "l <- f - (b' / a) d                          -- from the centre to the line's closest point",
      "D <- a (r^2 - l . l)                         -- Hearn-Baker: b'^2 - a cc without the cancellation",
      "if D < 0: miss",
      "q <- -(b' + sign(b') sqrt(D))                -- sign(0) = +1; both terms have one sign",
      "if q = 0: miss                               -- tangent at the origin: both roots are 0",
      "if b' >= 0: near <- q / a, far <- cc / q; else near <- cc / q, far <- q / a",
      "if near > 0: hit at near",
      "if far > 0: hit at far",
      "miss",
  };
  static constexpr Listing listing() { return {"Stable ray-sphere", lines}; }
};

template <class Num, class Probe = NoProbe>
[[gnu::always_inline]] inline SphereHit<Num> ray_sphere_stable(const Ray3<Num>& r, const Vec3<Num>& c, const Num& radius, Probe& probe) {
  using L = RaySphereStable;
  SphereHit<Num> out;
  const Vec3<Num> f = r.o - c;
  // Static filter bounds (docs/accuracy-rays.md): f one rounding, d and r exact; a = d.d, b' = f.d
  // and cc with their static bounds, then the discriminant's bound from the computed foot l.
  const Num a = certify(dot(r.d, r.d), [](double z) { return filter::poly(3.02, z); });
  const Num bh = certify(dot(f, r.d), [&](double) { return filter::poly(13, filter::mag(f), filter::mag(r.d)); });
  const Num r2 = Num(radius * radius);
  const Num cc = certify(Num(dot(f, f) - r2), [&](double) {
    const double fm = filter::mag(f), rm = std::fabs(num::to_double(radius));
    return filter::poly(19, fm, fm) + filter::poly(7, rm, rm);
  });
  if constexpr (Probe::on)
    probe.step(L::coeffs, StepKind::init).num("a", a).num("b'", bh).num("c", cc)
        .geo(GeoKind::ray3, r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z).geo(GeoKind::sphere, c.x, c.y, c.z, radius);
  const Vec3<Num> l = f - Num(bh / a) * r.d;
  if constexpr (Probe::on) probe.step(L::foot, StepKind::advance).num("lx", l.x).num("ly", l.y).num("lz", l.z).point(Vec3<Num>(c + l));
  const Num disc = certify(Num(a * Num(r2 - dot(l, l))), [&](double z) {
    const double lm = filter::mag(l), el = filter::poly(27, filter::mag(f)), ll = num::to_double(dot(l, l));
    const double rr = num::to_double(r2), g = rr - ll, ea = filter::err(a), u = filter::kU;
    const double bll = 3.02 * u * ll + el * (6 * lm + 3 * el);
    const double bg = filter::kSlack * (u * rr + bll + u * std::fabs(g));
    if (!filter::in_range(std::fabs(num::to_double(radius)))) return std::numeric_limits<double>::infinity();
    return filter::kSlack * (num::to_double(a) * bg + (std::fabs(g) + bg) * ea + u * std::fabs(z));
  });
  if constexpr (Probe::on) probe.step(L::disc, StepKind::decide).num("D", disc);
  if (disc < Num(0)) {
    if constexpr (Probe::on) probe.step(L::miss, StepKind::miss);
    return out;
  }
  const bool b_neg = bh < Num(0);
  // |sqrt(x) - sqrt(y)| <= |x - y| / sqrt(x) (x = disc > 0), plus one rounding; x = 0 is exact
  // only with a zero bound.
  const Num s = certify(sqrt_num(disc, out.t_exact), [&](double z) {
    const double e = filter::err(disc), b = filter::kSlack * (e * filter::recip_upper(z) + filter::kU * z);
    return filter::recip_ok(z) ? b : e == 0 && z == 0 ? 0.0 : std::numeric_limits<double>::infinity();
  });
  const Num q = certify(b_neg ? Num(s - bh) : Num(Num(-bh) - s), [&](double z) { return filter::sum(z, s, bh); });
  if constexpr (Probe::on) probe.step(L::q, StepKind::decide).num("q", q);
  if (q == Num(0)) {
    if constexpr (Probe::on) probe.step(L::degenerate, StepKind::miss);
    return out;
  }
  const Num t_qa = certify(Num(q / a), [&](double z) { return filter::quot(z, filter::err(q), a); });
  const Num t_cq = certify(Num(cc / q), [&](double z) { return filter::quot(z, filter::err(cc), q); });
  const Num near = b_neg ? t_cq : t_qa, far = b_neg ? t_qa : t_cq;
  if constexpr (Probe::on) probe.step(L::order, StepKind::decide).num("near", near).num("far", far);
  if (near > Num(0)) {
    out.hit = true, out.t = near;
    if constexpr (Probe::on) probe.step(L::near, StepKind::hit).point(Vec3<Num>(r.o + near * r.d));
  } else if (far > Num(0)) {
    out.hit = true, out.t = far;
    if constexpr (Probe::on) probe.step(L::far, StepKind::hit).point(Vec3<Num>(r.o + far * r.d));
  } else {
    if constexpr (Probe::on) probe.step(L::none, StepKind::miss);
  }
  return out;
}

}  // namespace sw::ray
