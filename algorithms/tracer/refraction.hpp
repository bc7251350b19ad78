// Refraction at a surface between indices n1 (the ray's side) and n2: the decision of total
// internal reflection made exactly, the transmitted direction by Snell's law, and the split of
// the energy between the mirror and the transmitted ray by Fresnel's reflectance (the lighting
// family's exact formula, or Schlick's). TIR is the sign of a polynomial of the raw d, N, n1 and
// n2: sin^2 of the transmitted angle >= 1 <=> n1^2 (|d|^2 |N|^2 - (d.N)^2) >= n2^2 |d|^2 |N|^2,
// decided in intervals and, where they cannot, in rationals (exact_sign). The implementor's guide
// tests n1/n2 sqrt(1 - e.n) >= 1 instead, without the square on e.n: its `guide_tir` is recorded
// beside, so a lesson can show where the two disagree. Semantics: docs/tracer/renderer.md.
#pragma once
#include <cmath>
#include <string_view>
#include "core/exact_sign.hpp"
#include "lighting/brdf.hpp"
#include "lighting/cook_torrance.hpp"
#include "lighting/lighting_common.hpp"

namespace sw::tracer {

template <class Num> struct Transmission {
  bool tir = false;         // total internal reflection: no transmitted ray
  bool guide_tir = false;   // the guide's test, n1/n2 sqrt(1 - c) >= 1 (a mistake: it needs 1 - c^2)
  Num cos_i{}, fresnel{1};  // the cosine of incidence; Fresnel's reflectance (1 under TIR)
  Vec3<Num> dir;            // the transmitted direction (unit), when !tir
};

struct Refract {
  static constexpr std::string_view id = "refract";
  static constexpr std::string_view summary =
      "Refraction: exact total-internal-reflection sign, Snell's direction, Fresnel's split";
#define SW_TRACER_REFRACT(X) \
  X(cosine, "c <- -d.N / (|d| |N|)                          -- N faces the incoming ray, so c > 0") \
  X(tir, "TIR <- n1^2 (|d|^2 |N|^2 - (d.N)^2) >= n2^2 |d|^2 |N|^2   -- sin^2(t) >= 1, an exact polynomial sign") \
  X(total, "if TIR: F <- 1; no transmitted ray") \
  X(direction, "eta <- n1/n2; k <- 1 - eta^2 (1 - c^2); T <- eta d/|d| + (eta c - sqrt(k)) N/|N|") \
  X(fresnel, "F <- Fresnel's reflectance at c for the relative index n2/n1 (exact, or Schlick's on the outer side's cosine)")
  SW_LISTING("Refraction with exact TIR", SW_TRACER_REFRACT)
#undef SW_TRACER_REFRACT
};

// n1^2 (|D|^2 |M|^2 - (D.M)^2) - n2^2 |D|^2 |M|^2: |D|^2 |M|^2 n2^2 (sin^2(t) - 1), so TIR is its
// sign >= 0 (core/exact_sign.hpp decides it exactly).
inline constexpr auto tir_polynomial = [](const auto& D, const auto& M, const auto& m1, const auto& m2) {
  const auto dd = dot(D, D), mm = dot(M, M), dm = dot(D, M);
  return m1 * m1 * (dd * mm - dm * dm) - m2 * m2 * dd * mm;
};

// d: the incoming direction; N: the normal facing it (d.N < 0); n1, n2 >= 1.
template <NumberType Num, StepProbe Probe = NoProbe> Transmission<Num> refract(const Vec3<Num>& d, const Vec3<Num>& N,
                                                                               const Num& n1, const Num& n2,
                                                                               lighting::Fresnel fresnel, Probe& probe) {
  using L = Refract;
  Transmission<Num> out;
  const Vec3<Num> dn = lighting::unit(d), nn = lighting::unit(N);
  out.cos_i = -dot(dn, nn);
  const Num c = out.cos_i < Num(0) ? Num(0) : out.cos_i > Num(1) ? Num(1) : out.cos_i;
  if constexpr (Probe::on) probe.step(L::cosine, StepKind::init).num("c", c).ray(Vec3<Num>{}, dn).label("d");
  out.tir = num::exact_sign(tir_polynomial, d, N, n1, n2) >= 0;
  const Num eta = n1 / n2;
  out.guide_tir = eta * std::sqrt(std::max(Num(0), Num(1) - c)) >= Num(1);
  if constexpr (Probe::on)
    probe.step(L::tir, StepKind::decide).idx("tir", out.tir).idx("guide_tir", out.guide_tir).num("eta", eta);
  if (out.tir) {
    out.fresnel = Num(1);
    if constexpr (Probe::on) probe.step(L::total, StepKind::miss).num("F", out.fresnel);
    return out;
  }
  // Not TIR exactly, so k >= 0 exactly; rounding may make it slightly negative: 0 then.
  const Num k = std::max(Num(0), Num(1) - eta * eta * (Num(1) - c * c));
  const Num cos_t = std::sqrt(k);
  out.dir = lighting::unit(Vec3<Num>(eta * dn + (eta * c - cos_t) * nn));
  if constexpr (Probe::on)
    probe.step(L::direction, StepKind::advance).num("k", k).vec("T", out.dir).ray(Vec3<Num>{}, out.dir).label("T");
  if (fresnel == lighting::Fresnel::schlick) {
    const Num outer = n1 <= n2 ? c : cos_t;  // Schlick's formula takes the angle on the rarer side
    out.fresnel = lighting::fresnel_schlick(outer, n1 <= n2 ? n2 / n1 : n1 / n2);
  } else {
    const Num rel = n2 / n1;  // g^2 = rel^2 + c^2 - 1 >= 0 exactly here; rounding may say otherwise
    out.fresnel = c > Num(0) && rel * rel + c * c - Num(1) >= Num(0) ? lighting::fresnel_exact(c, rel) : Num(1);
  }
  if constexpr (Probe::on) probe.step(L::fresnel, StepKind::done).num("F", out.fresnel);
  return out;
}

}  // namespace sw::tracer
