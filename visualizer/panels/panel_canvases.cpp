// The canvases (one, or two side by side in compare view), the view tabs over them, and the
// compare strip that counts what differs between the two runs.
#include <algorithm>
#include "panels/app.hpp"
#include "panels/view_registry.hpp"

namespace sw::vis {

void App::draw_canvases(ImVec2 pos, ImVec2 size) {
  constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                      ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar |
                                      ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoTitleBar |
                                      ImGuiWindowFlags_NoBackground;  // the canvas covers it: save llvmpipe a fill
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
  ImGui::Begin("Canvas", nullptr, kFixed);
  if (!error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, theme::kError);
    ImGui::TextWrapped("Could not load: %s", error_.c_str());
    ImGui::PopStyleColor();
    if (a_ && ImGui::SmallButton("Dismiss")) error_.clear();
  }
  if (b_) draw_compare_strip();
  draw_view_tabs();
  ImVec2 avail = ImGui::GetContentRegionAvail();
  if (a_ && canvases_[0]) {
    const int n = b_ ? 2 : 1;
    const float w = (avail.x - float(n - 1) * 4) / float(n);
    const std::string label_a = compare_.other ? Comparison(numeric_, alg_).label() : std::string(numeric_name(numeric_)), label_b = compare_.label();
    for (int i = 0; i < n; ++i) {
      if (i) ImGui::SameLine(0, 4);
      ImGui::PushID(i);
      if (i) canvases_[1]->follow(*canvases_[0]);
      // Keep the step in view while playing and after each step taken, never against a pan.
      const bool follow = i == 0 && (playing_ || step_ != followed_step_);
      CanvasInput in{i ? b_ : a_, std::min(step_, (i ? b_ : a_)->last()), true, i == 0, follow, n > 1 ? (i ? label_b : label_a).c_str() : "", quiz_.on, {}};
      if (stats_ && !compare_.other) in.marked = stats_->mismatched_cells;
      const CanvasEvents ev = canvases_[i]->draw(in, ImVec2(w, avail.y));
      const Question* q = quiz_pending();
      if (ev.clicked_cell && q && q->type == QuizType::pixel) answer(Json::array({ev.clicked_cell->x, ev.clicked_cell->y}));
      else if (ev.jump_to) set_step(*ev.jump_to), playing_ = false;
      if (ev.drag) on_drag(*ev.drag);
      if (ev.edit) apply_input(*ev.edit);
      ImGui::PopID();
    }
    if (b_) canvases_[0]->follow(*canvases_[1]);  // a pan on the right canvas moves both
    followed_step_ = step_;
  } else if (error_.empty()) {
    ImGui::TextDisabled("Open a lesson or choose an algorithm above.");
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

void App::draw_view_tabs() {
  if (!alg_ || alg_->views.size() < 2) return;
  std::optional<View> chosen;
  if (ImGui::BeginTabBar("##views")) {
    for (View v : alg_->views) {
      const ViewInfo& info = view_info(v);
      if (ImGui::BeginTabItem(info.label, nullptr, v == view_ && view_tab_pending_ ? ImGuiTabItemFlags_SetSelected : 0)) {
        if (v == view_) view_tab_pending_ = false;
        else if (!view_tab_pending_) chosen = v;
        ImGui::EndTabItem();
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (V: the next view)", info.help);
    }
    ImGui::EndTabBar();
  }
  if (chosen) show_view(*chosen);
}

void App::draw_compare_strip() {
  const CompareStats& s = *stats_;
  if (compare_.other) {  // two algorithms: their results side by side (their steps do not pair up)
    auto outcome = [](const TraceModel& m) {
      const Json& r = m.result();
      if (r.is_object() && r.contains("value")) return "value " + (r["value"].is_number() ? std::to_string(r["value"].get<double>()) : r["value"].dump());
      return std::string(m.size() ? "done" : "no steps");
    };
    ImGui::Text("%s: %zu steps, %s    %s: %zu steps, %s", std::string(alg_->id).c_str(), s.steps_a, outcome(*a_).c_str(), std::string(compare_.other->id).c_str(),
                s.steps_b, outcome(*b_).c_str());
    ImGui::TextDisabled("Both run on the keys their inputs share; each one's own parameters have their own sliders.");
    return;
  }
  const std::string na(numeric_name(numeric_)), nb(numeric_name(*compare_.numeric));
  if (std::find(alg_->views.begin(), alg_->views.end(), View::plane2d) != alg_->views.end()) {
    ImGui::Text("%s: %zu steps, %zu pixels    %s: %zu steps, %zu pixels    ", na.c_str(), s.steps_a, s.pixels_a, nb.c_str(), s.steps_b, s.pixels_b);
    ImGui::SameLine();
    ImGui::TextColored(s.pixel_mismatches ? theme::kError : theme::kGood, "%zu mismatched pixels", s.pixel_mismatches);
  } else {  // no pixels to count: compare the two outcomes (hit or miss)
    auto outcome = [](const TraceModel& m) { return m.result().is_object() && m.result().contains("hit") ? (m.result()["hit"] == true ? "hit" : "miss") : "done"; };
    const std::string oa = outcome(*a_), ob = outcome(*b_);
    ImGui::Text("%s: %zu steps, %s    %s: %zu steps, %s    ", na.c_str(), s.steps_a, oa.c_str(), nb.c_str(), s.steps_b, ob.c_str());
    ImGui::SameLine();
    ImGui::TextColored(oa != ob ? theme::kError : theme::kGood, oa != ob ? "different outcomes" : "same outcome");
  }
  if (s.first_decision_divergence) {
    if (ImGui::SmallButton("Jump to first divergence")) jump_and_focus(*s.first_decision_divergence);
    ImGui::SameLine();
    ImGui::Text("step %zu: line, kind or pixel differ", *s.first_decision_divergence);
  } else {
    ImGui::TextColored(theme::kGood, "Same decisions and pixels at every step.");
  }
  if (s.first_value_divergence) {
    ImGui::SameLine(0, 24);
    if (ImGui::SmallButton("Jump to first value difference")) jump_and_focus(*s.first_value_divergence);
    ImGui::SameLine();
    ImGui::Text("step %zu", *s.first_value_divergence);
  }
}

}  // namespace sw::vis
