// The image view: the algorithm swept untraced over a grid of inputs around the trace's input
// (Algorithm::sweep; for a ray test, parallel rays), once in the trace's number type and once
// exact, one texel per sample. Where both agree it shows the value (a hit's t, shaded) or nothing
// (a miss); where they disagree it shows which way, in two colours, and counts them: what the
// number type's accuracy costs. Wheel zooms, drag pans, F frames the input again, Z zooms onto the
// input itself, a click traces the sample clicked (Sweep::sample).
#pragma once
#include <chrono>
#include <vector>
#include "panels/canvas.hpp"

namespace sw::vis {

// The colours of the samples (the tests look for them); both hit: blue, brighter when nearer.
inline constexpr ImU32 kSweepMissBoth = IM_COL32(34, 37, 46, 255);
inline constexpr ImU32 kSweepFalseHit = IM_COL32(255, 60, 60, 255);  // the mode has a value, exact none
inline constexpr ImU32 kSweepMissed = IM_COL32(255, 200, 0, 255);    // exact has a value, the mode none

struct SweepImage {
  SweepGrid grid;
  std::vector<float> mode, exact;        // per sample, row 0 on top; NaN: none (a miss)
  Numeric reference = Numeric::exact;    // what `exact` was swept in: exact, else (transcendental) reference
  bool shaded = false;                   // values are intensities (Sweep::shaded)
  std::size_t hits = 0;                  // samples exact says have a value
  std::size_t false_hits = 0;            // the mode has a value, exact none; shaded: or brighter by > 1/255
  std::size_t missed = 0;                // exact has a value, the mode none; shaded: or darker by > 1/255
  double mode_ms = 0, exact_ms = 0;      // how long each sweep took
  std::size_t samples() const { return mode.size(); }
  std::size_t disagreements() const { return false_hits + missed; }
  // Sample k: +1 counted in false_hits, -1 in missed, 0 agreeing.
  int disagreement(std::size_t k) const;
};

// Sweeps m's algorithm on m's input over `grid` in m's number type and exactly; the grid's
// samples are rounded to m's number type, so both see the same inputs. `which`: the image view's
// sweep or the lobe view's. Throws InputError.
SweepImage sweep_image(const TraceModel& m, SweepGrid grid, bool lobe = false);

class ImageCanvas final : public Canvas {
 public:
  explicit ImageCanvas(TextureHost& textures) : host_(&textures) {}
  ~ImageCanvas() override;
  ImageCanvas(const ImageCanvas&) = delete;
  ImageCanvas& operator=(const ImageCanvas&) = delete;

  CanvasEvents draw(const CanvasInput& in, ImVec2 size) override;
  void fit() override { cx_ = cy_ = 0, half_ = 1; }
  // Centres the window on the input itself (Sweep::marker), zoomed in to kFocusHalf at least.
  void focus(const TraceModel& m, std::size_t step, double min_scale) override;
  void follow(const Canvas& other) override;

  // Test hooks: the last sweep, and the screen rectangle of sample (i, j) in the last frame.
  const SweepImage& image() const { return image_; }
  std::array<float, 4> sample_rect(int i, int j) const;
  static constexpr int kSide = 255;  // samples along the longer side (odd: a middle sample)
  static constexpr double kFocusHalf = 1.0 / 64;

 private:
  void handle_input(bool hovered);
  void upload();

  TextureHost* host_;
  ImTextureID tex_ = nullptr;
  int tex_w_ = 0, tex_h_ = 0;
  double cx_ = 0, cy_ = 0, half_ = 1;  // the window: centre and half height, in the sweep's frame
  ImVec2 origin_{0, 0}, size_{1, 1};
  bool moved_ = false;  // the press dragged (a pan), so its release is no click
  const TraceModel* swept_ = nullptr;  // the model and grid of image_
  std::shared_ptr<const TraceModel> keep_;
  SweepImage image_;
  std::string error_;
};

}  // namespace sw::vis
