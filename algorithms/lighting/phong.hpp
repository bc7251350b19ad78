// Phong's specular term (Phong 1975): (r.e)^shininess with r = 2 (n.l) n - l the mirror direction
// of l, and 0 where r.e <= 0. The side r.e > 0 is decided exactly on the raw vectors (the sign of
// 2 (N.L)(N.E) - (N.N)(L.E)). Not reciprocal: docs/lighting/semantics.md.
#pragma once
#include <string_view>
#include "lighting/lighting_common.hpp"

namespace sw::lighting {

struct Phong {
  static constexpr std::string_view id = "phong";
  static constexpr std::string_view summary = "Phong specular term (r.e)^n, one light";
#define SW_LIGHTING_PHONG(X) \
  SW_LIGHTING_FRAME_LINES(X) \
  X(reflect, "r <- 2 (n.l) n - l; c <- r.e") \
  X(side, "if r.e <= 0: s <- 0; stop    -- exact: sign of 2 (N.L)(N.E) - (N.N)(L.E)") \
  X(term, "s <- c^shininess")
  SW_LISTING("Phong", SW_LIGHTING_PHONG)
#undef SW_LIGHTING_PHONG
};

// Needs lit and seen (frame_term decides).
template <NumberType Num, StepProbe Probe> Num phong_term(const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  const Vec3<Num> r = mirror_of(f);
  const Num c = dot(r, f.e);
  if constexpr (Probe::on)
    probe.step(Phong::reflect, StepKind::advance).vec("r", r).num("c", c).segment(Vec3<Num>{}, r).label("r").keep();
  const bool front = f.mirror ? *f.mirror : Num(0) < c;
  if (!front) {
    if constexpr (Probe::on) probe.step(Phong::side, StepKind::done).idx("front", 0).num("s", Num(0));
    return Num(0);
  }
  if constexpr (Probe::on) probe.step(Phong::side, StepKind::decide).idx("front", 1);
  const Num s = num::pow(c, p.shininess);
  if constexpr (Probe::on) probe.step(Phong::term, StepKind::done).num("s", s);
  return s;
}

}  // namespace sw::lighting
