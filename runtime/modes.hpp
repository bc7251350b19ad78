// Mode dispatch: which number type runs a Spec in each numeric mode, and the filtered mode's chain
// of stages (cheapest first, exact rationals last). The run handle (register.hpp), the bench
// harness (bench_harness.hpp) and the sweeps (sweep.hpp) all compute through these.
#pragma once
#include <optional>
#include <tuple>
#include <type_traits>
#include "spec.hpp"

namespace sw {

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
template <class Spec> constexpr std::size_t kFilterStages = std::tuple_size_v<typename FiltersOf<Spec>::type>;

template <class Spec> constexpr bool spec_has(Numeric n) {
  for (Numeric m : Spec::numerics)
    if (m == n) return true;
  return false;
}

// Calls f(std::type_identity<Num>{}) for the number type of mode n (the first filter stage for
// filtered).
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

// Filtered mode's certification, as a Recorder's Check: every recorded number of a filter stage
// must be certified to kFilteredTraceRel, else the stage is Uncertain. At namespace scope so that
// the three ways a mode is computed (run, record, stream) share one instance of each compute.
template <class S> struct CertifyStep {
  static void check(std::span<const S> xs) {
    for (const S& x : xs)
      if (!num::certified(x, kFilteredTraceRel)) throw Uncertain{};
  }
};

// Computes the output for mode n. `visit(type_identity<Num>, compute)` makes a probe, calls
// compute(probe) and does what it likes with the probe afterwards. Filtered mode decides first on
// the filter stages and traces the first stage that is certain in its decisions and its recorded
// numbers, or exact rationals.
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
          // Undecided, or a recorded number not certified to kFilteredTraceRel: the next stage.
          // The recorder checks each step and forgets it, so memory stays flat.
          Recorder<S, CertifyStep<S>> rec;
          (void)Spec::template compute<S>(prepared, rec);
          CertifyStep<S>::check(rec.numbers());  // the last step's
        }
        stage = k;
        return 0;
      });
      *fell_back = stage == kFilterStages<Spec>;
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

}  // namespace sw
