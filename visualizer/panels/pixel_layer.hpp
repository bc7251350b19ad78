// The plotted pixels of a trace as one texture. Each texel remembers the first step that plotted
// any of its cells (computed once per trace and view window); moving the current step recolours
// only the texels whose plot step lies between the old and the new step, and uploads that
// rectangle. Scrubbing a 10^6-step trace is therefore a partial texture update, not a redraw.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>
#include "panels/texture_host.hpp"
#include "lessons/trace_model.hpp"

namespace sw::vis {

// A block of cells shown by the texture: texel (u, v) holds the k x k cells starting at
// (x0 + u*k, y0 + (h-1-v)*k); row 0 is the top of the picture (largest y).
struct CellWindow {
  std::int64_t x0 = 0, y0 = 0;
  int w = 0, h = 0, k = 1;
  bool contains(const CellWindow& o) const;
  WorldRect world() const;  // the world rectangle the texture covers
};

// The colour of a pixel plotted at `step` of a trace whose last step is `last` (RGBA, A = 255).
std::uint32_t plot_colour(std::size_t step, std::size_t last);

class PixelLayer {
 public:
  explicit PixelLayer(TextureHost& host) : host_(&host) {}
  ~PixelLayer();
  PixelLayer(const PixelLayer&) = delete;
  PixelLayer& operator=(const PixelLayer&) = delete;

  // Makes the texture show `model` at `step` over at least the `visible` world rectangle at
  // `scale` screen pixels per cell. Returns false when there is nothing to draw.
  bool prepare(const std::shared_ptr<const TraceModel>& model, const WorldRect& visible, double scale, std::size_t step);
  ImTextureID texture() const { return tex_; }
  const CellWindow& window() const { return win_; }
  // Texels touched by the last prepare() (for the scrub benchmark's report).
  std::size_t last_update_texels() const { return last_texels_; }

 private:
  void rebuild(const CellWindow& win);
  void recolour(std::size_t step);
  void upload_dirty();

  TextureHost* host_;
  std::shared_ptr<const TraceModel> model_;
  ImTextureID tex_ = nullptr;
  int tex_w_ = 0, tex_h_ = 0;
  CellWindow win_;
  std::vector<std::uint32_t> first_step_, rgba_;
  std::size_t shown_step_ = 0;
  bool shown_ = false;
  int dirty_x0_ = 0, dirty_y0_ = 0, dirty_x1_ = -1, dirty_y1_ = -1;  // inclusive texel rect
  std::size_t last_texels_ = 0;
};

}  // namespace sw::vis
