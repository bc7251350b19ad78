// The visualizer app: what is open (a lesson or an algorithm with an input and number types), the
// recorded traces, the timeline position, and the panels that draw it all with the ImGui API only.
// Both hosts (GLFW window, OSMesa headless) drive the same App; they differ only in the backend.
//
// Panels are App members, one file each: panel_toolbar.cpp, panel_timeline.cpp,
// panel_listing.cpp, panel_state.cpp, panel_narration.cpp; app.cpp holds loading and layout.
#pragma once
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include "panels/accuracy_panel.hpp"
#include "panels/canvas.hpp"
#include "lessons/compare.hpp"
#include "panels/compare_plot.hpp"
#include "panels/layout.hpp"
#include "lessons/lesson.hpp"
#include "lessons/quiz.hpp"
#include "panels/theme.hpp"
#include "lessons/trace_model.hpp"

namespace sw::vis {

class App {
 public:
  App(TextureHost& textures, theme::Fonts fonts, std::filesystem::path lessons_dir = default_lessons_dir());

  // Loading never throws: on failure it returns false, error() says why, and the app shows it.
  bool open_lesson(const std::filesystem::path& file);
  bool open_algorithm(const Algorithm& alg, const Json& input, Numeric numeric, Comparison compare = {});
  bool open_first_lesson();
  // Re-runs what is open (a lesson stays open, its narration with it) in other number types.
  bool set_numerics(Numeric numeric, Comparison compare);
  const std::string& error() const { return error_; }
  void show_error(std::string message) { error_ = std::move(message); }
  bool loaded() const { return a_ != nullptr; }
  // The work budget every run it records is held to (its max_steps; docs/cli.md).
  void set_budget(const Budget& budget) { budget_ = budget; }

  // Builds one frame of UI over the whole display (ImGui::GetIO().DisplaySize).
  void frame(float dt);

  void set_step(std::size_t step);
  std::size_t step() const { return step_; }
  std::size_t steps() const { return a_ ? a_->size() : 0; }
  void set_playing(bool p) { playing_ = p; }
  // Shows one of the open algorithm's declared views (false if it declares no such view). The
  // first declared view shows on opening; a re-run with a new input or number type keeps the view.
  bool set_view(View view);
  View view() const { return view_; }
  // Back to the view the open lesson or algorithm starts with, as a fresh open shows it: whatever
  // steps were taken since, set_step(N) then draws what `render --step N` draws (the HTML export).
  void restart_view();
  // Goes to a step and centres the canvas on it, zoomed in enough to see single pixels.
  void jump_and_focus(std::size_t step);
  // Something moves without input (playback): the window host redraws at full rate, else it
  // waits for events.
  bool animating() const { return playing_; }

  // Presentation mode (P, or the toolbar's toggle): big fonts, no edit rows, no state panel.
  void set_presenting(bool on) { presenting_ = on; }
  bool presenting() const { return presenting_; }
  // The lessons of the manifest by title (a file that fails to load shows its name and the error),
  // read once on first use (lesson_menu.cpp).
  const std::vector<std::string>& lesson_titles();
  // Opens the lesson `delta` places after the current one in manifest order (the first with none
  // open); false at either end or if it fails to load (error() says why).
  bool open_adjacent_lesson(int delta);

  // Quiz mode (a lesson only): the run switches to the quiz's exact number type, stepping forward
  // stops at each question until it is answered, and the future is hidden (docs/lessons.md).
  bool set_quiz(bool on);
  bool quiz() const { return quiz_.on; }
  // The question waiting at the current step, if any.
  const Question* quiz_pending() const;
  // Answers it (throws InputError for an answer of the wrong form); the grade, or nullopt if none waits.
  std::optional<Grade> answer(const Json& answer);
  // Right answers, answers.
  std::pair<int, int> quiz_score() const;

  const Lesson* lesson() const { return lesson_ ? &*lesson_ : nullptr; }

  // Test hooks: what the last frame showed.
  std::uint32_t highlighted_line() const { return highlighted_line_; }
  // Test hook: the screen rows of the listing as last drawn: left x, top y, bottom y per line.
  const std::vector<std::array<float, 3>>& listing_rows() const { return listing_rows_; }
  const Canvas* canvas(int i) const { return canvases_[i].get(); }
  const TraceModel* model(int i) const { return (i == 0 ? a_ : b_).get(); }
  const std::optional<CompareStats>& compare_stats() const { return stats_; }
  // Test hook: the panels' places in the last frame.
  const PanelLayout& layout() const { return layout_; }
  // The Accuracy window (a short bench of the open algorithm, then its chart): shown or not.
  void set_accuracy_open(bool open) { accuracy_open_ = open; }
  const AccuracyWindow& accuracy() const { return accuracy_; }
  const DiffPlot& diff_plot() const { return diff_plot_; }

 private:
  // Records the run(s); on failure returns the message and leaves the open run as it was.
  std::string load(const Algorithm& alg, const Json& input, Numeric numeric, Comparison compare, bool keep_view);
  bool rerun_with_input(const Json& input);  // keeps the relative timeline position
  void apply_input(const Json& input);        // from the edit fields; errors go to edit_error_
  void rerun_numerics(Numeric numeric, Comparison compare);
  void apply_other_input(const Json& other_input);  // the other algorithm's own sliders
  // The sliders of the declared params the input has; pointer keys in `skip` are left out.
  bool draw_param_sliders(const Algorithm& alg, Json& input, const char* prefix, const Json* skip);
  void on_drag(const CanvasEvents::Drag& d);
  void fill_endpoint_fields();
  void handle_keys();
  void advance_playback(float dt);
  void step_over(bool forward);  // Down/Up and the "over >" button: past nested calls

  void draw_toolbar(ImVec2 pos, ImVec2 size);
  void draw_menu_bar();      // lesson_menu.cpp
  bool has_sliders() const;  // the toolbar has a third row
  void draw_canvases(ImVec2 pos, ImVec2 size);
  void draw_compare_strip();
  void draw_timeline(ImVec2 pos, ImVec2 size);
  void draw_listing(ImVec2 pos, ImVec2 size);
  void draw_state(ImVec2 pos, ImVec2 size);
  void draw_narration(ImVec2 pos, ImVec2 size);
  void draw_quiz();  // the waiting question's prompt, answer buttons and feedback (panel_quiz.cpp)
  void draw_markdown(const std::string& text);

  TextureHost* textures_;
  theme::Fonts base_fonts_, fonts_;  // fonts_: this frame's, the big ones when presenting
  std::filesystem::path lessons_dir_;
  std::vector<std::filesystem::path> lessons_;
  std::string lessons_error_;
  std::vector<std::string> lesson_titles_;  // by lesson_titles(), once
  std::optional<std::size_t> lesson_pos_;   // the manifest entry last opened (or tried)
  bool presenting_ = false;
  PanelLayout layout_;
  float toolbar_content_h_ = 0, timeline_content_h_ = 0;  // measured each frame, for the next
  std::size_t followed_step_ = ~std::size_t(0);           // the step the canvas last kept in view

  // What is open.
  std::optional<Lesson> lesson_;
  const Algorithm* alg_ = nullptr;
  Json input_;
  Numeric numeric_ = Numeric::exact;
  Comparison compare_;
  Budget budget_;
  Json other_input_;  // the other algorithm's input, when compare_.other
  std::optional<std::pair<std::string, float>> slider_drag_;  // a slider held in the image view: its id, value
  std::shared_ptr<const TraceModel> a_, b_;
  std::optional<CompareStats> stats_;
  std::array<std::unique_ptr<Canvas>, 2> canvases_;  // the view now shown: main and compare
  View view_ = View::plane2d;  // the canvas kind now shown
  // The other views' canvases, kept (with their pan and zoom) while another view shows.
  std::array<std::array<std::unique_ptr<Canvas>, 2>, kViewNames.size()> stashed_;
  bool view_tab_pending_ = false;  // the view changed outside the tabs: select its tab
  void show_view(View view);
  void draw_view_tabs();

  struct QuizState {
    bool on = false;
    std::vector<Question> questions;  // on the quiz run, by step
    struct Answered {
      std::size_t step;
      Grade grade;
      std::string answer;
    };
    std::vector<Answered> answered;
  } quiz_;
  const QuizState::Answered* quiz_answered(std::size_t step) const;
  // Stops a forward move at the first unanswered question in [step_, target); returns where to go.
  std::size_t quiz_gate(std::size_t target);

  // Timeline.
  std::size_t step_ = 0;
  bool playing_ = false;
  int speed_ = 3;        // index into kSpeeds
  double carry_ = 0;     // fractional steps of playback
  int seek_kind_ = int(StepKind::plot);

  // Messages and edit fields.
  std::string error_, edit_error_;
  std::vector<std::array<std::string, 2>> handle_text_;  // the declared 2D handles' x and y, as typed
  std::string json_text_;
  std::uint32_t highlighted_line_ = 0;
  std::vector<std::array<float, 3>> listing_rows_;
  std::size_t listing_scrolled_to_ = ~std::size_t(0);
  int listing_scroll_frames_ = 0;  // frames left to keep the current line centred
  static constexpr float kUnmeasuredListingH = 300;
  float listing_content_h_ = kUnmeasuredListingH;  // the listing's full height, measured each frame
  DiffPlot diff_plot_;              // the compare view's |difference| plot (state panel)
  bool accuracy_open_ = false;
  AccuracyWindow accuracy_;         // last: its destructor joins the bench threads first
};

// Playback speeds in steps per second, chosen with +/-.
inline constexpr std::array<double, 14> kSpeeds = {1, 2, 4, 8, 15, 30, 60, 120, 250, 500, 1000, 5000, 25000, 100000};

}  // namespace sw::vis
