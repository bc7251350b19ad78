// TraceModel: one recorded run plus the indexes the panels need to stay fluid at 10^6 steps:
// the plotted pixels in plot order (with the step that plotted each), a cell -> first-step lookup,
// and checkpoints of the variable state so that any step's state is a short scan away.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>
#include "catalog.hpp"

namespace sw::vis {

struct PlotEvent {
  Pixel cell;
  std::uint32_t step;
};

struct WorldRect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return !(x1 >= x0 && y1 >= y0); }
  void add(double x, double y);
};

// One named variable as the state panel shows it at a step.
struct VarState {
  std::string_view name;
  std::string text;      // lossless: "p/q" for exact values
  double value = 0;
  bool is_int = false;
  bool set_here = false;  // recorded by this very step
  bool changed = false;   // differs from its value before this step (or new)
  VarShape shape = VarShape::scalar;
  std::array<float, 3> rgb{};  // a colour's components
  std::vector<double> parts{};  // every component of a vector, colour or list (value: the first)
};

// Two runs' values of one variable apart: the scalars' |a - b|, or the largest over a vector's,
// colour's or list's components (NaN where any is); none when the lists' lengths differ.
std::optional<double> value_difference(const VarState& a, const VarState& b);

inline constexpr std::uint32_t kNoStep = 0xffffffffu;

class TraceModel {
 public:
  TraceModel(Run run, Recorded rec);

  // The run handle it was recorded from: the parsed input, for the views' sweeps and outline.
  const Run& run() const { return run_; }
  const Algorithm& algorithm() const { return run_.algorithm(); }
  const Json& input() const { return run_.input(); }
  Numeric numeric() const { return run_.numeric(); }
  const TraceView& trace() const { return *rec_.trace; }
  const Json& result() const { return rec_.result; }
  std::size_t size() const { return rec_.trace->size(); }
  std::size_t last() const { return size() ? size() - 1 : 0; }

  std::span<const PlotEvent> plots() const { return plots_; }
  // How many plot events happened at steps <= step.
  std::size_t plots_through(std::size_t step) const;
  // The colour a step records (a colour variable, e.g. a fill's interpolated attributes) as
  // 0xAABBGGRR, or 0 if it records none: its pixel is painted in it.
  std::uint32_t step_rgba(std::size_t step) const { return step < step_rgba_.size() ? step_rgba_[step] : 0u; }
  // The step that first plotted this cell, or kNoStep.
  std::uint32_t step_of_cell(Pixel c) const;
  // Cells and continuous geometry of the whole trace.
  const WorldRect& bounds() const { return bounds_; }

  // Each declared handle's position (Algorithm::handles, same order); nothing for other kinds
  // than point2 or when the input does not hold it.
  const std::vector<std::optional<std::array<double, 2>>>& handle_points() const { return handles_; }
  // The latest 2D point at or before `step` (the q of a DDA), searching back a bounded way; its
  // label, if any, goes to *label.
  std::optional<std::array<double, 2>> point_at(std::size_t step, const char** label = nullptr) const;
  // The pixel geometry carried by `step`, if any.
  std::optional<Pixel> pixel_at(std::size_t step) const;

  // The geometry items a view shows at `step` (indices for trace().geo_at), by their lifetimes:
  // the kept items of steps <= step, the latest of each replaced label, then the step's own items.
  // A nested call's kept items end with the call (at the next step of the algorithm's own listing):
  // they are the callee's working state; what the caller wants shown, it keeps itself.
  std::vector<std::uint32_t> visible_items(std::size_t step) const;
  // Every kept or replacing item of the whole trace, in order (what a view frames).
  std::span<const std::uint32_t> lasting_items() const { return lasting_; }

  // Every variable seen up to `step` (in first-appearance order) with its latest value.
  std::vector<VarState> state_at(std::size_t step) const;
  std::span<const std::string_view> var_names() const { return names_; }
  // The latest record of the variable `name` at or before `step`; nullptr if none yet. One recorded
  // in the step's own listing (scope) wins over a later one of a callee or caller of the same name,
  // among the last kScopeScan steps.
  const VarRecord* latest_var(std::size_t step, std::string_view name) const;
  static constexpr std::size_t kScopeScan = 4096;

  // First step > from (or < from, backward) of the given kind; nullopt if none.
  std::optional<std::size_t> find_kind(std::size_t from, StepKind kind, bool forward) const;
  // Stepping over nested calls: the first step > from (< from, backward) in from's own listing
  // (scope) or in the algorithm's (scope 0), so a callee's steps are summarised by its caller's.
  std::optional<std::size_t> step_over(std::size_t from, bool forward) const;

 private:
  static constexpr std::size_t kCheckpoint = 256;
  void apply_step(std::size_t step, std::vector<std::uint32_t>& latest) const;

  Run run_;
  Recorded rec_;
  std::vector<PlotEvent> plots_;
  std::vector<PlotEvent> by_cell_;  // sorted by cell, for hover lookups
  std::vector<std::uint32_t> step_rgba_;  // empty when no step records a colour
  WorldRect bounds_;
  std::vector<std::optional<std::array<double, 2>>> handles_;
  std::vector<std::uint32_t> lasting_;  // geometry indices with life keep or replace, by step
  std::vector<std::uint32_t> lasting_end_;  // per lasting item, the first step it is gone (nested calls' items)
  std::vector<std::string_view> names_;
  std::vector<std::uint8_t> name_of_var_;        // var record -> index into names_
  std::vector<std::uint32_t> checkpoints_;       // names_.size() entries per checkpoint
};

// Records the run, held to the budget; throws InputError naming the problem.
std::shared_ptr<const TraceModel> record_model(const Run& run, const Budget& budget = {});
// The same for an input not yet opened (one parse).
std::shared_ptr<const TraceModel> record_model(const Algorithm& alg, const Json& input, Numeric numeric, const Budget& budget = {});

}  // namespace sw::vis
