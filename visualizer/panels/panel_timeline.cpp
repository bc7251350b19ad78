// The timeline: step, play, speed, scrub, jump to start/end or to the next step of a kind; the keys
// and the playback that move it.
#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include "panels/app.hpp"

namespace sw::vis {

void App::draw_timeline(ImVec2 pos, ImVec2 size) {
  place_next(pos, size);
  ImGui::Begin("Timeline", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar);
  if (!a_) {
    ImGui::TextDisabled("Nothing loaded.");
    ImGui::End();
    return;
  }
  const std::size_t last = a_->last();
  // Sizes in font sizes (--scale, presentation mode); groups wrap onto a new row (flow) when the
  // window is narrow, and the panel is as tall as its rows (measured below, for the next frame).
  const float em = ImGui::GetFontSize(), gap = 1.6f * em;
  const ImVec2 b(2.9f * em, 0);
  if (ImGui::Button("|<", b)) set_step(0), playing_ = false;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Start (Home)");
  ImGui::SameLine();
  if (ImGui::Button("<", b) && step_ > 0) set_step(step_ - 1), playing_ = false;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Step back (Left)");
  ImGui::SameLine();
  if (ImGui::Button(playing_ ? "Pause" : "Play", ImVec2(4.7f * em, 0))) {
    if (!playing_ && step_ >= last) set_step(0);
    playing_ = !playing_, carry_ = 0;
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Play or pause (Space)");
  ImGui::SameLine();
  if (ImGui::Button(">", b)) set_step(step_ + 1), playing_ = false;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Step forward (Right)");
  ImGui::SameLine();
  if (ImGui::Button(">|", b)) set_step(last), playing_ = false;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("End (End)");
  ImGui::SameLine();
  if (ImGui::Button("over >", ImVec2(4.7f * em, 0))) step_over(true);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Step over nested calls: the next step of this listing or the algorithm's (Down; Up goes back)");

  const float pad = ImGui::GetStyle().ItemSpacing.x;
  flow(ImGui::CalcTextSize("Speed 100000 steps/s").x + 2 * (1.7f * em + pad) + 2 * pad, gap);
  ImGui::TextUnformatted("Speed");
  ImGui::SameLine();
  if (ImGui::Button("-", ImVec2(1.7f * em, 0))) speed_ = std::max(speed_ - 1, 0);
  ImGui::SameLine();
  ImGui::Text("%6g steps/s", kSpeeds[speed_]);
  ImGui::SameLine();
  if (ImGui::Button("+", ImVec2(1.7f * em, 0))) speed_ = std::min<int>(speed_ + 1, int(kSpeeds.size()) - 1);

  flow(ImGui::CalcTextSize("Kind < prev next >").x + 6.4f * em + 6 * pad + 4 * ImGui::GetStyle().FramePadding.x, gap);
  ImGui::TextUnformatted("Kind");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(6.4f * em);
  if (ImGui::BeginCombo("##kind", std::string(kind_name(StepKind(seek_kind_))).c_str())) {
    for (std::size_t k = 0; k < kStepKindNames.size(); ++k)
      if (ImGui::Selectable(std::string(kStepKindNames[k]).c_str(), int(k) == seek_kind_)) seek_kind_ = int(k);
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Button("< prev")) {
    if (auto s = a_->find_kind(step_, StepKind(seek_kind_), false)) set_step(*s), playing_ = false;
  }
  ImGui::SameLine();
  if (ImGui::Button("next >")) {
    if (auto s = a_->find_kind(step_, StepKind(seek_kind_), true)) set_step(*s), playing_ = false;
  }
  const StepRecord& st = a_->trace().at(step_);

  // The scrub slider: a 64-bit step index, so 10^6-step traces scrub without overflow.
  ImGui::SetNextItemWidth(-1);
  std::uint64_t s = step_, lo = 0, hi = last;
  char format[160];  // the step, its line and kind on the slider: no row of their own
  std::snprintf(format, sizeof format, "step %%" PRIu64 " of %zu   line %u   %s", last, st.line, std::string(kind_name(st.kind)).c_str());
  if (ImGui::SliderScalar("##scrub", ImGuiDataType_U64, &s, &lo, &hi, format)) set_step(s), playing_ = false;
  if (stats_ && !compare_.other) draw_divergence_ticks(ImGui::GetWindowDrawList(), stats_->divergences, last, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  // The keys, for the one at the keyboard, in one row: the longest that fits (none when presenting).
  const char* keys[] = {("Space play/pause   Left/Right step   Up/Down over calls   Home/End   +/- speed   wheel or PgUp/PgDn zoom   drag or Shift+arrows pan   "
                         "F fit   P present   Ctrl+Left/Right lesson"),
                        "Space play   Left/Right step   Home/End   +/- speed   wheel zoom   drag pan   F fit   P present   Ctrl+Left/Right lesson",
                        "Space play   Left/Right step   F fit   P present"};
  for (const char* k : keys)
    if (!presenting_ && ImGui::CalcTextSize(k).x <= ImGui::GetContentRegionAvail().x) {
      ImGui::TextDisabled("%s", k);
      break;
    }
  timeline_content_h_ = content_height();  // the next frame's layout
  ImGui::End();
}

// Keys and playback, which move the timeline.

void App::handle_keys() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || !a_) return;
  auto pressed = [](ImGuiKey k) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(k)); };
  if (pressed(ImGuiKey_Space)) playing_ = !playing_, carry_ = 0;
  if (pressed(ImGuiKey_Escape)) presenting_ = false;
  if (io.KeyCtrl) {  // Ctrl + Left/Right: the previous or next lesson
    if (pressed(ImGuiKey_LeftArrow)) open_adjacent_lesson(-1);
    if (pressed(ImGuiKey_RightArrow)) open_adjacent_lesson(+1);
  } else if (!io.KeyShift) {  // Shift + arrows pan the canvas
    if (pressed(ImGuiKey_LeftArrow) && step_ > 0) set_step(step_ - 1), playing_ = false;
    if (pressed(ImGuiKey_RightArrow)) set_step(step_ + 1), playing_ = false;
    if (pressed(ImGuiKey_DownArrow)) step_over(true);
    if (pressed(ImGuiKey_UpArrow)) step_over(false);
  }
  if (pressed(ImGuiKey_Home)) set_step(0);
  if (pressed(ImGuiKey_End)) set_step(a_->last());
  for (ImWchar ch : io.InputQueueCharacters) {
    if (ch == '+' || ch == '=') speed_ = std::min<int>(speed_ + 1, int(kSpeeds.size()) - 1);
    if (ch == '-' || ch == '_') speed_ = std::max(speed_ - 1, 0);
    if (ch == 'p' || ch == 'P') presenting_ = !presenting_;
    if ((ch == 'v' || ch == 'V') && alg_ && alg_->views.size() > 1) {  // the next declared view
      const auto it = std::find(alg_->views.begin(), alg_->views.end(), view_);
      set_view(it == alg_->views.end() || it + 1 == alg_->views.end() ? alg_->views.front() : *(it + 1));
    }
    if ((ch == 'q' || ch == 'Q') && lesson_) set_quiz(!quiz_.on);
  }
}

void App::step_over(bool forward) {
  if (!a_) return;
  if (const auto s = a_->step_over(step_, forward)) set_step(*s);
  playing_ = false;
}

void App::advance_playback(float dt) {
  if (!playing_ || !a_) return;
  // The window host sleeps while idle: the first frame after a wake-up may report a long dt.
  carry_ += double(std::min(dt, 0.1f)) * kSpeeds[speed_];
  const double whole = std::floor(carry_);
  carry_ -= whole;
  set_step(step_ + static_cast<std::size_t>(whole));
  if (step_ >= a_->last()) playing_ = false;
}

}  // namespace sw::vis
