// The lighting family's oracle: each reflection model's term written directly from its paper's
// formula in 400-bit MPFR from the exact raw input: the angles theta_i, theta_r (acos of the raw
// cosines), the azimuths phi_i, phi_r in a tangent frame (atan2), tan(alpha) from alpha, and so on,
// not the algorithms' angle-free forms. The decisions (n.l > 0, n.e > 0, the mirror side, the toon
// cut of a Lambert-like term) are the exact signs of their polynomials, as the specification
// states them (docs/lighting/semantics.md). Also the intermediate quantities by the names the
// algorithms' steps record them under, for the step replays.
#pragma once
#include <map>
#include <string>
#include <string_view>
#include "core/number.hpp"
#include "core/vec.hpp"
#include "lighting/brdf.hpp"

namespace sw::lighting_oracle {

struct OracleTerm {
  bool lit = false, seen = false;
  Rational value;  // the term, rounded from 400 bits (exact where it is exactly 0 or 1)
  // Intermediate quantities, 400 bits rounded to rationals: "n.x", ..., "nl", "ne", "h.x", "c", ...
  std::map<std::string, Rational> named;
};

// The model `c` names: a diffuse model (toon when p.toon is set, over c.diffuse) or a specular one.
// N, L, E non-zero.
OracleTerm term(const lighting::ModelChoice& c, const Vec3<Rational>& N, const Vec3<Rational>& L,
                const Vec3<Rational>& E, const lighting::ModelParams<Rational>& p);

}  // namespace sw::lighting_oracle
