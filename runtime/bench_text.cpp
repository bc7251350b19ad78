#include "bench_text.hpp"
#include <algorithm>

namespace sw {

std::string_view judge_name(Numeric judge) {
  switch (judge) {
    case Numeric::exact: return "exact";
    case Numeric::reference: return "reference";
    default: return numeric_name(judge);
  }
}

std::string_view judge_text(Numeric judge) {
  switch (judge) {
    case Numeric::exact: return "exact rationals";
    case Numeric::reference: return "the 300-bit MPFR reference";
    default: return "double itself (no exact or reference mode)";
  }
}

std::string mismatch_label(Numeric judge) { return "differs from " + std::string(judge_name(judge)) + " (cases)"; }

std::string error_label(std::string_view unit) { return unit.empty() ? std::string() : "max error (" + std::string(unit) + ")"; }

BenchSummary bench_summary(const std::vector<BenchRow>& rows, bool quick) {
  BenchSummary s;
  if (rows.empty()) return s;
  s.judge = rows.front().judge;
  s.error_unit = rows.front().error_unit;
  std::vector<std::string_view> seen;
  for (const BenchRow& r : rows) {
    if (std::find(seen.begin(), seen.end(), r.set) != seen.end()) continue;
    seen.push_back(r.set);
    s.cases += (s.cases.empty() ? "" : ", ") + r.set + " " + std::to_string(r.cases) + (r.cases < r.full_cases ? " of " + std::to_string(r.full_cases) : "");
  }
  s.cases = "cases: " + s.cases + (quick ? " (quick: --full runs every case at full size)" : "");
  return s;
}

std::string repeats_text(int repeats, bool quick) {
  if (repeats <= 1) return "one run";
  return (quick ? "best of up to " : "best of ") + std::to_string(repeats) + " repeats";
}

std::string bench_progress_text(std::string_view alg, const BenchProgress& p) {
  std::string s = "bench " + std::string(alg) + ": set " + std::string(p.set) + ", ";
  if (p.judging) s += std::string(judge_name(p.numeric)) + " outputs to compare with: " + std::to_string(p.done) + "/" + std::to_string(p.total) + " cases";
  else s += std::string(numeric_name(p.numeric)) + ": " + std::to_string(p.done) + "/" + std::to_string(p.total) + " case runs";
  return s;
}

}  // namespace sw
