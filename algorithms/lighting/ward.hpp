// Ward's isotropic gaussian lobe (Ward 1992), a glossy term fitted to measured surfaces: the BRDF
//   f = exp(-tan^2(delta)/m^2) / (4 pi m^2 sqrt((n.l)(n.e))),  cos(delta) = n.h, m > 0 the RMS slope,
// and in the family's term convention (pi times the BRDF times n.l):
//   s = exp(-tan^2(delta)/m^2) sqrt((n.l)/(n.e)) / (4 m^2).
// Symmetric in l and e as a BRDF (s/(n.l) is), not bounded by 1, and unlike Beckmann's term it
// grows towards a grazing eye as 1/sqrt(n.e). docs/lighting/semantics.md.
#pragma once
#include <string_view>
#include "lighting/blinn_phong.hpp"

namespace sw::lighting {

struct Ward {
  static constexpr std::string_view id = "ward";
  static constexpr std::string_view summary = "Ward's isotropic term exp(-tan^2 d/m^2) sqrt(n.l/n.e)/(4 m^2), one light";
#define SW_LIGHTING_WARD(X) \
  SW_LIGHTING_FRAME_LINES(X) \
  SW_LIGHTING_HALF_LINE(X) \
  X(lobe, "t2 <- (1 - c^2)/c^2; g <- exp(-t2/m^2)   -- t2 = tan^2(delta)") \
  X(term, "s <- g sqrt((n.l)/(n.e)) / (4 m^2)")
  SW_LISTING("Ward", SW_LIGHTING_WARD)
#undef SW_LIGHTING_WARD
};

// Needs lit and seen (frame_term decides): n.l, n.e > 0.
template <NumberType Num, StepProbe Probe> Num ward_term(const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  Num c;
  (void)half_step<Ward>(f, c, probe);
  const Num c2 = c * c, m2 = p.m * p.m;
  const Num t2 = (Num(1) - c2) / c2;
  const Num g = num::exp(-(t2 / m2));
  if constexpr (Probe::on) probe.step(Ward::lobe, StepKind::advance).num("t2", t2).num("g", g);
  const Num s = g * num::sqrt_of(f.nl / f.ne) / (Num(4) * m2);
  if constexpr (Probe::on) probe.step(Ward::term, StepKind::done).num("s", s);
  return s;
}

}  // namespace sw::lighting
