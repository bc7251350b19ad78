#include "run.hpp"
#include <stdexcept>
#include "catalog.hpp"

namespace sw {

namespace {
std::atomic<std::uint64_t> g_opened{0};
[[noreturn]] void undeclared(const Algorithm& alg, const char* hook) {
  throw std::logic_error(std::string(alg.id) + " declares no " + hook);
}
}  // namespace

std::uint64_t inputs_opened() { return g_opened.load(); }

OpenInput::OpenInput(const Algorithm& alg, const Json& json) : alg_(&alg), json_(json) { ++g_opened; }

void OpenInput::sweep(Numeric, const SweepGrid&, std::vector<float>&) const { undeclared(*alg_, "sweep"); }
std::optional<std::array<double, 2>> OpenInput::sweep_marker() const { return std::nullopt; }
Json OpenInput::sweep_sample(const SweepGrid&, int, int) const { undeclared(*alg_, "sweep sample"); }
void OpenInput::lobe(Numeric, const SweepGrid&, std::vector<float>&) const { undeclared(*alg_, "lobe"); }
std::optional<std::array<double, 2>> OpenInput::lobe_angles() const { return std::nullopt; }
Json OpenInput::lobe_sample(const SweepGrid&, int) const { undeclared(*alg_, "lobe sample"); }
std::vector<Polyline2> OpenInput::outline(const Rect2&, double) const { undeclared(*alg_, "outline"); }
Picture OpenInput::picture(std::int64_t) const { undeclared(*alg_, "picture"); }
SummaryTable OpenInput::summary_table(const TraceView&) const { undeclared(*alg_, "summary table"); }

Run::Run(std::shared_ptr<const OpenInput> in, Numeric n) : in_(std::move(in)), n_(n) {
  const Algorithm& alg = in_->algorithm();
  if (!alg.supports(n)) throw InputError(std::string(alg.id) + " does not run on '" + std::string(numeric_name(n)) + "' (it runs on: " + alg.modes_text() + ")");
  in_->admit(n);
}

std::optional<std::uint64_t> Run::budget_units() const {
  const auto steps = in_->estimate_steps();
  if (!steps) return std::nullopt;
  return saturating_product({*steps, algorithm().step_cost(n_), step_weight(input(), n_)});
}

void Run::check_budget(const Budget& budget) const {
  const auto units = budget_units();
  if (!units || *units <= budget.max_steps) return;
  const Algorithm& alg = algorithm();
  const std::uint64_t cost = alg.step_cost(n_), weight = step_weight(input(), n_);
  std::string why;
  if (cost > 1) why += " x " + std::to_string(cost) + " for " + std::string(alg.id) + "'s steps in " + std::string(numeric_name(n_));
  if (weight > 1) why += " x " + std::to_string(weight) + " for exact numbers of " + std::to_string(longest_string(input())) + " characters";
  throw InputError("this input implies up to " + std::to_string(*in_->estimate_steps()) + " steps" + why + ", more than the budget of " +
                   std::to_string(budget.max_steps) + " (--max-steps raises it)");
}

}  // namespace sw
