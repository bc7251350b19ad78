// The implementor's-guide DDA line. Samples the segment at each integer position of the major
// axis and plots the pixel whose square holds the sample. Semantics: docs/lines/semantics.md.
#pragma once
#include <array>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"

namespace sw::lines {

struct DdaLine {
  static constexpr std::string_view id = "dda-line";
  static constexpr std::string_view summary = "DDA line: sample the major axis at integers, round the minor axis";
#define SW_LINES_DDA_LINE(X) \
  X(delta, "d <- p1 - p0") \
  X(major, "a <- x if |dx| > |dy|, else y            -- ties step rows") \
  X(swap, "if d_a < 0: swap p0 and p1, d <- -d      -- always walk upward along a") \
  X(empty, "if d_a = 0: stop                         -- empty segment") \
  X(slope, "dp <- d / d_a                            -- one unit along a per step") \
  X(offset, "q <- p0 + (ceil(p0_a) - p0_a) * dp       -- start offset dp0 lands on the first column") \
  X(test, "while q_a < p1_a:") \
  X(plot, "    plot (round(q_x), round(q_y))        -- round(v) = floor(v + 1/2)") \
  X(advance, "    q <- q + dp") \
  X(done, "done")
  SW_LISTING("DDA line", SW_LINES_DDA_LINE)
#undef SW_LINES_DDA_LINE
};

// Appends the pixels to `out`. Returns false if the loop bound stopped the walk (this happens only
// when the number type cannot represent q_a + 1, e.g. float beyond 2^24).
template <NumberType Num, StepProbe Probe = NoProbe>
bool dda_line(Vec2<Num> p0, Vec2<Num> p1, std::vector<Pixel>& out, Probe& probe) {
  using L = DdaLine;
  Vec2<Num> d = p1 - p0;
  if constexpr (Probe::on) probe.step(L::delta, StepKind::init).num("dx", d.x).num("dy", d.y).segment(p0, p1).keep();
  const int a = num::abs(d.x) > num::abs(d.y) ? 0 : 1;
  if constexpr (Probe::on) probe.step(L::major, StepKind::decide).idx("a", a);
  const bool swapped = d[a] < Num(0);
  if (swapped) {
    std::swap(p0, p1);
    d = Vec2<Num>{-d.x, -d.y};
  }
  if constexpr (Probe::on) probe.step(L::swap, StepKind::decide).idx("swapped", swapped).num("dx", d.x).num("dy", d.y);
  if (d[a] == Num(0)) {
    if constexpr (Probe::on) probe.step(L::empty, StepKind::done);
    return true;
  }
  Vec2<Num> dp;
  dp[a] = Num(1);
  dp[1 - a] = d[1 - a] / d[a];
  if constexpr (Probe::on) probe.step(L::slope, StepKind::init).num("dpx", dp.x).num("dpy", dp.y);
  const Num first = Num(num::ceil_int(p0[a]));
  const Num offset = first - p0[a];
  Vec2<Num> q = p0 + offset * dp;
  if constexpr (Probe::on)
    probe.step(L::offset, StepKind::init)
        .num("dp0x", offset * dp.x)
        .num("dp0y", offset * dp.y)
        .num("qx", q.x)
        .num("qy", q.y)
        .point(q)
        .label("q");
  // Columns in [p0_a, p1_a): ceil(p1_a) - ceil(p0_a) of them; one more pass detects a stall.
  const std::int64_t bound = num::ceil_int(p1[a]) - num::ceil_int(p0[a]) + 1;
  for (std::int64_t n = 0; n < bound; ++n) {
    if (!(q[a] < p1[a])) {
      if constexpr (Probe::on) probe.step(L::done, StepKind::done).num("qx", q.x).num("qy", q.y).point(q).label("q");
      return true;
    }
    const Pixel px{num::floor_int(q.x + Num(0.5)), num::floor_int(q.y + Num(0.5))};
    out.push_back(px);
    if constexpr (Probe::on)
      probe.step(L::plot, StepKind::plot)
          .num("qx", q.x)
          .num("qy", q.y)
          .idx("i", px.x)
          .idx("j", px.y)
          .pixel(px)
          .point(q)
          .label("q");
    q = q + dp;
    if constexpr (Probe::on) probe.step(L::advance, StepKind::advance).num("qx", q.x).num("qy", q.y).point(q).label("q");
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).num("qx", q.x).num("qy", q.y).idx("bound_hit", 1);
  return false;
}

}  // namespace sw::lines
