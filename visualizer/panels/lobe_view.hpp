// The lobe view: a reflection model's term as a polar plot in the plane of incidence. The eye
// sweeps from -90 to 90 degrees about the normal (Algorithm::lobe), once in the trace's number
// type and once in the reference; the radius is the term. The normal points up, the light comes
// in on the left, its mirror direction is dashed on the right. Where the mode differs from the
// reference by more than 1/255 a red dot marks it. Wheel scales the radius, F resets, hovering
// reads a direction, a click traces it. Side by side, both canvases share the outer ring's value.
#pragma once
#include "panels/canvas.hpp"
#include "panels/image_view.hpp"

namespace sw::vis {

class LobeCanvas final : public Canvas {
 public:
  CanvasEvents draw(const CanvasInput& in, ImVec2 size) override;
  void fit() override { zoom_ = 1; }
  void follow(const Canvas& other) override;

  // Test hooks: the last sweep (one row: sample i is the direction at grid.x(i) degrees), and the
  // screen position of sample i's point on the mode's curve in the last frame.
  const SweepImage& lobe() const { return lobe_; }
  ImVec2 sample_point(std::size_t i) const;
  ImVec2 centre() const { return centre_; }  // the shading point on screen
  static constexpr int kDirections = 361;  // every half degree from -90 to 90

 private:
  ImVec2 at(double deg, double value) const;  // screen point of a direction and a term value

  double zoom_ = 1;        // the radius scale, times the fitted one
  double full_ = 1;        // the term value at the outer ring
  double peak_ = 0;        // the largest value of both curves
  double other_peak_ = 0;  // the side-by-side canvas's peak (follow)
  ImVec2 centre_{0, 0};    // the shading point on screen
  float radius_ = 1;       // pixels of the outer ring
  const TraceModel* swept_ = nullptr;
  std::shared_ptr<const TraceModel> keep_;
  SweepImage lobe_;
  std::string error_;
};

}  // namespace sw::vis
