// Lambert's diffuse reflection: the term is n.l (a BRDF of 1/pi, times pi and the cosine; the
// term convention is in docs/lighting/semantics.md).
#pragma once
#include <string_view>
#include "lighting/lighting_common.hpp"

namespace sw::lighting {

struct Lambert {
  static constexpr std::string_view id = "lambert";
  static constexpr std::string_view summary = "Lambert diffuse term n.l, one light";
#define SW_LIGHTING_LAMBERT(X) \
  SW_LIGHTING_FRAME_LINES(X) \
  X(term, "d <- n.l")
  SW_LISTING("Lambert", SW_LIGHTING_LAMBERT)
#undef SW_LIGHTING_LAMBERT
};

// Needs lit and seen (frame_term decides).
template <NumberType Num, StepProbe Probe> Num lambert_term(const Frame<Num>& f, const ModelParams<Num>&, Probe& probe) {
  const Num d = f.nl;
  if constexpr (Probe::on) probe.step(Lambert::term, StepKind::done).num("d", d);
  return d;
}

}  // namespace sw::lighting
