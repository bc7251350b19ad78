// Ray-plane: the plane n . (x - p) = 0 meets o + t d at t = n . (p - o) / (n . d). A zero
// denominator (the ray parallel to the plane, including a ray lying in it) is a defined miss.
#pragma once
#include <array>
#include <string_view>
#include "core/probe.hpp"
#include "ray/ray_common.hpp"

namespace sw::ray {

template <class Num> struct PlaneHit {
  bool hit = false;
  Num t{};
};

struct RayPlane {
  static constexpr std::string_view id = "ray-plane";
  static constexpr std::string_view summary = "Ray-plane: t = n.(p - o) / n.d; parallel is a defined miss";
  enum Line : std::uint32_t { denom = 1, parallel, t, behind, hit };
  static constexpr std::array<std::string_view, 5> lines = {
      "den <- n . d",
      "if den = 0: miss                             -- parallel, or lying in the plane",
      "t <- n . (p - o) / den",
      "if t <= 0: miss                              -- behind the origin (or the origin is on it)",
      "hit at o + t d",
  };
  static constexpr Listing listing() { return {"Ray-plane", lines}; }
};

template <class Num, class Probe = NoProbe>
[[gnu::always_inline]] inline PlaneHit<Num> ray_plane(const Ray3<Num>& r, const Vec3<Num>& p, const Vec3<Num>& n, Probe& probe) {
  using L = RayPlane;
  PlaneHit<Num> out;
  // Static filter bounds (docs/accuracy-rays.md): n, d exact, p - o one rounding.
  const Num den = certify(dot(n, r.d), [&](double) { return filter::poly(10, filter::mag(n), filter::mag(r.d)); });
  if constexpr (Probe::on)
    probe.step(L::denom, StepKind::decide).num("den", den).geo(GeoKind::ray3, r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z)
        .geo(GeoKind::plane, p.x, p.y, p.z, n.x, n.y, n.z);
  if (den == Num(0)) {
    if constexpr (Probe::on) probe.step(L::parallel, StepKind::miss);
    return out;
  }
  const Num t = certify(Num(dot(n, Vec3<Num>(p - r.o)) / den), [&](double z) {
    return filter::quot(z, filter::poly(13, filter::mag(n), filter::mag(Vec3<Num>(p - r.o))), den);
  });
  if constexpr (Probe::on) probe.step(L::t, StepKind::decide).num("t", t);
  if (!(t > Num(0))) {
    if constexpr (Probe::on) probe.step(L::behind, StepKind::miss);
    return out;
  }
  out.hit = true, out.t = t;
  if constexpr (Probe::on) probe.step(L::hit, StepKind::hit).point(Vec3<Num>(r.o + t * r.d));
  return out;
}

}  // namespace sw::ray
