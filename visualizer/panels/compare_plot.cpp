#include "panels/compare_plot.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include "panels/pixel_canvas.hpp"
#include "panels/theme.hpp"

namespace sw::vis {

std::vector<std::string_view> shared_numeric_vars(const TraceModel& a, const TraceModel& b) {
  auto numeric_names = [](const TraceModel& m) {  // names recorded with a Num value anywhere
    std::vector<std::string_view> out;
    const TraceView& t = m.trace();
    for (std::size_t s = 0; s < t.size(); ++s)
      for (std::uint32_t k = t.at(s).var_begin; k < t.at(s).var_end; ++k)
        if (const VarRecord& v = t.var_at(k); !v.is_int && v.count && std::find(out.begin(), out.end(), v.name) == out.end()) out.push_back(v.name);
    return out;
  };
  const auto na = numeric_names(a), nb = numeric_names(b);
  std::vector<std::string_view> out;
  for (std::string_view n : na)
    if (std::find(nb.begin(), nb.end(), n) != nb.end()) out.push_back(n);
  return out;
}

namespace {

// The variable's latest components in one run, updated step by step.
struct Latest {
  std::array<double, 3> v{};
  std::uint32_t count = 0;
  void update(const TraceView& t, std::size_t s, std::string_view name) {
    for (std::uint32_t k = t.at(s).var_begin; k < t.at(s).var_end; ++k) {
      const VarRecord& r = t.var_at(k);
      if (r.is_int || name != r.name) continue;
      count = std::min<std::uint32_t>(r.count, 3);
      for (std::uint32_t c = 0; c < count; ++c) v[c] = t.component_double(r, c);
    }
  }
};

}  // namespace

DiffSeries diff_series(const TraceModel& a, const TraceModel& b, std::string_view name, std::size_t bins) {
  DiffSeries out;
  out.var = std::string(name);
  out.steps = std::min(a.size(), b.size());
  if (!out.steps || !bins) return out;
  out.bins.assign(std::min(bins, out.steps), 0.f);
  Latest la, lb;
  for (std::size_t s = 0; s < out.steps; ++s) {
    la.update(a.trace(), s, name), lb.update(b.trace(), s, name);
    if (!la.count || la.count != lb.count) continue;
    double d = 0;
    for (std::uint32_t c = 0; c < la.count; ++c) d = std::max(d, std::fabs(la.v[c] - lb.v[c]));
    if (!(d == d)) d = INFINITY;  // a NaN in one run: as far off as it gets
    float& bin = out.bins[s * out.bins.size() / out.steps];
    bin = std::max(bin, float(d));
    if (d > out.max) out.max = d, out.max_step = s;
  }
  return out;
}

std::optional<std::size_t> DiffPlot::draw(const std::shared_ptr<const TraceModel>& a, const std::shared_ptr<const TraceModel>& b, std::size_t step,
                                          float height) {
  if (!a || !b) return std::nullopt;
  if (a != a_ || b != b_) a_ = a, b_ = b, vars_ = shared_numeric_vars(*a, *b), series_ = {};
  const auto& vars = vars_;
  if (vars.empty()) return std::nullopt;
  if (std::find(vars.begin(), vars.end(), chosen_) == vars.end()) {  // the one that drifts furthest
    double best = -1;
    for (std::string_view v : vars)
      if (const double m = diff_series(*a, *b, v, 1).max; m > best) best = m, chosen_ = std::string(v);
  }
  ImGui::TextUnformatted("|difference| of");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  if (ImGui::BeginCombo("##diffvar", chosen_.c_str())) {
    for (std::string_view v : vars)
      if (ImGui::Selectable(std::string(v).c_str(), v == chosen_)) chosen_ = std::string(v);
    ImGui::EndCombo();
  }
  const ImVec2 o = ImGui::GetCursorScreenPos();
  const float w = ImGui::GetContentRegionAvail().x;
  if (series_.var != chosen_ || series_.bins.size() != std::min(std::size_t(std::max(w, 1.f)), std::min(a->size(), b->size())))
    series_ = diff_series(*a, *b, chosen_, std::size_t(std::max(w, 1.f)));
  ImGui::SameLine();
  if (series_.max > 0) ImGui::TextDisabled("max %.3g at step %zu", series_.max, series_.max_step);
  else ImGui::TextDisabled("0 at every step");
  const ImVec2 top(o.x, ImGui::GetCursorScreenPos().y);
  ImGui::InvisibleButton("##diffplot", ImVec2(std::max(w, 1.f), height));
  std::optional<std::size_t> clicked;
  if (ImGui::IsItemClicked() && series_.steps)
    clicked = std::size_t(std::clamp((ImGui::GetIO().MousePos.x - top.x) / w, 0.f, 1.f) * float(series_.steps - 1));
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(top, ImVec2(top.x + w, top.y + height), theme::kCanvasBg);
  const std::size_t n = series_.bins.size();
  for (std::size_t k = 0; k < n && series_.max > 0; ++k) {  // linear: 0 at the bottom, the max at the top
    const float f = std::isinf(series_.bins[k]) ? 1.f : float(series_.bins[k] / series_.max);
    const float x = top.x + w * float(k) / float(n);
    dl->AddRectFilled(ImVec2(x, top.y + height * (1 - f)), ImVec2(x + std::max(w / float(n), 1.f), top.y + height), IM_COL32(255, 115, 105, 220));
  }
  if (series_.steps > 1) {
    const float x = top.x + w * float(std::min(step, series_.steps - 1)) / float(series_.steps - 1);
    dl->AddLine(ImVec2(x, top.y), ImVec2(x, top.y + height), theme::kQ, 1.5f);
  }
  return clicked;
}

void draw_divergence_ticks(ImDrawList* dl, const std::vector<std::uint32_t>& steps, std::size_t last, ImVec2 min, ImVec2 max) {
  if (steps.empty()) return;
  // The slider's grab travels over the frame less its own width (ImGui's default grab minimum).
  const float grab = ImGui::GetStyle().GrabMinSize, x0 = min.x + grab / 2 + 2, x1 = max.x - grab / 2 - 2;
  int previous = -1;
  for (std::uint32_t s : steps) {
    const int x = int(x0 + (x1 - x0) * (last ? float(s) / float(last) : 0.f));
    if (x == previous) continue;  // steps ascend, so a shared column is the one just drawn
    previous = x;
    dl->AddLine(ImVec2(float(x), max.y), ImVec2(float(x), max.y + 5), theme::kDivergence, 1.f);
  }
}

std::string approx_suffix(const VarState& v) {
  if (v.shape != VarShape::scalar || v.is_int || v.text.find('/') == std::string::npos) return {};
  char buf[48];
  std::snprintf(buf, sizeof buf, " \xE2\x89\x88 %.9g", v.value);  // U+2248
  return buf;
}

// [SECTION] the plane2d canvas's outlines of the compare view's mismatched pixels
void PixelCanvas::draw_marked(ImDrawList* dl, std::span<const Pixel> cells) const {
  // The cell's outline, at least 9 px across so that it stays visible zoomed out; a bounded count
  // of visible ones (past that the view is too far out to tell them apart anyway).
  const WorldRect v = visible();
  const float half = std::max(float(scale_) * 0.5f, 4.5f);
  int drawn = 0;
  for (const Pixel& c : cells) {
    if (double(c.x) < v.x0 - 1 || double(c.x) > v.x1 + 1 || double(c.y) < v.y0 - 1 || double(c.y) > v.y1 + 1) continue;
    if (++drawn > 20000) break;
    const ImVec2 m = to_screen(double(c.x), double(c.y));
    dl->AddRect(ImVec2(m.x - half, m.y - half), ImVec2(m.x + half, m.y + half), theme::kMismatch, 0, 0, 2.f);
  }
}

}  // namespace sw::vis
