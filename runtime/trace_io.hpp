// Trace files (docs/trace-format.md): the header, writing a trace, running batches, the schema,
// and `check` (check.cpp).
#pragma once
#include <istream>
#include <ostream>
#include <string>
#include "catalog.hpp"

namespace sw {

// The JSON schema of a trace line (docs/trace.schema.json is this, written by `stepwise schema`),
// derived from the step kinds, the geometry table and the numeric modes.
std::string trace_schema();

// The first line of a trace.
std::string trace_header(const Run& run);

// Writes the header, one line per step and {"result":...}.
void write_trace(const Run& run, std::ostream& out);

// Reads one input per line (blank lines skipped), opens them all, then writes one result per
// line. Throws InputError("line K: ...") before writing anything if any input is bad.
// Each input's budget is checked with the rest, before any result.
std::size_t run_batch(const Algorithm& alg, Numeric n, std::istream& inputs, std::ostream& out, const Budget& budget = {});

// How closely `check` holds the numbers of a trace in mode n to the replay's, relative to
// 1 + |expected| (docs/trace-format.md): exact and int 0, float 2^-10, double and filtered 2^-36,
// reference 2^-200.
Rational mode_tolerance(Numeric n);

// A listing line's text as a message shows it: its indentation and column padding collapsed to
// single spaces (check's divergences, list --contract).
std::string listing_text(std::string_view text);

// `stepwise check` (check.cpp): replays a trace in exact (or reference) mode step by step, holding
// its numbers to mode_tolerance, and its result against the oracle.
enum class CheckScope : std::uint8_t {
  everything,  // every step's line, kind, variables and geometry, then the result
  decisions,   // --decisions-only: lines, kinds, integer variables and decision geometry (which may be
               // left out), then the result
  result,      // --results-only: the result alone; the steps are read past, whatever they hold
};
struct CheckReport {
  int status = 0;  // 0 agree, 1 diverge, 2 malformed
  std::string message;
  // At a divergence after step 0: the step before it, as the replay recorded it (its listing line
  // and variables: the values that led to the divergent one), on a line of its own; else empty.
  std::string context;
  std::size_t steps = 0;
};
// The replay's work is held to `budget` (its max_steps) before it starts.
CheckReport check_trace(std::istream& trace, CheckScope scope = CheckScope::everything, const Budget& budget = {});

}  // namespace sw
