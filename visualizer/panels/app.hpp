// The visualizer app: a Session (lessons/session.hpp: what is open, its runs, the timeline, the
// quiz) and the UI around it (the layout, fonts, canvases, the text being typed), drawn by the
// panels (panels.hpp) with the ImGui API only. Both hosts (GLFW window, OSMesa headless) drive the
// same App; they differ only in the backend.
#pragma once
#include <array>
#include <filesystem>
#include <vector>
#include "panels/accuracy_panel.hpp"
#include "panels/panels.hpp"

namespace sw::vis {

class App {
 public:
  App(TextureHost& textures, theme::Fonts fonts, std::filesystem::path lessons_dir = default_lessons_dir());

  // What is open and everything done to it: open a lesson or an algorithm, edit, step, quiz.
  Session& session() { return session_; }
  const Session& session() const { return session_; }

  // Builds one frame of UI over the whole display (ImGui::GetIO().DisplaySize).
  void frame(float dt);
  // Something moves without input (playback): the window host redraws at full rate, else it
  // waits for events.
  bool animating() const { return session_.animating(); }

  // Goes to a step and centres the canvas on it, zoomed in enough to see single pixels.
  void jump_and_focus(std::size_t step);
  // Back to the view the open lesson or algorithm starts with, as a fresh open shows it: whatever
  // steps were taken since, session().set_step(N) then draws what `render --step N` draws (the
  // HTML export).
  void restart_view();

  // Presentation mode (P, or the toolbar's toggle): big fonts, no edit rows, no state panel.
  void set_presenting(bool on) { chrome_.presenting = on; }
  bool presenting() const { return chrome_.presenting; }
  // The Accuracy window (a short bench of the open algorithm, then its chart): shown or not.
  void set_accuracy_open(bool open) { chrome_.accuracy_open = open; }
  // The host's way to hand a file to the person (Chrome::offer_file).
  void set_file_offer(std::function<void(const std::filesystem::path&)> offer) { chrome_.offer_file = std::move(offer); }
  const AccuracyWindow& accuracy() const { return accuracy_; }

  // Test hooks: what the last frame showed.
  const Canvas* canvas(int i) const { return canvases_.canvas(i); }
  std::uint32_t highlighted_line() const { return listing_.highlighted_line(); }
  const std::vector<std::array<float, 3>>& listing_rows() const { return listing_.rows(); }
  const PanelLayout& layout() const { return layout_; }
  const DiffPlot& diff_plot() const { return diff_plot_; }
  const NarrationMarks& narration_marks() const { return narration_marks_; }

 private:
  Session session_;
  theme::Fonts base_fonts_;
  Chrome chrome_;
  PanelLayout layout_;
  Toolbar toolbar_;
  CanvasPanel canvases_;
  ListingPanel listing_;
  float timeline_content_h_ = 0;  // measured each frame, for the next
  NarrationMarks narration_marks_;
  DiffPlot diff_plot_;            // the compare view's |difference| plot (state panel)
  AccuracyWindow accuracy_;       // last: its destructor joins the bench threads first
};

}  // namespace sw::vis
