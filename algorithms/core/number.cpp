#include "core/number.hpp"
#include <charconv>
#include <mpfr.h>

namespace sw::num {

// A dyadic q whose numerator fits the significand (most inputs: doubles, written exactly) is
// representable, and mpq_get_d returns it exactly: no MPFR rounding is needed.
static bool representable(const Rational& q, int significand, int max_exponent) {
  const mpz_srcptr n = q.get_num_mpz_t(), d = q.get_den_mpz_t();
  return mpz_sizeinbase(n, 2) <= std::size_t(significand) && mpz_popcount(d) == 1 && mpz_sizeinbase(d, 2) <= std::size_t(max_exponent);
}
bool is_double(const Rational& q) { return representable(q, 53, 1000); }

template <> float from_rational<float>(const Rational& q) {
  if (representable(q, 24, 120)) return static_cast<float>(mpq_get_d(q.get_mpq_t()));
  mpfr_t m;
  mpfr_init2(m, 24);
  mpfr_set_q(m, q.get_mpq_t(), MPFR_RNDN);
  float f = mpfr_get_flt(m, MPFR_RNDN);
  mpfr_clear(m);
  return f;
}
template <> double from_rational<double>(const Rational& q) {
  if (is_double(q)) return mpq_get_d(q.get_mpq_t());
  mpfr_t m;
  mpfr_init2(m, 53);
  mpfr_set_q(m, q.get_mpq_t(), MPFR_RNDN);
  double d = mpfr_get_d(m, MPFR_RNDN);
  mpfr_clear(m);
  return d;
}
// Precondition: q is an integer in range (the caller validates int-mode inputs).
template <> std::int64_t from_rational<std::int64_t>(const Rational& q) { return floor_int(q); }
template <> Rational from_rational<Rational>(const Rational& q) { return q; }

template <class F> static std::string shortest(F x) {
  char buf[64];
  return std::string(buf, shortest_chars(buf, buf + sizeof buf, x));
}
// A float is written as the shortest double that equals it, so that reading it back as a double
// (as JSON readers do) gives the float's exact value.
std::string to_text(float x) { return shortest(static_cast<double>(x)); }
std::string to_text(double x) { return shortest(x); }
std::string to_text(std::int64_t x) { return std::to_string(x); }
std::string to_text(const Rational& x) { return x.get_str(); }

Rational to_rational(double x) {
  Rational q;
  mpq_set_d(q.get_mpq_t(), x);  // exact for finite doubles
  return q;
}

}  // namespace sw::num
