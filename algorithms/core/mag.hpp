// The filtered number of the ray family: a double that carries its magnitude (the floating-point
// filter of Burnikel, Funke and Schirra, with the index as a fixed budget instead of a field).
//
// A value is the pair (v, m): v is the double result and m the same expression evaluated on
// magnitudes (|x| for an input, m_a + m_b for a sum or a difference, m_a m_b for a product). An
// expression of index k <= kIndexBudget has |v - exact| <= gamma_k m (index rules and the proof:
// docs/rays/accuracy.md, "Filtered mode"). A comparison is decided when the difference exceeds
// that bound. Otherwise it raises a per-thread flag instead of throwing, so that the hot path has
// no exception edges (a try block around inlined code cost the plane test 40%): whoever runs an
// algorithm on Mag clears the flag first and, when it is raised afterwards, discards the result
// and re-runs the case on a later stage (run_filter_stage does both). After an undecided
// comparison the algorithm runs on with an arbitrary answer, so an algorithm used with Mag must
// stay bounded whatever its comparisons return (the ray algorithms are straight-line code).
// The pair shares one SSE register, so a sum or a product is one packed instruction: the bound
// costs nothing until a comparison reads it.
//
// Without SSE2, or with SW_MAG_PORTABLE defined (CMake option SW_MAG_PORTABLE, to test it on
// x86), the pair is two plain doubles and each packed instruction becomes the same operation on
// each lane, so that each lane rounds exactly as in the SSE2 register: the same values, magnitudes,
// indices and flag (only a NaN's sign may differ, and a NaN is never certain). One caveat, shared
// with the SSE2 path built with -mfma: a compiler that contracts across statements (GCC's default
// -ffp-contract=fast where FMA exists, as on AArch64) may fuse a product into a following sum in
// either lane. That changes last bits, not the bound: a fused a b + c rounds once where the proof
// (docs/rays/accuracy.md) allows two, so the value's error stays within gamma_k of the magnitude
// and the magnitude still rounds only sums and products of non-negative numbers (test_mag passes
// built that way). -ffp-contract=off gives the SSE2 path's values bit for bit.
//
// Preconditions the type enforces itself: an input outside {0} U [2^-100, 2^100] gets m = NaN (no
// decision that depends on it is ever certain), which with the ray family's low degrees keeps
// every product's magnitude far above the subnormal range (the tests check it, via Checked). An
// overflow or a NaN makes m non-finite, which is never certain either.
//
// BasicMag<true> (MagChecked) also tracks each value's index and each product's magnitude and
// throws std::logic_error when the budget or the underflow margin is exceeded; the tests run every
// ray algorithm on it. Mag itself never pays for that.
//
// Included by number.hpp after its declarations; include number.hpp, not this file.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#if defined(__SSE2__) && !defined(SW_MAG_PORTABLE)
#define SW_MAG_SSE2 1
#include <emmintrin.h>  // the square root's packed sqrtpd and maxpd; SSE2 is baseline on x86-64
#else
#define SW_MAG_SSE2 0  // the portable fallback: two doubles
#endif

namespace sw {

namespace mag_detail {
#if SW_MAG_SSE2
typedef double Pair __attribute__((vector_size(16)));  // [0] value, [1] magnitude
typedef std::int64_t PairBits __attribute__((vector_size(16)));
#else
// The two lanes as two doubles, read like the vector ([0] value, [1] magnitude); each operator is
// the packed instruction's lane-by-lane operation.
struct Pair {
  double v, m;
  [[gnu::always_inline]] double operator[](int i) const { return i ? m : v; }
};
[[gnu::always_inline]] inline Pair operator+(Pair a, Pair b) { return {a.v + b.v, a.m + b.m}; }
[[gnu::always_inline]] inline Pair operator*(Pair a, Pair b) { return {a.v * b.v, a.m * b.m}; }
[[gnu::always_inline]] inline Pair operator/(Pair a, Pair b) { return {a.v / b.v, a.m / b.m}; }
// maxpd(0, x): x when x is NaN or a zero of either sign (maxpd returns its second operand then).
[[gnu::always_inline]] inline double max0(double x) { return 0.0 > x ? 0.0 : x; }
// c ? a : b as a bitwise blend, like the SSE2 path's (no branch on data).
[[gnu::always_inline]] inline double blend(std::uint64_t mask, double a, double b) {
  return sw::bit_cast<double>((sw::bit_cast<std::uint64_t>(a) & mask) | (sw::bit_cast<std::uint64_t>(b) & ~mask));
}
#endif
struct NoIndex {};
struct Index {
  int k = 0;
};
}  // namespace mag_detail

template <bool Checked> class BasicMag {
  using Pair = mag_detail::Pair;

 public:
  // The largest index any decision may have. The ray algorithms reach 38 (measured by
  // MagChecked on the test sets, where every run verifies it; docs/rays/accuracy.md).
  static constexpr int kIndexBudget = 64;
  // |v - exact| <= gamma_K M_exact <= gamma_K (1 + gamma_K) m for K <= kIndexBudget, below kC m.
  static constexpr double kC = kIndexBudget * 0x1p-53 * (1 + 0x1p-40);
  static constexpr double kMinInput = 0x1p-100, kMaxInput = 0x1p100;
  // A product's magnitude is 0 or at least this (Checked verifies it): an underflow's error,
  // at most 2^-1075, is then below 2^-53 u m, inside the slack of kC.
  static constexpr double kMinProduct = 0x1p-969;

  BasicMag() = default;
  [[gnu::always_inline]] BasicMag(double x) : p_{x, input_magnitude(x)} {}
  BasicMag(int x) : BasicMag(double(x)) {}

  // The flag: raised by an undecided comparison since the last clear.
  static void clear_uncertain() { uncertain_ = false; }
  static bool uncertain() { return uncertain_; }
  [[gnu::noinline, gnu::cold]] static void raise_uncertain() { uncertain_ = true; }

  double value() const { return p_[0]; }
  double magnitude() const { return p_[1]; }
  // The error index (tracked by Checked only; 0 otherwise).
  [[gnu::always_inline]] int index() const {
    if constexpr (Checked) return ix_.k;
    else return 0;
  }
  // The decision threshold for this value: |v| above it means the sign of v is the exact sign.
  double threshold() const { return kC * p_[1] - 0x1p-1074; }

  [[gnu::always_inline]] friend BasicMag operator-(const BasicMag& a) { return make(flip_value(a.p_), a.index()); }
  [[gnu::always_inline]] friend BasicMag operator+(const BasicMag& a, const BasicMag& b) {
    return make(a.p_ + b.p_, sum_index(a, b));
  }
  [[gnu::always_inline]] friend BasicMag operator-(const BasicMag& a, const BasicMag& b) {
    return make(a.p_ + flip_value(b.p_), sum_index(a, b));
  }
  [[gnu::always_inline]] friend BasicMag operator*(const BasicMag& a, const BasicMag& b) {
    return product(a.p_ * b.p_, a.index() + b.index() + 1);
  }
  // Needs |v_b| > 2 kC m_b (b's sign certain with room to spare); else it raises the flag. Then
  // |q - exact| <= gamma_{ka+kb+4} m_q with m_q = 2 m_a m_b / v_b^2 (for an input b, 2 m_a / |v_b|).
  [[gnu::always_inline]] friend BasicMag operator/(const BasicMag& a, const BasicMag& b) {
    const double vb = b.p_[0], mb = b.p_[1];
    // An unguarded divisor raises the flag, like an undecided comparison (the case is re-run on
    // the next stage). One packed division for both lanes: the divider is the bottleneck.
    if (!(std::fabs(vb) > 2 * kC * mb)) [[unlikely]]
      raise_uncertain();
    return product(a.p_ * Pair{1, 2 * mb} / Pair{vb, vb * vb}, a.index() + b.index() + 4);
  }
  BasicMag& operator+=(const BasicMag& b) { return *this = *this + b; }
  BasicMag& operator-=(const BasicMag& b) { return *this = *this - b; }
  BasicMag& operator*=(const BasicMag& b) { return *this = *this * b; }

  // Needs exact(x) >= 0 (the caller decided it). Then |sqrt v - sqrt exact| <= sqrt|v - exact| <
  // sqrt(kC m_x), so one packed square root of (v, 2^106 kC m_x) gives the root and, with the root
  // added, m_s = sqrt v + sqrt(kC m_x) / u; the root's index is 3 whatever x's was (proof:
  // docs/rays/accuracy.md). No division, unlike m_x / sqrt v. A negative v means the caller found
  // x < 0 (or the flag is up) and discards the root; the max with 0 keeps it from being NaN (and
  // keeps a NaN m, as max returns its second operand then).
  [[gnu::always_inline]] friend BasicMag sqrt(const BasicMag& x) {
    if constexpr (Checked)
      if (x.index() > kIndexBudget)
        throw std::logic_error("Mag: a square root's radicand of index " + std::to_string(x.index()) + " exceeds the budget");
#if SW_MAG_SSE2
    const Pair r =
        reinterpret_cast<Pair>(_mm_sqrt_pd(_mm_max_pd(__m128d{0, 0}, reinterpret_cast<__m128d>(x.p_ * Pair{1, kC * 0x1p106}))));
#else
    const Pair r{std::sqrt(mag_detail::max0(x.p_.v)), std::sqrt(mag_detail::max0(x.p_.m * (kC * 0x1p106)))};
#endif
    return product(r + Pair{0, r[0]}, 3);
  }

  // c ? a : b without a branch (a bitwise blend of both lanes), for selections that depend on the
  // data: a mispredicted branch costs more than the whole filter.
  [[gnu::always_inline]] static BasicMag blend(bool c, const BasicMag& a, const BasicMag& b) {
#if SW_MAG_SSE2
    using Bits = mag_detail::PairBits;
    const std::int64_t bit = -std::int64_t(c);
    const Bits mask{bit, bit};
    return make(reinterpret_cast<Pair>((reinterpret_cast<Bits>(a.p_) & mask) | (reinterpret_cast<Bits>(b.p_) & ~mask)),
                c ? a.index() : b.index());
#else
    const std::uint64_t mask = -std::uint64_t(c);
    return make(Pair{mag_detail::blend(mask, a.p_.v, b.p_.v), mag_detail::blend(mask, a.p_.m, b.p_.m)},
                c ? a.index() : b.index());
#endif
  }

  // Each comparison decides the exact sign of a - b or raises the flag; the result is the double
  // comparison itself, which the compiler can if-convert like plain double code.
  [[gnu::always_inline]] friend bool operator<(const BasicMag& a, const BasicMag& b) { return certain(a - b) < 0; }
  [[gnu::always_inline]] friend bool operator>(const BasicMag& a, const BasicMag& b) { return certain(a - b) > 0; }
  [[gnu::always_inline]] friend bool operator<=(const BasicMag& a, const BasicMag& b) { return certain(a - b) <= 0; }
  [[gnu::always_inline]] friend bool operator>=(const BasicMag& a, const BasicMag& b) { return certain(a - b) >= 0; }
  [[gnu::always_inline]] friend bool operator==(const BasicMag& a, const BasicMag& b) { return certain(a - b) == 0; }
  [[gnu::always_inline]] friend bool operator!=(const BasicMag& a, const BasicMag& b) { return certain(a - b) != 0; }

  [[gnu::always_inline]] static int sign_of(const BasicMag& x) {
    const double v = certain(x);
    return (v > 0) - (v < 0);
  }

  // |x|: exact, so the magnitude and the index are kept.
  [[gnu::always_inline]] BasicMag absolute() const { return make(Pair{std::fabs(p_[0]), p_[1]}, index()); }

 private:
  // 0 has magnitude -0.0, so that x - 0 folds to x at compile time (m + -0.0 = m); it compares
  // like 0 everywhere.
  [[gnu::always_inline]] static double input_magnitude(double x) {
    const double a = std::fabs(x);
    return a == 0 ? -0.0 : ((a >= kMinInput) & (a <= kMaxInput)) ? a : std::numeric_limits<double>::quiet_NaN();
  }
  [[gnu::always_inline]] static Pair flip_value(Pair p) {
#if SW_MAG_SSE2
    return reinterpret_cast<Pair>(reinterpret_cast<mag_detail::PairBits>(p) ^ mag_detail::PairBits{INT64_MIN, 0});
#else
    return {-p.v, p.m};  // negation flips the sign bit only, as the xor does
#endif
  }
  [[gnu::always_inline]] static int sum_index(const BasicMag& a, const BasicMag& b) {
    return (a.index() > b.index() ? a.index() : b.index()) + 1;
  }
  [[gnu::always_inline]] static BasicMag make(Pair p, int k) {
    BasicMag r;
    r.p_ = p;
    if constexpr (Checked) r.ix_.k = k;
    return r;
  }
  // A product or quotient: Checked verifies that it kept clear of underflow.
  [[gnu::always_inline]] static BasicMag product(Pair p, int k) {
    if constexpr (Checked)
      if (p[1] != 0 && p[1] < kMinProduct)
        throw std::logic_error("Mag: a product's magnitude " + std::to_string(p[1]) + " is near underflow");
    return make(p, k);
  }
  // d's value, whose sign is the exact sign unless the flag was raised here. m = 0 means every
  // term was 0, so v = 0 exactly. The flag is written only on the (cold) undecided path: a
  // read-modify-write per comparison would chain every decision through memory.
  [[gnu::always_inline]] static double certain(const BasicMag& d) {
    if constexpr (Checked)
      if (d.index() > kIndexBudget)
        throw std::logic_error("Mag: a decision of index " + std::to_string(d.index()) + " exceeds the budget");
    const double v = d.p_[0];
    if (!(std::fabs(v) > d.threshold())) [[unlikely]]
      raise_uncertain();
    return v;
  }
  static inline thread_local bool uncertain_ = false;

  Pair p_{0, 0};
  [[no_unique_address]] std::conditional_t<Checked, mag_detail::Index, mag_detail::NoIndex> ix_;
};
using Mag = BasicMag<false>;
using MagChecked = BasicMag<true>;

namespace num {
template <bool C> [[gnu::always_inline]] inline BasicMag<C> abs(const BasicMag<C>& x) { return x.absolute(); }
template <bool C> inline std::int64_t floor_int(const BasicMag<C>& x) {
  const double v = x.value();
  if (!(std::fabs(v) < 0x1p62) || (x.magnitude() != 0 && !(std::fabs(v - std::nearbyint(v)) > x.threshold()))) {
    BasicMag<C>::raise_uncertain();
    return 0;
  }
  return static_cast<std::int64_t>(std::floor(v));
}
template <bool C> [[gnu::always_inline]] inline double to_double(const BasicMag<C>& x) { return x.value(); }
// The value is within kC m of the exact value (an index within the budget, as for decisions).
template <bool C> inline bool certified(const BasicMag<C>& x, double rel) {
  return BasicMag<C>::kC * x.magnitude() <= rel * (1 + std::fabs(x.value()));
}
// One decision instead of the generic two comparisons.
template <bool C> [[gnu::always_inline]] inline int sign(const BasicMag<C>& x) { return BasicMag<C>::sign_of(x); }
template <bool C> [[gnu::always_inline]] inline BasicMag<C> select(bool c, const BasicMag<C>& a, const BasicMag<C>& b) {
  return BasicMag<C>::blend(c, a, b);
}
// Filtered traces record the double value; the decisions made from the bound are certified.
template <bool C> inline std::string to_text(const BasicMag<C>& x) { return to_text(x.value()); }
// An input that is not a double has no exact double to filter: the exact re-run decides (this
// runs while inputs are prepared, outside any algorithm, so it may throw).
template <> inline Mag from_rational<Mag>(const Rational& q) {
  const double d = from_rational<double>(q);
  if (num::to_rational(d) != q) throw Uncertain{};
  return Mag(d);
}
template <> inline MagChecked from_rational<MagChecked>(const Rational& q) { return MagChecked(from_rational<Mag>(q).value()); }
}  // namespace num

}  // namespace sw
