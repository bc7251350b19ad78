#include "panels/outline_layer.hpp"
#include <cmath>

namespace sw::vis {

void OutlineLayer::draw(ImDrawList* dl, const std::shared_ptr<const TraceModel>& model, const Rect2& v, double cell, const std::function<ImVec2(double, double)>& to_screen) {
  const TraceModel& m = *model;
  if (!m.algorithm().outline || !(cell > 0)) return;
  const bool inside = v.x0 >= window_.x0 && v.x1 <= window_.x1 && v.y0 >= window_.y0 && v.y1 <= window_.y1;
  if (model_ != &m || !inside || std::fabs(std::log2(cell / cell_)) > 0.5) {
    const double mx = (v.x1 - v.x0) / 2, my = (v.y1 - v.y0) / 2;
    window_ = {v.x0 - mx, v.y0 - my, v.x1 + mx, v.y1 + my};
    cell_ = cell, model_ = &m, keep_ = model;
    try {
      lines_ = m.run().outline(window_, cell);
    } catch (const std::exception&) {  // the input was validated when recorded: nothing to draw
      lines_.clear();
    }
  }
  std::vector<ImVec2> pts;
  for (const Polyline2& line : lines_) {
    pts.clear();
    for (const auto& p : line) pts.push_back(to_screen(p[0], p[1]));
    dl->AddPolyline(pts.data(), int(pts.size()), kOutline, ImDrawFlags_None, 1.5f);
  }
}

}  // namespace sw::vis
