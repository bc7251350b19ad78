// The canvases (one, or two side by side in compare view), the view tabs over them, and the
// compare strip that counts what differs between the two runs. The canvases follow the Session:
// its view, its fresh opens (fit) and the steps it asks to focus on.
#include <algorithm>
#include "lessons/result_keys.hpp"
#include "panels/panels.hpp"
#include "panels/view_registry.hpp"

namespace sw::vis {

void CanvasPanel::show(View view) {
  if (view != view_ && canvases_[0]) stashed_[static_cast<std::size_t>(view_)] = std::move(canvases_);
  if (view != view_ || !canvases_[0]) {
    view_ = view;
    canvases_ = std::move(stashed_[static_cast<std::size_t>(view)]);
    for (auto& c : canvases_)
      if (!c) c = make_canvas(view_, *textures_);
  }
}

void CanvasPanel::sync(Session& s) {
  if (!s.loaded()) return;
  if (s.view_requests() != view_requests_) view_requests_ = s.view_requests(), tab_pending_ = true;
  if (s.opens() != opens_) {  // a fresh open: every view frames the new trace
    opens_ = s.opens();
    for (auto& pair : stashed_)
      for (auto& c : pair)
        if (c) c->fit();
    show(s.view());
    canvases_[0]->fit();
  }
  show(s.view());
  if (const auto step = s.take_focus()) canvases_[0]->focus(*s.model(0), *step, 24.0);
}

void CanvasPanel::fit() {
  if (canvases_[0]) canvases_[0]->fit();
}

void CanvasPanel::restart() {
  for (auto& c : canvases_)
    if (c) c->fit();
  followed_step_ = ~std::size_t(0);
}

void CanvasPanel::draw(Session& s, Chrome& chrome, const PanelRect& r) {
  constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                      ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar |
                                      ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoTitleBar |
                                      ImGuiWindowFlags_NoBackground;  // the canvas covers it: save llvmpipe a fill
  sync(s);
  if (std::exchange(chrome.fit, false)) fit();
  ImGui::SetNextWindowPos(r.pos);
  ImGui::SetNextWindowSize(r.size);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
  ImGui::Begin("Canvas", nullptr, kFixed);
  if (!s.error().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, theme::kError);
    ImGui::TextWrapped("Could not load: %s", s.error().c_str());
    ImGui::PopStyleColor();
    if (s.loaded() && ImGui::SmallButton("Dismiss")) s.dismiss_error();
  }
  if (s.model(1) && !s.hide_future()) draw_compare_strip(s);  // its counts and jumps tell the future
  draw_tabs(s);
  sync(s);  // the strip's jumps and the tabs
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  if (s.loaded() && canvases_[0]) {
    const int n = s.model(1) ? 2 : 1;
    const float w = (avail.x - float(n - 1) * 4) / float(n);
    const Comparison& cmp = s.comparison();
    const std::string label_a = cmp.other ? Comparison(s.numeric(), s.algorithm()).label() : s.run_name(0), label_b = s.run_name(1);
    for (int i = 0; i < n; ++i) {
      const std::shared_ptr<const TraceModel> model = s.model_ptr(i);  // an edit on the left re-records both
      if (!model) break;
      if (i) ImGui::SameLine(0, 4);
      ImGui::PushID(i);
      if (i) canvases_[1]->follow(*canvases_[0]);
      // Keep the step in view while playing and after each step taken, never against a pan.
      const bool follow = i == 0 && (s.timeline().playing() || s.step() != followed_step_);
      CanvasInput in{model, std::min(s.shown_step(), model->last()), true, i == 0, follow, n > 1 ? (i ? label_b : label_a).c_str() : "",
                     s.hide_future(), s.hide_sweep(), {}};
      if (s.compare_stats() && !cmp.other && !s.hide_future()) in.marked = s.compare_stats()->mismatched_cells;
      const CanvasEvents ev = canvases_[std::size_t(i)]->draw(in, ImVec2(w, avail.y));
      const Question* q = s.quiz_pending();
      if (ev.clicked_cell && q && q->type == QuizType::pixel) s.answer(Json::array({ev.clicked_cell->x, ev.clicked_cell->y}));
      else if (ev.jump_to) s.go(*ev.jump_to);
      if (ev.drag) s.drag_handle(ev.drag->handle, ev.drag->x, ev.drag->y);
      if (ev.edit) s.apply_input(*ev.edit);
      ImGui::PopID();
    }
    if (s.model(1) && canvases_[1]) canvases_[0]->follow(*canvases_[1]);  // a pan on the right canvas moves both
    followed_step_ = s.step();
  } else if (s.error().empty()) {
    ImGui::TextDisabled("Open a lesson or choose an algorithm above.");
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

void CanvasPanel::draw_tabs(Session& s) {
  const Algorithm* alg = s.algorithm();
  if (!alg || alg->views.size() < 2) return;
  std::optional<View> chosen;
  if (ImGui::BeginTabBar("##views")) {
    for (View v : alg->views) {
      const ViewInfo& info = view_info(v);
      if (ImGui::BeginTabItem(info.label, nullptr, v == view_ && tab_pending_ ? ImGuiTabItemFlags_SetSelected : 0)) {
        if (v == view_) tab_pending_ = false;
        else if (!tab_pending_) chosen = v;
        ImGui::EndTabItem();
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (V: the next view)", info.help);
    }
    ImGui::EndTabBar();
  }
  if (chosen && s.set_view(*chosen)) view_requests_ = s.view_requests();  // chosen here: no tab to select
}

void CanvasPanel::draw_compare_strip(Session& s) {
  const CompareStats& st = *s.compare_stats();
  const Comparison& cmp = s.comparison();
  const TraceModel &a = *s.model(0), &b = *s.model(1);
  if (cmp.other) {  // two algorithms: their results side by side (their steps do not pair up)
    auto outcome = [](const TraceModel& m) {
      if (const Json* v = read_result(m, result_reads::strip_value)) return "value " + (v->is_number() ? std::to_string(v->get<double>()) : v->dump());
      return std::string(m.size() ? "done" : "no steps");
    };
    ImGui::Text("%s: %zu steps, %s    %s: %zu steps, %s", std::string(s.algorithm()->id).c_str(), st.steps_a, outcome(a).c_str(), std::string(cmp.other->id).c_str(),
                st.steps_b, outcome(b).c_str());
    ImGui::TextDisabled("Both run on the keys their inputs share; each one's own parameters have their own sliders.");
    return;
  }
  const std::string na = s.run_name(0), nb = s.run_name(1);
  const auto& views = s.algorithm()->views;
  if (std::find(views.begin(), views.end(), View::plane2d) != views.end()) {
    ImGui::Text("%s: %zu steps, %zu pixels    %s: %zu steps, %zu pixels    ", na.c_str(), st.steps_a, st.pixels_a, nb.c_str(), st.steps_b, st.pixels_b);
    ImGui::SameLine();
    ImGui::TextColored(st.pixel_mismatches ? theme::kError : theme::kGood, "%zu mismatched pixels", st.pixel_mismatches);
  } else {  // no pixels to count: compare the two outcomes (hit or miss, where the results say)
    auto outcome = [](const TraceModel& m) {
      const Json* hit = read_result(m, result_reads::strip_hit);
      return hit ? (*hit == true ? "hit" : "miss") : "done";
    };
    const std::string oa = outcome(a), ob = outcome(b);
    ImGui::Text("%s: %zu steps, %s    %s: %zu steps, %s    ", na.c_str(), st.steps_a, oa.c_str(), nb.c_str(), st.steps_b, ob.c_str());
    ImGui::SameLine();
    ImGui::TextColored(oa != ob ? theme::kError : theme::kGood, oa != ob ? "different outcomes" : "same outcome");
  }
  if (st.first_decision_divergence) {
    if (ImGui::SmallButton("Jump to first divergence")) s.jump_and_focus(*st.first_decision_divergence);
    ImGui::SameLine();
    ImGui::Text("step %zu: line, kind or pixel differ", *st.first_decision_divergence);
  } else {
    ImGui::TextColored(theme::kGood, "Same decisions and pixels at every step.");
  }
  if (st.first_value_divergence) {
    ImGui::SameLine(0, 24);
    if (ImGui::SmallButton("Jump to first value difference")) s.jump_and_focus(*st.first_value_divergence);
    ImGui::SameLine();
    ImGui::Text("step %zu", *st.first_value_divergence);
  }
}

}  // namespace sw::vis
