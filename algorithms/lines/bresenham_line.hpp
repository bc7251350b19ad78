// Bresenham: the integer-only DDA for integer endpoints. Walks from p0 toward p1 (p1 excluded),
// one pixel per major-axis unit, choosing the minor step with a decision variable e.
// Semantics: docs/lines/semantics.md.
#pragma once
#include <array>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"

namespace sw::lines {

struct BresenhamLine {
  static constexpr std::string_view id = "bresenham-line";
  static constexpr std::string_view summary = "Bresenham: integer endpoints, integer decision variable, p1 excluded";
#define SW_LINES_BRESENHAM_LINE(X) \
  X(delta, "d <- p1 - p0                              -- integer endpoints") \
  X(major, "a <- x if |dx| > |dy|, else y; b <- the other axis   -- ties step rows") \
  X(signs, "s_a <- sign(d_a); s_b <- sign(d_b); A <- |d_a|; B <- |d_b|") \
  X(decision, "e <- 2B - A                               -- 2A x (minor offset of the next sample - 1/2)") \
  X(loop, "p <- p0; repeat A times:") \
  X(plot, "    plot p") \
  X(test, "    if e > 0, or e = 0 and s_b > 0:        -- a tie rounds up: floor(v + 1/2)") \
  X(minor_step, "        p_b <- p_b + s_b; e <- e - 2A") \
  X(major_step, "    p_a <- p_a + s_a; e <- e + 2B") \
  X(done, "done")
  SW_LISTING("Bresenham line", SW_LINES_BRESENHAM_LINE)
#undef SW_LINES_BRESENHAM_LINE
};

// Precondition: p0 and p1 have integer coordinates (the caller validates this).
template <NumberType Num, StepProbe Probe = NoProbe>
bool bresenham_line(Vec2<Num> p0, Vec2<Num> p1, std::vector<Pixel>& out, Probe& probe) {
  using L = BresenhamLine;
  const Vec2<Num> d = p1 - p0;
  if constexpr (Probe::on) probe.step(L::delta, StepKind::init).num("dx", d.x).num("dy", d.y).segment(p0, p1).keep();
  const int a = num::abs(d.x) > num::abs(d.y) ? 0 : 1, b = 1 - a;
  if constexpr (Probe::on) probe.step(L::major, StepKind::decide).idx("a", a);
  const int sa = num::sign(d[a]), sb = num::sign(d[b]);
  const Num A = num::abs(d[a]), B = num::abs(d[b]);
  if constexpr (Probe::on) probe.step(L::signs, StepKind::init).idx("s_a", sa).idx("s_b", sb).num("A", A).num("B", B);
  Num e = Num(2) * B - A;
  if constexpr (Probe::on) probe.step(L::decision, StepKind::init).num("e", e);
  // The walk keeps p's major and minor coordinates apart (pa, pb); p is (pa, pb) or (pb, pa).
  Num pa = p0[a], pb = p0[b];
  auto point = [&] { return a == 0 ? Vec2<Num>{pa, pb} : Vec2<Num>{pb, pa}; };
  const std::int64_t count = num::floor_int(A);
  if constexpr (Probe::on) probe.step(L::loop, StepKind::init).idx("count", count).point(point());
  for (std::int64_t k = 0; k < count; ++k) {
    const std::int64_t ia = num::floor_int(pa), ib = num::floor_int(pb);
    const Pixel px = a == 0 ? Pixel{ia, ib} : Pixel{ib, ia};
    out.push_back(px);
    if constexpr (Probe::on) probe.step(L::plot, StepKind::plot).idx("i", px.x).idx("j", px.y).num("e", e).pixel(px);
    const bool up = e > Num(0) || (e == Num(0) && sb > 0);
    if constexpr (Probe::on) probe.step(L::test, StepKind::decide).num("e", e).idx("minor_step", up);
    if (up) {
      pb = pb + Num(sb);
      e = e - Num(2) * A;
      if constexpr (Probe::on) probe.step(L::minor_step, StepKind::advance).num("e", e).point(point());
    }
    pa = pa + Num(sa);
    e = e + Num(2) * B;
    if constexpr (Probe::on) probe.step(L::major_step, StepKind::advance).num("e", e).point(point());
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done);
  return true;
}

}  // namespace sw::lines
