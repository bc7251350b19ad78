#include "panels/plot_view.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include "panels/theme.hpp"

namespace sw::vis {

void PlotCanvas::load(const std::shared_ptr<const TraceModel>& m) {
  model_ = m;
  table_ = build_step_table(*m);
  all_ = table_values(*m, table_);
  exact_model_.reset();
  all_exact_.clear();
  if (m->numeric() != Numeric::exact && m->size() <= kMaxExactSteps && m->algorithm().supports(Numeric::exact)) {
    try {
      exact_model_ = record_model(m->run().in(Numeric::exact));
      exact_table_ = build_step_table(*exact_model_);
      // Rows are matched by index: only runs with the same rows and columns compare.
      if (exact_table_.columns == table_.columns && exact_table_.rows.size() == table_.rows.size()) all_exact_ = table_values(*exact_model_, exact_table_);
    } catch (const std::exception&) {
      exact_model_.reset();
    }
  }
  // The first column that is not integral, else the first that is not monotone, else the first.
  auto integral = [](const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isnan(x) || x == std::floor(x); });
  };
  auto monotone = [](const std::vector<double>& v) {
    return std::is_sorted(v.begin(), v.end()) || std::is_sorted(v.rbegin(), v.rend());
  };
  int chosen = -1;
  for (std::size_t c = 0; c < all_.size() && chosen < 0; ++c)
    if (!integral(all_[c])) chosen = int(c);
  for (std::size_t c = 0; c < all_.size() && chosen < 0; ++c)
    if (!monotone(all_[c])) chosen = int(c);
  pick(std::max(chosen, 0));
}

void PlotCanvas::pick(int column) {
  column_ = column;
  values_.clear(), exact_.clear();
  if (column < 0 || std::size_t(column) >= all_.size()) return;
  values_ = all_[column];
  if (!all_exact_.empty()) exact_ = all_exact_[column];
}

float PlotCanvas::row_x(std::size_t r) const {
  const std::size_t n = std::max<std::size_t>(values_.size(), 1);
  return x0_ + (x1_ - x0_) * (float(r) + 0.5f) / float(n);
}

CanvasEvents PlotCanvas::draw(const CanvasInput& in, ImVec2 size) {
  CanvasEvents ev;
  if (!in.model) return ev;
  if (in.model != model_) load(in.model);
  // One child window, so that the compare view can put two side by side.
  if (!ImGui::BeginChild("##plotview", size, false, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse)) {
    ImGui::EndChild();
    return ev;
  }
  ev = draw_inside(in, size);
  ImGui::EndChild();
  return ev;
}

CanvasEvents PlotCanvas::draw_inside(const CanvasInput& in, ImVec2 size) {
  CanvasEvents ev;
  const ImVec2 start = ImGui::GetCursorScreenPos();
  // Controls: the column, and value or difference from exact.
  if (!table_.columns.empty()) {
    ImGui::SetNextItemWidth(110);
    const std::string current(table_.columns[column_]);
    if (ImGui::BeginCombo("##column", current.c_str())) {
      for (std::size_t c = 0; c < table_.columns.size(); ++c)
        if (ImGui::Selectable(std::string(table_.columns[c]).c_str(), int(c) == column_)) pick(int(c));
      ImGui::EndCombo();
    }
    if (!all_exact_.empty()) {
      ImGui::SameLine();
      ImGui::Checkbox("minus exact", &difference_);
    } else if (in.model->numeric() != Numeric::exact) {
      ImGui::SameLine();
      ImGui::TextDisabled(exact_model_ ? "(the exact run's rows differ)" : "(no exact run: too long)");
    }
  }
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 area(std::max(size.x, 16.f), std::max(size.y - (origin.y - start.y), 16.f));
  ImGui::InvisibleButton("##plot", area, ImGuiButtonFlags_MouseButtonLeft);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 end(origin.x + area.x, origin.y + area.y);
  dl->AddRectFilled(origin, end, theme::kCanvasBg);
  const std::size_t n = values_.size();
  if (!n) {
    dl->AddText(ImVec2(origin.x + 10, origin.y + 10), theme::kLabel, "nothing to plot");
    return ev;
  }
  const bool diff = difference();
  std::vector<double> series(n);
  for (std::size_t r = 0; r < n; ++r) series[r] = diff ? values_[r] - exact_[r] : values_[r];
  // Quiz mode: rows after the current one are not drawn, nor counted, nor hovered.
  std::vector<double> exact = exact_;
  const auto now = table_.row_of(in.step);
  const std::size_t shown = in.hide_future ? (now ? *now + 1 : 0) : n;
  for (std::size_t r = shown; r < n; ++r) {
    series[r] = NAN;
    if (r < exact.size()) exact[r] = NAN;
  }
  double lo = INFINITY, hi = -INFINITY;
  auto extend = [&](const std::vector<double>& v) {
    for (double x : v)
      if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  };
  extend(series);
  if (!diff) extend(exact);
  if (diff) lo = std::min(lo, 0.0), hi = std::max(hi, 0.0);
  if (!(hi > lo)) lo = (std::isfinite(lo) ? lo : 0) - 1, hi = lo + 2;
  x0_ = origin.x + 64, x1_ = end.x - 12;
  const float top = origin.y + 24, bottom = end.y - 22;
  auto sy = [&](double v) { return float(bottom - (v - lo) / (hi - lo) * (bottom - top)); };
  dl->AddRect(ImVec2(x0_, top), ImVec2(x1_, bottom), theme::kGrid);
  if (lo < 0 && hi > 0) dl->AddLine(ImVec2(x0_, sy(0)), ImVec2(x1_, sy(0)), theme::kGridAxis);
  // Each series as a polyline, or per screen column its min-max bar when rows outnumber pixels.
  auto plot = [&](const std::vector<double>& v, ImU32 col) {
    const int px = std::max(1, int(x1_ - x0_));
    if (n <= std::size_t(2 * px)) {
      std::vector<ImVec2> pts;
      for (std::size_t r = 0; r < n; ++r)
        if (std::isfinite(v[r])) pts.push_back(ImVec2(row_x(r), sy(v[r])));
      dl->AddPolyline(pts.data(), int(pts.size()), col, ImDrawFlags_None, 1.5f);
      return;
    }
    for (int x = 0; x < px; ++x) {
      const std::size_t a = n * std::size_t(x) / std::size_t(px), b = std::max(a + 1, n * std::size_t(x + 1) / std::size_t(px));
      double mn = INFINITY, mx = -INFINITY;
      for (std::size_t r = a; r < b; ++r)
        if (std::isfinite(v[r])) mn = std::min(mn, v[r]), mx = std::max(mx, v[r]);
      if (mn <= mx) dl->AddLine(ImVec2(x0_ + float(x), sy(mx)), ImVec2(x0_ + float(x), sy(mn) + 1), col, 1.f);
    }
  };
  if (!diff && !exact.empty()) plot(exact, kPlotExact);
  plot(series, kPlotValue);
  // The current row.
  const auto row = table_.row_of(in.step);
  if (row) dl->AddLine(ImVec2(row_x(*row), top), ImVec2(row_x(*row), bottom), kPlotCurrent, 1.5f);
  // Labels.
  char buf[160];
  const std::string name(table_.columns[column_]), mode(numeric_name(in.model->numeric()));
  if (diff) std::snprintf(buf, sizeof buf, "%s (%s) - %s (exact), per row", name.c_str(), mode.c_str(), name.c_str());
  else std::snprintf(buf, sizeof buf, "%s (%s)%s, per row", name.c_str(), mode.c_str(), exact_.empty() ? "" : "; green: exact");
  dl->AddText(ImVec2(x0_, origin.y + 4), theme::kLabel, buf);
  std::snprintf(buf, sizeof buf, "%.4g", hi);
  dl->AddText(ImVec2(origin.x + 4, top - 2), theme::kLabel, buf);
  std::snprintf(buf, sizeof buf, "%.4g", lo);
  dl->AddText(ImVec2(origin.x + 4, bottom - 14), theme::kLabel, buf);
  if (row) {
    if (in.hide_future) std::snprintf(buf, sizeof buf, "row %zu (step %u): %.9g", *row, table_.rows[*row], series[*row]);
    else std::snprintf(buf, sizeof buf, "row %zu of %zu (step %u): %.9g", *row, n, table_.rows[*row], series[*row]);
    dl->AddText(ImVec2(x0_, bottom + 4), kPlotCurrent, buf);
  }
  // Hover and click: the row under the mouse.
  const ImGuiIO& io = ImGui::GetIO();
  const float mx = io.MousePos.x;
  if ((ImGui::IsItemHovered() || ImGui::IsItemDeactivated()) && mx >= x0_ && mx < x1_ &&
      std::min(n - 1, std::size_t((mx - x0_) / (x1_ - x0_) * float(n))) < shown) {
    const std::size_t r = std::min(n - 1, std::size_t((mx - x0_) / (x1_ - x0_) * float(n)));
    if (ImGui::IsItemDeactivated()) ev.jump_to = table_.rows[r];
    if (ImGui::IsItemHovered()) {
      if (exact_.empty()) ImGui::SetTooltip("row %zu, step %u\n%s = %.17g", r, table_.rows[r], name.c_str(), values_[r]);
      else ImGui::SetTooltip("row %zu, step %u\n%s = %.17g\nexact: %.17g", r, table_.rows[r], name.c_str(), values_[r], exact_[r]);
    }
  }
  corner_label(dl, origin, area, in.label);
  return ev;
}

}  // namespace sw::vis
