// The bench harness: a Spec's seeded input sets run untraced in one numeric mode, timed, and
// compared with exact (`stepwise bench`, BenchRow in catalog.hpp). Filtered mode's later stages
// and exact rationals run where the first stage is uncertain, inside the timing.
#pragma once
#include <algorithm>
#include <chrono>
#include <optional>
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

template <class Spec> std::vector<BenchRow> bench_spec(Numeric n, int repeats, const std::string& only_set) {
  using Output = typename Spec::Output;
  std::vector<BenchRow> rows;
  for (const auto& set : Spec::bench_sets()) {
    if (!only_set.empty() && set.name != only_set) continue;
    if constexpr (names_hook<Spec>(Hook::bench_runs))
      if (!Spec::bench_runs(set.name, n)) continue;
    BenchRow row;
    row.set = set.name;
    row.numeric = n;
    row.cases = set.inputs.size();
    std::vector<Output> exact;
    for (const auto& in : set.inputs) {
      NoProbe none;
      exact.push_back(Spec::template compute<Rational>(Spec::template prepare<Rational>(in), none));
    }
    with_number_type<Spec>(n, [&](auto t) {
      using Num = typename decltype(t)::type;
      std::vector<decltype(Spec::template prepare<Num>(set.inputs[0]))> prepared;
      for (const auto& in : set.inputs) prepared.push_back(Spec::template prepare<Num>(in));
      std::vector<Output> outs(prepared.size());
      const LaterInputs<Spec> later(set.inputs, is_filtered<Num>);
      double best = 1e300;
      for (int r = 0; r < repeats; ++r) {
        row.fallbacks = row.later_stage = 0;
        const auto t0 = std::chrono::steady_clock::now();
        bench_all<Spec, Num>(prepared, later, outs, row);
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      }
      for (std::size_t i = 0; i < outs.size(); ++i) {
        row.ops += Spec::ops(outs[i]);
        if (!(outs[i] == exact[i])) ++row.mismatches;
        if constexpr (names_hook<Spec>(Hook::error))
          row.max_error = std::max(row.max_error, Spec::error(outs[i], exact[i]));
      }
      row.ns_per_op = best * 1e9 / static_cast<double>(std::max<std::size_t>(row.ops, 1));
      return 0;
    });
    rows.push_back(row);
  }
  return rows;
}

}  // namespace sw
