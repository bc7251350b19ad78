// The toolbar: what is open (lesson, algorithm, number types), the input's exact fields and the
// sliders of its declared parameters.
#include "panels/panels.hpp"  // before imgui_stdlib.h, which needs imgui.h first
#include <imgui_stdlib.h>
#include <algorithm>
#include <cstdio>

namespace sw::vis {
namespace {

std::string numeric_label(Numeric n) { return std::string(numeric_name(n)); }

// The width of a text label, its gap and an item `item_w` wide after it: what flow() must fit.
float labelled(const char* label, float item_w) { return ImGui::CalcTextSize(label).x + ImGui::GetStyle().ItemSpacing.x + item_w; }

}  // namespace

void Toolbar::refill(const Session& s) {
  filled_ = s.loads();
  handle_text_.clear();
  json_text_ = s.input().dump();
  const Algorithm* alg = s.algorithm();
  if (!alg || !s.input().is_object()) return;
  for (const Handle& h : alg->handles) {
    if (h.kind != Handle::Kind::point2) continue;
    const Json::json_pointer ptr(h.pointer);
    const Json* pt = s.input().contains(ptr) ? &s.input()[ptr] : nullptr;
    std::array<std::string, 2> text;
    for (int a = 0; a < 2 && pt && pt->is_array() && pt->size() == 2; ++a) {
      try {
        text[std::size_t(a)] = num::to_text(parse_rational((*pt)[std::size_t(a)], h.label));
      } catch (const InputError&) {
        text[std::size_t(a)] = (*pt)[std::size_t(a)].dump();
      }
    }
    handle_text_.push_back(text);
  }
}

void Toolbar::draw(Session& s, Chrome& c, const PanelRect& r) {
  if (filled_ != s.loads()) refill(s);
  place_next(r.pos, r.size);
  ImGui::Begin("Toolbar", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_MenuBar);
  draw_menu_bar(s, c);
  // Widths in font sizes, so that --scale and presentation mode scale them; every row wraps
  // (flow) where the window is too narrow for it.
  const float em = ImGui::GetFontSize(), gap = 1.3f * em;
  // Row 1 (the lesson is chosen in the menu bar): algorithm, number types. Presenting: the
  // lesson buttons only.
  if (c.presenting) {
    if (ImGui::Button("< Previous lesson")) s.open_adjacent_lesson(-1);
    ImGui::SameLine();
    if (ImGui::Button("Next lesson >")) s.open_adjacent_lesson(+1);
    content_h_ = content_height();
    ImGui::End();
    return;
  }
  const Algorithm* alg = s.algorithm();
  const Numeric numeric = s.numeric();
  const Comparison compare = s.comparison();
  ImGui::TextUnformatted("Algorithm");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(11 * em);
  if (ImGui::BeginCombo("##alg", alg ? std::string(alg->id).c_str() : "(choose)")) {
    for (const Algorithm& a : catalog()) {
      if (ImGui::Selectable(std::string(a.id).c_str(), &a == alg) && &a != alg) {
        const Numeric n = a.supports(numeric) ? numeric : a.numerics.back();
        // Keep the comparison where it still makes sense: the same number type, or the same other
        // algorithm if the new one shares its group.
        Comparison cmp;
        if (compare.other && compare.other != &a && compare.other->compare_group == a.compare_group) cmp = Comparison(n, compare.other);
        else if (!compare.other && compare && a.supports(*compare.numeric)) cmp = compare;
        s.open_algorithm(a, parse_json_text(a.example, "example"), n, cmp);
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(a.summary).c_str());
    }
    ImGui::EndCombo();
  }
  if (alg) {
    flow(labelled("Numbers", 6 * em), gap);
    ImGui::TextUnformatted("Numbers");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(6 * em);
    if (ImGui::BeginCombo("##num", numeric_label(numeric).c_str())) {
      for (Numeric n : alg->numerics)
        if (ImGui::Selectable(numeric_label(n).c_str(), n == numeric) && n != numeric) s.edit_numerics(n, compare);
      ImGui::EndCombo();
    }
    const float cmp_w = compare ? (compare.other ? 12.5f : 6) * em + ImGui::GetStyle().ItemSpacing.x : 0;
    flow(ImGui::GetFrameHeight() + ImGui::CalcTextSize("Compare with").x + 2 * ImGui::GetStyle().ItemInnerSpacing.x + cmp_w, gap);
    bool on = bool(compare);
    if (ImGui::Checkbox("Compare with", &on)) {
      Comparison other;
      if (on)
        for (Numeric n : alg->numerics)
          if (n != numeric) other = n;
      s.edit_numerics(numeric, other);
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(alg->compare_group.empty() ? "Run the input in a second number type, side by side"
                                                   : "Run the input in a second number type, or in another model, side by side");
    if (compare) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(compare.other ? 12.5f * em : 6 * em);
      if (ImGui::BeginCombo("##cmp", compare.label().c_str())) {
        for (Numeric n : alg->numerics)
          if (ImGui::Selectable(numeric_label(n).c_str(), !compare.other && n == *compare.numeric) && (compare.other || n != *compare.numeric))
            s.edit_numerics(numeric, n);
        if (!alg->compare_group.empty()) {
          ImGui::Separator();
          ImGui::TextDisabled("%s", std::string(alg->compare_group).c_str());
          for (const Algorithm& a : catalog())
            if (&a != alg && a.compare_group == alg->compare_group && ImGui::Selectable(std::string(a.id).c_str(), compare.other == &a) && compare.other != &a)
              s.edit_numerics(numeric, Comparison(numeric, &a));
        }
        ImGui::EndCombo();
      }
    }
    flow(ImGui::CalcTextSize("Fit view").x + 2 * ImGui::GetStyle().FramePadding.x, gap);
    if (ImGui::Button("Fit view")) c.fit = true;
    ImGui::SameLine();
    if (ImGui::Button("Accuracy")) c.accuracy_open = !c.accuracy_open;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show or hide a chart of every number type's speed against its wrong outputs (a short bench)");
  }
  // Row 2: the input; row 3: sliders for the declared parameters the input has, then the other
  // model's own. Presentation mode hides both.
  if (s.algorithm()) draw_input_row(s, em, gap);
  if (s.algorithm() && has_sliders(s)) {
    Json in = s.input();
    if (draw_param_sliders(s, *s.algorithm(), in, s.comparison().other ? s.algorithm()->id.data() : "", nullptr)) s.apply_input(in);
    if (const Algorithm* other = s.comparison().other) {
      Json oin = s.other_input();
      ImGui::SameLine(0, 28);
      if (draw_param_sliders(s, *other, oin, other->id.data(), &s.input())) s.apply_other_input(oin);
    }
  }
  content_h_ = content_height();  // the next frame's layout
  ImGui::End();
}

// Segments get four exact fields; anything else a JSON field. Then the error, or the counts.
void Toolbar::draw_input_row(Session& s, float em, float gap) {
  if (filled_ != s.loads()) refill(s);  // the combos above may have opened something else
  const Algorithm& alg = *s.algorithm();
  bool apply = false;
  if (!handle_text_.empty()) {
    // One exact x and y field per declared 2D handle (p0 and p1, the centre, control points).
    std::size_t k = 0;
    for (const Handle& h : alg.handles) {
      if (h.kind != Handle::Kind::point2 || k >= handle_text_.size()) continue;
      const float field_w = (handle_text_.size() > 2 ? 4.7f : 7.3f) * em;
      for (int a = 0; a < 2; ++a) {
        const std::string label = a ? "y" : h.label + "  x";
        if (k || a) flow(labelled(label.c_str(), field_w), a ? 0.5f * em : gap);
        ImGui::TextUnformatted(label.c_str());
        ImGui::SameLine();
        ImGui::SetNextItemWidth(field_w);
        const std::string id = "##" + h.pointer + (a ? "y" : "x");
        apply |= ImGui::InputText(id.c_str(), &handle_text_[k][std::size_t(a)], ImGuiInputTextFlags_EnterReturnsTrue);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("An exact value: an integer, a decimal like 2.75, or p/q. Enter applies.");
      }
      ++k;
    }
    flow(ImGui::CalcTextSize("Apply").x + 2 * ImGui::GetStyle().FramePadding.x);
    apply |= ImGui::Button("Apply");
    if (apply) {
      Json in = s.input();
      std::size_t j = 0;
      for (const Handle& h : alg.handles)
        if (h.kind == Handle::Kind::point2 && j < handle_text_.size()) in[Json::json_pointer(h.pointer)] = Json::array({handle_text_[j][0], handle_text_[j][1]}), ++j;
      s.apply_input(in);
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
        s.apply_input(parse_json_text(json_text_, "input"));
      } catch (const InputError& e) {
        s.set_edit_error(e.what());
      }
    }
  }
  // The error, or the counts and a hint (dropped where the row has no room), after the fields;
  // wrapped onto a row of their own when they still do not fit.
  char note[160] = "";
  const TraceModel* m = s.model(0);
  const std::string& error = s.edit_error();
  if (m && error.empty()) {
    const float room = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x - ImGui::GetItemRectMax().x - 16;
    const bool segment = !handle_text_.empty(), counts_only = ImGui::CalcTextSize("0000 steps, 000 pixels; drag a handle on the canvas to edit the input").x > room;
    const char* hint = counts_only ? "" : "; drag a handle on the canvas to edit the input";
    if (s.view() == View::orbit3d || s.view() == View::lobe) std::snprintf(note, sizeof note, "%zu steps%s", m->size(), m->algorithm().handles.empty() ? "" : hint);
    else std::snprintf(note, sizeof note, "%zu steps, %zu pixels%s", m->size(), m->plots().size(), segment && !counts_only ? "; drag the handles on the canvas" : "");
  }
  const std::string shown = error.empty() ? std::string(note) : error;
  if (!shown.empty()) {
    flow(std::min(ImGui::CalcTextSize(shown.c_str()).x, ImGui::GetContentRegionMax().x), 16);
    ImGui::PushTextWrapPos(0);
    if (error.empty()) ImGui::TextDisabled("%s", shown.c_str());
    else ImGui::TextColored(theme::kError, "%s", shown.c_str());
    ImGui::PopTextWrapPos();
  }
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

bool Toolbar::has_sliders(const Session& s) const {
  for (const Param& p : s.algorithm()->params)
    if (param_value(s.input(), p, nullptr)) return true;
  if (const Algorithm* other = s.comparison().other)
    for (const Param& p : other->params)
      if (param_value(s.other_input(), p, &s.input())) return true;
  return false;
}

bool Toolbar::draw_param_sliders(const Session& s, const Algorithm& alg, Json& input, const char* prefix, const Json* skip) {
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
    const bool on_release = s.view() == View::image;
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
