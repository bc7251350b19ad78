// The orbit camera of the 3D ray view: a target point, yaw and pitch around it (z is up), a
// distance, and a perspective projection onto a screen rectangle. GLM in double precision
// (glm::dvec3, glm::dmat4), so a scene 1e8 units across still projects without jitter; the
// algorithms keep their own generic vectors. Plain value type: no ImGui state.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace sw::vis {

using V3 = glm::dvec3;  // never a float vector: see above

// glm::normalize divides by zero on a zero vector; this one returns the zero vector.
inline V3 unit(const V3& a) {
  const double n = glm::length(a);
  return n > 0 ? a / n : V3(0.0);
}

struct OrbitCamera {
  V3 target{0, 0, 0};
  double yaw = -0.9, pitch = 0.45, dist = 20;  // radians; pitch in (-pi/2, pi/2)
  double fov = 0.8;                             // vertical field of view, radians
  std::array<double, 2> origin{0, 0}, size{1, 1};  // the screen rectangle

  // The eye relative to the target, and in the world.
  V3 eye_offset() const { return dist * V3(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)); }
  V3 eye() const { return target + eye_offset(); }
  // World to eye space (right-handed, z up in the world): x right, y up, the camera looking down
  // -z, so a point's depth in front of the camera is -z. It is glm::lookAt(eye(), target, z),
  // built around the target (the lookAt of eye_offset() at the origin after moving the target
  // there), so that the eye's own rounding 1e8 from the origin never enters the rotation.
  glm::dmat4 view() const { return glm::lookAtRH(eye_offset(), V3(0.0), V3(0, 0, 1)) * glm::translate(glm::dmat4(1.0), -target); }
  // Eye space to clip space: the vertical fov over the rectangle's aspect, no far plane. Clip w
  // is the depth; x / w and y / w span [-1, 1] across the rectangle, y up.
  glm::dmat4 projection() const { return glm::infinitePerspectiveRH(fov, size[0] / size[1], near_plane()); }
  // The camera's axes in the world: the rows of the view's rotation.
  V3 right() const { return glm::row(rotation(), 0); }
  V3 up() const { return glm::row(rotation(), 1); }
  V3 forward() const { return -glm::row(rotation(), 2); }
  double focal() const { return 0.5 * size[1] / std::tan(fov / 2); }  // screen pixels per unit at depth 1
  double near_plane() const { return dist * 1e-4; }

  // Eye space of a world point: view() * (p, 1), with the differences taken first (p - target,
  // then the eye's offset) so that the digits of a point 1e8 from the origin are kept where they
  // matter, near the camera.
  V3 to_camera(V3 p) const { return rotation() * ((p - target) - eye_offset()); }
  static double depth(V3 c) { return -c.z; }
  std::array<double, 2> screen_of_camera(V3 c) const {
    const glm::dvec4 clip = projection() * glm::dvec4(c, 1.0);
    const double x = clip.x / clip.w, y = clip.y / clip.w;  // normalised device coordinates
    return {origin[0] + size[0] / 2 + x * (size[0] / 2), origin[1] + size[1] / 2 - y * (size[1] / 2)};
  }
  // Screen position of a world point, or nothing when it is behind the near plane.
  std::optional<std::array<double, 2>> project(V3 p) const {
    const V3 c = to_camera(p);
    if (depth(c) <= near_plane()) return std::nullopt;
    return screen_of_camera(c);
  }
  // The segment a-b clipped to the near plane, in screen coordinates.
  std::optional<std::array<double, 4>> project_segment(V3 a, V3 b) const {
    V3 ca = to_camera(a), cb = to_camera(b);
    const double n = near_plane(), da = depth(ca), db = depth(cb);
    if (da <= n && db <= n) return std::nullopt;
    if (da <= n) ca = ca + ((n - da) / (db - da)) * (cb - ca);
    if (db <= n) cb = cb + ((n - db) / (da - db)) * (ca - cb);
    const auto sa = screen_of_camera(ca), sb = screen_of_camera(cb);
    return std::array<double, 4>{sa[0], sa[1], sb[0], sb[1]};
  }
  // World units per screen pixel at the depth of p (for handle sizes, pans and snapping).
  double units_per_pixel(V3 p) const { return std::max(depth(to_camera(p)), near_plane()) / focal(); }

  // The point under screen position (sx, sy) on the plane through p facing the camera: the
  // projection undone at p's depth, then the view (a rotation, whose inverse is its transpose,
  // and the move of the eye to the origin).
  V3 unproject_on_facing_plane(double sx, double sy, V3 p) const {
    const double d = std::max(depth(to_camera(p)), near_plane());
    const glm::dmat4 proj = projection();
    const double x = (sx - origin[0] - size[0] / 2) / (size[0] / 2), y = -(sy - origin[1] - size[1] / 2) / (size[1] / 2);
    const V3 c(x * d / proj[0][0], y * d / proj[1][1], -d);
    return target + (eye_offset() + glm::transpose(rotation()) * c);
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

 private:
  // The view's rotation: the camera's right, up and backward axes as rows.
  glm::dmat3 rotation() const { return glm::dmat3(glm::lookAtRH(eye_offset(), V3(0.0), V3(0, 0, 1))); }
};

}  // namespace sw::vis
