// Comparing one input run in two number types, step by step (the compare panel).
#pragma once
#include <optional>
#include "trace_model.hpp"

namespace sw::vis {

struct CompareStats {
  std::size_t steps_a = 0, steps_b = 0, pixels_a = 0, pixels_b = 0;
  std::size_t pixel_mismatches = 0;  // cells plotted by one run and not the other
  // First step whose line, kind, integers or pixels differ (or where one trace ends).
  std::optional<std::size_t> first_decision_divergence;
  // First step where a number differs too (as doubles), which is usually earlier.
  std::optional<std::size_t> first_value_divergence;
};

CompareStats compare_traces(const TraceModel& a, const TraceModel& b);

}  // namespace sw::vis
