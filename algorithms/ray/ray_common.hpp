// Shared pieces of the ray family: the ray type, square roots for every number type, and the
// exact-mode helpers that keep sphere roots free of cancellation. Semantics: docs/semantics/rays.md.
#pragma once
#include <bit>
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

// Index of the component of largest magnitude (the first on ties). Static compares the double
// values: exact for inputs; for computed vectors any axis the caller then certifies will do.
template <class Num> int max_axis(const Vec3<Num>& v) {
  if constexpr (std::is_same_v<Num, Static>) return max_axis(Vec3<double>{v.x.value(), v.y.value(), v.z.value()});
  const Num ax = num::abs(v.x), ay = num::abs(v.y), az = num::abs(v.z);
  if (ax >= ay && ax >= az) return 0;
  return ay >= az ? 1 : 2;
}

// ---- The static filter (docs/accuracy-rays.md, "Filtered mode"). certify(x, bound) attaches
// bound(value of x) >= |x - exact x| to a Static x, so that comparisons of x are decided or throw
// Uncertain; for every other number type it returns x and never evaluates the bound. The bounds
// use the standard model fl(a op b) = (a op b)(1 + e), |e| <= u = 2^-53, valid while nothing
// underflows or overflows, which filter::poly's range check guarantees.
namespace filter {
constexpr double kU = 0x1p-53;
constexpr double kSlack = 1 + 0x1p-30;  // the bound's own roundings and (1 + u) factors, with room
template <class Num> constexpr bool on = std::is_same_v<Num, Static>;
template <class Num> [[gnu::always_inline]] inline double err(const Num& x) {
  if constexpr (on<Num>) return x.error();
  else return 0;
}
// max(a, b) as one maxsd (std::fmax is a libm call); a NaN here comes from a NaN value, whose own
// certification is uncertain anyway.
[[gnu::always_inline]] inline double max2(double a, double b) { return a > b ? a : b; }
template <class Num> [[gnu::always_inline]] inline double mag(const Vec3<Num>& a) {  // max |component|
  return max2(max2(std::fabs(num::to_double(a.x)), std::fabs(num::to_double(a.y))), std::fabs(num::to_double(a.z)));
}
// Maxima that are 0 or in [2^-200, 2^200]: no product of up to four of them overflows, and an
// underflowed partial product is off by at most 2^-1074, below 2^-800 times the bound.
// Bitwise & and | keep these checks branch-free (they are almost always true).
[[gnu::always_inline]] inline bool in_range(double m) { return (m == 0) | ((m >= 0x1p-200) & (m <= 0x1p200)); }
// c u m1 m2 ... (a polynomial's bound from the maxima of its factor groups), or +inf (uncertain)
// when a maximum is out of range. c includes the slack for the (1 + u) factors.
template <class... M> [[gnu::always_inline]] inline double poly(double c, M... m) {
  return (in_range(m) & ...) ? c * kU * (m * ...) : std::numeric_limits<double>::infinity();
}
// The error of z = fl(x / y) or fl(x * fl(1 / y)) from |x - x*| <= bx and |y - y*| <= by < |y|:
// |x/y - x*/y*| <= (bx + |x/y| by) / (|y| - by), plus two roundings of |z|.
// 1/gap is bounded by the power of two 2^-floor(log2 gap) from the exponent bits: no second division
// (a division's latency would cost more than the whole double test), at most a factor 2 looser.
// recip_upper(g) >= 1/g for g in (2^-1000, 2^1000) (else meaningless: callers check the range).
[[gnu::always_inline]] inline double recip_upper(double g) {
  constexpr std::uint64_t kExp = std::uint64_t(0x7ff) << 52;
  return std::bit_cast<double>((std::uint64_t(2046) << 52) - (std::bit_cast<std::uint64_t>(g) & kExp));
}
[[gnu::always_inline]] inline bool recip_ok(double g) { return (g > 0x1p-1000) & (g < 0x1p1000); }
[[gnu::always_inline]] inline double quot(double z, double bx, double y, double by) {
  const double gap = std::fabs(y) - by;
  const double e = kSlack * ((bx + std::fabs(z) * by) * recip_upper(gap) + 3 * kU * std::fabs(z));
  return recip_ok(gap) ? e : std::numeric_limits<double>::infinity();
}
template <class Num> [[gnu::always_inline]] inline double quot(double z, double bx, const Num& y) { return quot(z, bx, num::to_double(y), err(y)); }
// The error of fl(a + b) from the errors of a and b.
template <class Num> [[gnu::always_inline]] inline double sum(double z, const Num& a, const Num& b) { return kSlack * (err(a) + err(b) + kU * std::fabs(z)); }
}  // namespace filter

// The ray algorithms are [[gnu::always_inline]]: GCC inlines their double instantiations into the
// callers (the bench loop) but not the larger Static ones, whose call and returned struct then cost
// as much as the bounds; forcing it treats every number type alike.
template <class Num, class F> [[gnu::always_inline]] inline Num certify(const Num& x, F&& bound) {
  if constexpr (filter::on<Num>) return Static::certified(x.value(), bound(x.value()));
  else return x;
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
inline Bounded sqrt_num(const Bounded& x, bool& exact) { exact = false; return sqrt(x); }
inline Static sqrt_num(const Static& x, bool& exact) { exact = false; return sqrt(x); }
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
    return s > 0 ? Num(p + r) : Num(p - r);
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
