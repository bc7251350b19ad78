#include "panels/table_view.hpp"
#include <algorithm>
#include <cstdio>
#include <limits>
#include "panels/theme.hpp"

namespace sw::vis {

std::optional<std::size_t> StepTable::row_of(std::size_t step) const {
  auto it = std::upper_bound(rows.begin(), rows.end(), step);
  if (it == rows.begin()) return std::nullopt;
  return static_cast<std::size_t>(it - rows.begin()) - 1;
}

namespace {

// The steps whose variables count for a row: the algorithm's own (scope 0) when rows are
// declared, since a nested callee's steps number their lines in another listing.
bool in_rows(const StepRecord& st, bool declared) { return !declared || st.scope == 0; }

}  // namespace

StepTable build_step_table(const TraceModel& m) {
  StepTable t;
  const Algorithm& alg = m.algorithm();
  const TraceView& tr = m.trace();
  std::vector<std::uint32_t> lines;
  for (std::string_view name : alg.table_lines)
    if (const std::uint32_t id = alg.listing.find(name)) lines.push_back(id);
  const bool declared = !lines.empty();
  for (std::size_t s = 0; s < tr.size(); ++s) {
    const StepRecord& st = tr.at(s);
    if (!declared || (st.scope == 0 && std::find(lines.begin(), lines.end(), st.line) != lines.end()))
      t.rows.push_back(static_cast<std::uint32_t>(s));
    if (t.rows.empty() || !in_rows(st, declared)) continue;
    for (std::uint32_t v = st.var_begin; v < st.var_end; ++v) {
      const std::string_view name = tr.var_at(v).name;
      if (std::find(t.columns.begin(), t.columns.end(), name) == t.columns.end()) t.columns.push_back(name);
    }
  }
  return t;
}

std::vector<TableCell> table_row(const TraceModel& m, const StepTable& t, std::size_t r) {
  std::vector<TableCell> cells(t.columns.size());
  if (r >= t.rows.size()) return cells;
  const TraceView& tr = m.trace();
  const bool declared = !m.algorithm().table_lines.empty();
  const std::size_t end = r + 1 < t.rows.size() ? t.rows[r + 1] : tr.size();
  std::size_t missing = cells.size();
  for (std::size_t s = t.rows[r]; s < end && missing; ++s) {
    const StepRecord& st = tr.at(s);
    if (!in_rows(st, declared)) continue;
    for (std::uint32_t v = st.var_begin; v < st.var_end; ++v) {
      const VarRecord& rec = tr.var_at(v);
      const auto c = std::find(t.columns.begin(), t.columns.end(), std::string_view(rec.name)) - t.columns.begin();
      if (c == std::ssize(t.columns) || cells[c].recorded) continue;
      cells[c] = {tr.value_text(rec), tr.value_double(rec), true};
      --missing;
    }
  }
  if (missing)  // the rest carry their latest value from before the row
    for (const VarState& vs : m.state_at(t.rows[r])) {
      const auto c = std::find(t.columns.begin(), t.columns.end(), vs.name) - t.columns.begin();
      if (c < std::ssize(t.columns) && !cells[c].recorded) cells[c] = {vs.text, vs.value, false};
    }
  return cells;
}

std::vector<std::vector<double>> table_values(const TraceModel& m, const StepTable& t) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const std::size_t nc = t.columns.size(), nr = t.rows.size();
  std::vector<std::vector<double>> out(nc, std::vector<double>(nr, kNaN));
  const TraceView& tr = m.trace();
  const bool declared = !m.algorithm().table_lines.empty();
  std::vector<double> latest(nc, kNaN), carried(nc, kNaN);  // as table_row: latest before the row
  std::vector<char> set(nc, 0);
  std::size_t next = 0;  // the next row to start
  auto close = [&] {
    for (std::size_t c = 0; c < nc && next; ++c)
      if (!set[c]) out[c][next - 1] = carried[c];
  };
  for (std::size_t s = 0; s < tr.size(); ++s) {
    if (next < nr && t.rows[next] == s) close(), carried = latest, std::fill(set.begin(), set.end(), 0), ++next;
    const StepRecord& st = tr.at(s);
    for (std::uint32_t v = st.var_begin; v < st.var_end; ++v) {
      const VarRecord& rec = tr.var_at(v);
      const auto c = static_cast<std::size_t>(std::find(t.columns.begin(), t.columns.end(), std::string_view(rec.name)) - t.columns.begin());
      if (c == nc) continue;
      const double value = tr.value_double(rec);
      if (next && in_rows(st, declared) && !set[c]) out[c][next - 1] = value, set[c] = 1;
      latest[c] = value;
    }
  }
  close();
  return out;
}

std::optional<std::array<float, 4>> TableCanvas::row_rect(std::size_t row) const {
  for (const auto& [r, rect] : drawn_)
    if (r == row) return rect;
  return std::nullopt;
}

CanvasEvents TableCanvas::draw(const CanvasInput& in, ImVec2 size) {
  CanvasEvents ev;
  drawn_.clear();
  if (!in.model) return ev;
  if (in.model != model_) {
    model_ = in.model;
    table_ = build_step_table(*model_);
    scroll_pending_ = true;
  }
  const TraceModel& m = *model_;
  highlighted_ = table_.row_of(in.step);
  if (highlighted_ != scrolled_to_) scroll_pending_ = true;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  constexpr ImGuiTableFlags kFlags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_ScrollX | ImGuiTableFlags_RowBg |
                                     ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_BordersOuter | ImGuiTableFlags_SizingFixedFit;
  const int ncols = static_cast<int>(table_.columns.size()) + 1;
  if (!ImGui::BeginTable("steps", std::min(ncols, 64), kFlags, size)) return ev;
  ImGui::TableSetupScrollFreeze(1, 1);
  ImGui::TableSetupColumn("step", ImGuiTableColumnFlags_WidthFixed, 56);
  for (int c = 1; c < std::min(ncols, 64); ++c) ImGui::TableSetupColumn(std::string(table_.columns[c - 1]).c_str(), ImGuiTableColumnFlags_WidthFixed, 96);
  ImGui::TableHeadersRow();
  const float row_h = ImGui::GetTextLineHeight() + 2 * ImGui::GetStyle().CellPadding.y;
  if (scroll_pending_ && highlighted_) {
    const float view_h = ImGui::GetWindowHeight() - row_h;  // below the frozen header
    ImGui::SetScrollY(std::max(0.f, float(*highlighted_) * row_h - (view_h - row_h) / 2));
    scrolled_to_ = highlighted_;
    scroll_pending_ = false;
  }
  ImGuiListClipper clipper;
  // Quiz mode: no row after the current one.
  clipper.Begin(static_cast<int>(in.hide_future && highlighted_ ? *highlighted_ + 1 : table_.rows.size()), row_h);
  char buf[32];
  while (clipper.Step())
    for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) {
      ImGui::TableNextRow(ImGuiTableRowFlags_None, row_h);
      const bool current = highlighted_ && *highlighted_ == std::size_t(r);
      if (current) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, theme::kLineHighlight);
      ImGui::TableSetColumnIndex(0);
      std::snprintf(buf, sizeof buf, "%u##r%d", table_.rows[r], r);
      if (ImGui::Selectable(buf, current, ImGuiSelectableFlags_SpanAllColumns)) ev.jump_to = table_.rows[r];
      const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
      drawn_.push_back({std::size_t(r), {a.x, a.y, b.x, b.y}});
      const std::vector<TableCell> cells = table_row(m, table_, r);
      for (int c = 1; c < std::min(ncols, 64); ++c) {
        ImGui::TableSetColumnIndex(c);
        const TableCell& cell = cells[c - 1];
        const ImVec4 col = cell.recorded ? ImVec4(0.90f, 0.91f, 0.94f, 1) : theme::kDim;
        if (cell.text.size() <= 14) ImGui::TextColored(col, "%s", cell.text.c_str());
        else if (cell.text[0] == '(') ImGui::TextColored(col, "%.11s...", cell.text.c_str());  // a vector: its start, not one component
        else ImGui::TextColored(col, "~%.8g", cell.value);
        if (cell.text.size() > 14 && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", cell.text.c_str());
      }
    }
  ImGui::EndTable();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  if (table_.rows.empty()) dl->AddText(ImVec2(origin.x + 8, origin.y + 30), theme::kLabel, "no steps on the table's lines");
  corner_label(dl, origin, size, in.label);
  return ev;
}

}  // namespace sw::vis
