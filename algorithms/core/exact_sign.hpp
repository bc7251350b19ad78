// The number policy for one decision that must be exact in every mode: the sign of a polynomial of
// input values, by the filter chain (core/interval.hpp, then rationals). An algorithm whose numbers
// round (float, double) still takes the branch the exact input takes.
#pragma once
#include <type_traits>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::num {

namespace detail {
// An input value as a rational (exactly: a float or a double is a rational) and as an interval (a
// point). Scalars, and vectors of them.
inline Rational exact_of(const Rational& x) { return x; }
template <class T> Rational exact_of(const T& x) { return to_rational(double(x)); }
template <class T> Vec2<Rational> exact_of(const Vec2<T>& v) { return {exact_of(v.x), exact_of(v.y)}; }
template <class T> Vec3<Rational> exact_of(const Vec3<T>& v) { return {exact_of(v.x), exact_of(v.y), exact_of(v.z)}; }
template <class T> Interval interval_of(const T& x) { return Interval(double(x)); }
template <class T> Vec2<Interval> interval_of(const Vec2<T>& v) { return {interval_of(v.x), interval_of(v.y)}; }
template <class T> Vec3<Interval> interval_of(const Vec3<T>& v) { return {interval_of(v.x), interval_of(v.y), interval_of(v.z)}; }
template <class T> struct ScalarOf { using type = T; };
template <class T> struct ScalarOf<Vec2<T>> { using type = T; };
template <class T> struct ScalarOf<Vec3<T>> { using type = T; };
}  // namespace detail

// sign(f(values...)) exactly, for f a polynomial written once for any number type (generic
// lambda) and values the raw input: scalars or vectors of float, double or Rational. In intervals
// first (a comparison they cannot certify throws Uncertain), in rationals where they cannot decide;
// rationals at once when the values are rationals.
template <class F, class... V> int exact_sign(F&& f, const V&... values) {
  auto exact = [&] { return sgn(Rational(f(detail::exact_of(values)...))); };
  if constexpr ((std::is_same_v<typename detail::ScalarOf<V>::type, Rational> && ...)) {
    return exact();
  } else {
    try {
      const Interval v = f(detail::interval_of(values)...);
      return v > Interval(0) ? 1 : v < Interval(0) ? -1 : 0;
    } catch (const Uncertain&) {
      return exact();
    }
  }
}

}  // namespace sw::num
