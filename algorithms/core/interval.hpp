// Filtered arithmetic: a double interval that surely contains the exact value. Every decision
// (comparison, floor) is either certain or throws Uncertain; the caller then re-runs the case on
// the next stage, in the end exact rationals (run_filter_stage here, the chain in
// runtime/modes.hpp). Same idea as CGAL's filtered predicates.
//
// Included by number.hpp after its declarations; include number.hpp, not this file.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace sw {

struct Uncertain {};

class Interval {
 public:
  Interval() = default;
  Interval(double x) : lo_(x), hi_(x) {}  // exact: a double is its own interval
  Interval(int x) : lo_(x), hi_(x) {}
  Interval(std::int64_t x) : lo_(static_cast<double>(x)), hi_(static_cast<double>(x)) {
    if (static_cast<std::int64_t>(lo_) != x) widen();
  }
  static Interval hull(double lo, double hi) {
    Interval r;
    r.lo_ = lo;
    r.hi_ = hi;
    return r;
  }

  double lo() const { return lo_; }
  double hi() const { return hi_; }
  double mid() const { return lo_ == hi_ ? lo_ : 0.5 * lo_ + 0.5 * hi_; }
  bool is_point() const { return lo_ == hi_; }

  friend Interval operator-(const Interval& a) { return hull(-a.hi_, -a.lo_); }
  friend Interval operator+(const Interval& a, const Interval& b) {
    const double lo = a.lo_ + b.lo_;
    return outward(lo, a.hi_ + b.hi_, a.is_point() && b.is_point() && exact_sum(a.lo_, b.lo_, lo));
  }
  friend Interval operator-(const Interval& a, const Interval& b) {
    const double lo = a.lo_ - b.hi_;
    return outward(lo, a.hi_ - b.lo_, a.is_point() && b.is_point() && exact_sum(a.lo_, -b.lo_, lo));
  }
  friend Interval operator*(const Interval& a, const Interval& b) {
    double p1 = a.lo_ * b.lo_, p2 = a.lo_ * b.hi_, p3 = a.hi_ * b.lo_, p4 = a.hi_ * b.hi_;
    return outward(std::min({p1, p2, p3, p4}), std::max({p1, p2, p3, p4}),
                   a.is_point() && b.is_point() && exact_product(a.lo_, b.lo_, p1, p1));
  }
  friend Interval operator/(const Interval& a, const Interval& b) {
    if (b.lo_ <= 0 && b.hi_ >= 0) throw Uncertain{};  // the divisor's sign is not known
    double p1 = a.lo_ / b.lo_, p2 = a.lo_ / b.hi_, p3 = a.hi_ / b.lo_, p4 = a.hi_ / b.hi_;
    return outward(std::min({p1, p2, p3, p4}), std::max({p1, p2, p3, p4}),
                   a.is_point() && b.is_point() && exact_product(p1, b.lo_, a.lo_, a.lo_));
  }
  // Needs exact(x) >= 0 (the caller decided it); a lower end below 0 is rounding and clamps to 0.
  friend Interval sqrt(const Interval& x) {
    return outward(std::sqrt(std::max(x.lo_, 0.0)), std::sqrt(std::max(x.hi_, 0.0)), false);
  }
  // |x| without a decision: an interval that straddles 0 gives [0, its larger end's magnitude].
  friend Interval abs(const Interval& x) {
    if (x.lo_ >= 0) return x;
    if (x.hi_ <= 0) return -x;
    return hull(0, std::max(-x.lo_, x.hi_));
  }
  Interval& operator+=(const Interval& b) { return *this = *this + b; }
  Interval& operator-=(const Interval& b) { return *this = *this - b; }
  Interval& operator*=(const Interval& b) { return *this = *this * b; }

  friend bool operator<(const Interval& a, const Interval& b) {
    if (a.hi_ < b.lo_) return true;
    if (a.lo_ >= b.hi_) return false;
    throw Uncertain{};
  }
  friend bool operator>(const Interval& a, const Interval& b) { return b < a; }
  friend bool operator<=(const Interval& a, const Interval& b) { return !(b < a); }
  friend bool operator>=(const Interval& a, const Interval& b) { return !(a < b); }
  friend bool operator==(const Interval& a, const Interval& b) {
    if (a.hi_ < b.lo_ || b.hi_ < a.lo_) return false;
    if (a.is_point() && b.is_point()) return true;
    throw Uncertain{};
  }
  friend bool operator!=(const Interval& a, const Interval& b) { return !(a == b); }

 private:
  // Round-to-nearest endpoints are off by at most half an ulp, so each is widened by a safe
  // margin, unless the operands were points and the result is exact: then it stays a point (an
  // origin exactly on a plane gives p - o = 0 exactly, which then decides).
  static Interval outward(double lo, double hi, bool exact) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) throw Uncertain{};
    Interval r = hull(lo, hi);
    if (!exact) r.widen();
    return r;
  }
  // x y == p exactly, for a product p = fl(x y) or a quotient x = fl(p / y). Sufficient test,
  // inline (an fma residual is a libm call without -mfma, which doubled the grid walk's cost):
  // significands of at most 53 significant bits together multiply exactly. `scale`, the size of
  // the product, keeps subnormals out; a zero factor makes the product exactly 0.
  static bool exact_product(double x, double y, double p, double scale) {
    if (x == 0 || y == 0) return p == 0;
    return std::fabs(scale) >= 0x1p-969 && significant_bits(x) + significant_bits(y) <= 53 && x * y == p;
  }
  // The significant bits of a normal double's significand (trailing zeros dropped).
  static int significant_bits(double x) {
    const std::uint64_t m = (sw::bit_cast<std::uint64_t>(x) & ((std::uint64_t{1} << 52) - 1)) | (std::uint64_t{1} << 52);
    return 53 - __builtin_ctzll(m);
  }
  // Knuth's TwoSum: s = fl(a + b) is exact iff the rounding error it recovers is 0.
  static bool exact_sum(double a, double b, double s) {
    const double bv = s - a;
    return (a - (s - bv)) + (b - bv) == 0;
  }
  void widen() {
    constexpr double rel = 0x1p-51, abs_min = 0x1p-1021;
    lo_ = lo_ - (std::fabs(lo_) * rel + abs_min);
    hi_ = hi_ + (std::fabs(hi_) * rel + abs_min);
  }
  double lo_ = 0, hi_ = 0;
};

namespace num {
inline std::int64_t floor_int(const Interval& x) {
  double a = std::floor(x.lo()), b = std::floor(x.hi());
  if (a != b) throw Uncertain{};
  return static_cast<std::int64_t>(a);
}
inline double to_double(const Interval& x) { return x.mid(); }
// The midpoint is within rel (1 + |midpoint|) of the exact value, which the interval holds.
inline bool certified(const Interval& x, double rel) { return 0.5 * (x.hi() - x.lo()) <= rel * (1 + std::fabs(x.mid())); }
// Filtered traces record the midpoint; the decisions made from the interval are certified.
inline std::string to_text(const Interval& x) { return to_text(x.mid()); }
template <> inline Interval from_rational<Interval>(const Rational& q) {
  double d = from_rational<double>(q);
  if (is_double(q) || Rational(num::to_rational(d)) == q) return Interval(d);
  return Interval::hull(std::nextafter(d, -INFINITY), std::nextafter(d, INFINITY));
}
}  // namespace num

// Runs f() on filter stage S and returns its result, or throws Uncertain when a decision was not
// certain: Interval throws by itself, a flagging type (Mag) is cleared before and checked after.
template <class S, class F> auto run_filter_stage(F&& f) {
  if constexpr (requires { S::uncertain(); }) {
    S::clear_uncertain();
    auto out = f();
    if (S::uncertain()) throw Uncertain{};
    return out;
  } else {
    return f();
  }
}

}  // namespace sw
