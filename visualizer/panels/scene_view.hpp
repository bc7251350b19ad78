// The scene view of a ray tracer's pixel history (View::scene): the scene rendered once through
// the pixels' centres (tracer::render_preview, cached per scene, size, offset and plan), the traced
// pixel framed; a click traces the pixel clicked (an edited input). Beside it, the planner's
// decisions and the ray tree's table: per ray its depth, kind, path weight, the colour found there
// and its share of the pixel, summed; the current step's ray is highlighted, a click on a row
// jumps to its step.
#pragma once
#include <string>
#include <vector>
#include "panels/canvas.hpp"
#include "tracer/history.hpp"
#include "tracer/ray_tree.hpp"

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

  // Test hooks: the preview, the ray tree of the drawn trace, and the screen rectangle of the
  // preview pixel holding image pixel (i, j) in the last frame.
  const tracer::Preview& preview() const { return preview_; }
  const std::vector<tracer::RayNode>& tree() const { return tree_; }
  std::array<float, 4> pixel_rect(std::int64_t i, std::int64_t j) const;
  static constexpr std::int64_t kMaxSide = 200;  // preview pixels on the longer side

 private:
  void refresh(const TraceModel& m);
  void draw_side(const TraceModel& m, std::size_t step, CanvasEvents& ev);

  TextureHost* host_;
  ImTextureID tex_ = nullptr;
  std::string key_;  // the input the preview was rendered for, without its pixel
  tracer::Preview preview_;
  std::string error_;
  const TraceModel* treed_ = nullptr;  // the model tree_ was read from
  std::shared_ptr<const TraceModel> keep_;
  std::vector<tracer::RayNode> tree_;
  ImVec2 img0_{0, 0}, img1_{1, 1};  // the image on screen
};

}  // namespace sw::vis
