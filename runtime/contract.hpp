// The trace contract of an algorithm (`stepwise list --contract ALG`): what a student's trace must
// hold for `check` to accept it, generated from the listing and from traces of the algorithm, not
// written per algorithm. The algorithm is traced in check's replay mode on its example, its
// contract inputs and the first inputs of its seeded sets; each listing line (its own, and the
// callees' whose steps a trace holds) lists the step kinds, variables (name and type) and geometry
// items seen there. docs/trace-format.md states the rules the contract summarises.
#pragma once
#include <string>
#include <vector>
#include "catalog.hpp"

namespace sw {

// One form of step seen on a listing line: its kind, variables in the order recorded (type:
// "integer", "exact" or "real", or a vector, colour or list of them) and geometry items in order
// (a kind, with its label; "kind ..." is a run of one or more).
struct ContractStep {
  std::string kind;
  std::vector<std::pair<std::string, std::string>> vars;
  std::vector<std::string> geo;
  bool operator==(const ContractStep&) const = default;
};

struct ContractLine {
  std::string in;  // empty: the algorithm's own listing; else the callee whose listing it is
  std::size_t line = 0;
  std::string name, text;
  std::vector<ContractStep> steps;  // empty: no sample run reached this line
};

struct Contract {
  const Algorithm* algorithm = nullptr;
  Numeric replay = Numeric::exact;  // the mode `check` replays in (an int trace replays in int)
  std::string number_type;          // the replay's numbers: "exact" or "real"
  Json example;                     // the example input
  std::vector<std::pair<std::string, std::string>> result;  // key, type (from the sample runs' results)
  std::vector<ContractLine> lines;  // the algorithm's listing, then each callee's in order of first call
  std::size_t runs = 0, steps = 0;  // sample runs traced, steps seen
};

// Traces the samples (the example first, then others while the steps traced stay within
// kContractMaxSteps) and collects the contract; a callee that is an algorithm adds its own forms.
inline constexpr std::uint64_t kContractMaxSteps = 200'000;
Contract make_contract(const Algorithm& alg);
std::string contract_text(const Contract& c);
std::string contract_json(const Contract& c);  // one line of JSON

}  // namespace sw
