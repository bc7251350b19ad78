// What an algorithm declares for the visualizer's views: the view kinds, the sweep grid that fills
// image views and what a sweep offers. Specs declare them (register.hpp fills the entry); the run
// handle (run.hpp) computes them.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
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

// What an algorithm's sweep (the image view's grid, or the lobe view's row of directions) offers;
// the values come from Run::sweep / Run::lobe.
struct SweepInfo {
  bool present = false;  // the algorithm has this sweep
  // The values are intensities in [0, 1] (a shaded picture), not distances along a ray: the view
  // shows them grey and counts a difference over 1/255 from the reference as a disagreement.
  bool shaded = false;
  bool marker = false;   // Run::sweep_marker: where the input itself lies in the frame
  bool sample = false;   // Run::sweep_sample / lobe_sample: a sample's input as JSON (a click opens it)
  bool angles = false;   // Run::lobe_angles: the light's and the eye's angles in the swept plane
  std::string_view caption;  // what a sample is, for the view's legend
  explicit operator bool() const { return present; }
};

// A picture of the input (the scene view's: a ray tracer's scene rendered once, through each
// pixel's centre), at most max_side pixels on a side: a picture pixel covers scale x scale pixels
// of the input's own image. Its notes say how it was made (the planner's decisions: each effect
// on or off, and why).
struct Picture {
  std::int64_t width = 0, height = 0, scale = 1;
  std::vector<std::uint8_t> rgb;  // 8-bit rows, top first
  double seconds = 0;             // how long it took
  struct Note {
    std::string text, why;
    std::optional<bool> on;  // an effect turned on or off; none: a remark
  };
  std::string notes_title;  // "Planner"
  std::vector<Note> notes;
  // A second image of the same size in grey levels, one byte a pixel (a rasterized picture's depth
  // buffer), shown under the notes with its caption; empty for none.
  std::vector<std::uint8_t> grey;
  std::string grey_caption;
};

// What an algorithm's picture offers (Run::picture): a click on picture pixel (i, j) sets the
// input at the JSON pointer `pick` to [i, j] (in the input's own pixels), and the view frames the
// pixel the input has there.
struct PictureInfo {
  bool present = false;
  std::string_view pick;  // "/pixel"; empty: a click picks nothing
  explicit operator bool() const { return present; }
};

// A table computed from a recorded trace (Run::summary_table; the ray tree of a pixel's history): a row
// per item with the steps it spans (a click goes to `step`; the current row is the last whose span
// holds the current step; rows not begun yet are dimmed), cells of text and colour, and a total.
struct SummaryTable {
  struct Cell {
    std::string text;
    std::optional<std::array<double, 3>> rgb;  // a colour: a swatch, before the text
  };
  struct Row {
    std::size_t step = 0, end = 0;
    std::vector<Cell> cells;  // one per column
  };
  std::string title;  // "Ray tree"
  std::vector<std::string> columns;
  std::vector<Row> rows;
  std::optional<Row> total;
};

// A world-coordinate window, and polylines in it.
struct Rect2 {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
using Polyline2 = std::vector<std::array<double, 2>>;

}  // namespace sw
