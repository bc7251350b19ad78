// Light sources for the full local model (shade.hpp): point, directional and spot lights with
// OpenGL's constant, linear and quadratic attenuation and its spot cone (cut-off and exponent),
// and the two number policies they need beyond + - * / and sqrt: a power x^s, and the exact spot
// cone decision. Semantics: docs/lighting/shade.md.
#pragma once
#include <cmath>
#include <cstdint>
#include <optional>
#include <mpfr.h>
#include "core/functions.hpp"
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::lighting {

enum class LightType : std::uint8_t { point, directional, spot };

// The spot cone: cut-off in degrees, in [0, 90], or 180 (no cone: every direction, factor 1).
// cos2 = cos^2(cut-off) in the number type; cos2_exact marks the angles whose cos^2 is rational
// (0, 30, 45, 60, 90 degrees: by Niven's theorem no other rational number of degrees has one).
template <class Num> struct SpotCone {
  bool all = true;  // cut-off 180
  Num degrees{180};
  Num cos{-1}, cos2{1};
  bool cos2_exact = false;
  Num exponent{0};
};

template <class Num> struct Light {
  LightType type = LightType::point;
  Vec3<Num> where;          // point, spot: the position; directional: the direction towards the light
  Vec3<Num> spot_dir;       // spot: the axis of the cone, pointing away from the light
  SpotCone<Num> cone;       // spot only
  Num k0{1}, k1{0}, k2{0};  // attenuation 1/(k0 + k1 d + k2 d^2); all >= 0, not all 0
  Vec3<Num> ambient, diffuse, specular;
};

// cos^2 of a rational number of degrees in [0, 90] when it is rational, else nullopt (Niven).
inline std::optional<Rational> rational_cos2(const Rational& deg) {
  if (deg == 0) return Rational(1);
  if (deg == 30) return Rational(3, 4);
  if (deg == 45) return Rational(1, 2);
  if (deg == 60) return Rational(1, 4);
  if (deg == 90) return Rational(0);
  return std::nullopt;
}

// Is the direction d (from the light to the point) inside the cone around s, closed on its
// boundary (GL: d.s >= cos(cut-off) |d||s|)? Given ds = d.s and q = |d|^2 |s|^2, for a cut-off
// in [0, 90] (cos >= 0): ds >= 0 and ds^2 >= cos^2 q. float and double evaluate this polynomial
// as it stands (and may decide wrongly near the boundary).
template <class Num> bool cone_contains(const Num& ds, const Num& q, const SpotCone<Num>& c) {
  if (c.all) return true;
  return !(ds < Num(0)) && !(ds * ds < c.cos2 * q);
}
// Rational: exact. A rational cos^2 is compared exactly; an irrational one is never equal to the
// rational ds^2/q, so it is evaluated in MPFR at 300 bits and then at twice the precision until
// the difference exceeds the evaluation's error bound (2^-(bits - 4): the angle's rounding and
// cos's, each well under an ulp, through a derivative of at most 1).
inline bool cone_contains(const Rational& ds, const Rational& q, const SpotCone<Rational>& c) {
  if (c.all) return true;
  if (sgn(ds) < 0) return false;
  if (c.cos2_exact) return Rational(ds * ds) >= Rational(c.cos2 * q);
  if (sgn(q) == 0) return true;  // d = 0 is decided by the caller (no light); here ds = 0 too
  const Rational ratio = Rational(ds * ds / q);
  for (int bits = num::kReferenceBits; bits <= 1 << 16; bits *= 2) {
    mpfr_t a, pi;
    mpfr_inits2(bits + 16, a, pi, static_cast<mpfr_ptr>(nullptr));
    mpfr_const_pi(pi, MPFR_RNDN);
    mpfr_set_q(a, c.degrees.get_mpq_t(), MPFR_RNDN);
    mpfr_mul(a, a, pi, MPFR_RNDN);
    mpfr_div_ui(a, a, 180, MPFR_RNDN);
    mpfr_cos(a, a, MPFR_RNDN);
    mpfr_sqr(a, a, MPFR_RNDN);
    Rational cos2;
    mpfr_get_q(cos2.get_mpq_t(), a);
    mpfr_clears(a, pi, static_cast<mpfr_ptr>(nullptr));
    Rational bound(1);
    bound /= Rational(mpz_class(1) << (bits - 4));
    const Rational diff = Rational(ratio - cos2);
    if (diff > bound) return true;
    if (diff < Rational(-bound)) return false;
  }
  return true;  // not separated at 65536 bits: never seen (an irrational cos^2 differs from every rational)
}

// Attenuation 1/(k0 + k1 d + k2 d^2) at distance d (the caller passes d^2 too, exact in Rational).
template <class Num> Num attenuation(const Light<Num>& L, const Num& d, const Num& d2) {
  return Num(1) / (L.k0 + L.k1 * d + L.k2 * d2);
}

}  // namespace sw::lighting
