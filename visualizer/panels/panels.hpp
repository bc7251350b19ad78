// The App's panels, each a function of the Session (lessons/session.hpp) and of the UI state it
// keeps itself (text being typed, canvases with their pan and zoom, measured heights). They draw
// with the ImGui API only; what they change goes to the Session. One file each: panel_toolbar.cpp
// (and lesson_menu.cpp, its menu bar), panel_canvases.cpp, panel_timeline.cpp (and the keys),
// panel_listing.cpp, panel_state.cpp, panel_narration.cpp (and panel_quiz.cpp).
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>
#include "lessons/session.hpp"
#include "panels/canvas.hpp"
#include "panels/compare_plot.hpp"
#include "panels/layout.hpp"
#include "panels/theme.hpp"

namespace sw::vis {

// The UI's own state that several panels share; none of it is the session's.
struct Chrome {
  theme::Fonts fonts;       // this frame's: the big ones when presenting
  bool presenting = false;  // presentation mode (P): big fonts, no edit rows, no state panel
  bool accuracy_open = false;
  bool fit = false;  // "Fit view" (toolbar, View menu): the canvas panel fits on its next draw
  // Where the host can hand a file to the person (the browser: a download), the quiz panel
  // offers the saved answers through it; none on the desktop, where they are a file already.
  std::function<void(const std::filesystem::path&)> offer_file;
};

// The toolbar: the menu bar, the algorithm and number types, the input's fields (exact x and y
// per declared 2D handle, else the JSON) and the sliders of its declared parameters.
class Toolbar {
 public:
  void draw(Session& s, Chrome& c, const PanelRect& r);
  float measured_height() const { return content_h_; }  // for the next frame's layout
  void forget_height() { content_h_ = 0; }

 private:
  void refill(const Session& s);  // the fields from the input the session now has
  void draw_input_row(Session& s, float em, float gap);
  bool has_sliders(const Session& s) const;
  // The sliders of the declared params the input has; pointer keys in `skip` are left out.
  bool draw_param_sliders(const Session& s, const Algorithm& alg, Json& input, const char* prefix, const Json* skip);

  std::uint64_t filled_ = ~std::uint64_t(0);             // the Session::loads() the fields were filled at
  std::vector<std::array<std::string, 2>> handle_text_;  // the declared 2D handles' x and y, as typed
  std::string json_text_;
  std::optional<std::pair<std::string, float>> slider_drag_;  // a slider held in the image view: its id, value
  float content_h_ = 0;
};

// The Lesson and View menus and the lesson's place, in the toolbar's menu bar (lesson_menu.cpp).
void draw_menu_bar(Session& s, Chrome& c);

// The canvases of the view shown (one, or two side by side in compare view), the view tabs over
// them and the compare strip. Each view keeps its own canvases, with their pan and zoom.
class CanvasPanel {
 public:
  explicit CanvasPanel(TextureHost& textures) : textures_(&textures) {}
  // Brings the canvases up to the session: the view's canvases, fitted after a fresh open, and
  // centred on the step the session asked to focus.
  void sync(Session& s);
  void draw(Session& s, Chrome& c, const PanelRect& r);
  void fit();      // frames the trace on the next draw
  void restart();  // fits, and keeps the next step in view afresh
  const Canvas* canvas(int i) const { return canvases_[std::size_t(i)].get(); }

 private:
  void show(View view);
  void draw_tabs(Session& s);
  void draw_compare_strip(Session& s);

  TextureHost* textures_;
  std::array<std::unique_ptr<Canvas>, 2> canvases_;  // the view now shown: main and compare
  View view_ = View::plane2d;
  // The other views' canvases, kept (with their pan and zoom) while another view shows.
  std::array<std::array<std::unique_ptr<Canvas>, 2>, kViewNames.size()> stashed_;
  std::uint64_t opens_ = 0, view_requests_ = 0;  // the session's counters last seen
  bool tab_pending_ = false;                     // the view changed outside the tabs: select its tab
  std::size_t followed_step_ = ~std::size_t(0);  // the step the canvas last kept in view
};

// The timeline: start, back, play, forward, end, step over, speed, seek by kind, the scrub slider
// and the keys. Returns its content height, for the next frame's layout.
float draw_timeline(Session& s, const Chrome& c, const PanelRect& r);
// The keys that move the timeline, switch views and lessons, present and quiz.
void handle_keys(Session& s, Chrome& c);

// The listing: the algorithm's pseudocode (or the callee's, inside a nested call), the current
// step's line highlighted and kept centred.
class ListingPanel {
 public:
  void draw(const Session& s, const Chrome& c, const PanelRect& r);
  void restart() { scrolled_to_ = ~std::size_t(0), content_h_ = kUnmeasured; }
  float measured_height() const { return content_h_; }
  // Test hooks: the line highlighted in the last frame, and each listing row's left x, top y and
  // bottom y on screen.
  std::uint32_t highlighted_line() const { return highlighted_; }
  const std::vector<std::array<float, 3>>& rows() const { return rows_; }

 private:
  static constexpr float kUnmeasured = 300;
  std::uint32_t highlighted_ = 0;
  std::vector<std::array<float, 3>> rows_;
  std::size_t scrolled_to_ = ~std::size_t(0);
  int scroll_frames_ = 0;          // frames left to keep the current line centred
  float content_h_ = kUnmeasured;  // the listing's full height, measured each frame
};

// The state panel: every variable at the step; in compare view both runs, their difference and
// the |difference| plot.
void draw_state(Session& s, DiffPlot& plot, const PanelRect& r);

// A widget drawn this frame (a button, a text field): its label and screen rectangle (x0, y0, x1, y1).
struct WidgetMark {
  std::string label;
  std::array<float, 4> rect;
};
// The narration: the lesson's title, the quiz (panel_quiz.cpp) when on, the section each run shows
// at the step, then the intro; with no lesson, the algorithm's summary. Returns where the step's
// own text starts and where the quiz ends, in screen y (NaN for what is not drawn).
struct NarrationMarks {
  float text_y = NAN, quiz_bottom = NAN;
  std::vector<WidgetMark> quiz_widgets;  // the quiz panel's answer and download buttons, its name field
};
NarrationMarks draw_narration(Session& s, const Chrome& c, const PanelRect& r);
// The quiz panel; its buttons and fields go to *marks.
void draw_quiz(Session& s, const Chrome& c, std::vector<WidgetMark>* marks);
// Narration Markdown (lessons/markdown.hpp), laid out word by word.
void draw_markdown(const std::string& text, const theme::Fonts& fonts);

}  // namespace sw::vis
