// The timeline: step, play, speed, scrub, jump to start/end or to the next step of a kind.
#include <cinttypes>
#include "app.hpp"

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
  const ImVec2 b(44, 0);
  if (ImGui::Button("|<", b)) set_step(0), playing_ = false;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Start (Home)");
  ImGui::SameLine();
  if (ImGui::Button("<", b) && step_ > 0) set_step(step_ - 1), playing_ = false;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Step back (Left)");
  ImGui::SameLine();
  if (ImGui::Button(playing_ ? "Pause" : "Play", ImVec2(70, 0))) {
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

  ImGui::SameLine(0, 24);
  ImGui::TextUnformatted("Speed");
  ImGui::SameLine();
  if (ImGui::Button("-", ImVec2(26, 0))) speed_ = std::max(speed_ - 1, 0);
  ImGui::SameLine();
  ImGui::Text("%6g steps/s", kSpeeds[speed_]);
  ImGui::SameLine();
  if (ImGui::Button("+", ImVec2(26, 0))) speed_ = std::min<int>(speed_ + 1, int(kSpeeds.size()) - 1);

  ImGui::SameLine(0, 24);
  ImGui::TextUnformatted("Kind");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(96);
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
  ImGui::SameLine(0, 24);
  ImGui::Text("step %zu of %zu   line %u   %s", step_, last, st.line, std::string(kind_name(st.kind)).c_str());

  // The scrub slider: a 64-bit step index, so 10^6-step traces scrub without overflow.
  ImGui::SetNextItemWidth(-1);
  std::uint64_t s = step_, lo = 0, hi = last;
  if (ImGui::SliderScalar("##scrub", ImGuiDataType_U64, &s, &lo, &hi, "step %" PRIu64)) set_step(s), playing_ = false;
  if (stats_ && !compare_.other) draw_divergence_ticks(ImGui::GetWindowDrawList(), stats_->divergences, last, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  ImGui::TextDisabled("Space play/pause   Left/Right step   Home/End   +/- speed   wheel or PgUp/PgDn zoom   drag or Shift+arrows pan   F fit");
  ImGui::End();
}

}  // namespace sw::vis
