// The words and units of bench results, shared by `stepwise bench` (its table, its progress line
// and --plot) and the app's Accuracy window, so that every chart and table names the same units
// and the same judge (exact rationals, or the 300-bit reference where a Spec has no exact mode).
#pragma once
#include <string>
#include <string_view>
#include <vector>
#include "catalog.hpp"

namespace sw {

// "exact", "reference" or "double": what a row's outputs are compared with (BenchRow::judge).
std::string_view judge_name(Numeric judge);
// The judge in a sentence: "exact rationals", "the 300-bit MPFR reference", "double itself".
std::string_view judge_text(Numeric judge);
// "differs from exact (cases)": the mismatch column's heading.
std::string mismatch_label(Numeric judge);
// "max error (ulps)"; "" when the family has no error measure (empty unit).
std::string error_label(std::string_view unit);
// The time column's and axis's name with its unit.
inline constexpr std::string_view kBenchTimeLabel = "time per output unit (ns)";

// The facts every row of one bench shares, from its first row: judge, error unit, and how many
// cases of how many each set ran ("cases: long 4, random 64 of 2000 (quick: --full runs every case
// at full size)"; a set not cut shows its count alone).
struct BenchSummary {
  Numeric judge = Numeric::exact;
  std::string_view error_unit;
  std::string cases;
};
BenchSummary bench_summary(const std::vector<BenchRow>& rows, bool quick);

// "best of 3 repeats"; quick: "best of up to 3 repeats" (a mode stops repeating after 0.5 s);
// "one run" for 1.
std::string repeats_text(int repeats, bool quick);

// The progress line of `stepwise bench` on a terminal, without a line end:
// "bench dda-line: set long, double: 128/192 case runs".
std::string bench_progress_text(std::string_view alg, const BenchProgress& p);

}  // namespace sw
