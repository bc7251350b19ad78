// The state panel: every variable seen so far, at the current step, exactly (rationals as p/q).
// Changed since the previous step: amber. Set again with the same value: blue. In compare mode,
// one column per number type and their difference, which shows a float run drifting.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include "panels/panels.hpp"

namespace sw::vis {
namespace {

const VarState* find_var(const std::vector<VarState>& vs, std::string_view name) {
  for (const VarState& v : vs)
    if (v.name == name) return &v;
  return nullptr;
}

ImVec4 var_colour(const VarState& v) {
  return v.changed ? theme::kChanged : v.set_here ? theme::kSetSame : ImVec4(0.85f, 0.86f, 0.89f, 1);
}

// The exact text, and for a fraction its decimal approximation too.
void value_cell(const VarState& v) {
  if (v.shape == VarShape::colour) {  // a swatch first, clamped to the displayable range
    auto c = [](float x) { return std::clamp(x, 0.f, 1.f); };
    ImGui::ColorButton("##rgb", ImVec4(c(v.rgb[0]), c(v.rgb[1]), c(v.rgb[2]), 1.f), ImGuiColorEditFlags_NoTooltip, ImVec2(ImGui::GetFontSize(), ImGui::GetFontSize()));
    ImGui::SameLine();
  }
  ImGui::TextColored(var_colour(v), "%s", v.text.c_str());
  if (const std::string approx = approx_suffix(v); !approx.empty()) ImGui::SameLine(0, 0), ImGui::TextDisabled("%s", approx.c_str());
}

// Exact irrational results (a sphere's t, rounded to 128 bits) run to 80 digits and would squeeze
// the compare columns: show those as a decimal, the exact text on hover.
void compare_cell(const VarState& v) {
  if (v.text.size() <= 24) {
    ImGui::TextColored(var_colour(v), "%s", v.text.c_str());
    if (const std::string approx = approx_suffix(v); !approx.empty()) ImGui::SameLine(0, 0), ImGui::TextDisabled("%s", approx.c_str());
    return;
  }
  if (v.text[0] == '(') ImGui::TextColored(var_colour(v), "%.21s...", v.text.c_str());  // a vector: its start, not one component
  else ImGui::TextColored(var_colour(v), "~%.15g", v.value);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", v.text.c_str());
}

// Each new step scrolls the table once to the first variable set there, so what the step did is
// in view in a short panel; the reader's own scrolling stands until the step changes.
class ScrollToStep {
 public:
  ScrollToStep(std::size_t step) : store_(ImGui::GetStateStorage()), key_(ImGui::GetID("##scrolled-step")) {
    fresh_ = store_->GetInt(key_, -1) != int(step);
    store_->SetInt(key_, int(step));
  }
  // Call on each row; scrolls to the first one set at the step.
  void row(bool set_here) {
    if (fresh_ && set_here) ImGui::SetScrollHereY(0.2f), fresh_ = false;
  }

 private:
  ImGuiStorage* store_;
  ImGuiID key_;
  bool fresh_ = false;
};

}  // namespace

void draw_state(Session& s, DiffPlot& plot, const PanelRect& r) {
  place_next(r.pos, r.size);
  ImGui::Begin("State", nullptr, kPanelFlags);
  const TraceModel* a = s.model(0);
  if (!a) {
    ImGui::End();
    return;
  }
  const TraceModel* b = s.model(1);
  const std::size_t step = s.shown_step();
  const bool other = s.comparison().other != nullptr;
  const auto sa = a->state_at(step);
  ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, ImVec2(4, 1));
  ImGui::TextColored(theme::kChanged, "changed");
  ImGui::SameLine();
  ImGui::TextColored(theme::kSetSame, "set, same value");
  ImGui::SameLine();
  ImGui::TextDisabled("earlier");
  constexpr ImGuiTableFlags kTable = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp |
                                     ImGuiTableFlags_ScrollY;
  ScrollToStep scroll(step);
  if (!b) {
    if (ImGui::BeginTable("vars", 2, kTable)) {
      ImGui::TableSetupScrollFreeze(0, 1);
      ImGui::TableSetupColumn("variable", ImGuiTableColumnFlags_WidthFixed, 96);
      ImGui::TableSetupColumn(("value (" + std::string(numeric_name(s.numeric())) + ")").c_str());
      ImGui::TableHeadersRow();
      for (const VarState& v : sa) {
        ImGui::TableNextRow();
        scroll.row(v.set_here);
        ImGui::TableNextColumn();
        ImGui::TextColored(var_colour(v), "%.*s", int(v.name.size()), v.name.data());
        ImGui::TableNextColumn();
        value_cell(v);
      }
      ImGui::EndTable();
    }
    ImGui::PopStyleVar();
    ImGui::End();
    return;
  }
  const std::size_t step_b = std::min(step, b->last());
  const auto sb = b->state_at(step_b);
  if (step_b != step && !other) ImGui::TextColored(theme::kError, "%s has only %zu steps", s.run_name(1).c_str(), b->size());
  // Steps pair up only for two number types; the quiz hides the plot, which spans the whole run.
  const bool with_plot = !other && !s.hide_future();
  const float plot_h = 64;
  if (ImGui::BeginTable("vars2", 4, kTable, ImVec2(0, with_plot ? -(plot_h + ImGui::GetFrameHeightWithSpacing() + 8) : 0))) {
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("variable", ImGuiTableColumnFlags_WidthFixed, 70);
    ImGui::TableSetupColumn(s.run_name(0).c_str());
    ImGui::TableSetupColumn(s.run_name(1).c_str());
    ImGui::TableSetupColumn("|difference|", ImGuiTableColumnFlags_WidthFixed, 90);
    ImGui::TableHeadersRow();
    for (std::string_view name : a->var_names()) {
      const VarState *x = find_var(sa, name), *y = find_var(sb, name);
      if (!x && !y) continue;
      ImGui::TableNextRow();
      scroll.row((x && x->set_here) || (y && y->set_here));
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name.data(), name.data() + name.size());
      ImGui::TableNextColumn();
      if (x) compare_cell(*x);
      ImGui::TableNextColumn();
      if (y) compare_cell(*y);
      ImGui::TableNextColumn();
      if (x && y) {
        const std::optional<double> diff = value_difference(*x, *y);
        if (!diff) ImGui::TextColored(theme::kError, "lengths differ");
        else if (*diff == 0) ImGui::TextDisabled("0");
        else ImGui::TextColored(theme::kError, "%.3g", *diff);
      }
    }
    ImGui::EndTable();
  }
  if (with_plot)
    if (const auto to = plot.draw(s.model_ptr(0), s.model_ptr(1), step, plot_h)) s.go(*to);
  ImGui::PopStyleVar();
  ImGui::End();
}

}  // namespace sw::vis
