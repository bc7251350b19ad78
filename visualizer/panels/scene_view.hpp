// The scene view (View::scene; the ray tracer's pixel history): the algorithm's picture of its
// input (Run::picture: the scene rendered once through the pixels' centres, made from the opened
// input and kept until the input changes other than at its pick), the picked pixel framed; a click
// picks the pixel clicked (the input with Algorithm::picture.pick set: an edit). Beside it, the
// result's colour, the picture's notes (the planner's decisions) and the algorithm's table of the
// trace (Run::summary_table: the ray tree, per ray its depth, kind, path weight, the colour found
// there and its share of the pixel, summed); the current step's row is highlighted, a click on a
// row jumps to its step. Everything comes through declared hooks: nothing here knows the tracer.
#pragma once
#include <string>
#include <vector>
#include "panels/canvas.hpp"

namespace sw::vis {

class SceneCanvas final : public Canvas {
 public:
  explicit SceneCanvas(TextureHost& textures) : host_(&textures) {}
  ~SceneCanvas() override;
  SceneCanvas(const SceneCanvas&) = delete;
  SceneCanvas& operator=(const SceneCanvas&) = delete;

  CanvasEvents draw(const CanvasInput& in, ImVec2 size) override;
  void fit() override {}
  void follow(const Canvas&) override {}

  // Test hooks: the picture, the table of the drawn trace, and the screen rectangle of the
  // picture pixel holding image pixel (i, j) in the last frame.
  const Picture& picture() const { return picture_; }
  const SummaryTable& summary() const { return summary_; }
  std::array<float, 4> pixel_rect(std::int64_t i, std::int64_t j) const;
  static constexpr std::int64_t kMaxSide = 200;  // picture pixels on the longer side

 private:
  void refresh(const TraceModel& m);
  void draw_side(const TraceModel& m, const CanvasInput& in, CanvasEvents& ev);

  TextureHost* host_;
  ImTextureID tex_ = nullptr, grey_tex_ = nullptr;  // the picture and its grey image
  std::string key_;  // the input the picture was made for, without its pick
  Picture picture_;
  std::string error_;
  const TraceModel* summarised_ = nullptr;  // the model summary_ was computed from
  std::shared_ptr<const TraceModel> keep_;
  SummaryTable summary_;
  ImVec2 img0_{0, 0}, img1_{1, 1};  // the image on screen
};

}  // namespace sw::vis
