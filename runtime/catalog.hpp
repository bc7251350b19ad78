// The algorithm catalog: the type-erased face of every algorithm, shared by the CLI, the
// visualizer, the tests and the benchmarks. Each family registers its entries (lines.cpp, ...).
#pragma once
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/step.hpp"
#include "input.hpp"
#include "views.hpp"

namespace sw {

// One benchmark measurement: a seeded input set run untraced in one numeric mode.
struct BenchRow {
  std::string set;
  Numeric numeric = Numeric::f64;
  std::size_t cases = 0, ops = 0;       // ops: output units (pixels, tests), for ns per op
  double ns_per_op = 0;                 // best of the repeats
  std::size_t mismatches = 0;           // cases whose output differs from exact
  std::size_t fallbacks = 0;            // filtered mode: cases that needed the exact re-run
  std::size_t later_stage = 0;          // filtered mode: cases a later (slower) filter stage decided
  double max_error = 0;                 // family-defined (e.g. t error in ulps), 0 if none
};

// A recorded run: the steps (random access) and the result as written to JSON.
struct Recorded {
  std::unique_ptr<TraceView> trace;
  Json result;
};

// An input value the user may drag or type on a view: a JSON pointer into the input, what it is,
// and the grid it snaps to (1/snap; an integer input snaps to 1).
struct Handle {
  enum class Kind : std::uint8_t { point2, point3, direction3 };
  std::string pointer;  // e.g. "/p0", "/bezier/2", "/ray/o"
  Kind kind = Kind::point2;
  int snap = 8;
  std::string label;    // drawn beside it
};

// A scalar input the app offers as a slider (a model's exponent, roughness or index).
struct Param {
  std::string pointer;  // e.g. "/shininess", "/material/m"
  std::string label;    // beside the slider
  double lo = 0, hi = 1;
  bool logarithmic = false;  // the slider moves in ratios (exponents, roughness)
  std::string help;          // the tooltip
};

struct Algorithm {
  std::string_view id, family, summary;
  Listing listing;
  std::vector<View> views;         // the first is shown first (views.hpp)
  // The table view's rows: steps on these listing lines each start a row (empty: every step).
  std::vector<std::string_view> table_lines;
  Sweep sweep;                     // optional: fills the image view
  Sweep lobe;                      // optional: fills the lobe view (one row of directions)
  std::vector<Param> params;       // optional: sliders
  // Algorithms of one non-empty group take the same input shape and can run side by side (the
  // app's "compare with" another algorithm): keys their examples share carry over.
  std::string_view compare_group;
  Outline outline;                 // optional: the exact curve, drawn with the pixels
  std::vector<Handle> handles;
  std::vector<Numeric> numerics;  // the number types this algorithm runs on
  std::string example;            // a default input, as JSON text
  // All of these validate the input first and throw InputError naming the problem.
  std::function<void(const Json& input, Numeric)> validate;
  std::function<Recorded(const Json& input, Numeric)> record;
  // Writes one JSON line per step, then the line {"result":...}. Memory stays flat in the
  // number of steps (the result itself is held once, as the algorithm's output).
  std::function<void(const Json& input, Numeric, std::ostream& out)> stream;
  std::function<Json(const Json& input, Numeric)> run;  // untraced
  // run's result as one line, written as it is made (no Json of a large result is built).
  std::function<void(const Json& input, Numeric, std::ostream& out)> run_to;
  // An upper estimate of the steps a run takes (empty if the Spec gives none); the work budget.
  std::function<std::size_t(const Json& input, Numeric)> estimate_steps;
  // What one of those steps costs against the budget in a mode, where a mode's step is much dearer
  // than a line step (measured, docs/cli.md); empty: 1.
  std::function<std::size_t(Numeric)> step_cost;
  // The independent exact oracle's result for this input (brute force, oracle/).
  std::function<Json(const Json& input)> oracle;
  // A result in the form the oracle states it (sorted, for results the oracle gives as a set).
  std::function<Json(const Json& result)> canonical;
  // Times the untraced algorithm on the family's seeded bench sets (or only_set, if not empty),
  // against the exact mode.
  std::function<std::vector<BenchRow>(Numeric, int repeats, const std::string& only_set)> bench;
  // The names of those sets, in order (makes the seeded inputs: call it off the UI thread).
  std::function<std::vector<std::string>()> bench_sets;

  bool supports(Numeric n) const;
};

const std::vector<Algorithm>& catalog();
// Throws InputError("unknown algorithm ...") listing the known ids.
const Algorithm& find_algorithm(std::string_view id);
// Throws InputError for an unknown name or one the algorithm does not run on.
Numeric parse_numeric_for(const Algorithm& alg, std::string_view name);

// The README's algorithm table: one row per algorithm, grouped by family, with its modes.
// One JSON object per algorithm: id, family, what, modes and its example input (`list --json`).
std::string catalog_jsonl();
std::string catalog_markdown();

// Families register themselves here (catalog.cpp calls each once, in this order).
void register_lines(std::vector<Algorithm>& out);
void register_curves(std::vector<Algorithm>& out);
void register_fill(std::vector<Algorithm>& out);
void register_rays(std::vector<Algorithm>& out);
void register_spatial(std::vector<Algorithm>& out);
void register_lighting(std::vector<Algorithm>& out);
void register_tracer(std::vector<Algorithm>& out);

}  // namespace sw
