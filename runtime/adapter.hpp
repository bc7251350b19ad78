// Builds a catalog entry from a typed algorithm spec, so each family writes only what differs.
//
// A Spec provides:
//   using Algo = <the listing struct>;  static constexpr std::string_view family;
//   static constexpr std::array<View, N> views;              // what the visualizer draws
//   static constexpr std::array<Numeric, N> numerics;
//   static inline const std::string example;                 // default input, JSON text
//   struct Input;  struct Output (with ==);
//   static Input parse(const Json&, Numeric);                // validates, throws InputError
//   template <class Num> static auto prepare(const Input&);  // inputs converted to Num
//   template <class Num, class Probe> static Output compute(const Prepared&, Probe&);
//   static Json to_json(const Output&);
//   static std::size_t ops(const Output&);                   // output units, for ns per op
//   static Output oracle(const Input&);                      // independent exact result
//   static std::vector<BenchSet<Input>> bench_sets();        // seeded
// (AlgorithmSpec in spec.hpp checks these.) Optional hooks, each named in the Spec's
// `static constexpr std::array hooks{Hook::...}` (a hook defined but not named, or named but not
// defined, fails to compile):
//             static void write_members(const Output&, std::ostream&) writes the result object's
//             members without braces, for large results (else to_json is used);
//             static double error(const Output& got, const Output& exact), reported as max;
//             static std::size_t estimate_steps(const Input&): an upper estimate the recorder
//             reserves (reserved memory costs nothing until touched; regrowth copies it all);
//             static std::size_t step_cost(Numeric): budget units a step costs in that mode;
//             static Json canonical(Json result): the result in the form the oracle states it
//             (e.g. a set sorted), for comparing with the oracle;
//             static bool bench_runs(set name, Numeric): false skips a set in that mode;
//             static std::vector<Handle> handles(): the inputs a view lets the user drag;
//             the view hooks of sweep.hpp (table_lines, sweeper, outline);
//             using Filters = std::tuple<number types for filtered mode> (default Interval): the
//             stages of the filter, cheapest first. Each must throw Uncertain when it cannot
//             decide, or raise its flag (Mag; see run_filter_stage), and have a NumericOf
//             specialization = filtered; exact rationals follow last.
#pragma once
#include <chrono>
#include <optional>
#include <tuple>
#include <type_traits>
#include "catalog.hpp"
#include "spec.hpp"
#include "core/jsonl_probe.hpp"

namespace sw {

template <class Input> struct BenchSet {
  std::string name;
  std::vector<Input> inputs;
};

template <class Spec> struct FiltersOf {
  using type = std::tuple<Interval>;
};
template <class Spec>
  requires(names_hook<Spec>(Hook::filters))
struct FiltersOf<Spec> {
  using type = typename Spec::Filters;
};
// The first (cheapest) filter stage: the number type of filtered mode's prepared inputs.
template <class Spec> using FirstFilter = std::tuple_element_t<0, typename FiltersOf<Spec>::type>;

template <class Spec> constexpr bool spec_has(Numeric n) {
  for (Numeric m : Spec::numerics)
    if (m == n) return true;
  return false;
}

// Calls f(std::type_identity<Num>{}) for the number type of mode n (FilteredOf for filtered).
template <class Spec, class F> auto with_number_type(Numeric n, F&& f) {
  switch (n) {
    case Numeric::f32: if constexpr (spec_has<Spec>(Numeric::f32)) return f(std::type_identity<float>{}); break;
    case Numeric::f64: if constexpr (spec_has<Spec>(Numeric::f64)) return f(std::type_identity<double>{}); break;
    case Numeric::integer: if constexpr (spec_has<Spec>(Numeric::integer)) return f(std::type_identity<std::int64_t>{}); break;
    case Numeric::filtered: if constexpr (spec_has<Spec>(Numeric::filtered)) return f(std::type_identity<FirstFilter<Spec>>{}); break;
    case Numeric::exact: if constexpr (spec_has<Spec>(Numeric::exact)) return f(std::type_identity<Rational>{}); break;
    case Numeric::reference: if constexpr (spec_has<Spec>(Numeric::reference)) return f(std::type_identity<Rational>{}); break;
  }
  throw InputError(std::string(Spec::Algo::id) + " does not run on '" + std::string(numeric_name(n)) + "'");
}

// Filtered mode: runs the filter stages from `first` on, untraced, and returns f<S>(input, stage)
// for the first stage S that decides every comparison, or f<Rational>(input, number of stages)
// when none does. prep<S>() gives the input prepared for S (it may throw Uncertain).
template <class Spec, class Prep, class F> auto first_certain_stage(Prep&& prep, std::size_t first, F&& f) {
  return [&]<class... S>(std::type_identity<std::tuple<S...>>) {
    using R = decltype(f.template operator()<Rational>(prep.template operator()<Rational>(), std::size_t{0}));
    std::optional<R> out;
    std::size_t stage = 0;
    (void)((stage++ >= first && [&] {
              try {
                out.emplace(run_filter_stage<S>([&] { return f.template operator()<S>(prep.template operator()<S>(), stage - 1); }));
                return true;
              } catch (const Uncertain&) {
                return false;
              }
            }()) || ...);
    if (!out) out.emplace(f.template operator()<Rational>(prep.template operator()<Rational>(), sizeof...(S)));
    return std::move(*out);
  }(std::type_identity<typename FiltersOf<Spec>::type>{});
}
template <class Spec> auto preparer(const typename Spec::Input& in) {
  return [&in]<class S>() { return Spec::template prepare<S>(in); };
}

// Computes the output for mode n. `visit(type_identity<Num>, compute)` makes a probe, calls
// compute(probe) and does what it likes with the probe afterwards. Filtered mode decides first on
// the filter stages, untraced, and traces the first stage that is certain, or exact rationals.
template <class Spec, class Visit>
auto compute_mode(const typename Spec::Input& in, Numeric n, Visit&& visit, bool* fell_back) {
  auto go = [&](auto t) {
    using Num = typename decltype(t)::type;
    const auto prepared = Spec::template prepare<Num>(in);
    return visit(t, [&](auto& probe) { return Spec::template compute<Num>(prepared, probe); });
  };
  *fell_back = false;
  if constexpr (spec_has<Spec>(Numeric::filtered)) {
    if (n == Numeric::filtered) {
      std::size_t stage = 0;
      (void)first_certain_stage<Spec>(preparer<Spec>(in), 0, [&]<class S>(const auto& prepared, std::size_t k) {
        if constexpr (!std::is_same_v<S, Rational>) {
          NoProbe none;
          (void)Spec::template compute<S>(prepared, none);  // undecided: the next stage
        }
        stage = k;
        return 0;
      });
      *fell_back = stage == std::tuple_size_v<typename FiltersOf<Spec>::type>;
      return [&]<class... S>(std::type_identity<std::tuple<S...>>) {
        using R = decltype(go(std::type_identity<Rational>{}));
        std::optional<R> out;
        std::size_t k = 0;
        (void)((k++ == stage && (out.emplace(go(std::type_identity<S>{})), true)) || ...);
        if (!out) out.emplace(go(std::type_identity<Rational>{}));
        return std::move(*out);
      }(std::type_identity<typename FiltersOf<Spec>::type>{});
    }
  }
  return with_number_type<Spec>(n, go);
}

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
  (decided_by == std::tuple_size_v<typename FiltersOf<Spec>::type> ? row.fallbacks : row.later_stage)++;
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

template <class Spec> void fill_view_hooks(Algorithm& a);  // sweep.hpp: table rows, sweep, outline

template <AlgorithmSpec Spec> Algorithm make_algorithm() {
  static_assert(HookNamedAndDefined<hook_mismatch<Spec>()>::ok);
  Algorithm a;
  a.id = Spec::Algo::id;
  a.family = Spec::family;
  a.summary = Spec::Algo::summary;
  a.listing = Spec::Algo::listing();
  a.views.assign(Spec::views.begin(), Spec::views.end());
  if constexpr (names_hook<Spec>(Hook::handles)) a.handles = Spec::handles();
  a.numerics.assign(Spec::numerics.begin(), Spec::numerics.end());
  a.example = Spec::example;
  auto result = [](const auto& out, Numeric n, bool fell_back) {
    Json r = Spec::to_json(out);
    // A rounded mode that produced NaN or an infinity failed; the result says so, whatever else
    // the Spec reports (docs/trace-format.md).
    if (encode_nonfinite(r) && r.is_object() && !r.contains("failure")) r["failure"] = "nan-or-inf";
    if (n == Numeric::filtered) r["fallback"] = fell_back;
    return r;
  };
  a.validate = [](const Json& j, Numeric n) { (void)Spec::parse(j, n); };
  if constexpr (names_hook<Spec>(Hook::estimate_steps)) a.estimate_steps = [](const Json& j, Numeric n) { return std::size_t(Spec::estimate_steps(Spec::parse(j, n))); };
  if constexpr (names_hook<Spec>(Hook::step_cost)) a.step_cost = [](Numeric n) { return std::size_t(Spec::step_cost(n)); };
  a.run = [=](const Json& j, Numeric n) {
    bool fb;
    auto out = compute_mode<Spec>(Spec::parse(j, n), n, [](auto, auto&& compute) {
      NoProbe none;
      return compute(none);
    }, &fb);
    return result(out, n, fb);
  };
  a.record = [=](const Json& j, Numeric n) {
    Recorded rec;
    bool fb;
    const typename Spec::Input in = Spec::parse(j, n);
    auto out = compute_mode<Spec>(in, n, [&](auto t, auto&& compute) {
      auto r = std::make_unique<Recorder<typename decltype(t)::type>>();
      if constexpr (names_hook<Spec>(Hook::estimate_steps)) r->reserve(std::min<std::size_t>(Spec::estimate_steps(in), std::size_t{1} << 27));
      auto o = compute(*r);
      rec.trace = std::move(r);
      return o;
    }, &fb);
    rec.result = result(out, n, fb);
    return rec;
  };
  // The result object, streamed from the output where the Spec writes its members itself.
  auto write_result = [=](const auto& out, Numeric n, bool fb, std::ostream& os) {
    if constexpr (names_hook<Spec>(Hook::write_members)) {
      os << '{';
      Spec::write_members(out, os);
      if (n == Numeric::filtered) os << ",\"fallback\":" << (fb ? "true" : "false");
      os << '}';
    } else {
      os << result(out, n, fb).dump();
    }
  };
  a.stream = [=](const Json& j, Numeric n, std::ostream& os) {
    bool fb;
    auto out = compute_mode<Spec>(Spec::parse(j, n), n, [&](auto t, auto&& compute) {
      JsonlProbe<typename decltype(t)::type> probe(os);
      auto o = compute(probe);
      probe.finish();
      return o;
    }, &fb);
    os << "{\"result\":";
    write_result(out, n, fb, os);
    os << "}\n";
  };
  a.run_to = [=](const Json& j, Numeric n, std::ostream& os) {
    bool fb;
    auto out = compute_mode<Spec>(Spec::parse(j, n), n, [](auto, auto&& compute) {
      NoProbe none;
      return compute(none);
    }, &fb);
    write_result(out, n, fb, os);
    os << '\n';
  };
  a.oracle = [](const Json& j) {
    Json r = Spec::to_json(Spec::oracle(Spec::parse(j, Numeric::exact)));
    encode_nonfinite(r);
    return r;
  };
  if constexpr (names_hook<Spec>(Hook::canonical)) a.canonical = [](const Json& r) { return Spec::canonical(r); };
  else a.canonical = [](const Json& r) { return r; };
  a.bench = [](Numeric n, int repeats, const std::string& only_set) { return bench_spec<Spec>(n, repeats, only_set); };
  a.bench_sets = [] {
    std::vector<std::string> names;
    for (const auto& set : Spec::bench_sets()) names.push_back(set.name);
    return names;
  };
  fill_view_hooks<Spec>(a);
  return a;
}

}  // namespace sw

#include "sweep.hpp"  // the view hooks, built on the helpers above
