// Filtered arithmetic with an a-priori (static) error bound, in the style of Shewchuk's and CGAL's
// static filters but carried along with the value: a double v plus the magnitude m of the same
// expression evaluated on absolute values (m = |x| for an input, a.m + b.m for a sum or difference,
// a.m * b.m for a product). For an expression with at most D roundings on any path,
// |v - exact| <= D 2^-53 m (1 + small). With kGamma = 2^-44 the bound holds for D <= 256, far
// more than any algorithm here uses. A sum costs one extra add and a product one extra multiply,
// with no dependency on the value chain, so this runs close to double. A comparison is decided
// when |a.v - b.v| > kGamma (a.m + b.m), else it throws Uncertain and the caller re-runs on exact
// rationals (as with Interval).
//
// Division and sqrt keep the invariant err <= kGamma m by bounding the quotient's (root's) error
// explicitly. Exact leaves (inputs that are doubles, and constants) store -|x|: a negative (or -0)
// magnitude marks a value with no error at all, so two of them compare exactly (an origin exactly
// on a slab plane, equal direction components) instead of falling back. Operations use |m|. Underflow: inputs of magnitude below 2^-100 get m = inf (every decision that depends
// on them is uncertain), so products of at most ~8 factors never reach the subnormal range
// relative to m. Overflow or NaN makes the bound non-finite and every decision uncertain.
//
// Included by number.hpp after its declarations; include number.hpp, not this file.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace sw {

class Bounded {
 public:
  static constexpr double kGamma = 0x1p-44;

  Bounded() = default;
  Bounded(double x) : v_(x), m_(input_magnitude(x)) {}
  Bounded(int x) : v_(x), m_(-std::fabs(double(x))) {}
  static Bounded make(double v, double m) { Bounded r; r.v_ = v; r.m_ = m; return r; }

  double value() const { return v_; }
  double magnitude() const { return std::fabs(m_); }
  double error() const { return m_ <= 0 ? 0.0 : kGamma * m_; }

  friend Bounded operator-(const Bounded& a) { return make(-a.v_, a.m_); }
  friend Bounded operator+(const Bounded& a, const Bounded& b) { return make(a.v_ + b.v_, std::fabs(a.m_) + std::fabs(b.m_)); }
  friend Bounded operator-(const Bounded& a, const Bounded& b) { return make(a.v_ - b.v_, std::fabs(a.m_) + std::fabs(b.m_)); }
  friend Bounded operator*(const Bounded& a, const Bounded& b) { return make(a.v_ * b.v_, std::fabs(a.m_) * std::fabs(b.m_)); }
  // The divisor's sign must be certain; then |a/b - va/vb| <= (ea + |v| eb) / (|vb| - eb).
  friend Bounded operator/(const Bounded& a, const Bounded& b) {
    const double mb = std::fabs(b.v_), bm = std::fabs(b.m_), eb = kGamma * bm * kInflate;
    if (!(mb > eb)) throw Uncertain{};
    const double v = a.v_ / b.v_, av = std::fabs(v);
    return make(v, (std::fabs(a.m_) + av * bm) / (mb - eb) * kInflate + av);
  }
  Bounded& operator+=(const Bounded& b) { return *this = *this + b; }
  Bounded& operator-=(const Bounded& b) { return *this = *this - b; }
  Bounded& operator*=(const Bounded& b) { return *this = *this * b; }

  // Precondition: the exact radicand is >= 0 (the caller decided it).
  friend Bounded sqrt(const Bounded& x) {
    const double xm = std::fabs(x.m_), e = kGamma * xm * kInflate;
    if (x.v_ > e) {  // |sqrt(y) - sqrt(v)| <= |y - v| / sqrt(v)
      const double s = std::sqrt(x.v_);
      return make(s, xm / s * kInflate + s);
    }
    if (xm == 0 && x.v_ == 0) return make(0, 0);
    // The radicand may be 0: the root lies in [0, sqrt(v + e)]; report the midpoint.
    const double half = 0.5 * std::sqrt(std::fmax(x.v_, 0.0) + e) * kInflate;
    return make(half, half / kGamma);
  }

  friend bool operator<(const Bounded& a, const Bounded& b) { return compare(a, b) < 0; }
  friend bool operator>(const Bounded& a, const Bounded& b) { return compare(a, b) > 0; }
  friend bool operator<=(const Bounded& a, const Bounded& b) { return compare(a, b) <= 0; }
  friend bool operator>=(const Bounded& a, const Bounded& b) { return compare(a, b) >= 0; }
  friend bool operator==(const Bounded& a, const Bounded& b) { return compare(a, b) == 0; }
  friend bool operator!=(const Bounded& a, const Bounded& b) { return compare(a, b) != 0; }

 private:
  static constexpr double kInflate = 1 + 0x1p-40;  // covers the rounding of the bound itself
  static double input_magnitude(double x) {
    const double a = std::fabs(x);
    return (a != 0 && a < 0x1p-100) ? std::numeric_limits<double>::infinity() : -a;  // -a: an exact leaf
  }
  // The sign of exact(a) - exact(b), or Uncertain. With m <= 0 on both sides the values are exact
  // (leaves, or computed from zeros), and the rounded difference of two finite doubles has the
  // exact difference's sign.
  [[gnu::always_inline]] static int compare(const Bounded& a, const Bounded& b) {
    const double d = a.v_ - b.v_, ad = std::fabs(d);
    if (ad > kGammaInflated * (std::fabs(a.m_) + std::fabs(b.m_)) && ad <= std::numeric_limits<double>::max()) [[likely]]
      return d > 0 ? 1 : -1;
    return compare_slow(d, a.m_, b.m_);
  }
  [[gnu::noinline, gnu::cold]] static int compare_slow(double d, double ma, double mb) {
    if (ma <= 0 && mb <= 0 && std::fabs(d) <= std::numeric_limits<double>::max()) return (d > 0) - (d < 0);
    throw Uncertain{};
  }
  static constexpr double kGammaInflated = kGamma * kInflate;
  double v_ = 0, m_ = 0;
};

namespace num {
inline std::int64_t floor_int(const Bounded& x) {
  const double a = std::floor(x.value() - x.error() * 1.01), b = std::floor(x.value() + x.error() * 1.01);
  if (a != b) throw Uncertain{};
  return static_cast<std::int64_t>(a);
}
inline double to_double(const Bounded& x) { return x.value(); }
// Filtered traces record the double value; the decisions made from the bound are certified.
inline std::string to_text(const Bounded& x) { return to_text(x.value()); }
template <> inline Bounded from_rational<Bounded>(const Rational& q) {
  const double d = from_rational<double>(q);
  if (num::to_rational(d) == q) return Bounded(d);
  // Rounded to nearest: half an ulp, one more rounding on every path (m = |d| covers it).
  if (std::fabs(d) < 0x1p-100) return Bounded::make(d, std::numeric_limits<double>::infinity());
  return Bounded::make(d, std::fabs(d) * 2);
}
}  // namespace num

}  // namespace sw
