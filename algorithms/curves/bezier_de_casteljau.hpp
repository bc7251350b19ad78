// A cubic Bezier curve by de Casteljau subdivision: halve the control polygon at t = 1/2 down to a
// fixed depth, and draw each final piece's chord P0 -> P3 with dda-line (a nested listing). The
// chords end at B(k / 2^depth), the same points as bezier-forward-diff with n = 2^depth, but every
// point is a chain of midpoints (convex combinations), so rounded modes stay on the curve.
// Semantics: docs/curves/semantics.md.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "core/vec.hpp"
#include "curves/bezier_forward_diff.hpp"
#include "lines/dda_line.hpp"

namespace sw::curves {

// Control points and the subdivision depth. Precondition (validated): 0 <= depth <= 10.
template <class Num> struct BezierDepth {
  std::array<Vec2<Num>, 4> p;
  int depth = 0;
};

struct BezierDeCasteljau {
  static constexpr std::string_view id = "bezier-de-casteljau";
  static constexpr std::string_view summary = "Cubic Bezier: de Casteljau halving to a depth, chords drawn by dda-line";
#define SW_LINES_BEZIER_DE_CASTELJAU(X) \
  X(call, "subdivide(P0, P1, P2, P3, level)              -- piece k of the curve; level = depth at the top") \
  X(leaf, "    if level = 0: draw P0 -> P3 with dda-line; return") \
  X(halve, "    P01 <- (P0 + P1)/2; P12 <- (P1 + P2)/2; P23 <- (P2 + P3)/2") \
  X(halve2, "    P012 <- (P01 + P12)/2; P123 <- (P12 + P23)/2; M <- (P012 + P123)/2   -- M is on the curve") \
  X(left, "    subdivide(P0, P01, P012, M, level - 1)       -- the first half, then") \
  X(right, "    subdivide(M, P123, P23, P3, level - 1)       -- the second") \
  X(done, "done")
  SW_LISTING("Bezier by de Casteljau subdivision", SW_LINES_BEZIER_DE_CASTELJAU)
#undef SW_LINES_BEZIER_DE_CASTELJAU
};

namespace detail {

// Piece k at `level` covers t in [k, k + 1] / 2^(depth - level). Recursion depth <= 10 (validated).
template <NumberType Num, StepProbe Probe>
void subdivide(const std::array<Vec2<Num>, 4>& p, int level, std::int64_t k, std::vector<Pixel>& out, Probe& probe) {
  using L = BezierDeCasteljau;
  if constexpr (Probe::on)
    probe.step(L::call, StepKind::visit).idx("level", level).idx("k", k).geo_list(GeoKind::polyline, std::span(p));
  if (level == 0) {
    if constexpr (Probe::on) probe.step(L::leaf, StepKind::advance).idx("level", level).idx("k", k).segment(p[0], p[3]);
    const auto call = nested<lines::DdaLine>(probe);
    (void)lines::dda_line<Num>(p[0], p[3], out, probe);
    return;
  }
  const Num half(0.5);
  const Vec2<Num> p01 = half * (p[0] + p[1]), p12 = half * (p[1] + p[2]), p23 = half * (p[2] + p[3]);
  if constexpr (Probe::on) probe.step(L::halve, StepKind::advance).vec("P01", p01).vec("P12", p12).vec("P23", p23);
  const Vec2<Num> p012 = half * (p01 + p12), p123 = half * (p12 + p23), m = half * (p012 + p123);
  if constexpr (Probe::on)
    probe.step(L::halve2, StepKind::advance).vec("P012", p012).vec("P123", p123).vec("M", m).point(m).label("M");
  if constexpr (Probe::on) probe.step(L::left, StepKind::advance).idx("level", level - 1).idx("k", 2 * k);
  subdivide<Num>({p[0], p01, p012, m}, level - 1, 2 * k, out, probe);
  if constexpr (Probe::on) probe.step(L::right, StepKind::advance).idx("level", level - 1).idx("k", 2 * k + 1);
  subdivide<Num>({m, p123, p23, p[3]}, level - 1, 2 * k + 1, out, probe);
}

}  // namespace detail

template <NumberType Num, StepProbe Probe = NoProbe>
void bezier_de_casteljau(const BezierDepth<Num>& b, std::vector<Pixel>& out, Probe& probe) {
  using L = BezierDeCasteljau;
  detail::subdivide<Num>(b.p, b.depth, 0, out, probe);
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("pieces", std::int64_t{1} << b.depth);
}

}  // namespace sw::curves
