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
    if (!handle_text_.empty()) {
      // One exact x and y field per declared 2D handle (p0 and p1, the centre, control points).
      std::size_t k = 0;
      for (const Handle& h : alg_->handles) {
        if (h.kind != Handle::Kind::point2 || k >= handle_text_.size()) continue;
        for (int a = 0; a < 2; ++a) {
          if (k || a) ImGui::SameLine(0, a ? 8 : 20);
          ImGui::TextUnformatted(a ? "y" : (h.label + "  x").c_str());
          ImGui::SameLine();
          ImGui::SetNextItemWidth(handle_text_.size() > 2 ? 70 : 110);
          const std::string id = "##" + h.pointer + (a ? "y" : "x");
          apply |= ImGui::InputText(id.c_str(), &handle_text_[k][a], ImGuiInputTextFlags_EnterReturnsTrue);
          if (ImGui::IsItemHovered()) ImGui::SetTooltip("An exact value: an integer, a decimal like 2.75, or p/q. Enter applies.");
        }
        ++k;
      }
      ImGui::SameLine();
      apply |= ImGui::Button("Apply");
      if (apply) {
        Json in = input_;
        std::size_t j = 0;
        for (const Handle& h : alg_->handles)
          if (h.kind == Handle::Kind::point2 && j < handle_text_.size()) in[Json::json_pointer(h.pointer)] = Json::array({handle_text_[j][0], handle_text_[j][1]}), ++j;
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
      const bool segment = !handle_text_.empty();
      if (view_ == View::orbit3d) ImGui::TextDisabled("%zu steps%s", a_->size(), a_->algorithm().handles.empty() ? "" : "; drag a handle on the canvas to edit the input");
      else ImGui::TextDisabled("%zu steps, %zu pixels%s", a_->size(), a_->plots().size(), segment ? "; drag the handles on the canvas" : "");
    }
  }
  ImGui::End();
}

}  // namespace sw::vis
