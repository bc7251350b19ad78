// The 3D canvas of the "ray" family: the ray, its primitive (sphere, box, triangle, plane) and the
// quantities of the current step, drawn with ImDrawList through an orbit camera (projection.hpp).
// The ray's origin o and the point o + d are handles: dragging one edits the input and the app
// re-records the trace at once (CanvasEvents::edit).
#pragma once
#include <string>
#include <vector>
#include "canvas.hpp"
#include "projection.hpp"

namespace sw::vis {

// The geometry of a ray trace: the first ray and the first primitive of any step, falling back
// to the input JSON ({"ray":{"o","d"}}, {"sphere":{"c","r"}}) for algorithms that record neither.
struct RayScene {
  enum class Prim { none, sphere, box, triangle, plane } prim = Prim::none;
  bool has_ray = false;
  V3 o{0, 0, 0}, d{0, 0, 0};
  std::array<V3, 3> v{};  // sphere: v[0] = centre; box: min, max; triangle: vertices; plane: p, n
  double r = 0;           // sphere radius
  double t_max = 1;       // the ray is drawn from o to o + t_max d

  static RayScene from_model(const TraceModel& m);
  // A ball holding the ray's drawn part and the primitive (what F frames).
  void bounds(V3& centre, double& radius) const;
};

// The input with the ray handle moved to p: handle 0 moves o (keeping d), handle 1 sets d = p - o.
// Coordinates snap to multiples of `snap` (a power of two keeps them float-representable).
// Nothing when the input has no {"ray":{"o","d"}} or the direction would be zero.
std::optional<Json> ray_input_edit(const Json& input, int handle, V3 p, double snap);

class RayCanvas final : public Canvas {
 public:
  CanvasEvents draw(const CanvasInput& in, ImVec2 size) override;
  void fit() override { fit_pending_ = orient_pending_ = true; }
  void focus(const TraceModel& m, std::size_t step, double min_scale) override;
  void follow(const Canvas& other) override;
  // Test hook: the screen position of a world point in the last drawn frame, if in front of the
  // camera and inside the canvas.
  std::optional<std::array<float, 2>> screen_of(V3 p) const;
  const OrbitCamera& camera() const { return cam_; }

 private:
  void handle_input(const CanvasInput& in, const RayScene& sc, bool hovered, CanvasEvents& ev);

  OrbitCamera cam_;
  void face_ray(const RayScene& sc);

  bool fit_pending_ = true, orient_pending_ = true;  // F re-frames; a new trace also turns to face its ray
  int dragging_ = -1;  // 0: o, 1: o + d, 2: orbit, 3: pan
  V3 drag_anchor_{0, 0, 0};  // the handle's world position when the drag began (its facing plane)
};

// The drawing of one frame, given the scene and the step (ray_draw.cpp).
void draw_ray_scene(ImDrawList* dl, const OrbitCamera& cam, const RayScene& sc, const TraceModel& m, std::size_t step, int active_handle);

// Colours the tests look for.
inline constexpr ImU32 kRayHit = IM_COL32(255, 70, 200, 255);
inline constexpr ImU32 kRayOrigin = IM_COL32(90, 220, 140, 255);
inline constexpr ImU32 kRayDir = IM_COL32(240, 96, 96, 255);

}  // namespace sw::vis
