// The number policy for functions beyond + - * /: one overload per number type, so that algorithms
// call num::root, num::sin, ... and contain no type tests.
//  - float, double: <cmath>.
//  - filtered (Interval, Mag): their own certified square roots; no transcendental functions.
//  - Rational: exact where the value is rational (the root of a rational square), else the value
//    in 300-bit MPFR rounded to a rational. That is reference mode's meaning of sqrt, sin, cos,
//    tan and atan2; exact mode uses only root, and reports whether it was exact.
#pragma once
#include <array>
#include <cmath>
#include <type_traits>
#include <mpfr.h>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::num {

// A square root and whether it is the exact value (it travels with the value, not in a flag
// argument). Rounded types are never exact.
template <class Num> struct Rooted {
  Num value;
  bool exact;
};

inline constexpr int kReferenceBits = 300;

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

// sqrt(x) for x >= 0 (the caller decided the sign; x < 0 gives 0 in exact mode).
inline Rooted<float> root(float x) { return {std::sqrt(x), false}; }
inline Rooted<double> root(double x) { return {std::sqrt(x), false}; }
template <class Num>
requires is_filtered<Num> Rooted<Num> root(const Num& x) {
  return {sqrt(x), false};  // the type's own certified root (found by ADL)
}
inline Rooted<Rational> root(const Rational& x) {
  if (sgn(x) <= 0) return {Rational(0), sgn(x) == 0};
  if (mpz_perfect_square_p(x.get_num_mpz_t()) && mpz_perfect_square_p(x.get_den_mpz_t())) {
    mpz_class n, d;
    mpz_sqrt(n.get_mpz_t(), x.get_num_mpz_t());
    mpz_sqrt(d.get_mpz_t(), x.get_den_mpz_t());
    return {Rational(n, d), true};  // n/d is canonical: the roots of coprime squares are coprime
  }
  mpfr_t m;
  mpfr_init2(m, kReferenceBits);
  mpfr_set_q(m, x.get_mpq_t(), MPFR_RNDN);
  mpfr_sqrt(m, m, MPFR_RNDN);
  Rational r;
  mpfr_get_q(r.get_mpq_t(), m);
  mpfr_clear(m);
  return {r, false};
}
template <class Num> Num sqrt_of(const Num& x) { return root(x).value; }

// Transcendental functions: float and double by <cmath>, Rational at 300 bits (reference mode).
enum class Fn { sin, cos, tan, atan2, pow, exp, acos, atan };
inline Rational mpfr_eval(Fn f, const Rational& x, const Rational& y = Rational(1)) {
  mpfr_t a, b;
  mpfr_inits2(kReferenceBits, a, b, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_q(a, x.get_mpq_t(), MPFR_RNDN);
  mpfr_set_q(b, y.get_mpq_t(), MPFR_RNDN);
  switch (f) {
    case Fn::sin: mpfr_sin(a, a, MPFR_RNDN); break;
    case Fn::cos: mpfr_cos(a, a, MPFR_RNDN); break;
    case Fn::tan: mpfr_tan(a, a, MPFR_RNDN); break;
    case Fn::atan2: mpfr_atan2(a, a, b, MPFR_RNDN); break;  // atan2(x = y-coordinate, y = x-coordinate)
    case Fn::pow: mpfr_pow(a, a, b, MPFR_RNDN); break;      // x^y
    case Fn::exp: mpfr_exp(a, a, MPFR_RNDN); break;
    case Fn::acos: mpfr_acos(a, a, MPFR_RNDN); break;
    case Fn::atan: mpfr_atan(a, a, MPFR_RNDN); break;
  }
  Rational r;
  mpfr_get_q(r.get_mpq_t(), a);
  mpfr_clears(a, b, static_cast<mpfr_ptr>(nullptr));
  return r;
}
template <class Num> Num sin(const Num& x) {
  if constexpr (std::is_same_v<Num, Rational>) return mpfr_eval(Fn::sin, x);
  else return std::sin(x);
}
template <class Num> Num cos(const Num& x) {
  if constexpr (std::is_same_v<Num, Rational>) return mpfr_eval(Fn::cos, x);
  else return std::cos(x);
}
template <class Num> Num tan(const Num& x) {
  if constexpr (std::is_same_v<Num, Rational>) return mpfr_eval(Fn::tan, x);
  else return std::tan(x);
}
// atan2(y, x) in (-pi, pi]; atan2(+-0, x < 0) = +-pi (the seam), atan2(0, 0) = 0.
template <class Num> Num atan2(const Num& y, const Num& x) {
  if constexpr (std::is_same_v<Num, Rational>) {
    if (sgn(y) == 0 && sgn(x) == 0) return Rational(0);
    return mpfr_eval(Fn::atan2, y, x);
  } else {
    return std::atan2(y, x);
  }
}
// x^y for x >= 0 (the caller decided the sign; 0^0 = 1). Rational: exact for an integer
// 0 <= y <= 64 (so an exponent 1 or 0 leaves the value untouched: Minnaert's k = 1 is Lambert
// exactly, and GL's integer shininess and spot exponents stay exact) and for x = 0, else 300-bit MPFR.
template <class Num> Num pow(const Num& x, const Num& y) {
  if constexpr (std::is_same_v<Num, Rational>) {
    if (sgn(y) == 0) return Rational(1);
    if (sgn(x) == 0) return Rational(0);  // 0^y for y > 0 (y < 0 has no rational value; callers never ask)
    if (y.get_den() == 1 && sgn(y) > 0 && y <= 64) {
      const unsigned long e = y.get_num().get_ui();
      Rational r;
      mpz_pow_ui(r.get_num_mpz_t(), x.get_num_mpz_t(), e);
      mpz_pow_ui(r.get_den_mpz_t(), x.get_den_mpz_t(), e);
      return r;  // canonical: powers of coprime integers stay coprime
    }
    return mpfr_eval(Fn::pow, x, y);
  } else {
    return std::pow(x, y);
  }
}
// e^x; Rational: exact at x = 0.
template <class Num> Num exp(const Num& x) {
  if constexpr (std::is_same_v<Num, Rational>) return sgn(x) == 0 ? Rational(1) : mpfr_eval(Fn::exp, x);
  else return std::exp(x);
}
// acos(x) for x in [-1, 1]; Rational: exact at x = 1.
template <class Num> Num acos(const Num& x) {
  if constexpr (std::is_same_v<Num, Rational>) return x == 1 ? Rational(0) : mpfr_eval(Fn::acos, x);
  else return std::acos(x);
}
// atan(x); Rational: exact at x = 0.
template <class Num> Num atan(const Num& x) {
  if constexpr (std::is_same_v<Num, Rational>) return sgn(x) == 0 ? Rational(0) : mpfr_eval(Fn::atan, x);
  else return std::atan(x);
}
template <class Num> Num pi() {
  if constexpr (std::is_same_v<Num, Rational>) return Rational(4) * mpfr_eval(Fn::atan2, Rational(1), Rational(1));
  else return Num(3.14159265358979323846);
}

// Index of the component of largest magnitude (the first on ties). Filtered types compare the
// double values: exact for inputs, and for computed vectors any axis the caller then decides on
// will do (a wrong one only makes a later decision uncertain).
template <class Num> int max_axis(const Vec3<Num>& v) {
  if constexpr (is_filtered<Num>) {
    return max_axis(Vec3<double>{to_double(v.x), to_double(v.y), to_double(v.z)});
  } else {
    const Num ax = abs(v.x), ay = abs(v.y), az = abs(v.z);
    if (ax >= ay && ax >= az) return 0;
    return ay >= az ? 1 : 2;
  }
}

// c[0] x^(N-1) + c[1] x^(N-2) + ... + c[N-1] by Horner's rule (leading coefficient first, as
// polynomials are written).
template <class Num, std::size_t N> Num polynomial(const std::array<Num, N>& c, const Num& x) {
  Num y = c[0];
  for (std::size_t k = 1; k < N; ++k) y = y * x + c[k];
  return y;
}

}  // namespace sw::num
