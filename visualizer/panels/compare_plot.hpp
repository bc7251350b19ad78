// The compare view's extras: |difference| of one shared variable over the steps (a small plot in
// the state panel), the divergence ticks on the timeline, and the "≈ decimal" of exact values.
#pragma once
#include <imgui.h>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include "lessons/trace_model.hpp"

namespace sw::vis {

// The non-integer variables both runs record, in the first run's order.
std::vector<std::string_view> shared_numeric_vars(const TraceModel& a, const TraceModel& b);

// |a - b| of variable `name` (its largest component difference for vectors) at each step both
// runs have, using each run's latest value at or before the step; reduced to at most `bins`
// maxima. Steps where either run has not yet set it count as 0.
struct DiffSeries {
  std::string var;
  std::vector<float> bins;  // bin k covers steps [k * steps / bins.size(), (k + 1) * steps / bins.size())
  double max = 0;
  std::size_t steps = 0, max_step = 0;  // the step of the largest difference
};
DiffSeries diff_series(const TraceModel& a, const TraceModel& b, std::string_view name, std::size_t bins);

// The plot under the state panel's table: a combo of the shared variables, then the series as
// bars, the current step marked. Returns the step clicked.
class DiffPlot {
 public:
  std::optional<std::size_t> draw(const std::shared_ptr<const TraceModel>& a, const std::shared_ptr<const TraceModel>& b, std::size_t step, float height);
  const DiffSeries& series() const { return series_; }  // test hook

 private:
  std::shared_ptr<const TraceModel> a_, b_;  // what vars_ and series_ were computed for
  std::vector<std::string_view> vars_;
  std::string chosen_;
  DiffSeries series_;
};

// Red ticks under the rectangle (x0..x1 at y) of a slider over steps 0..last, one per divergent
// step (those sharing a screen column drawn once).
void draw_divergence_ticks(ImDrawList* dl, const std::vector<std::uint32_t>& steps, std::size_t last, ImVec2 min, ImVec2 max);

// " ≈ 0.333333333" for an exact fraction (a scalar whose text has a '/'), else "".
std::string approx_suffix(const VarState& v);

}  // namespace sw::vis
