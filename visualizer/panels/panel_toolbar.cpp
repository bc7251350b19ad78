// The toolbar: what is open (lesson, algorithm, number types) and the exact input endpoints.
#include "panels/app.hpp"  // before imgui_stdlib.h, which needs imgui.h first
#include <imgui_stdlib.h>
#include <algorithm>
#include <cstdio>

namespace sw::vis {
namespace {

std::string numeric_label(Numeric n) { return std::string(numeric_name(n)); }

// The width of a text label, its gap and an item `item_w` wide after it: what flow() must fit.
float labelled(const char* label, float item_w) { return ImGui::CalcTextSize(label).x + ImGui::GetStyle().ItemSpacing.x + item_w; }

}  // namespace

void App::draw_toolbar(ImVec2 pos, ImVec2 size) {
  place_next(pos, size);
  ImGui::Begin("Toolbar", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_MenuBar);
  draw_menu_bar();
  // Widths in font sizes, so that --scale and presentation mode scale them; every row wraps
  // (flow) where the window is too narrow for it.
  const float em = ImGui::GetFontSize(), gap = 1.3f * em;
  // Row 1 (the lesson is chosen in the menu bar): algorithm, number types. Presenting: the
  // lesson buttons only.
  if (presenting_) {
    if (ImGui::Button("< Previous lesson")) open_adjacent_lesson(-1);
    ImGui::SameLine();
    if (ImGui::Button("Next lesson >")) open_adjacent_lesson(+1);
    toolbar_content_h_ = content_height();
    ImGui::End();
    return;
  }
  ImGui::TextUnformatted("Algorithm");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(11 * em);
  if (ImGui::BeginCombo("##alg", alg_ ? std::string(alg_->id).c_str() : "(choose)")) {
    for (const Algorithm& a : catalog()) {
      if (ImGui::Selectable(std::string(a.id).c_str(), &a == alg_) && &a != alg_) {
        const Numeric n = a.supports(numeric_) ? numeric_ : a.numerics.back();
        // Keep the comparison where it still makes sense: the same number type, or the same other
        // algorithm if the new one shares its group.
        Comparison cmp;
        if (compare_.other && compare_.other != &a && compare_.other->compare_group == a.compare_group) cmp = Comparison(n, compare_.other);
        else if (!compare_.other && compare_ && a.supports(*compare_.numeric)) cmp = compare_;
        open_algorithm(a, parse_json_text(a.example, "example"), n, cmp);
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(a.summary).c_str());
    }
    ImGui::EndCombo();
  }
  if (alg_) {
    flow(labelled("Numbers", 6 * em), gap);
    ImGui::TextUnformatted("Numbers");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(6 * em);
    if (ImGui::BeginCombo("##num", numeric_label(numeric_).c_str())) {
      for (Numeric n : alg_->numerics)
        if (ImGui::Selectable(numeric_label(n).c_str(), n == numeric_) && n != numeric_) rerun_numerics(n, compare_);
      ImGui::EndCombo();
    }
    const float cmp_w = compare_ ? (compare_.other ? 12.5f : 6) * em + ImGui::GetStyle().ItemSpacing.x : 0;
    flow(ImGui::GetFrameHeight() + ImGui::CalcTextSize("Compare with").x + 2 * ImGui::GetStyle().ItemInnerSpacing.x + cmp_w, gap);
    bool on = bool(compare_);
    if (ImGui::Checkbox("Compare with", &on)) {
      Comparison other;
      if (on)
        for (Numeric n : alg_->numerics)
          if (n != numeric_) other = n;
      rerun_numerics(numeric_, other);
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(alg_->compare_group.empty() ? "Run the input in a second number type, side by side"
                                                    : "Run the input in a second number type, or in another model, side by side");
    if (compare_) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(compare_.other ? 12.5f * em : 6 * em);
      if (ImGui::BeginCombo("##cmp", compare_.label().c_str())) {
        for (Numeric n : alg_->numerics)
          if (ImGui::Selectable(numeric_label(n).c_str(), !compare_.other && n == *compare_.numeric) && (compare_.other || n != *compare_.numeric))
            rerun_numerics(numeric_, n);
        if (!alg_->compare_group.empty()) {
          ImGui::Separator();
          ImGui::TextDisabled("%s", std::string(alg_->compare_group).c_str());
          for (const Algorithm& a : catalog())
            if (&a != alg_ && a.compare_group == alg_->compare_group && ImGui::Selectable(std::string(a.id).c_str(), compare_.other == &a) && compare_.other != &a)
              rerun_numerics(numeric_, Comparison(numeric_, &a));
        }
        ImGui::EndCombo();
      }
    }
    flow(ImGui::CalcTextSize("Fit view").x + 2 * ImGui::GetStyle().FramePadding.x, gap);
    if (ImGui::Button("Fit view") && canvases_[0]) canvases_[0]->fit();
    ImGui::SameLine();
    if (ImGui::Button("Accuracy")) accuracy_open_ = !accuracy_open_;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show or hide a chart of every number type's speed against its wrong outputs (a short bench)");
  }
  // Row 2: the input. Segments get four exact fields; anything else a JSON field. Presentation
  // mode hides rows 2 and 3.
  if (alg_ && !presenting_) {
    bool apply = false;
    if (!handle_text_.empty()) {
      // One exact x and y field per declared 2D handle (p0 and p1, the centre, control points).
      std::size_t k = 0;
      for (const Handle& h : alg_->handles) {
        if (h.kind != Handle::Kind::point2 || k >= handle_text_.size()) continue;
        const float field_w = (handle_text_.size() > 2 ? 4.7f : 7.3f) * em;
        for (int a = 0; a < 2; ++a) {
          const std::string label = a ? "y" : h.label + "  x";
          if (k || a) flow(labelled(label.c_str(), field_w), a ? 0.5f * em : gap);
          ImGui::TextUnformatted(label.c_str());
          ImGui::SameLine();
          ImGui::SetNextItemWidth(field_w);
          const std::string id = "##" + h.pointer + (a ? "y" : "x");
          apply |= ImGui::InputText(id.c_str(), &handle_text_[k][a], ImGuiInputTextFlags_EnterReturnsTrue);
          if (ImGui::IsItemHovered()) ImGui::SetTooltip("An exact value: an integer, a decimal like 2.75, or p/q. Enter applies.");
        }
        ++k;
      }
      flow(ImGui::CalcTextSize("Apply").x + 2 * ImGui::GetStyle().FramePadding.x);
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
      // The JSON field takes what the row has left, between 12 and 28 em.
      const float apply_w = ImGui::CalcTextSize("Apply").x + 2 * ImGui::GetStyle().FramePadding.x + ImGui::GetStyle().ItemSpacing.x;
      ImGui::SetNextItemWidth(std::clamp(ImGui::GetContentRegionAvail().x - apply_w, 12 * em, 28 * em));
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
    // The error, or the counts and a hint (dropped where the row has no room), after the fields;
    // wrapped onto a row of their own when they still do not fit.
    char note[160] = "";
    if (a_ && edit_error_.empty()) {
      const float room = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x - ImGui::GetItemRectMax().x - 16;
      const bool segment = !handle_text_.empty(), counts_only = ImGui::CalcTextSize("0000 steps, 000 pixels; drag a handle on the canvas to edit the input").x > room;
      const char* hint = counts_only ? "" : "; drag a handle on the canvas to edit the input";
      if (view_ == View::orbit3d || view_ == View::lobe) std::snprintf(note, sizeof note, "%zu steps%s", a_->size(), a_->algorithm().handles.empty() ? "" : hint);
      else std::snprintf(note, sizeof note, "%zu steps, %zu pixels%s", a_->size(), a_->plots().size(), segment && !counts_only ? "; drag the handles on the canvas" : "");
    }
    const std::string& shown = edit_error_.empty() ? std::string(note) : edit_error_;
    if (!shown.empty()) {
      flow(std::min(ImGui::CalcTextSize(shown.c_str()).x, ImGui::GetContentRegionMax().x), 16);
      ImGui::PushTextWrapPos(0);
      if (edit_error_.empty()) ImGui::TextDisabled("%s", shown.c_str());
      else ImGui::TextColored(theme::kError, "%s", shown.c_str());
      ImGui::PopTextWrapPos();
    }
  }
  // Row 3: sliders for the declared parameters the input has, then the other model's own.
  if (alg_ && has_sliders() && !presenting_) {
    Json in = input_;
    if (draw_param_sliders(*alg_, in, compare_.other ? alg_->id.data() : "", nullptr)) apply_input(in);
    if (compare_.other) {
      Json other = other_input_;
      ImGui::SameLine(0, 28);
      if (draw_param_sliders(*compare_.other, other, compare_.other->id.data(), &input_)) apply_other_input(other);
    }
  }
  toolbar_content_h_ = content_height();  // the next frame's layout
  ImGui::End();
}

namespace {

// A parameter shown when the input holds a number (or an exact string) at its pointer.
std::optional<double> param_value(const Json& input, const Param& p, const Json* skip) {
  const Json::json_pointer ptr(p.pointer);
  if (!input.is_object() || !input.contains(ptr)) return std::nullopt;
  if (skip && skip->is_object() && skip->contains(ptr)) return std::nullopt;  // shared: set on the left
  try {
    return parse_rational(input[ptr], p.label).get_d();
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace

bool App::has_sliders() const {
  if (!alg_) return false;
  for (const Param& p : alg_->params)
    if (param_value(input_, p, nullptr)) return true;
  if (compare_.other)
    for (const Param& p : compare_.other->params)
      if (param_value(other_input_, p, &input_)) return true;
  return false;
}

bool App::draw_param_sliders(const Algorithm& alg, Json& input, const char* prefix, const Json* skip) {
  bool changed = false, first = true;
  for (const Param& p : alg.params) {
    const auto v = param_value(input, p, skip);
    if (!v) continue;
    const float em = ImGui::GetFontSize(), slider_w = 8.7f * em;
    const std::string caption = *prefix ? std::string(prefix) + " " + p.label : p.label;
    if (!first) flow(labelled(caption.c_str(), slider_w), 16);
    first = false;
    if (*prefix) ImGui::TextDisabled("%s", prefix), ImGui::SameLine();
    ImGui::TextUnformatted(p.label.c_str());
    ImGui::SameLine();
    ImGui::SetNextItemWidth(slider_w);
    const std::string id = "##" + std::string(prefix) + p.pointer;
    // The image view sweeps every sample again on a change: there the value applies on release,
    // and the slider shows the value being dragged meanwhile.
    const bool on_release = view_ == View::image;
    float f = slider_drag_ && slider_drag_->first == id ? slider_drag_->second : float(*v);
    const ImGuiSliderFlags flags = p.logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
    const bool moved = ImGui::SliderFloat(id.c_str(), &f, float(p.lo), float(p.hi), "%.4g", flags);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\n%s, %g to %g%s; Ctrl+click types a value", p.help.c_str(), p.pointer.c_str(), p.lo, p.hi, p.logarithmic ? ", logarithmic" : "");
    if (moved && on_release) slider_drag_ = {id, f};
    const bool released = on_release && ImGui::IsItemDeactivated() && slider_drag_ && slider_drag_->first == id;
    if ((moved && !on_release) || released) {
      char text[32];
      std::snprintf(text, sizeof text, "%.4g", double(f));  // a short decimal, read exactly
      input[Json::json_pointer(p.pointer)] = std::strtod(text, nullptr);
      changed = true;
    }
    if (released) slider_drag_.reset();
  }
  return changed;
}

}  // namespace sw::vis
