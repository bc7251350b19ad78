// Grid walk (Amanatides-Woo in 2D): every pixel whose half-open square meets the half-open
// segment [p0, p1), in the order the segment enters them. Semantics: docs/lines/semantics.md.
#pragma once
#include <array>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"

namespace sw::lines {

struct DdaGridWalk {
  static constexpr std::string_view id = "dda-grid-walk";
  static constexpr std::string_view summary = "Grid walk: every pixel the half-open segment passes through, in order";
#define SW_LINES_DDA_GRID_WALK(X) \
  X(delta, "d <- p1 - p0; if d = 0: stop              -- empty segment") \
  X(start, "cell <- (round(p0_x), round(p0_y)); visit cell") \
  X(setup, "for each axis a: step_a <- sign(d_a); tDelta_a <- 1/|d_a|") \
  X(first_exit, "    tMax_a <- (cell_a + step_a/2 - p0_a) / d_a   -- t where we leave the cell along a") \
  X(pick, "loop: t <- min_a tMax_a") \
  X(test, "    if t >= 1 or a step leaves p1's cell range: stop  -- p1 excluded; the range guards a stalled tMax") \
  X(up, "    for axes with tMax_a = t, step_a > 0: cell_a += 1; tMax_a += tDelta_a") \
  X(visit_up, "    if any moved: visit cell               -- an upward boundary belongs to the new cell") \
  X(down, "    for axes with tMax_a = t, step_a < 0: cell_a -= 1; tMax_a += tDelta_a") \
  X(visit_down, "    if any moved: visit cell               -- a downward boundary belongs to the old one") \
  X(done, "done")
  SW_LISTING("Grid walk", SW_LINES_DDA_GRID_WALK)
#undef SW_LINES_DDA_GRID_WALK
};

// Appends the cells to `out` in walk order. Returns false if the loop bound stopped the walk
// (only when the number type cannot advance tMax, e.g. float with |d| > 2^24).
template <NumberType Num, StepProbe Probe = NoProbe>
bool dda_grid_walk(Vec2<Num> p0, Vec2<Num> p1, std::vector<Pixel>& out, Probe& probe) {
  using L = DdaGridWalk;
  const Vec2<Num> d = p1 - p0;
  if constexpr (Probe::on) probe.step(L::delta, StepKind::init).num("dx", d.x).num("dy", d.y).segment(p0, p1).keep();
  if (d.x == Num(0) && d.y == Num(0)) {
    if constexpr (Probe::on) probe.step(L::done, StepKind::done);
    return true;
  }
  Pixel cell{num::floor_int(p0.x + Num(0.5)), num::floor_int(p0.y + Num(0.5))};
  // Every point p0 + t d with t < 1 lies in a cell between p0's and p1's along each axis, so no
  // walk steps past p1's cell. Exact arithmetic stops on t >= 1 first; a number type whose tMax
  // stalls (float, |d| beyond 2^24) stops here instead of running on past p1.
  const Pixel last{num::floor_int(p1.x + Num(0.5)), num::floor_int(p1.y + Num(0.5))};
  out.push_back(cell);
  if constexpr (Probe::on) probe.step(L::start, StepKind::visit).idx("i", cell.x).idx("j", cell.y).pixel(cell).point(p0);
  std::array<int, 2> step{num::sign(d.x), num::sign(d.y)};
  std::array<Num, 2> t_max{}, t_delta{};
  std::int64_t bound = 4;  // crossings of each axis, plus slack to detect a stall
  for (int a = 0; a < 2; ++a) {
    if (step[a] == 0) continue;
    t_delta[a] = Num(step[a]) / d[a];
    const std::int64_t c = a == 0 ? cell.x : cell.y;
    t_max[a] = (Num(c) + Num(step[a] * 0.5) - p0[a]) / d[a];
    bound += num::floor_int(num::abs(d[a])) + 2;
  }
  if constexpr (Probe::on)
    probe.step(L::setup, StepKind::init)
        .idx("step_x", step[0])
        .idx("step_y", step[1])
        .num("tDelta_x", t_delta[0])
        .num("tDelta_y", t_delta[1]);
  if constexpr (Probe::on) probe.step(L::first_exit, StepKind::init).num("tMax_x", t_max[0]).num("tMax_y", t_max[1]);
  for (std::int64_t n = 0; n < bound; ++n) {
    // Which axes leave the cell first: x, y or both at once (a corner). Comparisons only, so a
    // filtered number type either decides this surely or asks for the exact re-run.
    const bool x_first = step[1] == 0 || (step[0] != 0 && t_max[0] < t_max[1]);
    const bool y_first = !x_first && (step[0] == 0 || t_max[1] < t_max[0]);
    const bool hit[2] = {!y_first, !x_first};
    const Num t = hit[0] ? t_max[0] : t_max[1];
    if constexpr (Probe::on)
      probe.step(L::pick, StepKind::decide).num("t", t).num("tMax_x", t_max[0]).num("tMax_y", t_max[1]).point(p0 + t * d);
    const bool past = (hit[0] && step[0] != 0 && (cell.x + step[0] - last.x) * step[0] > 0) ||
                      (hit[1] && step[1] != 0 && (cell.y + step[1] - last.y) * step[1] > 0);
    const bool reached = !(t < Num(1));
    if (reached || past) {
      if constexpr (Probe::on)
        probe.step(L::test, StepKind::done).num("t", t).idx("past_p1", !reached);  // 1: the range guard stopped it
      return true;
    }
    for (int dir : {1, -1}) {
      bool moved = false;
      for (int a = 0; a < 2; ++a) {
        if (!hit[a] || step[a] != dir) continue;
        (a == 0 ? cell.x : cell.y) += dir;
        t_max[a] = t_max[a] + t_delta[a];
        moved = true;
      }
      if (!moved) continue;
      out.push_back(cell);
      if constexpr (Probe::on)
        probe.step(dir > 0 ? L::visit_up : L::visit_down, StepKind::visit)
            .idx("i", cell.x)
            .idx("j", cell.y)
            .num("tMax_x", t_max[0])
            .num("tMax_y", t_max[1])
            .pixel(cell);
    }
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("bound_hit", 1);
  return false;
}

}  // namespace sw::lines
