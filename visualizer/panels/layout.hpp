// The app's panel layout from the display size and what the panels measured last frame, in units
// of the font size (em), so that it holds from 1024x640 to 2560x1440 at any --scale and in
// presentation mode. Pure arithmetic: tests check it without GL.
#pragma once
#include <imgui.h>

namespace sw::vis {

struct PanelRect {
  ImVec2 pos, size;
  float right() const { return pos.x + size.x; }
  float bottom() const { return pos.y + size.y; }
};

struct LayoutInput {
  ImVec2 display;
  float em = 15;                // the body font's size
  float toolbar_h = 0;          // the toolbar's content height, measured last frame (0: not yet)
  float timeline_h = 0;         // the timeline's, likewise
  float listing_content_h = 0;  // the listing's full height
  bool lesson = false;          // a lesson is open: the narration gets more room
  bool presenting = false;      // presentation mode: no state panel, more narration
  bool quiz = false;            // quiz mode: room for the question and its buttons too
};

struct PanelLayout {
  float em = 15;                                                   // the font size it was laid out for
  PanelRect toolbar, canvas, narration, listing, state, timeline;  // state is empty when presenting
};

PanelLayout layout_panels(const LayoutInput& in);

// Throws InputError (one line naming it) unless theme::kMinScale <= scale <= theme::kMaxScale.
void check_scale(double scale);

// The current window's content height so far (to its lowest item, plus the bottom padding):
// what a panel sized to its rows needs.
float content_height();

// Continues the row when an item `width` wide still fits before the window's right edge, else
// starts a new row: toolbar rows wrap instead of running off a narrow window.
void flow(float width, float gap = -1);

}  // namespace sw::vis
