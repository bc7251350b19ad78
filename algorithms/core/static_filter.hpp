// Statically filtered numbers (Shewchuk; CGAL's Static_filtered predicates): arithmetic is plain
// double, and a value can only be compared once the algorithm has attached an a-priori bound on its
// error (sw::ray::certify, derived per decision in docs/accuracy-rays.md). A comparison is decided
// when the computed difference exceeds the summed bounds; otherwise it throws Uncertain and the
// caller re-runs the case on exact rationals.
//
// e_ is the error bound: 0 for an exact value (an input double, a constant, a negation of one),
// +inf for a computed value nobody certified (so comparing it always throws: a forgotten bound costs
// speed, never correctness), NaN when the certified value is not finite (also throws).
//
// Included by number.hpp after its declarations; include number.hpp, not this file.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace sw {

class Static {
 public:
  Static() = default;
  [[gnu::always_inline]] Static(double x) : v_(x), e_(0) {}  // an input double is exact
  Static(int x) : v_(x), e_(0) {}
  // x with |x - exact| <= e. A non-finite x gets a NaN bound, so every decision on it is uncertain.
  [[gnu::always_inline]] static Static certified(double x, double e) { return make(x, e + (x - x)); }

  double value() const { return v_; }
  double error() const { return e_; }

  [[gnu::always_inline]] friend Static operator-(const Static& a) { return make(-a.v_, a.e_); }  // exact
  [[gnu::always_inline]] friend Static operator+(const Static& a, const Static& b) { return raw(a.v_ + b.v_); }
  [[gnu::always_inline]] friend Static operator-(const Static& a, const Static& b) { return raw(a.v_ - b.v_); }
  [[gnu::always_inline]] friend Static operator*(const Static& a, const Static& b) { return raw(a.v_ * b.v_); }
  [[gnu::always_inline]] friend Static operator/(const Static& a, const Static& b) { return raw(a.v_ / b.v_); }
  Static& operator+=(const Static& b) { return *this = *this + b; }
  Static& operator-=(const Static& b) { return *this = *this - b; }
  Static& operator*=(const Static& b) { return *this = *this * b; }
  [[gnu::always_inline]] friend Static sqrt(const Static& x) { return raw(std::sqrt(x.v_)); }

  [[gnu::always_inline]] friend bool operator<(const Static& a, const Static& b) { return compare(a, b) < 0; }
  [[gnu::always_inline]] friend bool operator>(const Static& a, const Static& b) { return compare(a, b) > 0; }
  [[gnu::always_inline]] friend bool operator<=(const Static& a, const Static& b) { return compare(a, b) <= 0; }
  [[gnu::always_inline]] friend bool operator>=(const Static& a, const Static& b) { return compare(a, b) >= 0; }
  [[gnu::always_inline]] friend bool operator==(const Static& a, const Static& b) { return compare(a, b) == 0; }
  [[gnu::always_inline]] friend bool operator!=(const Static& a, const Static& b) { return compare(a, b) != 0; }

 private:
  [[gnu::always_inline]] static Static make(double v, double e) { Static r; r.v_ = v; r.e_ = e; return r; }
  [[gnu::always_inline]] static Static raw(double v) { return make(v, std::numeric_limits<double>::infinity()); }
  // The sign of exact(a) - exact(b). d = fl(va - vb) is within a relative 2^-53 of va - vb, and
  // |exact difference - (va - vb)| <= ea + eb; the factor 1 + 2^-50 covers both roundings.
  [[gnu::always_inline]] static int compare(const Static& a, const Static& b) {
    // The sign is computed without a branch, so callers can if-convert on it; the only branch
    // (is the sign certain?) is almost always taken.
    const double d = a.v_ - b.v_;
    const int sign = (d > 0) - (d < 0);
    if (std::fabs(d) > (a.e_ + b.e_) * (1 + 0x1p-50)) [[likely]]
      return sign;
    return compare_slow(d, a.e_ + b.e_);
  }
  // Both exact: the rounded difference of two doubles has the exact difference's sign.
  [[gnu::noinline, gnu::cold]] static int compare_slow(double d, double e) {
    if (e == 0 && d == d) return (d > 0) - (d < 0);
    throw Uncertain{};
  }
  double v_ = 0, e_ = 0;
};

namespace num {
[[gnu::always_inline]] inline Static abs(const Static& x) { return x.value() < 0 ? -x : x; }  // exact: keeps the bound
inline std::int64_t floor_int(const Static& x) {
  if (x.error() != 0) throw Uncertain{};
  return static_cast<std::int64_t>(std::floor(x.value()));
}
[[gnu::always_inline]] inline double to_double(const Static& x) { return x.value(); }
// Filtered traces record the double value; the decisions made from the bounds are certified.
inline std::string to_text(const Static& x) { return to_text(x.value()); }
// An input that is not a double has no exact double to filter: the exact re-run decides.
template <> inline Static from_rational<Static>(const Rational& q) {
  const double d = from_rational<double>(q);
  if (num::to_rational(d) != q) throw Uncertain{};
  return Static(d);
}
}  // namespace num

}  // namespace sw
