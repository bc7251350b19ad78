// The timeline: step, play, speed, scrub, jump to start/end or to the next step of a kind; the
// keys that move it. What it moves is the Session's Timeline (lessons/timeline.hpp).
#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include "panels/panels.hpp"

namespace sw::vis {

float draw_timeline(Session& s, const Chrome& c, const PanelRect& r) {
  place_next(r.pos, r.size);
  ImGui::Begin("Timeline", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar);
  const TraceModel* m = s.model(0);
  if (!m) {
    ImGui::TextDisabled("Nothing loaded.");
    ImGui::End();
    return 0;
  }
  const std::size_t last = m->last();
  // Sizes in font sizes (--scale, presentation mode); groups wrap onto a new row (flow) when the
  // window is narrow, and the panel is as tall as its rows (measured below, for the next frame).
  const float em = ImGui::GetFontSize(), gap = 1.6f * em;
  const ImVec2 b(2.9f * em, 0);
  if (ImGui::Button("|<", b)) s.go(0);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Start (Home)");
  ImGui::SameLine();
  if (ImGui::Button("<", b)) s.step_back();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Step back (Left)");
  ImGui::SameLine();
  if (ImGui::Button(s.timeline().playing() ? "Pause" : "Play", ImVec2(4.7f * em, 0))) s.toggle_playing(true);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Play or pause (Space)");
  ImGui::SameLine();
  if (ImGui::Button(">", b)) s.step_forward();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Step forward (Right)");
  ImGui::SameLine();
  if (ImGui::Button(">|", b)) s.go(last);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("End (End)");
  ImGui::SameLine();
  if (ImGui::Button("over >", ImVec2(4.7f * em, 0))) s.step_over(true);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Step over nested calls: the next step of this listing or the algorithm's (Down; Up goes back)");

  const float pad = ImGui::GetStyle().ItemSpacing.x;
  flow(ImGui::CalcTextSize("Speed 100000 steps/s").x + 2 * (1.7f * em + pad) + 2 * pad, gap);
  ImGui::TextUnformatted("Speed");
  ImGui::SameLine();
  if (ImGui::Button("-", ImVec2(1.7f * em, 0))) s.slower();
  ImGui::SameLine();
  ImGui::Text("%6g steps/s", s.timeline().speed());
  ImGui::SameLine();
  if (ImGui::Button("+", ImVec2(1.7f * em, 0))) s.faster();

  flow(ImGui::CalcTextSize("Kind < prev next >").x + 6.4f * em + 6 * pad + 4 * ImGui::GetStyle().FramePadding.x, gap);
  ImGui::TextUnformatted("Kind");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(6.4f * em);
  const StepKind seek = s.timeline().seek_kind();
  if (ImGui::BeginCombo("##kind", std::string(kind_name(seek)).c_str())) {
    for (std::size_t k = 0; k < kStepKindNames.size(); ++k)
      if (ImGui::Selectable(std::string(kStepKindNames[k]).c_str(), StepKind(k) == seek)) s.set_seek_kind(StepKind(k));
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Button("< prev")) s.seek(false);
  ImGui::SameLine();
  if (ImGui::Button("next >")) s.seek(true);
  const StepRecord& st = m->trace().at(s.step());

  // The scrub slider: a 64-bit step index, so 10^6-step traces scrub without overflow.
  ImGui::SetNextItemWidth(-1);
  std::uint64_t at = s.step(), lo = 0, hi = last;
  char format[160];  // the step, its line and kind on the slider: no row of their own
  std::snprintf(format, sizeof format, "step %%" PRIu64 " of %zu   line %u   %s", last, st.line, std::string(kind_name(st.kind)).c_str());
  if (ImGui::SliderScalar("##scrub", ImGuiDataType_U64, &at, &lo, &hi, format)) s.go(at);
  if (const auto& stats = s.compare_stats(); stats && !s.comparison().other && !s.hide_future())
    draw_divergence_ticks(ImGui::GetWindowDrawList(), stats->divergences, last, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  // The keys, for the one at the keyboard, in one row: the longest that fits (none when presenting).
  const char* keys[] = {("Space play/pause   Left/Right step   Up/Down over calls   Home/End   +/- speed   wheel or PgUp/PgDn zoom   drag or Shift+arrows pan   "
                         "F fit   P present   Ctrl+Left/Right lesson"),
                        "Space play   Left/Right step   Home/End   +/- speed   wheel zoom   drag pan   F fit   P present   Ctrl+Left/Right lesson",
                        "Space play   Left/Right step   F fit   P present"};
  for (const char* k : keys)
    if (!c.presenting && ImGui::CalcTextSize(k).x <= ImGui::GetContentRegionAvail().x) {
      ImGui::TextDisabled("%s", k);
      break;
    }
  const float h = content_height();  // the next frame's layout
  ImGui::End();
  return h;
}

// Keys, which move the timeline (playback is Session::tick).

void handle_keys(Session& s, Chrome& c) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || !s.loaded()) return;
  auto pressed = [](ImGuiKey k) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(k)); };
  if (pressed(ImGuiKey_Space)) s.toggle_playing();
  if (pressed(ImGuiKey_Escape)) c.presenting = false;
  if (io.KeyCtrl) {  // Ctrl + Left/Right: the previous or next lesson
    if (pressed(ImGuiKey_LeftArrow)) s.open_adjacent_lesson(-1);
    if (pressed(ImGuiKey_RightArrow)) s.open_adjacent_lesson(+1);
  } else if (!io.KeyShift) {  // Shift + arrows pan the canvas
    if (pressed(ImGuiKey_LeftArrow)) s.step_back();
    if (pressed(ImGuiKey_RightArrow)) s.step_forward();
    if (pressed(ImGuiKey_DownArrow)) s.step_over(true);
    if (pressed(ImGuiKey_UpArrow)) s.step_over(false);
  }
  if (pressed(ImGuiKey_Home)) s.set_step(0);
  if (pressed(ImGuiKey_End)) s.set_step(s.model(0)->last());
  for (ImWchar ch : io.InputQueueCharacters) {
    if (ch == '+' || ch == '=') s.faster();
    if (ch == '-' || ch == '_') s.slower();
    if (ch == 'p' || ch == 'P') c.presenting = !c.presenting;
    if (ch == 'v' || ch == 'V') s.next_view();  // the next declared view
    if ((ch == 'q' || ch == 'Q') && s.lesson()) s.set_quiz(!s.quiz());
  }
}

}  // namespace sw::vis
