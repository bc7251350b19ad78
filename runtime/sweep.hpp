// The image and lobe views' sweeps: a Spec run untraced over a grid of inputs made from one parsed
// input (the run handle's, register.hpp). The Spec's optional sweep hooks (spec.hpp):
//   template <class Num> static auto sweeper(const Input& base, const SweepGrid&);  // returns
//       f(i, j, Prepared& p), which sets what varies at sample (i, j) in p = prepare<Num>(base)
//   static float sweep_value(const Output&);                  // NaN for none (a miss)
//   template <class Num> static auto lobe_sweeper(const Input& base, const SweepGrid&);  // the lobe
//       view's sweep: sample (i, 0) is the direction at angle g.x(i) degrees (sweep_value as above)
#pragma once
#include <limits>
#include <optional>
#include <tuple>
#include <type_traits>
#include "modes.hpp"

namespace sw {

template <class Spec, class N> using SweepPrepared = decltype(Spec::template prepare<N>(std::declval<const typename Spec::Input&>()));

// Which of a Spec's sweeps: the image view's grid, or the lobe view's row of directions.
struct ImageSweep {
  template <class Spec, class N> static auto setter(const typename Spec::Input& in, const SweepGrid& g) { return Spec::template sweeper<N>(in, g); }
};
struct LobeSweep {
  template <class Spec, class N> static auto setter(const typename Spec::Input& in, const SweepGrid& g) { return Spec::template lobe_sweeper<N>(in, g); }
};
template <class Spec, class N, class Which>
using SweepSetter = decltype(Which::template setter<Spec, N>(std::declval<const typename Spec::Input&>(), std::declval<const SweepGrid&>()));

// Filtered and exact sweeps: each sample through the filter stages, then exact rationals where
// none decides, so the values equal exact. One prepared input per stage, changed in place.
template <class Spec, class Which, class Stages = typename FiltersOf<Spec>::type> struct CertifiedSweep;
template <class Spec, class Which, class... S> struct CertifiedSweep<Spec, Which, std::tuple<S...>> {
  template <class N> struct Stage {
    std::optional<SweepPrepared<Spec, N>> prepared;  // none: the stage cannot take the input
    SweepSetter<Spec, N, Which> set;
    Stage(const typename Spec::Input& in, const SweepGrid& g) : set(Which::template setter<Spec, N>(in, g)) {
      try {
        prepared.emplace(Spec::template prepare<N>(in));
      } catch (const Uncertain&) {
      }
    }
  };
  std::tuple<Stage<S>..., Stage<Rational>> stages;
  CertifiedSweep(const typename Spec::Input& in, const SweepGrid& g) : stages(Stage<S>(in, g)..., Stage<Rational>(in, g)) {}
  template <class N> static constexpr std::size_t index() {  // by position, as in LaterInputs
    constexpr bool same[] = {std::is_same_v<N, S>..., false};
    for (std::size_t k = 0; k < sizeof...(S); ++k)
      if (same[k]) return k;
    return sizeof...(S);
  }
  float at(int x, int y) {
    NoProbe none;
    auto prep = [&]<class N>() -> const auto& {
      auto& st = std::get<index<N>()>(stages);
      if (!st.prepared) throw Uncertain{};
      st.set(x, y, *st.prepared);
      return *st.prepared;
    };
    return Spec::sweep_value(first_certain_stage<Spec>(prep, 0, [&]<class N>(const auto& p, std::size_t) {
      return Spec::template compute<N>(p, none);
    }));
  }
};

// Runs Spec untraced over the grid (Run::sweep): the input is prepared once per number type and
// the Spec's sweeper (Which) changes what varies, sample by sample.
template <class Spec, class Which> void run_sweep(const typename Spec::Input& base, Numeric n, const SweepGrid& g, std::vector<float>& out) {
  out.assign(static_cast<std::size_t>(std::max(g.w, 0)) * static_cast<std::size_t>(std::max(g.h, 0)),
             std::numeric_limits<float>::quiet_NaN());
  auto each = [&](auto&& value) {
    for (int y = 0; y < g.h; ++y)
      for (int x = 0; x < g.w; ++x) out[static_cast<std::size_t>(y) * g.w + x] = value(x, y);
  };
  if constexpr (spec_has<Spec>(Numeric::filtered)) {
    if (n == Numeric::filtered || n == Numeric::exact) {
      CertifiedSweep<Spec, Which> sweep(base, g);
      each([&](int x, int y) { return sweep.at(x, y); });
      return;
    }
  }
  with_number_type<Spec>(n, [&](auto t) {
    using Num = typename decltype(t)::type;
    auto p = Spec::template prepare<Num>(base);
    auto set = Which::template setter<Spec, Num>(base, g);
    NoProbe none;
    each([&](int x, int y) {
      set(x, y, p);
      return Spec::sweep_value(Spec::template compute<Num>(p, none));
    });
    return 0;
  });
}

}  // namespace sw
