// The exact curve an algorithm declares from its definition (Algorithm::outline), drawn thin over
// the plane2d canvas's pixels, so that the pixels can be judged against the true curve. Computed
// over a margin around the visible window and reused while the view stays inside it.
#pragma once
#include <imgui.h>
#include <functional>
#include <memory>
#include <vector>
#include "lessons/trace_model.hpp"

namespace sw::vis {

inline constexpr ImU32 kOutline = IM_COL32(80, 200, 255, 235);

class OutlineLayer {
 public:
  // cell: world units per sample (a few screen pixels).
  void draw(ImDrawList* dl, const std::shared_ptr<const TraceModel>& m, const Rect2& visible, double cell, const std::function<ImVec2(double, double)>& to_screen);
  // Test hook: the polylines last computed (world coordinates).
  const std::vector<Polyline2>& lines() const { return lines_; }

 private:
  const TraceModel* model_ = nullptr;
  std::shared_ptr<const TraceModel> keep_;
  Rect2 window_;
  double cell_ = 0;
  std::vector<Polyline2> lines_;
};

}  // namespace sw::vis
