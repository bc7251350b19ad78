// The raster canvas: pixel grid texture (PixelLayer) with the continuous geometry drawn over it.
#pragma once
#include "panels/canvas.hpp"
#include "panels/outline_layer.hpp"
#include "panels/pixel_layer.hpp"

namespace sw::vis {

class PixelCanvas final : public Canvas {
 public:
  explicit PixelCanvas(TextureHost& textures) : layer_(textures) {}
  CanvasEvents draw(const CanvasInput& in, ImVec2 size) override;
  void fit() override { fit_pending_ = true; }
  void focus(const TraceModel& m, std::size_t step, double min_scale) override;
  void follow(const Canvas& other) override;
  std::optional<std::array<float, 4>> cell_rect(Pixel c) const override;

 private:
  ImVec2 to_screen(double x, double y) const;
  std::array<double, 2> to_world(ImVec2 p) const;
  WorldRect visible() const;
  void do_fit(const TraceModel& m);
  void handle_view_input(bool hovered, bool keys);
  void draw_grid(ImDrawList* dl) const;
  void draw_geometry(ImDrawList* dl, const CanvasInput& in) const;
  void draw_marked(ImDrawList* dl, std::span<const Pixel> cells) const;
  // The step's visible 2D items other than pixels (the pixel layer draws those), by kind.
  void paint_items(ImDrawList* dl, const TraceModel& m, std::size_t step) const;

  PixelLayer layer_;
  OutlineLayer outline_;  // the exact curve, if the algorithm declares one
  double cx_ = 0, cy_ = 0, scale_ = 32;  // world centre and screen pixels per cell
  ImVec2 origin_{0, 0}, size_{1, 1};
  bool fit_pending_ = true;
  int dragging_ = -1;  // the declared handle being dragged (its index)
  bool moved_ = false;
};

}  // namespace sw::vis
