// The orbit camera of the 3D ray view: a target point, yaw and pitch around it (z is up), a
// distance, and a perspective projection onto a screen rectangle. Doubles throughout, so a scene
// 1e8 units across still projects without jitter. Plain value type: no ImGui state.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace sw::vis {

struct V3 {
  double x = 0, y = 0, z = 0;
  friend V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
  friend double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
  friend V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
  friend double norm(V3 a) { return std::sqrt(dot(a, a)); }
  friend V3 unit(V3 a) {
    const double n = norm(a);
    return n > 0 ? (1 / n) * a : V3{};
  }
};

struct OrbitCamera {
  V3 target;
  double yaw = -0.9, pitch = 0.45, dist = 20;  // radians; pitch in (-pi/2, pi/2)
  double fov = 0.8;                             // vertical field of view, radians
  std::array<double, 2> origin{0, 0}, size{1, 1};  // the screen rectangle

  V3 eye() const { return target + dist * V3{std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)}; }
  V3 forward() const { return unit(target - eye()); }
  V3 right() const { return unit(cross(forward(), V3{0, 0, 1})); }
  V3 up() const { return cross(right(), forward()); }
  double focal() const { return 0.5 * size[1] / std::tan(fov / 2); }  // screen pixels per unit at depth 1
  double near_plane() const { return dist * 1e-4; }

  // Camera space: x right, y up, z depth along forward.
  V3 to_camera(V3 p) const {
    const V3 v = p - eye();
    return {dot(v, right()), dot(v, up()), dot(v, forward())};
  }
  std::array<double, 2> screen_of_camera(V3 c) const {
    const double f = focal() / c.z;
    return {origin[0] + size[0] / 2 + c.x * f, origin[1] + size[1] / 2 - c.y * f};
  }
  // Screen position of a world point, or nothing when it is behind the near plane.
  std::optional<std::array<double, 2>> project(V3 p) const {
    const V3 c = to_camera(p);
    if (c.z <= near_plane()) return std::nullopt;
    return screen_of_camera(c);
  }
  // The segment a-b clipped to the near plane, in screen coordinates.
  std::optional<std::array<double, 4>> project_segment(V3 a, V3 b) const {
    V3 ca = to_camera(a), cb = to_camera(b);
    const double n = near_plane();
    if (ca.z <= n && cb.z <= n) return std::nullopt;
    if (ca.z <= n) ca = ca + ((n - ca.z) / (cb.z - ca.z)) * (cb - ca);
    if (cb.z <= n) cb = cb + ((n - cb.z) / (ca.z - cb.z)) * (ca - cb);
    const auto sa = screen_of_camera(ca), sb = screen_of_camera(cb);
    return std::array<double, 4>{sa[0], sa[1], sb[0], sb[1]};
  }
  // World units per screen pixel at the depth of p (for handle sizes, pans and snapping).
  double units_per_pixel(V3 p) const { return std::max(to_camera(p).z, near_plane()) / focal(); }

  // The point under screen position (sx, sy) on the plane through p facing the camera.
  V3 unproject_on_facing_plane(double sx, double sy, V3 p) const {
    const double depth = std::max(to_camera(p).z, near_plane());
    const double x = (sx - origin[0] - size[0] / 2) * depth / focal(), y = -(sy - origin[1] - size[1] / 2) * depth / focal();
    return eye() + depth * forward() + x * right() + y * up();
  }

  void orbit(double dyaw, double dpitch) {
    yaw += dyaw;
    pitch = std::clamp(pitch + dpitch, -1.55, 1.55);
  }
  // Moves the target with the mouse: a drag of (dx, dy) pixels keeps the target under the cursor.
  void pan(double dx, double dy) {
    const double k = dist / focal();
    target = target - (dx * k) * right() + (dy * k) * up();
  }
  void zoom(double factor) { dist = std::clamp(dist * factor, 1e-9, 1e13); }
  // Frames a ball of radius r around c.
  void frame(V3 c, double r) {
    target = c;
    dist = std::clamp(std::max(r, 1e-9) / std::sin(fov / 2) * 1.1, 1e-9, 1e13);
  }
};

}  // namespace sw::vis
