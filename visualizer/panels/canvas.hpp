// The canvas behind a small interface, one kind per view an algorithm declares: plane2d draws the
// pixel grid and 2D geometry (pixel_canvas.cpp), orbit3d the 3D scene (orbit_canvas.cpp).
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include "panels/texture_host.hpp"
#include "lessons/trace_model.hpp"

namespace sw::vis {

// What the user did on the canvas this frame; the app acts on it.
struct CanvasEvents {
  std::optional<std::size_t> jump_to;  // clicked a plotted pixel: go to its step
  std::optional<Pixel> clicked_cell;   // clicked a cell (without dragging): a quiz answer
  struct Drag {
    int handle;       // the index of the declared handle (Algorithm::handles)
    double x, y;      // world position under the mouse
    bool released;    // the drag ended this frame
  };
  std::optional<Drag> drag;
  std::optional<Json> edit;  // the input as edited on the canvas (the 3D view's ray handles): re-run with it
};

struct CanvasInput {
  std::shared_ptr<const TraceModel> model;
  std::size_t step = 0;
  bool editable = false;   // endpoints may be dragged
  bool keys = false;       // this canvas takes the pan/zoom keys
  bool follow = false;     // keep the current step in view (while playing)
  const char* label = "";  // drawn in the corner (e.g. the number type)
  bool hide_future = false;  // quiz mode: draw and say nothing of steps after `step` (tooltips, jumps, counts)
  bool hide_sweep = false;   // quiz mode until every question is answered: no whole-sweep picture
  std::span<const Pixel> marked;  // sorted cells to outline (the compare view's mismatched pixels)
};

class Canvas {
 public:
  virtual ~Canvas() = default;
  // Draws into the current window at the cursor, filling `size`.
  virtual CanvasEvents draw(const CanvasInput& in, ImVec2 size) = 0;
  // Frames the whole trace on the next draw.
  virtual void fit() = 0;
  // Centres the view on the geometry of `step`, zooming in to at least `min_scale` px per cell.
  virtual void focus(const TraceModel&, std::size_t, double) {}
  // Shares pan and zoom with another canvas of the same kind (the compare view).
  virtual void follow(const Canvas& other) = 0;
  // Test hook: the screen rectangle (x0, y0, x1, y1) of a cell in the last drawn frame, if the
  // cell lies wholly inside the canvas.
  virtual std::optional<std::array<float, 4>> cell_rect(Pixel) const { return std::nullopt; }
};

// The canvas for a declared view (view_registry.cpp).
std::unique_ptr<Canvas> make_canvas(View view, TextureHost& textures);

}  // namespace sw::vis
