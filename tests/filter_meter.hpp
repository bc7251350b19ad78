// The filtered types measured against exact shadows, for tests/test_filter_bounds.cpp: a value
// `Sh<F>` carries the filtered type F and its exact value E, and a `Meter<F>` records, per row and
// set, how close each operation's error comes to the bound F declares (Mag: its index's gamma and
// decision threshold; Interval: its widening and its half width).
#pragma once
#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include "core/functions.hpp"
#include "core/number.hpp"

namespace sw::testing::filter {

enum class Op { sum, difference, product, quotient, root };
inline const char* op_name(Op op) {
  static const char* names[] = {"op: sum", "op: difference", "op: product", "op: quotient", "op: square root"};
  return names[static_cast<int>(op)];
}

// The largest ratios of one row on one set. ratio: error / bound (Mag: gamma_k (1 + gamma_k) m;
// Interval: an operation's rounding error / its widening, or for a value |mid - E| / half width);
// ratio_c: Mag's error / its decision threshold kC m - 2^-1074, Interval's |mid - E| / half width.
struct Worst {
  double ratio = 0, ratio_c = 0;
  long count = 0;
  int max_index = 0;
  void add(double r, double rc, int k) {
    ++count;
    ratio = std::max(ratio, r);
    ratio_c = std::max(ratio_c, rc);
    max_index = std::max(max_index, k);
  }
};

inline double ratio_of(double err, double bound) {
  if (err == 0) return 0;
  return bound > 0 ? err / bound : std::numeric_limits<double>::infinity();
}

template <class F> struct Meter;

// A filtered value with its exact shadow. ok is false below an operation the filter could not
// certify (Mag's unguarded division, an Interval that threw Uncertain): no claim holds there.
template <class F> struct Sh {
  F f{};
  Rational e;
  Meter<F>* m = nullptr;
  bool ok = true;

  Sh() = default;
  Sh(double x) : f(x), e(x) {}
  Sh(int x) : f(x), e(x) {}
  Sh(F fv, Rational ev, Meter<F>* mv, bool okv) : f(fv), e(std::move(ev)), m(mv), ok(okv) {}

  friend Sh operator-(const Sh& a) { return {F(-a.f), Rational(-a.e), a.m, a.ok}; }
  friend Sh operator+(const Sh& a, const Sh& b) {
    return apply(Op::sum, a, b, [](const auto& x, const auto& y) { return x + y; });
  }
  friend Sh operator-(const Sh& a, const Sh& b) {
    return apply(Op::difference, a, b, [](const auto& x, const auto& y) { return x - y; });
  }
  friend Sh operator*(const Sh& a, const Sh& b) {
    return apply(Op::product, a, b, [](const auto& x, const auto& y) { return x * y; });
  }
  // Needs E_b != 0 (the algorithms decide the divisor first).
  friend Sh operator/(const Sh& a, const Sh& b) {
    return apply(Op::quotient, a, b, [](const auto& x, const auto& y) { return x / y; });
  }

  // fn on the filtered values and on the exact ones, measured.
  template <class Fn> static Sh apply(Op op, const Sh& a, const Sh& b, Fn&& fn) {
    Sh r;
    r.m = a.m ? a.m : b.m;
    r.ok = a.ok && b.ok;
    if constexpr (requires { F::uncertain(); }) {
      F::clear_uncertain();
      r.f = F(fn(a.f, b.f));
      if (F::uncertain()) r.ok = false;
      F::clear_uncertain();
    } else {
      try {
        r.f = F(fn(a.f, b.f));
      } catch (const Uncertain&) {
        r.ok = false;
      }
    }
    r.e = Rational(fn(a.e, b.e));
    if (r.m && r.ok) r.m->record(op, a, b, r);
    return r;
  }
};

template <class F> F filter_sqrt(const F& x) { return sqrt(x); }  // the type's own root, by ADL

// Needs E_x >= 0 (the caller decided it).
template <class F> Sh<F> root(const Sh<F>& x) {
  Sh<F> r{filter_sqrt(x.f), num::sqrt_of(x.e), x.m, x.ok};
  if (r.m && r.ok) r.m->record(Op::root, x, x, r);
  return r;
}

using Table = std::map<std::string, std::map<std::string, Worst>>;  // row -> set -> worst

// Mag: each node against its index's bound and the decision threshold.
template <bool C> struct Meter<BasicMag<C>> {
  using M = BasicMag<C>;
  Table table;
  std::string set;

  void measure(const std::string& row, const Sh<M>& x) {
    Worst& w = table[row][set];
    const double m = x.f.magnitude();
    const int k = x.f.index();
    if (!std::isfinite(m) || k > M::kIndexBudget) return;  // never certain, or beyond the budget
    const double err = std::fabs(Rational(Rational(x.f.value()) - x.e).get_d());
    const double ku = k * 0x1p-53, gamma = ku / (1 - ku);
    w.add(ratio_of(err, gamma * (1 + gamma) * std::fabs(m)), ratio_of(err, x.f.threshold()), k);
  }
  void record(Op op, const Sh<M>&, const Sh<M>&, const Sh<M>& r) { measure(op_name(op), r); }
  void out(const std::string& row, const Sh<M>& x) {
    if (x.ok) measure(row, x);
  }
};

// Interval: each operation's rounding error against its widening, from the exact image of its
// operands' intervals; each output's |mid - E| against its half width.
template <> struct Meter<Interval> {
  Table table;
  std::string set;

  static Rational lo(const Interval& x) { return Rational(x.lo()); }
  static Rational hi(const Interval& x) { return Rational(x.hi()); }
  void record(Op op, const Sh<Interval>& a, const Sh<Interval>& b, const Sh<Interval>& r) {
    Rational rlo, rhi;
    switch (op) {
      case Op::sum: rlo = lo(a.f) + lo(b.f), rhi = hi(a.f) + hi(b.f); break;
      case Op::difference: rlo = lo(a.f) - hi(b.f), rhi = hi(a.f) - lo(b.f); break;
      case Op::product:
      case Op::quotient: {
        std::array<Rational, 4> p;
        const Rational al = lo(a.f), ah = hi(a.f), bl = lo(b.f), bh = hi(b.f);
        if (op == Op::product) p = {al * bl, al * bh, ah * bl, ah * bh};
        else p = {al / bl, al / bh, ah / bl, ah / bh};
        rlo = *std::min_element(p.begin(), p.end()), rhi = *std::max_element(p.begin(), p.end());
        break;
      }
      case Op::root: {
        rlo = num::sqrt_of(Rational(std::max(a.f.lo(), 0.0))), rhi = num::sqrt_of(Rational(std::max(a.f.hi(), 0.0)));
        break;
      }
    }
    Worst& w = table[op_name(op)][set];
    w.add(std::max(end_ratio(rlo, r.f.lo(), -1), end_ratio(rhi, r.f.hi(), 1)), 0, 0);
    measure_value(r, w);
  }
  // An end's rounding error |RN(R) - R| against the widening applied to it, RN(R) - end outward
  // (outward: -1 for the lower end, +1 for the upper). An end inside the exact image R is
  // unsound: infinity.
  static double end_ratio(const Rational& exact_end, double end, int outward) {
    const Rational rounded(num::from_rational<double>(exact_end)), e(end);
    if (outward * sgn(Rational(e - exact_end)) < 0) return std::numeric_limits<double>::infinity();
    return ratio_of(std::fabs(Rational(rounded - exact_end).get_d()), outward * Rational(e - rounded).get_d());
  }
  // |mid - E| / half width: above 1 exactly when E is outside. Folded into w's ratio_c column.
  static void measure_value(const Sh<Interval>& x, Worst& w) {
    const Rational lo_q(x.f.lo()), hi_q(x.f.hi());
    const Rational mid = (lo_q + hi_q) / 2, half = (hi_q - lo_q) / 2;
    const bool inside = lo_q <= x.e && x.e <= hi_q;
    const double r = ratio_of(std::fabs(Rational(mid - x.e).get_d()), half.get_d());
    w.ratio_c = std::max(w.ratio_c, inside ? std::min(r, 1.0) : std::max(r, 1.5));
  }
  void out(const std::string& row, const Sh<Interval>& x) {
    if (!x.ok) return;
    Worst& w = table[row][set];
    ++w.count;
    measure_value(x, w);
    w.ratio = w.ratio_c;
  }
};

}  // namespace sw::testing::filter
