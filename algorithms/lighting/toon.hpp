// Toon shading: a cut-off applied to any diffuse model's term d: 1 where d >= cutoff, else 0.
// The diffuse model runs as a nested listing. The cut is decided exactly when the caller can
// (ModelParams::toon_above: the runtime decides it on the exact input, see docs/lighting/
// semantics.md), else on the mode's value of d.
#pragma once
#include <string_view>
#include "lighting/lambert.hpp"
#include "lighting/minnaert.hpp"
#include "lighting/oren_nayar.hpp"

namespace sw::lighting {

struct Toon {
  static constexpr std::string_view id = "toon";
  static constexpr std::string_view summary = "Toon cut-off of a diffuse term (lambert, minnaert, oren-nayar), one light";
#define SW_LIGHTING_TOON(X) \
  SW_LIGHTING_FRAME_LINES(X) \
  X(diffuse, "d <- the diffuse model's term               -- nested listing") \
  X(cut, "t <- 1 if d >= cutoff, else 0")
  SW_LISTING("Toon", SW_LIGHTING_TOON)
#undef SW_LIGHTING_TOON
};

// The diffuse model's term inside its own nested listing (needs lit and seen).
template <NumberType Num, StepProbe Probe>
Num diffuse_nested(DiffuseModel m, const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  auto run = [&]<class Algo>(std::type_identity<Algo>, auto term) -> Num {
    const auto call = nested<Algo>(probe);
    return term();
  };
  switch (m) {
    case DiffuseModel::minnaert: return run(std::type_identity<Minnaert>{}, [&]() -> Num { return minnaert_term(f, p, probe); });
    case DiffuseModel::oren_nayar:
      return run(std::type_identity<OrenNayar>{}, [&]() -> Num { return oren_nayar_term(f, p, probe); });
    case DiffuseModel::lambert: break;
  }
  return run(std::type_identity<Lambert>{}, [&]() -> Num { return lambert_term(f, p, probe); });
}

// The toon term on a lit and seen frame: the nested diffuse term, then the cut. Needs p.toon.
template <NumberType Num, StepProbe Probe>
Num toon_term(DiffuseModel m, const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  const Num d = diffuse_nested(m, f, p, probe);
  if constexpr (Probe::on) probe.step(Toon::diffuse, StepKind::advance).num("d", d);
  const bool above = p.toon_above ? *p.toon_above : !(d < *p.toon);
  const Num t = above ? Num(1) : Num(0);
  if constexpr (Probe::on) probe.step(Toon::cut, StepKind::done).idx("above", above).num("t", t);
  return t;
}

}  // namespace sw::lighting
