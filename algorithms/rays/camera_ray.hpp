// Camera rays. The view-plane model: an orthonormal frame (u, v, n) from the view-plane normal
// VPN and the up vector VUP, the pixel (i, j) mapped to a point P1 on a window of the view plane
// at distance d in front of the eye P0, and the ray P0 -> P1. Perspective takes the window from
// a vertical field of view; fisheye (equidistant) and cylindrical map the pixel to angles instead.
// Pixel convention (docs/rays/semantics.md): pixel (i, j) is the unit square centred on (i, j), as
// in the raster family; the image spans [-1/2, W - 1/2] x [-1/2, H - 1/2], row 0 at the top.
#pragma once
#include <array>
#include <string_view>
#include "core/probe.hpp"
#include "rays/ray_common.hpp"

namespace sw::ray {

enum class Projection { perspective, fisheye, cylindrical };

template <class Num> struct Camera {
  Vec3<Num> eye, vpn, vup;  // vpn points from the scene to the eye: the camera looks along -n
  Num dist;                 // d > 0: distance of the view plane
  Num fov;                  // vertical field of view, radians (fisheye: of the image circle's diameter)
  std::int64_t width = 1, height = 1;
  Projection projection = Projection::perspective;
  // Perspective only: a window [umin, umax] x [vmin, vmax] on the view plane replaces fov (the
  // ray-tracing notes' model; it may be off-centre, and its pixels need not be square).
  bool has_window = false;
  std::array<Num, 4> window{};
};

template <class Num> struct CameraRay {
  bool valid = false;  // fisheye: false outside the image circle
  Ray3<Num> ray;
};

struct CameraRayAlgo {
  static constexpr std::string_view id = "camera-ray";
  static constexpr std::string_view summary = "Camera ray: view-plane model (perspective), fisheye, cylindrical";
#define SW_LINES_CAMERA_RAY_ALGO(X) \
  X(frame, "n <- VPN/|VPN|; u <- (VUP x n)/|VUP x n|; v <- n x u") \
  X(screen, "sx <- 2 (i + 1/2 + di)/W - 1; sy <- 1 - 2 (j + 1/2 + dj)/H  -- (di, dj): a sample's offset, 0 at the centre") \
  X(window, "perspective: hh <- d tan(fov/2); hw <- hh W/H       -- the window's half sizes") \
  X(point, "P1 <- P0 - d n + sx hw u + sy hh v; dir <- P1 - P0") \
  X(given, "a given window: P1 <- P0 - d n + (umin + (sx+1)/2 (umax-umin)) u + (vmin + (sy+1)/2 (vmax-vmin)) v") \
  X(fisheye, "fisheye: x <- sx W/H; rho <- sqrt(x^2 + sy^2); theta <- rho fov/2; phi <- atan2(sy, x)") \
  X(circle, "if rho > 1: no ray (outside the image circle); dir <- sin(theta)(cos(phi) u + sin(phi) v) - cos(theta) n") \
  X(cyl, "cylindrical: phi <- sx (fov/2) W/H; dir <- d (sin(phi) u - cos(phi) n) + sy d tan(fov/2) v") \
  X(ray, "ray <- (P0, dir)")
  SW_LISTING("Camera rays", SW_LINES_CAMERA_RAY_ALGO)
#undef SW_LINES_CAMERA_RAY_ALGO
};

// The ray through the point (i + di, j + dj) of the image, (di, dj) in [-1/2, 1/2]: a sample of
// pixel (i, j) (supersampling); camera_ray below is the pixel's centre.
template <NumberType Num, StepProbe Probe = NoProbe>
CameraRay<Num> camera_ray_at(const Camera<Num>& c, std::int64_t i, std::int64_t j, const Num& di, const Num& dj, Probe& probe) {
  using L = CameraRayAlgo;
  CameraRay<Num> out;
  auto unit = [](const Vec3<Num>& a) { return (Num(1) / num::sqrt_of(dot(a, a))) * a; };
  const Vec3<Num> n = unit(c.vpn), u = unit(cross(c.vup, n)), v = cross(n, u);
  if constexpr (Probe::on)
    probe.step(L::frame, StepKind::init)
        .num("ux", u.x)
        .num("uy", u.y)
        .num("uz", u.z)
        .num("vx", v.x)
        .num("vy", v.y)
        .num("vz", v.z)
        .num("nx", n.x)
        .num("ny", n.y)
        .num("nz", n.z)
        .point(c.eye)
        .label("eye")
        .keep()
        .segment(c.eye, Vec3<Num>(c.eye + u))
        .label("u")
        .keep()
        .segment(c.eye, Vec3<Num>(c.eye + v))
        .label("v")
        .keep()
        .segment(c.eye, Vec3<Num>(c.eye + n))
        .label("n")
        .keep();
  const Num w = Num(double(c.width)), h = Num(double(c.height)), half(0.5);
  // Adding an offset of 0 is exact: the centre's sx, sy are those of the formula without it.
  const Num sx = Num(2) * (Num(double(i)) + half + di) / w - Num(1), sy = Num(1) - Num(2) * (Num(double(j)) + half + dj) / h;
  if constexpr (Probe::on) {
    auto& st = probe.step(L::screen, StepKind::init).idx("i", i).idx("j", j).num("sx", sx).num("sy", sy);
    if (!(di == Num(0) && dj == Num(0))) st.num("di", di).num("dj", dj);
  }
  Vec3<Num> dir;
  if (c.projection == Projection::perspective && c.has_window) {
    const Num wu = c.window[0] + (sx + Num(1)) * half * (c.window[1] - c.window[0]);
    const Num wv = c.window[2] + (sy + Num(1)) * half * (c.window[3] - c.window[2]);
    const Vec3<Num> p1 = c.eye - c.dist * n + wu * u + wv * v;
    dir = p1 - c.eye;
    if constexpr (Probe::on) probe.step(L::given, StepKind::advance).num("wu", wu).num("wv", wv).point(p1).label("P1").keep();
  } else if (c.projection == Projection::perspective) {
    const Num hh = c.dist * num::tan(c.fov * half), hw = hh * w / h;
    if constexpr (Probe::on) probe.step(L::window, StepKind::init).num("hh", hh).num("hw", hw);
    const Vec3<Num> p1 = c.eye - c.dist * n + sx * hw * u + sy * hh * v;
    dir = p1 - c.eye;
    if constexpr (Probe::on) probe.step(L::point, StepKind::advance).point(p1).label("P1").keep();
  } else if (c.projection == Projection::fisheye) {
    const Num x = sx * w / h, rho = num::sqrt_of(x * x + sy * sy);
    const Num theta = rho * c.fov * half, phi = num::atan2(sy, x);
    if constexpr (Probe::on) probe.step(L::fisheye, StepKind::decide).num("rho", rho).num("theta", theta).num("phi", phi);
    if (rho > Num(1)) {
      if constexpr (Probe::on) probe.step(L::circle, StepKind::miss);
      return out;
    }
    const Num st = num::sin(theta);
    dir = st * num::cos(phi) * u + st * num::sin(phi) * v - num::cos(theta) * n;
  } else {
    const Num phi = sx * c.fov * half * w / h;
    if constexpr (Probe::on) probe.step(L::cyl, StepKind::decide).num("phi", phi);
    dir = c.dist * (num::sin(phi) * u - num::cos(phi) * n) + sy * c.dist * num::tan(c.fov * half) * v;
  }
  out.valid = true;
  out.ray = {c.eye, dir};
  if constexpr (Probe::on)
    probe.step(L::ray, StepKind::done).num("dx", dir.x).num("dy", dir.y).num("dz", dir.z).ray(c.eye, dir).label("ray").keep();
  return out;
}

template <NumberType Num, StepProbe Probe = NoProbe>
CameraRay<Num> camera_ray(const Camera<Num>& c, std::int64_t i, std::int64_t j, Probe& probe) {
  return camera_ray_at(c, i, j, Num(0), Num(0), probe);
}

}  // namespace sw::ray
