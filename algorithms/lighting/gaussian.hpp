// The Gaussian facet distribution as a highlight (Torrance & Sparrow 1967; Blinn 1977):
// exp(-(alpha/m)^2), alpha = acos(n.h) the angle of the half vector from n, m > 0 the slope
// roughness in radians. Peak 1 at h = n. (The guide prints exp(-m acos^2(...)) with m in the
// numerator: docs/lighting/deviations.md.) acos of a rounded n.h just above 1 is NaN in float and
// double: a failure the bench counts, not clamped away.
#pragma once
#include <string_view>
#include "lighting/blinn_phong.hpp"

namespace sw::lighting {

struct Gaussian {
  static constexpr std::string_view id = "gaussian";
  static constexpr std::string_view summary = "Gaussian highlight exp(-(alpha/m)^2), one light";
#define SW_LIGHTING_GAUSSIAN(X) \
  SW_LIGHTING_FRAME_LINES(X) \
  SW_LIGHTING_HALF_LINE(X) \
  X(angle, "alpha <- acos(c)") \
  X(term, "s <- exp(-(alpha/m)^2)")
  SW_LISTING("Gaussian highlight", SW_LIGHTING_GAUSSIAN)
#undef SW_LIGHTING_GAUSSIAN
};

// Needs lit and seen (frame_term decides).
template <NumberType Num, StepProbe Probe> Num gaussian_term(const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  Num c;
  (void)half_step<Gaussian>(f, c, probe);
  const Num alpha = num::acos(c);
  if constexpr (Probe::on) probe.step(Gaussian::angle, StepKind::advance).num("alpha", alpha);
  const Num q = alpha / p.m;
  const Num s = num::exp(-(q * q));
  if constexpr (Probe::on) probe.step(Gaussian::term, StepKind::done).num("s", s);
  return s;
}

}  // namespace sw::lighting
