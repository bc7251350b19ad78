// The bench harness: a Spec's seeded input sets (each cut to BenchOptions::max_cases) run untraced
// in each numeric mode asked, timed, and compared with the judge's outputs: exact rationals, or
// the 300-bit reference where the Spec has no exact mode (`stepwise bench`, BenchRow in
// catalog.hpp). Filtered mode's later stages and exact rationals run where the first stage is
// uncertain, inside the timing.
#pragma once
#include <algorithm>
#include <chrono>
#include <optional>
#include <span>
#include <tuple>
#include <type_traits>
#include "modes.hpp"

namespace sw {

template <class Input> struct BenchSet {
  std::string name;
  std::vector<Input> inputs;
};

// Inputs prepared ahead (outside the timing, as for every mode) for the filter stages after the
// first (whose inputs the bench loop holds) and for exact rationals; nullopt where a stage cannot
// take the input. Empty unless `needed` (filtered mode).
template <class Spec, class Stages = typename FiltersOf<Spec>::type> struct LaterInputs;
template <class Spec, class... S> struct LaterInputs<Spec, std::tuple<S...>> {
  template <class N> using Column = std::vector<std::optional<decltype(Spec::template prepare<N>(std::declval<const typename Spec::Input&>()))>>;
  std::tuple<Column<S>..., Column<Rational>> columns;
  // Columns are found by the stage's position, since two stages may prepare the same type.
  template <class N> static constexpr std::size_t index() {
    constexpr bool same[] = {std::is_same_v<N, S>..., false};
    for (std::size_t k = 0; k < sizeof...(S); ++k)
      if (same[k]) return k;
    return sizeof...(S);
  }

  LaterInputs(const std::vector<typename Spec::Input>& inputs, bool needed) {
    if (!needed) return;
    std::size_t stage = 0;
    ((stage++ > 0 ? fill<S>(inputs) : void()), ...);
    fill<Rational>(inputs);
  }
  template <class N> const auto& at(std::size_t i) const {
    const auto& p = std::get<index<N>()>(columns)[i];
    if (!p) throw Uncertain{};
    return *p;
  }

 private:
  template <class N> void fill(const std::vector<typename Spec::Input>& inputs) {
    auto& column = std::get<index<N>()>(columns);
    for (const auto& in : inputs) {
      try {
        column.emplace_back(Spec::template prepare<N>(in));
      } catch (const Uncertain&) {
        column.emplace_back();
      }
    }
  }
};

// The later filter stages and exact rationals for case i, counting who decided.
template <class Spec> [[gnu::noinline]] typename Spec::Output bench_later_stages(const LaterInputs<Spec>& later, std::size_t i, BenchRow& row) {
  NoProbe none;
  auto prep = [&]<class S>() -> const auto& { return later.template at<S>(i); };
  std::size_t decided_by = 0;
  auto out = first_certain_stage<Spec>(prep, 1, [&]<class S>(const auto& p, std::size_t stage) {
    decided_by = stage;
    return Spec::template compute<S>(p, none);
  });
  (decided_by == kFilterStages<Spec> ? row.fallbacks : row.later_stage)++;
  return out;
}

// One untraced run for benchmarks, into out. Filtered mode runs its first stage on the prepared
// input and, when that is uncertain, the later stages (a cost the timing includes). A flagging
// first stage needs no try block in the loop, and assigning to out directly (rather than returning
// one of two results) keeps the output out of a stack temporary.
template <class Spec, class Num>
[[gnu::always_inline]] inline void bench_one(const auto& prepared, const LaterInputs<Spec>& later, std::size_t i, typename Spec::Output& out, BenchRow& row) {
  NoProbe none;
  if constexpr (requires { Num::uncertain(); }) {
    Num::clear_uncertain();
    out = Spec::template compute<Num>(prepared, none);
    if (Num::uncertain()) [[unlikely]]
      out = bench_later_stages<Spec>(later, i, row);
  } else if constexpr (is_filtered<Num>) {
    try {
      out = Spec::template compute<Num>(prepared, none);
    } catch (const Uncertain&) {
      out = bench_later_stages<Spec>(later, i, row);
    }
  } else {
    out = Spec::template compute<Num>(prepared, none);
  }
}

// The timed loop, in a function of its own at a fixed alignment, so that its code layout (and so
// its speed) does not shift with unrelated code around it: without this, one edit elsewhere in the
// binary moved ray-plane's double time from 3.4 to 5.2 ns.
template <class Spec, class Num>
[[gnu::noinline, gnu::aligned(64)]] void bench_all(const auto& prepared, const LaterInputs<Spec>& later, std::vector<typename Spec::Output>& outs, BenchRow& row) {
  for (std::size_t i = 0; i < prepared.size(); ++i) bench_one<Spec, Num>(prepared[i], later, i, outs[i], row);
}

// What a Spec's bench compares with: exact rationals, else the 300-bit reference (whose compute
// runs on Rational too), else double itself.
template <class Spec> constexpr Numeric bench_judge() {
  return spec_has<Spec>(Numeric::exact) ? Numeric::exact : spec_has<Spec>(Numeric::reference) ? Numeric::reference : Numeric::f64;
}

// At most max_cases of `inputs` (0: all), evenly spaced through them, in their order.
template <class Input> std::vector<Input> bench_cases(std::vector<Input>&& inputs, std::size_t max_cases) {
  if (max_cases == 0 || inputs.size() <= max_cases) return std::move(inputs);
  std::vector<Input> out;
  out.reserve(max_cases);
  for (std::size_t k = 0; k < max_cases; ++k) out.push_back(std::move(inputs[k * inputs.size() / max_cases]));
  return out;
}

// Quick benches stop repeating a mode once its repeats have taken this long (at least one runs).
inline constexpr double kQuickRepeatSeconds = 0.5;

// One mode on one set's cases, timed (best of the repeats) and compared with the judge's outputs.
template <class Spec, class Num>
void bench_mode(const std::vector<typename Spec::Input>& inputs, const std::vector<typename Spec::Output>& judged, const BenchOptions& options,
                BenchRow& row) {
  using Output = typename Spec::Output;
  std::vector<decltype(Spec::template prepare<Num>(inputs[0]))> prepared;
  for (const auto& in : inputs) prepared.push_back(Spec::template prepare<Num>(in));
  std::vector<Output> outs(prepared.size());
  const LaterInputs<Spec> later(inputs, is_filtered<Num>);
  const std::size_t runs = std::size_t(std::max(options.repeats, 1)) * inputs.size();
  double best = 1e300, spent = 0;
  for (int r = 0; r < options.repeats; ++r) {
    // Quick (max_cases set): no further repeat once the mode has had its time budget.
    if (r > 0 && options.max_cases != 0 && spent > kQuickRepeatSeconds) break;
    if (options.progress) options.progress({row.set, row.numeric, false, std::size_t(r) * inputs.size(), runs});  // between timed loops
    row.fallbacks = row.later_stage = 0;
    const auto t0 = std::chrono::steady_clock::now();
    bench_all<Spec, Num>(prepared, later, outs, row);
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::min(best, took), spent += took;
  }
  for (std::size_t i = 0; i < outs.size(); ++i) {
    row.ops += Spec::ops(outs[i]);
    if (!(outs[i] == judged[i])) ++row.mismatches;
    if constexpr (names_hook<Spec>(Hook::error)) row.max_error = std::max(row.max_error, Spec::error(outs[i], judged[i]));
  }
  row.ns_per_op = best * 1e9 / static_cast<double>(std::max<std::size_t>(row.ops, 1));
}

// Every mode of `modes` on each set: the sets are made, and the judge's outputs computed, once
// for all the modes.
template <class Spec> std::vector<BenchRow> bench_spec(std::span<const Numeric> modes, const BenchOptions& options) {
  using Output = typename Spec::Output;
  for (Numeric n : modes) with_number_type<Spec>(n, [](auto) { return 0; });  // a mode it lacks: refused before any work
  std::vector<BenchRow> rows;
  for (auto& set : make_bench_sets<Spec>(options.max_cases == 0 ? BenchSize::full : BenchSize::quick)) {
    if (!options.only_set.empty() && set.name != options.only_set) continue;
    const std::size_t full_cases = set.inputs.size();
    std::vector<typename Spec::Input> inputs = bench_cases(std::move(set.inputs), options.max_cases);
    // The judge's outputs, once for every mode. A quick bench stays deterministic: the same cases
    // on every machine, its heavy Specs' sets made small by their generators (bench_sets(BenchSize)).
    std::vector<Output> judged;
    judged.reserve(inputs.size());
    for (const auto& in : inputs) {
      if (options.progress) options.progress({set.name, bench_judge<Spec>(), true, judged.size(), inputs.size()});
      NoProbe none;
      judged.push_back(Spec::template compute<Rational>(Spec::template prepare<Rational>(in), none));
    }
    for (Numeric n : modes) {
      if constexpr (names_hook<Spec>(Hook::bench_runs))
        if (!Spec::bench_runs(set.name, n)) continue;
      BenchRow row;
      row.set = set.name;
      row.numeric = n;
      row.cases = inputs.size();
      row.full_cases = full_cases;
      row.judge = bench_judge<Spec>();
      if constexpr (names_hook<Spec>(Hook::error)) row.error_unit = Spec::error_unit;
      if (!inputs.empty()) with_number_type<Spec>(n, [&](auto t) { return bench_mode<Spec, typename decltype(t)::type>(inputs, judged, options, row), 0; });
      rows.push_back(row);
    }
  }
  return rows;
}

}  // namespace sw
