// The run handle: one algorithm opened on one input. Algorithm::open parses the JSON once (a mesh
// file is read once) into the Spec's Input; everything a front end does with that input goes
// through the handle: the budget estimate, the untraced run, the recorded or streamed trace, the
// oracle, the views' sweeps and outline. The CLI, the app, `check`, the tests, the benches and the
// fuzz harnesses all enter here (docs/architecture.md).
#pragma once
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <vector>
#include "core/probe.hpp"
#include "budget.hpp"
#include "input.hpp"
#include "views.hpp"

namespace sw {

struct Algorithm;

// A recorded run: the steps (random access) and the result as written to JSON.
struct Recorded {
  std::unique_ptr<TraceView> trace;
  Json result;
};

// The parsed input, as each Spec's entry builds it (register.hpp); front ends hold it through Run.
// Every computation takes the numeric mode, so runs in several modes share one parse.
class OpenInput {
 public:
  virtual ~OpenInput() = default;
  const Algorithm& algorithm() const { return *alg_; }
  const Json& json() const { return json_; }

  // Throws InputError if this input cannot run in mode n (int mode takes integer inputs, say).
  virtual void admit(Numeric n) const = 0;
  // An upper estimate of the steps a run takes, if the Spec gives one.
  virtual std::optional<std::uint64_t> estimate_steps() const = 0;
  virtual Json run(Numeric) const = 0;
  virtual void run_to(Numeric, std::ostream& out) const = 0;
  virtual Recorded record(Numeric) const = 0;
  virtual void stream(Numeric, std::ostream& out) const = 0;
  virtual Json oracle() const = 0;
  virtual void oracle_to(std::ostream& out) const = 0;
  // The views' hooks (views.hpp); only those the algorithm declares (Algorithm::sweep, ...) are
  // called, and the others throw std::logic_error.
  virtual void sweep(Numeric, const SweepGrid&, std::vector<float>& out) const;
  virtual std::optional<std::array<double, 2>> sweep_marker() const;
  virtual Json sweep_sample(const SweepGrid&, int i, int j) const;
  virtual void lobe(Numeric, const SweepGrid&, std::vector<float>& out) const;
  virtual std::optional<std::array<double, 2>> lobe_angles() const;
  virtual Json lobe_sample(const SweepGrid&, int i) const;
  virtual std::vector<Polyline2> outline(const Rect2& window, double cell) const;
  virtual Picture picture(std::int64_t max_side) const;
  virtual SummaryTable summary_table(const TraceView& trace) const;

 protected:
  OpenInput(const Algorithm& alg, const Json& json);

 private:
  const Algorithm* alg_;
  Json json_;
};

// How many inputs have been parsed (opened) in this process: the parse-once tests read it.
std::uint64_t inputs_opened();

class Run {
 public:
  Run(std::shared_ptr<const OpenInput> in, Numeric n);

  const Algorithm& algorithm() const { return in_->algorithm(); }
  const Json& input() const { return in_->json(); }  // as given
  Numeric numeric() const { return n_; }
  // The same parsed input in another mode; throws InputError if the algorithm cannot run it so.
  Run in(Numeric other) const { return Run(in_, other); }

  // An upper estimate of the steps a run takes, if the Spec gives one (the recorder reserves it).
  std::optional<std::uint64_t> estimate_steps() const { return in_->estimate_steps(); }
  // The work budget (budget.hpp): the estimated steps, times what a step costs in this mode and on
  // numbers this long; nullopt when the Spec gives no estimate (constant or parse-bounded work).
  std::optional<std::uint64_t> budget_units() const;
  // Throws InputError naming the estimate, the budget and the flag that raises it.
  void check_budget(const Budget& budget) const;

  Json run() const { return in_->run(n_); }  // untraced
  // run()'s result as one line, written as it is made (no Json of a large result is built).
  void run_to(std::ostream& out) const { in_->run_to(n_, out); }
  Recorded record() const { return in_->record(n_); }
  // One JSON line per step, then {"result":...}; memory stays flat in the number of steps.
  void stream(std::ostream& out) const { in_->stream(n_, out); }
  // The independent oracle's result (brute force, oracle/), whatever this run's mode.
  Json oracle() const { return in_->oracle(); }
  // The same as JSON text, written as it is made where the Spec writes its members (as run_to).
  void oracle_to(std::ostream& out) const { in_->oracle_to(out); }

  void sweep(const SweepGrid& g, std::vector<float>& out) const { in_->sweep(n_, g, out); }
  std::optional<std::array<double, 2>> sweep_marker() const { return in_->sweep_marker(); }
  Json sweep_sample(const SweepGrid& g, int i, int j) const { return in_->sweep_sample(g, i, j); }
  void lobe(const SweepGrid& g, std::vector<float>& out) const { in_->lobe(n_, g, out); }
  std::optional<std::array<double, 2>> lobe_angles() const { return in_->lobe_angles(); }
  Json lobe_sample(const SweepGrid& g, int i) const { return in_->lobe_sample(g, i); }
  std::vector<Polyline2> outline(const Rect2& window, double cell) const { return in_->outline(window, cell); }
  // A picture of the input, at most max_side pixels on a side (Algorithm::picture).
  Picture picture(std::int64_t max_side) const { return in_->picture(max_side); }
  // The algorithm's table of a trace recorded from this input (Algorithm::summary_table).
  SummaryTable summary_table(const TraceView& trace) const { return in_->summary_table(trace); }

 private:
  std::shared_ptr<const OpenInput> in_;
  Numeric n_;
};

}  // namespace sw
