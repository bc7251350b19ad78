// The orbit3d view: the 3D geometry a trace records (rays, spheres, boxes, triangles, planes,
// points, segments), painted by kind, label, lifetime and value through an orbit camera
// (projection.hpp). The algorithm's declared point3 and direction3 handles can be dragged: the app
// re-records the trace at once (CanvasEvents::edit).
#pragma once
#include <optional>
#include <string>
#include <vector>
#include "panels/canvas.hpp"
#include "panels/projection.hpp"

namespace sw::vis {

// One recorded 3D item, in doubles.
struct Item3 {
  GeoKind kind = GeoKind::point3;
  std::vector<double> v;
  const char* label = nullptr;
  std::optional<double> value;
  bool current = false;  // recorded by the step shown, not kept from an earlier one
  V3 at(int k) const { return {v[std::size_t(k)], v[std::size_t(k) + 1], v[std::size_t(k) + 2]}; }
};
Item3 item_of(const TraceView& t, std::uint32_t g);

// What the view frames: the trace's lasting items (its scene) and every point it records.
struct Scene3 {
  std::optional<std::pair<V3, V3>> first_ray;  // o, d of the first ray item
  double ray_length = 1;                       // rays are drawn from o to o + ray_length d
  V3 centre{0, 0, 0};
  double radius = 1;          // a ball holding the scene
  double primitive_size = 1;  // the lasting items other than rays: what focus frames
  V3 primitive_centre{0, 0, 0};
  static Scene3 from_model(const TraceModel& m, const std::vector<std::optional<V3>>& handles);
};

// The declared 3D handles' positions in the input: a point3 handle is its value, a direction3
// handle the previous point handle plus its value. Nothing for one the input lacks.
std::vector<std::optional<V3>> handle_points3(const Algorithm& alg, const Json& input);
// The input with handle k moved to p, coordinates snapped to multiples of `snap` (a power of two
// keeps them float-representable). Nothing when the input lacks it or a direction would be zero.
std::optional<Json> handle_edit3(const Algorithm& alg, const Json& input, std::size_t k, V3 p, double snap);

class OrbitCanvas final : public Canvas {
 public:
  CanvasEvents draw(const CanvasInput& in, ImVec2 size) override;
  void fit() override { fit_pending_ = orient_pending_ = true; }
  void focus(const TraceModel& m, std::size_t step, double min_scale) override;
  void follow(const Canvas& other) override;
  // Test hook: the screen position of a world point in the last drawn frame, if in front of the
  // camera and inside the canvas.
  std::optional<std::array<float, 2>> screen_of(V3 p) const;
  const OrbitCamera& camera() const { return cam_; }
  // Test hook: the label boxes of the last drawn frame (draw_scene3).
  const std::vector<std::array<float, 4>>& label_rects() const { return labels_; }

 private:
  void handle_input(const CanvasInput& in, const std::vector<std::optional<V3>>& handles, bool hovered, CanvasEvents& ev);
  void face(const Scene3& sc);
  void keep_in_view(const TraceModel& m, std::size_t step);  // pans to the step's point if off-canvas

  OrbitCamera cam_;
  std::vector<std::array<float, 4>> labels_;
  bool fit_pending_ = true, orient_pending_ = true;  // F re-frames; a new trace also turns to face its ray
  int dragging_ = -1;        // a handle's index, or kOrbit, kPan
  V3 drag_anchor_{0, 0, 0};  // the handle's world position when the drag began (its facing plane)
  static constexpr int kOrbit = -2, kPan = -3;
};

// The drawing of one frame (orbit_draw.cpp). Returns the label boxes it drew (x0, y0, x1, y1),
// pairwise disjoint: labels that found no clear place near their item were dropped.
std::vector<std::array<float, 4>> draw_scene3(ImDrawList* dl, const OrbitCamera& cam, const Scene3& sc, const TraceModel& m, std::size_t step,
                 const std::vector<std::optional<V3>>& handles, int active_handle);

// The colour of a point recorded on a hit step (tests look for it).
inline constexpr ImU32 kHitColour = IM_COL32(255, 70, 200, 255);

}  // namespace sw::vis
