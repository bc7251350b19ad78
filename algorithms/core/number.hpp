// Number policies: one algorithm body runs on float, double, int64, exact rationals (GMP mpq) and
// filtered intervals. Algorithms only use + - * /, comparisons and the helpers in namespace num.
#pragma once
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <gmpxx.h>
#include "core/portable.hpp"

namespace sw {

// reference: for algorithms with transcendental functions (no exact value): rationals, with each
// sqrt, sin, cos, tan and atan2 evaluated in 300-bit MPFR and rounded; polynomial decisions stay
// exact. The same number type as exact mode (Rational); only the functions differ in what they mean.
enum class Numeric : std::uint8_t { f32, f64, integer, filtered, exact, reference };

constexpr std::string_view numeric_name(Numeric n) {
  switch (n) {
    case Numeric::f32: return "float";
    case Numeric::f64: return "double";
    case Numeric::integer: return "int";
    case Numeric::filtered: return "filtered";
    case Numeric::exact: return "exact";
    case Numeric::reference: return "reference";
  }
  return "?";
}

inline constexpr std::array kNumerics{Numeric::f32,      Numeric::f64,   Numeric::integer,
                                      Numeric::filtered, Numeric::exact, Numeric::reference};

inline std::optional<Numeric> parse_numeric(std::string_view s) {
  for (Numeric n : kNumerics)
    if (numeric_name(n) == s) return n;
  return std::nullopt;
}

// Exact rationals with eager operators: a + b of two Rationals is a Rational (GMP's expression
// templates return lazy expressions, which templates cannot deduce). Operators on temporaries
// reuse the temporary's storage, so a chain of operations allocates about as gmpxx's does.
class Rational : public mpq_class {
 public:
  using mpq_class::mpq_class;
  Rational() = default;
  Rational(const mpq_class& q) : mpq_class(q) {}
  Rational(mpq_class&& q) : mpq_class(std::move(q)) {}
  // GMP takes a long, which holds an int64 on x86-64 but not on wasm32 (the browser build), where
  // std::int64_t is long long: that goes through the int64 helpers (core/portable.hpp).
  // Templates, so that an int still takes GMP's own overloads.
  template <class LL> requires std::is_same_v<LL, long long> Rational(LL v) : mpq_class(num::mpz_of(v)) {}
  template <class LL> requires std::is_same_v<LL, long long> Rational(LL p, LL q) : mpq_class(num::mpz_of(p), num::mpz_of(q)) {}
#define SW_RATIONAL_CMP(op) \
  template <class LL> requires std::is_same_v<LL, long long> friend bool operator op(const Rational& a, LL b) { return a op Rational(b); } \
  template <class LL> requires std::is_same_v<LL, long long> friend bool operator op(LL a, const Rational& b) { return Rational(a) op b; }
  SW_RATIONAL_CMP(<)
  SW_RATIONAL_CMP(>)
  SW_RATIONAL_CMP(<=)
  SW_RATIONAL_CMP(>=)
  SW_RATIONAL_CMP(==)
  SW_RATIONAL_CMP(!=)
#undef SW_RATIONAL_CMP
  template <class T, class U> Rational(const __gmp_expr<T, U>& e) : mpq_class(e) {}
  Rational(const Rational&) = default;
  Rational(Rational&&) = default;
  Rational& operator=(const Rational&) = default;
  Rational& operator=(Rational&&) = default;
  template <class T> Rational& operator=(T&& v) {
    mpq_class::operator=(std::forward<T>(v));
    return *this;
  }

#define SW_RATIONAL_OP(op, fn) \
  friend Rational operator op(const Rational& a, const Rational& b) { \
    Rational r; \
    fn(r.get_mpq_t(), a.get_mpq_t(), b.get_mpq_t()); \
    return r; \
  } \
  friend Rational operator op(Rational&& a, const Rational& b) { \
    fn(a.get_mpq_t(), a.get_mpq_t(), b.get_mpq_t()); \
    return std::move(a); \
  } \
  friend Rational operator op(const Rational& a, Rational&& b) { \
    fn(b.get_mpq_t(), a.get_mpq_t(), b.get_mpq_t()); \
    return std::move(b); \
  } \
  friend Rational operator op(Rational&& a, Rational&& b) { \
    fn(a.get_mpq_t(), a.get_mpq_t(), b.get_mpq_t()); \
    return std::move(a); \
  } \
  template <class I> \
  requires std::is_integral_v<I> \
  friend Rational operator op(const Rational& a, I b) { return a op Rational(b); } \
  template <class I> \
  requires std::is_integral_v<I> \
  friend Rational operator op(Rational&& a, I b) { return std::move(a) op Rational(b); } \
  template <class I> \
  requires std::is_integral_v<I> \
  friend Rational operator op(I a, const Rational& b) { return Rational(a) op b; } \
  template <class I> \
  requires std::is_integral_v<I> \
  friend Rational operator op(I a, Rational&& b) { return Rational(a) op std::move(b); } \
  template <class T, class U> friend Rational operator op(const Rational& a, const __gmp_expr<T, U>& b) { \
    return a op Rational(b); \
  } \
  template <class T, class U> friend Rational operator op(const __gmp_expr<T, U>& a, const Rational& b) { \
    return Rational(a) op b; \
  } \
  template <class T, class U> friend Rational operator op(Rational&& a, const __gmp_expr<T, U>& b) { \
    return std::move(a) op Rational(b); \
  } \
  template <class T, class U> friend Rational operator op(const __gmp_expr<T, U>& a, Rational&& b) { \
    return Rational(a) op std::move(b); \
  }
  SW_RATIONAL_OP(+, mpq_add)
  SW_RATIONAL_OP(-, mpq_sub)
  SW_RATIONAL_OP(*, mpq_mul)
  SW_RATIONAL_OP(/, mpq_div)
#undef SW_RATIONAL_OP
  friend Rational operator-(const Rational& a) {
    Rational r;
    mpq_neg(r.get_mpq_t(), a.get_mpq_t());
    return r;
  }
  friend Rational operator-(Rational&& a) {
    mpq_neg(a.get_mpq_t(), a.get_mpq_t());
    return std::move(a);
  }
};
class Interval;  // core/interval.hpp

namespace num {

// Largest integer <= x, and smallest integer >= x.
// Truncation, one less below a negative fraction: std::floor is a call into libm on the x86-64
// baseline (no SSE4.1 rounding), and the z-buffer floors once a fragment. Precondition: x fits.
inline std::int64_t floor_int(double x) {
  const auto t = static_cast<std::int64_t>(x);
  return t - (x < static_cast<double>(t));
}
inline std::int64_t floor_int(float x) { return floor_int(static_cast<double>(x)); }
inline std::int64_t floor_int(std::int64_t x) { return x; }
inline std::int64_t floor_int(const Rational& x) {
  mpz_class q;
  mpz_fdiv_q(q.get_mpz_t(), x.get_num_mpz_t(), x.get_den_mpz_t());
  return int64_of(q);
}
std::int64_t floor_int(const Interval& x);
template <class T> std::int64_t ceil_int(const T& x) { return -floor_int(T(-x)); }
// floor(x / unit) and ceil(x / unit) for unit > 0: exact for integers too (fixed point), where
// C++'s / truncates toward zero.
template <class T> std::int64_t floor_div(const T& x, const T& unit) {
  if constexpr (std::is_integral_v<T>) return x / unit - (x % unit != 0 && x < 0);
  else return floor_int(T(x / unit));
}
template <class T> std::int64_t ceil_div(const T& x, const T& unit) { return -floor_div(T(-x), unit); }

inline double to_double(float x) { return x; }
inline double to_double(double x) { return x; }
inline double to_double(std::int64_t x) { return static_cast<double>(x); }
inline double to_double(const Rational& x) { return x.get_d(); }
double to_double(const Interval& x);

template <class T> T abs(const T& x) { return x < T(0) ? T(-x) : x; }
template <class T> [[gnu::always_inline]] inline int sign(const T& x) { return (T(0) < x) - (x < T(0)); }
// c ? a : b, where the choice depends on the data. Filtered types overload it with a bitwise
// blend; here GCC is told that c is unpredictable, so that it prefers a blend to a branch (it still
// branches in some contexts).
template <class T> [[gnu::always_inline]] inline T select(bool c, const T& a, const T& b) {
  return __builtin_expect_with_probability(c, true, 0.5) ? a : b;
}

// Converts an exact input value to T, rounding to nearest (ties to even) for float and double.
template <class T> T from_rational(const Rational& q);
template <> float from_rational<float>(const Rational& q);
template <> double from_rational<double>(const Rational& q);
template <> std::int64_t from_rational<std::int64_t>(const Rational& q);
template <> Rational from_rational<Rational>(const Rational& q);

// Whether q is exactly a double (then from_rational<double> returns it without rounding).
bool is_double(const Rational& q);

// Lossless text: shortest round-trip decimal for float/double (read back as a double, it is the
// same value), "p/q" or "n" for rationals, the integer for int64.
std::string to_text(float x);
std::string to_text(double x);
std::string to_text(std::int64_t x);
std::string to_text(const Rational& x);
std::string to_text(const Interval& x);

// The exact rational value of a finite float or double.
Rational to_rational(double x);

}  // namespace num

}  // namespace sw

#include "core/interval.hpp"  // filtered numbers; needs the declarations above
#include "core/mag.hpp"       // filtered doubles carrying their magnitude (the ray family)

namespace sw {

template <class T> struct NumericOf;
template <> struct NumericOf<float> { static constexpr Numeric value = Numeric::f32; };
template <> struct NumericOf<double> { static constexpr Numeric value = Numeric::f64; };
template <> struct NumericOf<std::int64_t> { static constexpr Numeric value = Numeric::integer; };
template <> struct NumericOf<Rational> { static constexpr Numeric value = Numeric::exact; };
template <> struct NumericOf<Interval> { static constexpr Numeric value = Numeric::filtered; };
template <bool C> struct NumericOf<BasicMag<C>> { static constexpr Numeric value = Numeric::filtered; };
template <class T> constexpr bool is_filtered = NumericOf<T>::value == Numeric::filtered;

// Lossless JSON text for a value: strings for rationals, numbers otherwise, and the strings "NaN",
// "Infinity" and "-Infinity" for the non-finite values (JSON has no token for them;
// docs/trace-format.md).
// An exact number's text in a trace is at most this long (1 MiB; docs/trace-format.md): a run that
// records a longer one throws std::length_error (the command's one-line error), so `check`, which
// reads up to it, reads every trace `trace` writes.
inline constexpr std::size_t kMaxExactTextChars = std::size_t{1} << 20;
// A filtered trace's numbers are within this of their exact values, relative to 1 + |value|
// (half of `check`'s tolerance for filtered traces): a stage whose decisions are certain but whose
// recorded numbers are not certified this closely is not traced; the next stage is.
inline constexpr double kFilteredTraceRel = 0x1p-37;

template <class T> std::string json_value(const T& x) {
  if constexpr (std::is_same_v<T, Rational>) {
    std::string t = num::to_text(x);
    if (t.size() > kMaxExactTextChars)
      throw std::length_error("an exact number of " + std::to_string(t.size()) + " characters, more than the " +
                              std::to_string(kMaxExactTextChars) + " a trace's numbers may have");
    return '"' + t + '"';
  } else {
    const double d = num::to_double(x);  // a test on the value, not a search of every number's text
    if (!std::isfinite(d)) return std::isnan(d) ? "\"NaN\"" : d > 0 ? "\"Infinity\"" : "\"-Infinity\"";
    return num::to_text(x);
  }
}

// json_value(x) appended to `out`. Finite floats, doubles and integers go straight in (the
// JSONL probe's hot path: no temporary string); everything else through json_value.
template <class T> void append_json(std::string& out, const T& x) {
  char buf[32];  // a double's shortest text has at most 24 characters, an int64's 20
  if constexpr (std::is_same_v<T, std::int64_t>) {
    out.append(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
    return;
  } else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, float>) {
    const double d = x;  // a float as the shortest double equal to it, as to_text writes it
    if (std::isfinite(d)) {
      out.append(buf, shortest_chars(buf, buf + sizeof buf, d));
      return;
    }
  }
  out += json_value(x);
}

}  // namespace sw
