#include "core/number.hpp"
#include <charconv>
#include <mpfr.h>

namespace sw::num {

template <> float from_rational<float>(const Rational& q) {
  mpfr_t m;
  mpfr_init2(m, 24);
  mpfr_set_q(m, q.get_mpq_t(), MPFR_RNDN);
  float f = mpfr_get_flt(m, MPFR_RNDN);
  mpfr_clear(m);
  return f;
}
template <> double from_rational<double>(const Rational& q) {
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
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
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
