// The number policy for one decision that must be exact in every mode: the sign of a polynomial of
// input values, by the filter chain (core/mag.hpp's forward bound, core/interval.hpp, then
// rationals). An algorithm whose numbers round (float, double) still takes the branch the exact
// input takes.
#pragma once
#include <type_traits>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::num {

namespace detail {
// An input value as a rational (exactly: a float or a double is a rational). Scalars, and vectors
// of them.
inline Rational exact_of(const Rational& x) { return x; }
template <class T> Rational exact_of(const T& x) { return to_rational(double(x)); }
template <class T> Vec2<Rational> exact_of(const Vec2<T>& v) { return {exact_of(v.x), exact_of(v.y)}; }
template <class T> Vec3<Rational> exact_of(const Vec3<T>& v) { return {exact_of(v.x), exact_of(v.y), exact_of(v.z)}; }
// An input value on a filter stage S (Mag or Interval): exactly, as a double is.
// Inlined: a call per coordinate cost as much as the Mag stage's arithmetic.
template <class S, class T> [[gnu::always_inline]] inline S stage_of(const T& x) { return S(double(x)); }
template <class S, class T> [[gnu::always_inline]] inline Vec2<S> stage_of(const Vec2<T>& v) {
  return {stage_of<S>(v.x), stage_of<S>(v.y)};
}
template <class S, class T> [[gnu::always_inline]] inline Vec3<S> stage_of(const Vec3<T>& v) {
  return {stage_of<S>(v.x), stage_of<S>(v.y), stage_of<S>(v.z)};
}
template <class T> struct ScalarOf { using type = T; };
template <class T> struct ScalarOf<Vec2<T>> { using type = T; };
template <class T> struct ScalarOf<Vec3<T>> { using type = T; };
}  // namespace detail

// The stages after Mag: intervals, then rationals. Out of line, so that the Mag stage inlines
// into its caller without the exception edges of the interval stage.
template <class F, class... V> [[gnu::noinline]] int exact_sign_after_filter(F&& f, const V&... values) {
  try {
    const Interval v = f(detail::stage_of<Interval>(values)...);
    return v > Interval(0) ? 1 : v < Interval(0) ? -1 : 0;
  } catch (const Uncertain&) {
    return sgn(Rational(f(detail::exact_of(values)...)));
  }
}

// exact_sign with the first stage on M (Mag, or MagChecked in the tests).
template <class M, class F, class... V> [[gnu::always_inline]] inline int exact_sign_on(F&& f, const V&... values) {
  if constexpr ((std::is_same_v<typename detail::ScalarOf<V>::type, Rational> && ...)) {
    return sgn(Rational(f(detail::exact_of(values)...)));
  } else {
    // The flag is per thread and may belong to a caller running on Mag: kept as it was.
    const bool outer = M::uncertain();
    M::clear_uncertain();
    const int s = M::sign_of(f(detail::stage_of<M>(values)...));
    const bool decided = !M::uncertain();
    M::clear_uncertain();
    if (outer) M::raise_uncertain();
    if (decided) return s;
    return exact_sign_after_filter(f, values...);
  }
}

// sign(f(values...)) exactly, for f a polynomial written once for any number type (generic
// lambda) and values the raw input: scalars or vectors of float, double or Rational. First in Mag
// (a double and its magnitude: a few packed instructions, and a sign it certifies is exact), then
// in intervals (tighter; a comparison they cannot certify throws Uncertain), in rationals where
// neither decides; rationals at once when the values are rationals.
// Precondition of the Mag stage: f's error index within Mag::kIndexBudget (64); the callers' reach
// at most 11 (a degree-6 polynomial of dot products), checked on MagChecked by tests/test_exact_sign.
template <class F, class... V> [[gnu::always_inline]] inline int exact_sign(F&& f, const V&... values) {
  return exact_sign_on<Mag>(f, values...);
}

}  // namespace sw::num
