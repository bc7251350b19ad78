// What an algorithm declares for the visualizer's views, type-erased: the view kinds, the table
// view's rows, the sweep that fills image views and the exact curve drawn under the pixels.
// Specs fill these through make_algorithm (adapter.hpp, sweep.hpp); the visualizer reads only these.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "input.hpp"

namespace sw {

// The views an algorithm declares; the visualizer shows the first and lets the user switch.
enum class View : std::uint8_t {
  plane2d,  // pixels and 2D geometry over a grid
  orbit3d,  // 3D geometry under an orbit camera
  table,    // steps x recorded variables
  image,    // a sweep of the algorithm over a grid of inputs, against exact
  plot,     // the table's columns over its rows, against an exact run
  tree,     // a tree's nodes as a diagram: built so far, the current node, the traversal stack
  lobe,     // a polar plot: the algorithm swept over directions in a plane (a BRDF's lobe), against exact
  scene,    // a ray tracer's rendered image: a click traces that pixel; the planner's decisions, the ray tree's shares
};
inline constexpr std::array<std::string_view, 8> kViewNames = {"plane2d", "orbit3d", "table", "image", "plot", "tree", "lobe", "scene"};
constexpr std::string_view view_name(View v) { return kViewNames[static_cast<std::size_t>(v)]; }
inline std::optional<View> parse_view(std::string_view s) {
  for (std::size_t i = 0; i < kViewNames.size(); ++i)
    if (kViewNames[i] == s) return static_cast<View>(i);
  return std::nullopt;
}

// A grid of samples over a window of the Spec's sweep frame, in which the window [-1, 1]^2
// frames the input (a ray's primitive, say). Row 0 is the top. With w and h odd, the middle
// sample lies exactly on the centre (so a window centred on Sweep::marker samples the input).
struct SweepGrid {
  int w = 0, h = 0;
  double cx = 0, cy = 0;  // the window's centre
  double dx = 0, dy = 0;  // the samples' spacing
  // Sample inputs are rounded to this mode's numbers, so that every mode sweeping the grid sees
  // the same inputs and a difference is the algorithm's arithmetic, not its input's rounding.
  Numeric inputs = Numeric::f64;
  double x(int i) const { return cx + (i - (w - 1) / 2.0) * dx; }
  double y(int j) const { return cy - (j - (h - 1) / 2.0) * dy; }
  friend bool operator==(const SweepGrid&, const SweepGrid&) = default;
};

struct Sweep {
  // Runs the algorithm untraced at every sample, no JSON per sample: out[j * w + i] is the
  // Spec's value there (a ray's t), NaN for none (a miss). Exact mode decides through the filter
  // stages, whose results equal exact. Throws InputError for bad input.
  std::function<void(const Json& input, Numeric, const SweepGrid&, std::vector<float>& out)> run;
  // Where the input itself lies in the frame (the input ray's origin), if the Spec says.
  std::function<std::optional<std::array<double, 2>>(const Json& input)> marker;
  // Sample (i, j)'s input as JSON, as the sweep ran it (the app opens it on a click).
  std::function<Json(const Json& input, const SweepGrid&, int i, int j)> sample;
  std::string_view caption;  // what a sample is, for the view's legend
  // The lobe view's sweep only: the angles in degrees (in its grid's x) of the input's light and, if
  // it lies in the swept plane, of its eye (NaN if not).
  std::function<std::optional<std::array<double, 2>>(const Json& input)> angles;
  // The values are intensities in [0, 1] (a shaded picture), not distances along a ray: the view
  // shows them grey and counts a difference over 1/255 from the reference as a disagreement.
  bool shaded = false;
  explicit operator bool() const { return bool(run); }
};

// A world-coordinate window, and polylines in it.
struct Rect2 {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
using Polyline2 = std::vector<std::array<double, 2>>;
// The exact curve of the input, from its definition (not from the trace), over `window`, sampled
// about every `cell` world units.
using Outline = std::function<std::vector<Polyline2>(const Json& input, const Rect2& window, double cell)>;

}  // namespace sw
