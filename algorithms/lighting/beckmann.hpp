// Beckmann's facet distribution (Beckmann & Spizzichino 1963, as Cook & Torrance 1982 use it),
// normalised so that the projected facet area integrates to 1:
//   D = exp(-tan^2(alpha)/m^2) / (pi m^2 cos^4(alpha)),  cos(alpha) = n.h, m > 0,
// and the model's term is the microfacet BRDF with F = G = 1, D/(4 (n.l)(n.e)), in the family's
// term convention (pi times the BRDF times n.l): s = pi D / (4 (n.e)). Cook-Torrance with F = 1
// and G = 1 is this term. docs/lighting/semantics.md.
#pragma once
#include <string_view>
#include "lighting/blinn_phong.hpp"

namespace sw::lighting {

// The distribution's line, shared with cook-torrance.
#define SW_LIGHTING_BECKMANN_LINE(X) \
  X(distribution, "t2 <- (1 - c^2)/c^2; D <- exp(-t2/m^2) / (pi m^2 c^4)   -- t2 = tan^2(alpha)")

struct Beckmann {
  static constexpr std::string_view id = "beckmann";
  static constexpr std::string_view summary = "Beckmann microfacet term pi D/(4 n.e), one light";
#define SW_LIGHTING_BECKMANN(X) \
  SW_LIGHTING_FRAME_LINES(X) \
  SW_LIGHTING_HALF_LINE(X) \
  SW_LIGHTING_BECKMANN_LINE(X) \
  X(term, "s <- pi D / (4 (n.e))")
  SW_LISTING("Beckmann", SW_LIGHTING_BECKMANN)
#undef SW_LIGHTING_BECKMANN
};

// D at c = n.h > 0, recorded on listing L's `distribution` line.
template <class L, NumberType Num, StepProbe Probe> Num beckmann_step(const Num& c, const Num& m, Probe& probe) {
  const Num c2 = c * c, m2 = m * m;
  const Num t2 = (Num(1) - c2) / c2;
  const Num D = num::exp(-(t2 / m2)) / (num::pi<Num>() * m2 * c2 * c2);
  if constexpr (Probe::on) probe.step(L::distribution, StepKind::advance).num("t2", t2).num("D", D);
  return D;
}

// Needs lit and seen (frame_term decides).
template <NumberType Num, StepProbe Probe> Num beckmann_term(const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  Num c;
  (void)half_step<Beckmann>(f, c, probe);
  const Num D = beckmann_step<Beckmann>(c, p.m, probe);
  const Num s = num::pi<Num>() * D / (Num(4) * f.ne);
  if constexpr (Probe::on) probe.step(Beckmann::term, StepKind::done).num("s", s);
  return s;
}

}  // namespace sw::lighting
