// Inverse mapping of a sphere: the unit normal at a point, its latitude and longitude, and the
// texture coordinates (u, v). The pole axis is +z; longitude is measured from +x toward +y.
// Seam: longitude jumps from +pi to -pi across the half-plane y = 0, x < 0 (atan2(+0, x<0) = +pi
// gives u = 1, atan2(-0, x<0) = -pi gives u = 0). Poles: x = y = 0 gives longitude atan2(0, 0) = 0
// (u = 1/2) and v = 0 or 1. The point is projected radially (it need not lie exactly on the sphere).
#pragma once
#include <array>
#include <string_view>
#include "core/probe.hpp"
#include "rays/ray_common.hpp"

namespace sw::ray {

template <class Num> struct SphereUV {
  Vec3<Num> normal;
  Num lat{}, lon{}, u{}, v{};
};

struct SphereUVAlgo {
  static constexpr std::string_view id = "sphere-uv";
  static constexpr std::string_view summary = "Inverse mapping of a sphere: normal, latitude/longitude (atan2), (u, v)";
#define SW_LINES_SPHERE_U_V_ALGO(X) \
  X(normal, "N <- (P - c) / |P - c|                        -- the outward unit normal") \
  X(lon, "lon <- atan2(N_y, N_x)                          -- in (-pi, pi]; the seam is y = 0, x < 0") \
  X(lat, "lat <- atan2(N_z, sqrt(N_x^2 + N_y^2))          -- in [-pi/2, pi/2]; well conditioned at the poles") \
  X(uv, "u <- (lon + pi) / 2pi; v <- (lat + pi/2) / pi")
  SW_LISTING("Sphere inverse mapping", SW_LINES_SPHERE_U_V_ALGO)
#undef SW_LINES_SPHERE_U_V_ALGO
};

// Precondition: p != c (validated).
template <NumberType Num, StepProbe Probe = NoProbe>
SphereUV<Num> sphere_uv(const Vec3<Num>& c, const Vec3<Num>& p, Probe& probe) {
  using L = SphereUVAlgo;
  SphereUV<Num> out;
  const Vec3<Num> q = p - c;
  out.normal = (Num(1) / num::sqrt_of(dot(q, q))) * q;
  const Vec3<Num>& n = out.normal;
  if constexpr (Probe::on)
    probe.step(L::normal, StepKind::init)
        .num("Nx", n.x)
        .num("Ny", n.y)
        .num("Nz", n.z)
        .sphere(c, num::sqrt_of(dot(q, q)))
        .keep()
        .point(p)
        .label("P")
        .keep()
        .segment(p, Vec3<Num>(p + n))
        .label("N")
        .keep();
  out.lon = num::atan2(n.y, n.x);
  if constexpr (Probe::on) probe.step(L::lon, StepKind::advance).num("lon", out.lon);
  out.lat = num::atan2(n.z, num::sqrt_of(n.x * n.x + n.y * n.y));
  if constexpr (Probe::on) probe.step(L::lat, StepKind::advance).num("lat", out.lat);
  const Num pi = num::pi<Num>();
  out.u = (out.lon + pi) / (Num(2) * pi);
  out.v = (out.lat + pi * Num(0.5)) / pi;
  if constexpr (Probe::on) probe.step(L::uv, StepKind::done).num("u", out.u).num("v", out.v);
  return out;
}

}  // namespace sw::ray
