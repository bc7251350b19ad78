// Oren and Nayar's qualitative model (Oren & Nayar 1994, their "qualitative model" with the
// interreflection term dropped): with theta_i, theta_r the angles of l and e from n, phi the
// azimuths, alpha = max(theta_i, theta_r), beta = min(theta_i, theta_r),
//   term = cos(theta_i) (A + B max(0, cos(phi_r - phi_i)) sin(alpha) tan(beta)),
//   A = 1 - 0.5 s2/(s2 + 0.33), B = 0.45 s2/(s2 + 0.09), s2 = sigma^2.
// Evaluated without angles: sin(theta_i) sin(theta_r) cos(phi_r - phi_i) = l.e - (n.l)(n.e), and
// sin(alpha) tan(beta) / (sin(theta_i) sin(theta_r)) = 1/max(n.l, n.e), so the term is
//   (n.l) (A + B max(0, l.e - (n.l)(n.e)) / max(n.l, n.e)),
// defined at theta = 0 too (where the guide's projected vectors are 0/0). docs/lighting/.
#pragma once
#include <string_view>
#include "lighting/lighting_common.hpp"

namespace sw::lighting {

struct OrenNayar {
  static constexpr std::string_view id = "oren-nayar";
  static constexpr std::string_view summary = "Oren-Nayar qualitative diffuse term (roughness sigma), one light";
#define SW_LIGHTING_OREN_NAYAR(X) \
  SW_LIGHTING_FRAME_LINES(X) \
  X(coeffs, "A <- 1 - 0.5 s2/(s2 + 0.33); B <- 0.45 s2/(s2 + 0.09)    -- s2 = sigma^2") \
  X(azimuth, "g <- l.e - (n.l)(n.e)        -- sin(ti) sin(tr) cos(phi_r - phi_i)") \
  X(term, "d <- (n.l) (A + B max(0, g) / max(n.l, n.e))")
  SW_LISTING("Oren-Nayar (qualitative)", SW_LIGHTING_OREN_NAYAR)
#undef SW_LIGHTING_OREN_NAYAR
};

// Needs lit and seen (frame_term decides).
template <NumberType Num, StepProbe Probe> Num oren_nayar_term(const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  const Num s2 = p.sigma * p.sigma;
  const Num A = Num(1) - (Num(1) / Num(2)) * s2 / (s2 + Num(33) / Num(100));
  const Num B = (Num(45) / Num(100)) * s2 / (s2 + Num(9) / Num(100));
  if constexpr (Probe::on) probe.step(OrenNayar::coeffs, StepKind::init).num("A", A).num("B", B);
  const Num g = dot(f.l, f.e) - f.nl * f.ne;
  if constexpr (Probe::on) probe.step(OrenNayar::azimuth, StepKind::decide).num("g", g);
  const Num gp = g > Num(0) ? g : Num(0), big = f.nl > f.ne ? f.nl : f.ne;
  const Num d = f.nl * (A + B * gp / big);
  if constexpr (Probe::on) probe.step(OrenNayar::term, StepKind::done).num("d", d);
  return d;
}

}  // namespace sw::lighting
