// A cubic Bezier curve sampled at t = k/n by forward differences (the guide's polynomial DDA on
// vectors), and drawn as n DDA segments: the lines family's dda-line runs as a nested listing.
// Semantics: docs/curves/semantics.md.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"
#include "lines/dda_line.hpp"

namespace sw::curves {

// Control points and the number of segments. Precondition (validated): 1 <= n <= 1024.
template <class Num> struct Bezier {
  std::array<Vec2<Num>, 4> p;
  std::int64_t n = 1;
};

// B(t) in Bernstein form: (1-t)^3 P0 + 3 (1-t)^2 t P1 + 3 (1-t) t^2 P2 + t^3 P3.
template <class Num> Vec2<Num> bezier_at(const std::array<Vec2<Num>, 4>& p, const Num& t) {
  const Num s = Num(1) - t;
  const std::array<Num, 4> w = {s * s * s, Num(3) * s * s * t, Num(3) * s * t * t, t * t * t};
  Vec2<Num> q{Num(0), Num(0)};
  for (int i = 0; i < 4; ++i) q = q + w[i] * p[i];
  return q;
}

struct BezierForwardDiff {
  static constexpr std::string_view id = "bezier-forward-diff";
  static constexpr std::string_view summary =
      "Cubic Bezier: points at t = k/n by forward differences, joined by dda-line segments";
#define SW_LINES_BEZIER_FORWARD_DIFF(X) \
  X(samples, "q_k <- B(k/n) for k = 0, 1, 2, 3             -- four curve points start the table (Bernstein form)") \
  X(table, "d1 <- q_1 - q_0; d2 <- (q_2 - q_1) - d1; d3 <- ((q_3 - q_2) - (q_2 - q_1)) - d2   -- vectors") \
  X(test, "for k <- 0, 1, ..., n - 1:") \
  X(segment, "    draw q -> q + d1 with dda-line             -- q + d1 is B((k + 1)/n)") \
  X(step, "    q <- q + d1; d1 <- d1 + d2; d2 <- d2 + d3   -- lowest first, each with the old next") \
  X(done, "done")
  SW_LISTING("Bezier by forward differences", SW_LINES_BEZIER_FORWARD_DIFF)
#undef SW_LINES_BEZIER_FORWARD_DIFF
};

template <NumberType Num, StepProbe Probe = NoProbe>
void bezier_forward_diff(const Bezier<Num>& b, std::vector<Pixel>& out, Probe& probe) {
  using L = BezierForwardDiff;
  std::array<Vec2<Num>, 4> q;
  for (int k = 0; k < 4; ++k) q[k] = bezier_at(b.p, Num(k) / Num(b.n));
  if constexpr (Probe::on) {
    std::vector<Vec2<Num>> curve;  // the curve itself, for the canvas: 8 points per segment, at most 512
    const std::int64_t m = std::min<std::int64_t>(8 * b.n, 512);
    for (std::int64_t k = 0; k <= m; ++k) curve.push_back(bezier_at(b.p, Num(k) / Num(m)));
    probe.step(L::samples, StepKind::init)
        .vec("q0", q[0])
        .vec("q1", q[1])
        .vec("q2", q[2])
        .vec("q3", q[3])
        .geo_list(GeoKind::polyline, curve)
        .keep();
  }
  const Vec2<Num> e0 = q[1] - q[0], e1 = q[2] - q[1], e2 = q[3] - q[2];
  Vec2<Num> d1 = e0, d2 = e1 - e0;
  const Vec2<Num> d3 = (e2 - e1) - d2;
  if constexpr (Probe::on) probe.step(L::table, StepKind::init).vec("d1", d1).vec("d2", d2).vec("d3", d3);
  Vec2<Num> p = q[0];
  for (std::int64_t k = 0; k < b.n; ++k) {  // bounded: n is validated
    const Vec2<Num> next = p + d1;
    if constexpr (Probe::on) probe.step(L::segment, StepKind::advance).idx("k", k).segment(p, next);
    {
      const auto call = nested<lines::DdaLine>(probe);
      (void)lines::dda_line<Num>(p, next, out, probe);
    }
    p = next;
    d1 = d1 + d2;
    d2 = d2 + d3;
    if constexpr (Probe::on) probe.step(L::step, StepKind::advance).idx("k", k + 1).vec("q", p).vec("d1", d1).point(p);
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("k", b.n);
}

}  // namespace sw::curves
