// Filtered arithmetic: a double interval that surely contains the exact value. Every decision
// (comparison, floor) is either certain or throws Uncertain; the caller then re-runs the whole
// algorithm on exact rationals (see run_filtered). Same idea as CGAL's filtered predicates.
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
  static Interval hull(double lo, double hi) { Interval r; r.lo_ = lo; r.hi_ = hi; return r; }

  double lo() const { return lo_; }
  double hi() const { return hi_; }
  double mid() const { return lo_ == hi_ ? lo_ : 0.5 * lo_ + 0.5 * hi_; }
  bool is_point() const { return lo_ == hi_; }

  friend Interval operator-(const Interval& a) { return hull(-a.hi_, -a.lo_); }
  friend Interval operator+(const Interval& a, const Interval& b) {
    return outward(a.lo_ + b.lo_, a.hi_ + b.hi_, int_points(a, b));
  }
  friend Interval operator-(const Interval& a, const Interval& b) {
    return outward(a.lo_ - b.hi_, a.hi_ - b.lo_, int_points(a, b));
  }
  friend Interval operator*(const Interval& a, const Interval& b) {
    double p1 = a.lo_ * b.lo_, p2 = a.lo_ * b.hi_, p3 = a.hi_ * b.lo_, p4 = a.hi_ * b.hi_;
    return outward(std::min({p1, p2, p3, p4}), std::max({p1, p2, p3, p4}), int_points(a, b));
  }
  friend Interval operator/(const Interval& a, const Interval& b) {
    if (b.lo_ <= 0 && b.hi_ >= 0) throw Uncertain{};  // the divisor's sign is not known
    double p1 = a.lo_ / b.lo_, p2 = a.lo_ / b.hi_, p3 = a.hi_ / b.lo_, p4 = a.hi_ / b.hi_;
    return outward(std::min({p1, p2, p3, p4}), std::max({p1, p2, p3, p4}), false);
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
  // margin, unless both operands are small integers and so is the result (then it is exact).
  static bool int_points(const Interval& a, const Interval& b) {
    return a.is_point() && b.is_point() && is_small_integer(a.lo_) && is_small_integer(b.lo_);
  }
  static Interval outward(double lo, double hi, bool int_operands) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) throw Uncertain{};
    Interval r = hull(lo, hi);
    if (!(int_operands && lo == hi && is_small_integer(lo))) r.widen();
    return r;
  }
  static bool is_small_integer(double x) { return std::fabs(x) < 0x1p52 && x == std::floor(x); }
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
// Filtered traces record the midpoint; the decisions made from the interval are certified.
inline std::string to_text(const Interval& x) { return to_text(x.mid()); }
template <> inline Interval from_rational<Interval>(const Rational& q) {
  double d = from_rational<double>(q);
  if (Rational(num::to_rational(d)) == q) return Interval(d);
  return Interval::hull(std::nextafter(d, -INFINITY), std::nextafter(d, INFINITY));
}
}  // namespace num

// Runs f on intervals; if any decision is uncertain, runs g on exact rationals. Returns whether
// the exact fallback ran.
template <class F, class G> bool run_filtered(F&& f, G&& g) {
  try {
    f();
    return false;
  } catch (const Uncertain&) {
    g();
    return true;
  }
}

}  // namespace sw
