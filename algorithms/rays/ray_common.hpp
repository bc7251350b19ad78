// Shared pieces of the ray family: the ray type, square roots for every number type, and the
// exact-mode helpers that keep sphere roots free of cancellation. Semantics: docs/rays/semantics.md.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <mpfr.h>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::ray {

template <class Num> struct Ray3 {
  Vec3<Num> o, d;  // the ray is o + t d, t > 0; d != 0 (validated)
};

// Index of the component of largest magnitude (the first on ties). Filtered types compare the
// double values: exact for inputs, and for computed vectors any axis the caller then decides on
// will do (a wrong one only makes a later decision uncertain).
template <class Num> int max_axis(const Vec3<Num>& v) {
  if constexpr (is_filtered<Num>) return max_axis(Vec3<double>{num::to_double(v.x), num::to_double(v.y), num::to_double(v.z)});
  const Num ax = num::abs(v.x), ay = num::abs(v.y), az = num::abs(v.z);
  if (ax >= ay && ax >= az) return 0;
  return ay >= az ? 1 : 2;
}

// A rational rounded to `bits` significant bits (nearest), as a rational.
inline Rational round_bits(const Rational& x, int bits) {
  mpfr_t m;
  mpfr_init2(m, bits);
  mpfr_set_q(m, x.get_mpq_t(), MPFR_RNDN);
  Rational r;
  mpfr_get_q(r.get_mpq_t(), m);
  mpfr_clear(m);
  return r;
}

// sqrt(x) for x >= 0 (the caller decided the sign). `exact` is cleared when the value is rounded.
// Exact mode: the exact root when x is the square of a rational, else a rational within a
// relative 2^-300 (MPFR), which is what the >= 100-bit t of the sphere family rests on.
inline float sqrt_num(float x, bool& exact) { exact = false; return std::sqrt(x); }
inline double sqrt_num(double x, bool& exact) { exact = false; return std::sqrt(x); }
template <class Num>
  requires is_filtered<Num>
Num sqrt_num(const Num& x, bool& exact) {
  exact = false;
  return sqrt(x);
}
inline Rational sqrt_num(const Rational& x, bool& exact) {
  if (sgn(x) <= 0) return Rational(0);
  if (mpz_perfect_square_p(x.get_num_mpz_t()) && mpz_perfect_square_p(x.get_den_mpz_t())) {
    mpz_class n, d;
    mpz_sqrt(n.get_mpz_t(), x.get_num_mpz_t());
    mpz_sqrt(d.get_mpz_t(), x.get_den_mpz_t());
    return Rational(n, d);
  }
  exact = false;
  mpfr_t m;
  mpfr_init2(m, 300);
  mpfr_set_q(m, x.get_mpq_t(), MPFR_RNDN);
  mpfr_sqrt(m, m, MPFR_RNDN);
  Rational r;
  mpfr_get_q(r.get_mpq_t(), m);
  mpfr_clear(m);
  return r;
}

// p + s*sqrt(q) for s = +1 or -1 and q >= 0. Float types evaluate it as written (that is the
// naive formula's behaviour under test). Exact mode avoids the cancellation when p and s*sqrt(q)
// have opposite signs by using (p^2 - q) / (p - s*sqrt(q)), so the result keeps its precision
// and its sign is exact (p^2 - q is exact).
template <class Num> Num add_root(const Num& p, int s, const Num& q, bool& exact) {
  const Num r = sqrt_num(q, exact);
  if constexpr (std::is_same_v<Num, Rational>) {
    if (exact || sgn(p) * s >= 0) return Num(p + s * r);
    return Num(Num(p * p - q) / Num(p - s * r));
  } else {
    return num::select(s > 0, Num(p + r), Num(p - r));
  }
}

// Transcendental helpers for the camera and the inverse mapping. They have no exact rational
// value: float and double use <cmath>; Rational (used only as the bench and oracle reference of
// those algorithms, which do not offer exact mode) evaluates in 300-bit MPFR and rounds to a
// rational.
enum class Fn { sin, cos, tan, atan2 };
inline Rational mpfr_eval(Fn f, const Rational& x, const Rational& y = Rational(1)) {
  mpfr_t a, b;
  mpfr_inits2(300, a, b, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_q(a, x.get_mpq_t(), MPFR_RNDN);
  mpfr_set_q(b, y.get_mpq_t(), MPFR_RNDN);
  switch (f) {
    case Fn::sin: mpfr_sin(a, a, MPFR_RNDN); break;
    case Fn::cos: mpfr_cos(a, a, MPFR_RNDN); break;
    case Fn::tan: mpfr_tan(a, a, MPFR_RNDN); break;
    case Fn::atan2: mpfr_atan2(a, a, b, MPFR_RNDN); break;  // atan2(x = y-coordinate, y = x-coordinate)
  }
  Rational r;
  mpfr_get_q(r.get_mpq_t(), a);
  mpfr_clears(a, b, static_cast<mpfr_ptr>(nullptr));
  return r;
}
template <class Num> Num sin_num(const Num& x) {
  if constexpr (std::is_same_v<Num, Rational>) return mpfr_eval(Fn::sin, x);
  else return std::sin(x);
}
template <class Num> Num cos_num(const Num& x) {
  if constexpr (std::is_same_v<Num, Rational>) return mpfr_eval(Fn::cos, x);
  else return std::cos(x);
}
template <class Num> Num tan_num(const Num& x) {
  if constexpr (std::is_same_v<Num, Rational>) return mpfr_eval(Fn::tan, x);
  else return std::tan(x);
}
// atan2(y, x) in (-pi, pi]; atan2(+-0, x < 0) = +-pi (the seam), atan2(0, 0) = 0.
template <class Num> Num atan2_num(const Num& y, const Num& x) {
  if constexpr (std::is_same_v<Num, Rational>) {
    if (sgn(y) == 0 && sgn(x) == 0) return Rational(0);
    return mpfr_eval(Fn::atan2, y, x);
  } else {
    return std::atan2(y, x);
  }
}
template <class Num> Num pi_num() {
  if constexpr (std::is_same_v<Num, Rational>) return Rational(4) * mpfr_eval(Fn::atan2, Rational(1), Rational(1));
  else return Num(3.14159265358979323846);
}
template <class Num> Num sqrt_any(const Num& x) {
  bool exact = true;
  return sqrt_num(x, exact);
}

}  // namespace sw::ray
