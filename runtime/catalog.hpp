// The algorithm catalog: the type-erased face of every algorithm, shared by the CLI, the
// visualizer, the tests and the benchmarks. Each Spec registers itself in its own file with one
// SW_REGISTER line (register.hpp); its family is the folder it is registered in (runtime/<family>/).
#pragma once
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/step.hpp"
#include "input.hpp"
#include "run.hpp"
#include "views.hpp"

namespace sw {

// One benchmark measurement: a seeded input set run untraced in one numeric mode.
struct BenchRow {
  std::string set;
  Numeric numeric = Numeric::f64;
  std::size_t cases = 0, ops = 0;       // ops: output units (pixels, tests), for ns per op
  std::size_t full_cases = 0;           // the set's cases under --full (cases is fewer when capped)
  double ns_per_op = 0;                 // best of the repeats
  std::size_t mismatches = 0;           // cases whose output differs from the judge's
  std::size_t fallbacks = 0;            // filtered mode: cases that needed the exact re-run
  std::size_t later_stage = 0;          // filtered mode: cases a later (slower) filter stage decided
  double max_error = 0;                 // in error_unit (e.g. t error in ulps), 0 if none
  std::string_view error_unit;          // the Spec's error_unit ("ulps", "pixels"); empty: no error measure
  // What the outputs are compared with: exact rationals, else the 300-bit MPFR reference (a Spec
  // whose arithmetic has no exact form), else double itself (a Spec that runs in double only).
  Numeric judge = Numeric::exact;
};

// Where a bench is: computing the judge's outputs for a set, or timing one mode on it.
struct BenchProgress {
  std::string_view set;
  Numeric numeric = Numeric::f64;  // the mode timed, or the judge while `judging`
  bool judging = false;
  std::size_t done = 0, total = 0;  // case runs, over every repeat when timing
};

// How much a bench runs. The one knob for its size is max_cases: each set is cut to at most that
// many cases, evenly spaced through the set (its easy and hard cases alike); 0 runs every case.
struct BenchOptions {
  static constexpr std::size_t kQuickCases = 64;  // the default (`bench` without --full)
  int repeats = 3;
  std::string only_set;                           // "": every set
  std::size_t max_cases = kQuickCases;
  // Called between runs (never inside a timed loop) when set: the CLI's progress line.
  std::function<void(const BenchProgress&)> progress;
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

struct Algorithm;
// What make_algorithm<Spec> (register.hpp) gives an entry besides its facts: the functions that
// need the Spec's types.
struct SpecFunctions {
  std::shared_ptr<const OpenInput> (*open)(const Algorithm&, const Json&);
  Json (*canonical)(Json result);
  std::vector<BenchRow> (*bench)(std::span<const Numeric> modes, const BenchOptions&);
  std::vector<std::string> (*bench_sets)();
  std::size_t (*step_cost)(Numeric);
  // The first `per_set` inputs of each seeded bench set, opened (`list --contract` traces them).
  std::vector<std::shared_ptr<const OpenInput>> (*seeded)(const Algorithm&, std::size_t per_set);
};

struct Algorithm {
  std::string_view id, family, summary;
  Listing listing;
  std::vector<View> views;         // the first is shown first (views.hpp)
  // The table view's rows: steps on these listing lines each start a row (empty: every step).
  std::vector<std::string_view> table_lines;
  SweepInfo sweep;                 // optional: fills the image view (Run::sweep)
  SweepInfo lobe;                  // optional: fills the lobe view (Run::lobe)
  bool outline = false;            // Run::outline gives the exact curve, drawn with the pixels
  std::vector<Param> params;       // optional: sliders
  // Algorithms of one non-empty group take the same input shape and can run side by side (the
  // app's "compare with" another algorithm): keys their examples share carry over.
  std::string_view compare_group;
  std::vector<Handle> handles;
  // Keys every result of this algorithm has (its Spec's result_keys): the only result keys a
  // view may read (visualizer/lessons/result_keys.hpp).
  std::vector<std::string_view> result_keys;
  PictureInfo picture;             // optional: the scene view's picture of the input (Run::picture)
  bool summary_table = false;      // Run::summary_table gives a table from a recorded trace (the ray tree)
  std::vector<Numeric> numerics;  // the number types this algorithm runs on
  std::string example;            // a default input, as JSON text
  // More inputs (JSON text) for `list --contract`: ones that reach listing lines the example and
  // the seeded sets miss (the Spec's contract_inputs).
  std::vector<std::string_view> contract_inputs;
  SpecFunctions fn{};

  // Parses the input once and returns the run handle in mode n; throws InputError naming the
  // problem (bad input, or a mode this algorithm or this input cannot run in).
  Run open(const Json& input, Numeric n) const;
  // The same in the replay mode (`check`, the oracle): exact, else reference, else double.
  Run open(const Json& input) const { return open(input, replay_mode()); }
  Numeric replay_mode() const;

  // A result in the form the oracle states it (sorted, for results the oracle gives as a set).
  Json canonical(Json result) const { return fn.canonical(std::move(result)); }
  // The result members the oracle states as sets (the circles' pixels): canonical() sorts each,
  // as sort_result_set does.
  std::vector<std::string_view> result_sets;
  // Whether canonical() does more than sort result_sets (the Spec's canonical hook: counters of
  // work dropped, a clipped shape reduced).
  bool reshapes_result = false;
  // Times the untraced algorithm in each of `modes` on its seeded bench sets (or options.only_set),
  // against its judge (BenchRow::judge): rows set by set, modes in the order given.
  std::vector<BenchRow> bench(std::span<const Numeric> modes, const BenchOptions& options) const { return fn.bench(modes, options); }
  // The names of those sets, in order (makes the seeded inputs: call it off the UI thread).
  std::vector<std::string> bench_sets() const { return fn.bench_sets(); }
  // What one step costs against the work budget in mode n (measured, docs/cli.md): 1 for most.
  std::size_t step_cost(Numeric n) const { return fn.step_cost(n); }
  // Runs in mode n of the first `per_set` inputs of each seeded bench set.
  std::vector<Run> seeded_runs(std::size_t per_set, Numeric n) const;

  bool supports(Numeric n) const;
  bool declares_result(std::string_view key) const;
  std::string modes_text() const;  // "float, double, exact"
};

// Sorts the member `key` of a result (a set the oracle states): a missing member becomes null.
void sort_result_set(Json& result, std::string_view key);

const std::vector<Algorithm>& catalog();
// Throws InputError("unknown algorithm ...") listing the known ids.
const Algorithm& find_algorithm(std::string_view id);
// The algorithm with this id, or nullptr (a callee such as refract is no algorithm).
const Algorithm* algorithm_by_id(std::string_view id);
// Throws InputError for an unknown name or one the algorithm does not run on.
Numeric parse_numeric_for(const Algorithm& alg, std::string_view name);

// The README's algorithm table: one row per algorithm, grouped by family, with its modes.
std::string catalog_markdown();
// One JSON object per algorithm: id, family, what, modes and its example input (`list --json`).
std::string catalog_jsonl();

// The registrar (SW_REGISTER in register.hpp): adds an entry at start-up. `file` is the Spec's
// source file; its folder names the family.
struct Registrar {
  Registrar(Algorithm (*make)(), const char* file);
};

// Callees that are no algorithm of their own (refract, scene-hit) but whose steps a trace holds
// ("in": "refract"): their listings, registered beside their caller's Spec (SW_REGISTER_CALLEE).
struct CalleeRegistrar {
  CalleeRegistrar(std::string_view id, Listing listing);
};
// The listing of an algorithm or of a registered callee; nullptr if neither has this id.
const Listing* find_listing(std::string_view id);
// Every id find_listing knows, algorithms first.
std::vector<std::string_view> listing_ids();

}  // namespace sw
