// Trace files (docs/trace-format.md): the header, writing a trace, running batches.
#include "trace_io.hpp"
#include <algorithm>

namespace sw {

std::string trace_header(const Run& run) {
  const Algorithm& alg = run.algorithm();
  const Numeric n = run.numeric();
  nlohmann::ordered_json h;  // keeps the documented key order
  h["format"] = "stepwise-trace";
  h["version"] = 2;
  h["algorithm"] = alg.id;
  h["numeric"] = numeric_name(n);
  h["input"] = nlohmann::ordered_json::parse(run.input().dump());
  // How closely `check` holds this trace's numbers to the replay's (0: exactly).
  h["tolerance"] = mode_tolerance(n).get_str();
  nlohmann::ordered_json names = nlohmann::ordered_json::array();
  for (const ListingLine& l : alg.listing.lines) names.push_back(l.name);
  h["listing"] = std::move(names);  // step "line" k is listing[k - 1]
  return h.dump();
}

void write_trace(const Run& run, std::ostream& out) {
  out << trace_header(run) << '\n';
  run.stream(out);
}

std::size_t run_batch(const Algorithm& alg, Numeric n, std::istream& in, std::ostream& out, const Budget& budget) {
  std::vector<Run> runs;
  std::string line;
  for (std::size_t k = 1; read_line(in, line, kMaxJsonBytes, "line " + std::to_string(k)); ++k) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      Run run = alg.open(parse_json_text(line, "input"), n);
      run.check_budget(budget);
      runs.push_back(std::move(run));
    } catch (const InputError& e) {
      throw InputError("line " + std::to_string(k) + ": " + e.what());
    }
  }
  for (const Run& run : runs) run.run_to(out);
  return runs.size();
}

std::string listing_text(std::string_view text) {
  std::string s;
  for (char c : text)
    if (c != ' ' || (!s.empty() && s.back() != ' ')) s += c;
  return s;
}

// Exact and int traces are exact; float, double and filtered traces are rounded by design;
// reference traces carry the 300-bit functions' rounding.
Rational mode_tolerance(Numeric n) {
  auto pow2 = [](int e) { return Rational(1, mpz_class(1) << e); };
  switch (n) {
    case Numeric::f32: return pow2(10);
    case Numeric::f64:
    case Numeric::filtered: return pow2(36);
    case Numeric::reference: return pow2(200);
    case Numeric::integer:
    case Numeric::exact: return 0;
  }
  return 0;
}

}  // namespace sw
