// An MPFR number with value semantics, for the oracles' reference values (the lighting family's
// formulas in 256 and 400 bits). A value has Bits bits unless it is given a precision; an operation
// rounds to its (left) operand's precision, an assignment to the target's. Oracle .cpp files only.
#pragma once
#include <mpfr.h>
#include "core/number.hpp"

namespace sw::oracle {

template <int Bits> class Mpfr {
 public:
  Mpfr() : Mpfr(0) {}
  Mpfr(int i, int bits = Bits) { mpfr_init2(v_, bits), mpfr_set_si(v_, i, MPFR_RNDN); }
  Mpfr(const Rational& q, int bits = Bits) { mpfr_init2(v_, bits), mpfr_set_q(v_, q.get_mpq_t(), MPFR_RNDN); }
  Mpfr(const Mpfr& o) { mpfr_init2(v_, mpfr_get_prec(o.v_)), mpfr_set(v_, o.v_, MPFR_RNDN); }
  Mpfr& operator=(const Mpfr& o) {
    mpfr_set(v_, o.v_, MPFR_RNDN);
    return *this;
  }
  ~Mpfr() { mpfr_clear(v_); }
  static Mpfr pi(int bits = Bits) {
    Mpfr r(0, bits);
    mpfr_const_pi(r.v_, MPFR_RNDN);
    return r;
  }

  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }
  int bits() const { return static_cast<int>(mpfr_get_prec(v_)); }
  int sign() const { return mpfr_sgn(v_); }
  Rational q() const {
    Rational r;
    mpfr_get_q(r.get_mpq_t(), v_);
    return r;
  }

  // f(a) and f(a, b) for an MPFR function f (mpfr_sqrt, mpfr_pow, ...), at a's precision.
  template <class F> static Mpfr fn(F f, const Mpfr& a) {
    Mpfr r(0, a.bits());
    f(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  template <class F> static Mpfr fn2(F f, const Mpfr& a, const Mpfr& b) {
    Mpfr r(0, a.bits());
    f(r.v_, a.v_, b.v_, MPFR_RNDN);
    return r;
  }
  friend Mpfr operator+(const Mpfr& a, const Mpfr& b) { return fn2(mpfr_add, a, b); }
  friend Mpfr operator-(const Mpfr& a, const Mpfr& b) { return fn2(mpfr_sub, a, b); }
  friend Mpfr operator*(const Mpfr& a, const Mpfr& b) { return fn2(mpfr_mul, a, b); }
  friend Mpfr operator/(const Mpfr& a, const Mpfr& b) { return fn2(mpfr_div, a, b); }
  friend Mpfr operator-(const Mpfr& a) { return fn(mpfr_neg, a); }
  friend bool operator<(const Mpfr& a, const Mpfr& b) { return mpfr_less_p(a.v_, b.v_); }

 private:
  mpfr_t v_;
};

}  // namespace sw::oracle
