// Minnaert's limb-darkening law (Minnaert 1941): the term is (n.l)^k (n.e)^(k-1), k in [0, 1].
// k = 1 is Lambert; a smaller k brightens the limb (the guide prints the exponent 1 - k, which
// darkens it: docs/lighting/deviations.md). The BRDF (n.l n.e)^(k-1)/pi is reciprocal.
#pragma once
#include <string_view>
#include "lighting/lighting_common.hpp"

namespace sw::lighting {

struct Minnaert {
  static constexpr std::string_view id = "minnaert";
  static constexpr std::string_view summary = "Minnaert diffuse term (n.l)^k (n.e)^(k-1), one light";
#define SW_LIGHTING_MINNAERT(X) \
  SW_LIGHTING_FRAME_LINES(X) \
  X(powers, "a <- (n.l)^k; b <- (n.e)^(k-1)") \
  X(term, "d <- a b")
  SW_LISTING("Minnaert", SW_LIGHTING_MINNAERT)
#undef SW_LIGHTING_MINNAERT
};

// Needs lit and seen (frame_term decides).
template <NumberType Num, StepProbe Probe> Num minnaert_term(const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  const Num a = num::pow(f.nl, p.minnaert_k), b = num::pow(f.ne, p.minnaert_k - Num(1));
  if constexpr (Probe::on) probe.step(Minnaert::powers, StepKind::advance).num("a", a).num("b", b);
  const Num d = a * b;
  if constexpr (Probe::on) probe.step(Minnaert::term, StepKind::done).num("d", d);
  return d;
}

}  // namespace sw::lighting
