// Trace files (docs/trace-format.md): writing them atomically, running batches, and `check`.
#pragma once
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <string>
#include "catalog.hpp"

namespace sw {

// An output file (--out), the way cp and tee treat their target (docs/cli.md):
// - a new or regular file is written under a temporary name beside it and renamed into place by
//   commit(); if it is never committed (an error on the way) the temporary is removed, and so it
//   is on SIGINT or SIGTERM: no partial output file;
// - a symbolic link is followed: its final target is replaced that way, and the link stays;
// - a FIFO or a character device (/dev/stdout, /dev/null) is written through, in place;
// - a directory, a socket or a block device is refused (InputError).
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  std::ostream& stream() { return out_; }
  void commit();

 private:
  std::filesystem::path target_, temp_;  // temp_ empty: written through
  std::ofstream out_;
  bool committed_ = false;
};

// The work budget of trace, run and render (docs/cli.md): the steps an input implies, estimated
// before running (Algorithm::estimate_steps), and the bytes written. The defaults keep the largest
// accepted input within about 10 s and 1 GB on a 2-core machine.
struct Budget {
  std::uint64_t max_steps = 4'000'000;
  std::uint64_t max_output = std::uint64_t{1} << 30;
};
// In exact and filtered modes a step costs more the longer the input's exact numbers: a step counts
// 1 + (longest string) / kDigitsPerWeight against max_steps (measured on dda-grid-walk: 1.3 us a
// step at 1 character, 5.5 us at 2000, 12 us at 4000; docs/cli.md).
inline constexpr std::size_t kDigitsPerWeight = 400;
std::uint64_t step_weight(const Json& input, Numeric n);
// Throws InputError naming the estimate, the budget and the flag that raises it.
void check_budget(const Algorithm& alg, const Json& input, Numeric n, const Budget& budget);

// A stream that passes bytes on to `out` and throws InputError once more than `max` have passed
// (naming --max-output). The caller's AtomicFile then leaves no file behind.
class BudgetedStream : public std::ostream {
 public:
  BudgetedStream(std::ostream& out, std::uint64_t max);

 private:
  struct Buf : std::streambuf {
    std::ostream* out = nullptr;
    std::uint64_t max = 0, written = 0;
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* s, std::streamsize n) override;
    void count(std::streamsize n);
  } buf_;
};

// The JSON schema of a trace line (docs/trace.schema.json is this, written by `stepwise schema`),
// derived from the step kinds, the geometry table and the numeric modes.
std::string trace_schema();

// The first line of a trace.
std::string trace_header(const Algorithm& alg, Numeric n, const Json& input);

// Writes the header, one line per step and {"result":...}.
void write_trace(const Algorithm& alg, Numeric n, const Json& input, std::ostream& out);

// Reads one input per line (blank lines skipped), validates them all, then writes one result per
// line. Throws InputError("line K: ...") before writing anything if any input is bad.
// Each input's budget is checked with the rest, before any result.
std::size_t run_batch(const Algorithm& alg, Numeric n, std::istream& inputs, std::ostream& out, const Budget& budget = {});

// How closely `check` holds the numbers of a trace in mode n to the replay's, relative to
// 1 + |expected| (docs/trace-format.md): exact and int 0, float 2^-10, double and filtered 2^-36,
// reference 2^-200.
Rational mode_tolerance(Numeric n);

// `stepwise check` (check.cpp): replays a trace in exact (or reference) mode step by step, holding
// its numbers to mode_tolerance, and its result against the oracle. decisions_only compares
// lines, kinds, integer variables and decision geometry, not numbers.
struct CheckReport {
  int status = 0;  // 0 agree, 1 diverge, 2 malformed
  std::string message;
  std::size_t steps = 0;
};
// The replay's work is held to `budget` (its max_steps) before it starts.
CheckReport check_trace(std::istream& trace, bool decisions_only, const Budget& budget = {});

}  // namespace sw
