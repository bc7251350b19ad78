// Blinn's half-vector form of Phong's highlight (Blinn 1977): (n.h)^shininess with
// h = (l + e)/|l + e|. Symmetric in l and e (reciprocal as a BRDF over n.l: see semantics.md).
#pragma once
#include <string_view>
#include "lighting/lighting_common.hpp"

namespace sw::lighting {

// The half vector's line, shared by the half-vector models.
#define SW_LIGHTING_HALF_LINE(X) X(half, "h <- (l + e)/|l + e|; c <- n.h      -- l != -e when lit and seen")

struct BlinnPhong {
  static constexpr std::string_view id = "blinn-phong";
  static constexpr std::string_view summary = "Blinn-Phong specular term (n.h)^n, one light";
#define SW_LIGHTING_BLINN_PHONG(X) \
  SW_LIGHTING_FRAME_LINES(X) \
  SW_LIGHTING_HALF_LINE(X) \
  X(term, "s <- c^shininess")
  SW_LISTING("Blinn-Phong", SW_LIGHTING_BLINN_PHONG)
#undef SW_LIGHTING_BLINN_PHONG
};

// The half vector and n.h, recorded on listing L's `half` line.
template <class L, NumberType Num, StepProbe Probe> Vec3<Num> half_step(const Frame<Num>& f, Num& c, Probe& probe) {
  const Vec3<Num> h = half_vector(f);
  c = dot(f.n, h);
  if constexpr (Probe::on)
    probe.step(L::half, StepKind::advance).vec("h", h).num("c", c).segment(Vec3<Num>{}, h).label("h").keep();
  return h;
}

// Needs lit and seen (frame_term decides).
template <NumberType Num, StepProbe Probe> Num blinn_phong_term(const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  Num c;
  (void)half_step<BlinnPhong>(f, c, probe);
  const Num s = num::pow(c, p.shininess);
  if constexpr (Probe::on) probe.step(BlinnPhong::term, StepKind::done).num("s", s);
  return s;
}

}  // namespace sw::lighting
