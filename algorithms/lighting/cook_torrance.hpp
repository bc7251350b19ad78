// Cook and Torrance's specular model (Cook & Torrance 1982): the microfacet BRDF D F G/(4 (n.l)(n.e))
// with Beckmann's D (beckmann.hpp), Fresnel's reflectance F of unpolarised light at the facet
// (c = e.h, the paper's exact form with g^2 = ior^2 + c^2 - 1, or Schlick's approximation) and the
// V-groove attenuation G = min(1, 2(n.h)(n.e)/(e.h), 2(n.h)(n.l)/(e.h)). The term (pi times the
// BRDF times n.l) is s = pi D F G / (4 (n.e)). The paper prints pi where later work derives 4:
// docs/lighting/deviations.md. ior >= 1, so there is no total internal reflection.
#pragma once
#include <string_view>
#include "lighting/beckmann.hpp"

namespace sw::lighting {

struct CookTorrance {
  static constexpr std::string_view id = "cook-torrance";
  static constexpr std::string_view summary =
      "Cook-Torrance microfacet term pi D F G/(4 n.e) (Beckmann D, Fresnel, V-groove G), one light";
#define SW_LIGHTING_COOK_TORRANCE(X) \
  SW_LIGHTING_FRAME_LINES(X) \
  SW_LIGHTING_HALF_LINE(X) \
  SW_LIGHTING_BECKMANN_LINE(X) \
  X(fresnel, "exact: g <- sqrt(ior^2 + eh^2 - 1); F <- (g-eh)^2/(2 (g+eh)^2) (1 + (eh(g+eh)-1)^2/(eh(g-eh)+1)^2)") \
  X(schlick, "schlick: F0 <- ((ior-1)/(ior+1))^2; F <- F0 + (1 - F0)(1 - eh)^5      -- eh = e.h") \
  X(geometry, "G <- min(1, 2 c (n.e)/eh, 2 c (n.l)/eh)") \
  X(term, "s <- pi D F G / (4 (n.e))")
  SW_LISTING("Cook-Torrance", SW_LIGHTING_COOK_TORRANCE)
#undef SW_LIGHTING_COOK_TORRANCE
};

// Fresnel's reflectance of unpolarised light at cos(theta) = c > 0 and relative index ior >= 1.
template <class Num> Num fresnel_exact(const Num& c, const Num& ior) {
  const Num g = num::sqrt_of(ior * ior + c * c - Num(1));
  const Num gm = g - c, gp = g + c;
  const Num a = c * gp - Num(1), b = c * gm + Num(1);
  return gm * gm / (Num(2) * gp * gp) * (Num(1) + a * a / (b * b));
}
template <class Num> Num fresnel_schlick(const Num& c, const Num& ior) {
  const Num r = (ior - Num(1)) / (ior + Num(1)), f0 = r * r;
  const Num u = Num(1) - c, u2 = u * u;
  return f0 + (Num(1) - f0) * u2 * u2 * u;
}

// Needs lit and seen (frame_term decides).
template <NumberType Num, StepProbe Probe> Num cook_torrance_term(const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  using L = CookTorrance;
  Num c;
  const Vec3<Num> h = half_step<L>(f, c, probe);
  const Num D = beckmann_step<L>(c, p.m, probe);
  const Num eh = dot(f.e, h);
  Num F(1);
  if (p.fresnel == Fresnel::exact) {
    F = fresnel_exact(eh, p.ior);
    if constexpr (Probe::on) probe.step(L::fresnel, StepKind::advance).num("eh", eh).num("F", F);
  } else if (p.fresnel == Fresnel::schlick) {
    F = fresnel_schlick(eh, p.ior);
    if constexpr (Probe::on) probe.step(L::schlick, StepKind::advance).num("eh", eh).num("F", F);
  }
  Num G(1);
  if (p.shadowing) {
    const Num ge = Num(2) * c * f.ne / eh, gl = Num(2) * c * f.nl / eh;
    G = ge < G ? ge : G;
    G = gl < G ? gl : G;
    if constexpr (Probe::on) probe.step(L::geometry, StepKind::decide).num("G", G);
  }
  const Num s = num::pi<Num>() * D * F * G / (Num(4) * f.ne);
  if constexpr (Probe::on) probe.step(L::term, StepKind::done).num("s", s);
  return s;
}

}  // namespace sw::lighting
