// The toolbar: what is open (lesson, algorithm, number types) and the exact input endpoints.
#include "app.hpp"  // before imgui_stdlib.h, which needs imgui.h first
#include <imgui_stdlib.h>

namespace sw::vis {
namespace {

std::string numeric_label(Numeric n) { return std::string(numeric_name(n)); }

}  // namespace

void App::draw_toolbar(ImVec2 pos, ImVec2 size) {
  place_next(pos, size);
  ImGui::Begin("Toolbar", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
  // Row 1: lesson, algorithm, number types.
  ImGui::TextUnformatted("Lesson");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(300);
  const std::string current_lesson = lesson_ ? lesson_->title : std::string("(none)");
  if (ImGui::BeginCombo("##lesson", current_lesson.c_str())) {
    if (!lessons_error_.empty()) ImGui::TextColored(theme::kError, "%s", lessons_error_.c_str());
    for (const auto& path : lessons_)
      if (ImGui::Selectable(path.filename().string().c_str(), lesson_ && lesson_->path == path)) open_lesson(path);
    ImGui::EndCombo();
  }
  ImGui::SameLine(0, 20);
  ImGui::TextUnformatted("Algorithm");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(170);
  if (ImGui::BeginCombo("##alg", alg_ ? std::string(alg_->id).c_str() : "(choose)")) {
    for (const Algorithm& a : catalog()) {
      if (ImGui::Selectable(std::string(a.id).c_str(), &a == alg_) && &a != alg_) {
        const Numeric n = a.supports(numeric_) ? numeric_ : a.numerics.back();
        const auto cmp = compare_ && a.supports(*compare_) ? compare_ : std::nullopt;
        open_algorithm(a, parse_json_text(a.example, "example"), n, cmp);
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(a.summary).c_str());
    }
    ImGui::EndCombo();
  }
  if (alg_) {
    ImGui::SameLine(0, 20);
    ImGui::TextUnformatted("Numbers");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    if (ImGui::BeginCombo("##num", numeric_label(numeric_).c_str())) {
      for (Numeric n : alg_->numerics)
        if (ImGui::Selectable(numeric_label(n).c_str(), n == numeric_) && n != numeric_) rerun_numerics(n, compare_);
      ImGui::EndCombo();
    }
    ImGui::SameLine(0, 20);
    bool on = compare_.has_value();
    if (ImGui::Checkbox("Compare with", &on)) {
      std::optional<Numeric> other;
      if (on)
        for (Numeric n : alg_->numerics)
          if (n != numeric_) other = n;
      rerun_numerics(numeric_, other);
    }
    if (compare_) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(90);
      if (ImGui::BeginCombo("##cmp", numeric_label(*compare_).c_str())) {
        for (Numeric n : alg_->numerics)
          if (ImGui::Selectable(numeric_label(n).c_str(), n == *compare_) && n != *compare_) rerun_numerics(numeric_, n);
        ImGui::EndCombo();
      }
    }
    ImGui::SameLine(0, 20);
    if (ImGui::Button("Fit view") && canvases_[0]) canvases_[0]->fit();
  }
  // Row 2: the input. Segments get four exact fields; anything else a JSON field.
  if (alg_) {
    bool apply = false;
    if (!endpoint_text_[0].empty() || !endpoint_text_[2].empty()) {
      const char* labels[4] = {"p0 x", "y##p0", "p1 x", "y##p1"};
      for (int k = 0; k < 4; ++k) {
        if (k) ImGui::SameLine(0, k == 2 ? 20 : 8);
        ImGui::TextUnformatted(k % 2 ? "y" : (k ? "p1  x" : "p0  x"));
        ImGui::SameLine();
        ImGui::SetNextItemWidth(110);
        apply |= ImGui::InputText((std::string("##") + labels[k]).c_str(), &endpoint_text_[k], ImGuiInputTextFlags_EnterReturnsTrue);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("An exact value: an integer, a decimal like 2.75, or p/q. Enter applies.");
      }
      ImGui::SameLine();
      apply |= ImGui::Button("Apply");
      if (apply) {
        Json in = input_;
        in["p0"] = Json::array({endpoint_text_[0], endpoint_text_[1]});
        in["p1"] = Json::array({endpoint_text_[2], endpoint_text_[3]});
        apply_input(in);
      }
    } else {
      ImGui::TextUnformatted("Input");
      ImGui::SameLine();
      ImGui::SetNextItemWidth(420);
      apply |= ImGui::InputText("##json", &json_text_, ImGuiInputTextFlags_EnterReturnsTrue);
      ImGui::SameLine();
      apply |= ImGui::Button("Apply");
      if (apply) {
        try {
          apply_input(parse_json_text(json_text_, "input"));
        } catch (const InputError& e) {
          edit_error_ = e.what();
        }
      }
    }
    if (!edit_error_.empty()) {
      ImGui::SameLine(0, 16);
      ImGui::TextColored(theme::kError, "%s", edit_error_.c_str());
    } else if (a_) {
      ImGui::SameLine(0, 16);
      const bool segment = !endpoint_text_[0].empty() || !endpoint_text_[2].empty();
      if (view_ == View::orbit3d) ImGui::TextDisabled("%zu steps%s", a_->size(), input_.contains("ray") ? "; drag o or o + d on the canvas" : "");
      else ImGui::TextDisabled("%zu steps, %zu pixels%s", a_->size(), a_->plots().size(), segment ? "; drag p0 or p1 on the canvas" : "");
    }
  }
  ImGui::End();
}

}  // namespace sw::vis
