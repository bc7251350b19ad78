// The frame: keys and playback, then the panels in their places (layout.cpp), each drawing the
// session. The panels: panels.hpp.
#include "panels/app.hpp"

namespace sw::vis {

App::App(TextureHost& textures, theme::Fonts fonts, std::filesystem::path lessons_dir)
    : session_(std::move(lessons_dir)), base_fonts_(fonts), canvases_(textures) {
  chrome_.fonts = fonts;
}

void App::jump_and_focus(std::size_t step) {
  session_.jump_and_focus(step);
  canvases_.sync(session_);
}

void App::restart_view() {
  canvases_.restart();
  // The panels' measured heights too: a fresh open fits the canvas on its first frame, at the size
  // the unmeasured layout gives, and the frames after settle from there.
  toolbar_.forget_height();
  timeline_content_h_ = 0;
  listing_.restart();
  if (const Lesson* l = session_.lesson(); l && l->focus) jump_and_focus(l->start_step);
}

void App::frame(float dt) {
  handle_keys(session_, chrome_);
  session_.tick(dt);
  chrome_.fonts = chrome_.presenting ? base_fonts_.big() : base_fonts_;
  ImGui::PushFont(chrome_.fonts.body);
  // Toolbar on top, timeline at the bottom, each as tall as its rows measured last frame; canvas
  // with the narration under it on the left; the listing and the state on the right (layout.cpp).
  LayoutInput in{ImGui::GetIO().DisplaySize, ImGui::GetFontSize(), toolbar_.measured_height(), timeline_content_h_,
                 listing_.measured_height()};
  in.lesson = session_.lesson() != nullptr, in.presenting = chrome_.presenting, in.quiz = session_.quiz();
  const PanelLayout& l = layout_ = layout_panels(in);
  toolbar_.draw(session_, chrome_, l.toolbar);
  canvases_.draw(session_, chrome_, l.canvas);
  narration_marks_ = draw_narration(session_, chrome_, l.narration);
  listing_.draw(session_, chrome_, l.listing);
  if (!chrome_.presenting) draw_state(session_, diff_plot_, l.state);
  timeline_content_h_ = draw_timeline(session_, chrome_, l.timeline);
  accuracy_.draw(session_.algorithm(), &chrome_.accuracy_open);
  ImGui::PopFont();
}

}  // namespace sw::vis
