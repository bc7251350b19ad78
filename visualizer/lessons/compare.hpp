// Comparing one input run in two number types, step by step (the compare panel), or in two
// algorithms of one compare group (two reflection models side by side).
#pragma once
#include <optional>
#include <string_view>
#include <vector>
#include "lessons/trace_model.hpp"

namespace sw::vis {

// What the right-hand run is: the same algorithm in another number type, or another algorithm of
// the same compare group (Algorithm::compare_group), then in the same number type as the left.
struct Comparison {
  std::optional<Numeric> numeric;    // none: no right-hand run
  const Algorithm* other = nullptr;  // another algorithm, run on the keys its input shares
  Comparison() = default;
  Comparison(std::nullopt_t) {}
  Comparison(Numeric n, const Algorithm* o = nullptr) : numeric(n), other(o) {}
  Comparison(std::optional<Numeric> n) : numeric(n) {}
  explicit operator bool() const { return numeric.has_value(); }
  // The right-hand run's label: its number type, or the other algorithm and its number type.
  std::string label() const;
};

// `name`: a number type alg runs on, or another algorithm of alg's compare group (which then runs
// in `numeric`). Throws InputError naming both kinds.
Comparison parse_comparison(const Algorithm& alg, std::string_view name, Numeric numeric);

// The other algorithm's input: `previous` (its example at first), with every top-level key that
// `input` also has taken from `input` (the shared vectors and parameters carry over).
Json carried_input(const Json& input, const Json& previous);

struct CompareStats {
  std::size_t steps_a = 0, steps_b = 0, pixels_a = 0, pixels_b = 0;
  std::size_t pixel_mismatches = 0;  // cells plotted by one run and not the other
  // First step whose line, kind, integers or pixels differ (or where one trace ends).
  std::optional<std::size_t> first_decision_divergence;
  // First step where a number differs too (as doubles), which is usually earlier.
  std::optional<std::size_t> first_value_divergence;
  // Every step (of those both runs have) whose line, kind, integers or pixels differ, ascending;
  // the timeline's ticks. At most kMaxListed.
  std::vector<std::uint32_t> divergences;
  // The cells plotted by one run and not the other, sorted; both canvases outline them. At most
  // kMaxListed (pixel_mismatches counts them all).
  std::vector<Pixel> mismatched_cells;
  static constexpr std::size_t kMaxListed = 1 << 20;
};

CompareStats compare_traces(const TraceModel& a, const TraceModel& b);
// Whether step s (which both have) agrees in line, kind, scope, integers and decision geometry:
// the rule of first_decision_divergence, as in `check --decisions-only`.
bool same_decisions_at(const TraceModel& a, const TraceModel& b, std::size_t s);

}  // namespace sw::vis
