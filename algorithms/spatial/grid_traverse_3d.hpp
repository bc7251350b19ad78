// 3D grid walk (Amanatides & Woo): every unit cell whose half-open cube meets the half-open
// segment [p0, p1), in the order the segment enters them -- lines' dda-grid-walk in 3D, with the
// same cells and tie rules. Semantics: docs/spatial/grid.md.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"

namespace sw::spatial {

// A grid cell: cell (i, j, k) is [i-1/2, i+1/2) x [j-1/2, j+1/2) x [k-1/2, k+1/2).
struct Cell3 {
  std::int64_t i = 0, j = 0, k = 0;
  std::int64_t& operator[](int a) { return a == 0 ? i : a == 1 ? j : k; }
  std::int64_t operator[](int a) const { return a == 0 ? i : a == 1 ? j : k; }
  friend bool operator==(const Cell3&, const Cell3&) = default;
  friend auto operator<=>(const Cell3&, const Cell3&) = default;
};

// The index of the cell holding coordinate x: floor(x + 1/2), computed without rounding (x - floor(x)
// is exact in every number type). `from_below`: the limit from below instead (the cell of the
// points just before x on an increasing walk), which differs only when x is on a cell boundary.
template <NumberType Num> std::int64_t cell_index(const Num& x, bool from_below) {
  const std::int64_t f = num::floor_int(x);
  const Num r = x - Num(f);
  const Num half = Num(1) / Num(2);
  return from_below ? f + (half < r) : f + !(r < half);
}

struct GridTraverse3d {
  static constexpr std::string_view id = "grid-traverse-3d";
  static constexpr std::string_view summary =
      "3D grid walk (Amanatides-Woo): every cell the half-open segment passes through, in order";
#define SW_SPATIAL_GRID_TRAVERSE_3D(X) \
  X(delta, "d <- p1 - p0; if d = 0: stop                       -- empty segment") \
  X(start, "cell <- round(p0); last <- the cell of the points just before p1; visit cell") \
  X(setup, "for each axis a: step_a <- sign(d_a); tDelta_a <- 1/|d_a|; left_a <- |last_a - cell_a|") \
  X(first_exit, "    tMax_a <- (cell_a + step_a/2 - p0_a) / d_a    -- t where we leave the cell along a") \
  X(pick, "while cell != last: t <- min of tMax_a over the axes with left_a > 0") \
  X(visit_up, "    axes with tMax_a = t, step_a > 0: cell_a += 1; tMax_a += tDelta_a; visit  -- the new cell owns the face") \
  X(visit_down, "    axes with tMax_a = t, step_a < 0: cell_a -= 1; tMax_a += tDelta_a; visit  -- the old cell owns the face") \
  X(done, "done                                              -- cell = last")
  SW_LISTING("3D grid walk", SW_SPATIAL_GRID_TRAVERSE_3D)
#undef SW_SPATIAL_GRID_TRAVERSE_3D
};

// Appends the cells to `out` in walk order. The loop runs at most |last - first| (summed over the
// axes) times, so every mode stops, and stops at `last`, whatever its rounding.
template <NumberType Num, StepProbe Probe = NoProbe>
void grid_traverse_3d(const Vec3<Num>& p0, const Vec3<Num>& p1, std::vector<Cell3>& out, Probe& probe) {
  using L = GridTraverse3d;
  const Vec3<Num> d = p1 - p0;
  if constexpr (Probe::on)
    probe.step(L::delta, StepKind::init).num("dx", d.x).num("dy", d.y).num("dz", d.z).segment(p0, p1).keep();
  if (d.x == Num(0) && d.y == Num(0) && d.z == Num(0)) {
    if constexpr (Probe::on) probe.step(L::done, StepKind::done);
    return;
  }
  std::array<int, 3> step{num::sign(d.x), num::sign(d.y), num::sign(d.z)};
  Cell3 cell, last;
  for (int a = 0; a < 3; ++a) {
    cell[a] = cell_index(p0[a], false);
    last[a] = step[a] > 0 ? cell_index(p1[a], true) : step[a] < 0 ? cell_index(p1[a], false) : cell[a];
  }
  auto cell_box = [](const Cell3& c, Vec3<Num>& lo, Vec3<Num>& hi) {
    for (int a = 0; a < 3; ++a) lo[a] = Num(c[a]) - Num(0.5), hi[a] = Num(c[a]) + Num(0.5);
  };
  auto visit = [&](std::uint32_t line) {
    out.push_back(cell);
    if constexpr (Probe::on) {
      Vec3<Num> lo, hi;
      cell_box(cell, lo, hi);
      probe.step(line, StepKind::visit).idx("i", cell.i).idx("j", cell.j).idx("k", cell.k).box(lo, hi).keep();
    }
  };
  visit(L::start);
  std::array<Num, 3> t_max{}, t_delta{};
  std::array<std::int64_t, 3> left{};
  for (int a = 0; a < 3; ++a) {
    left[a] = last[a] < cell[a] ? cell[a] - last[a] : last[a] - cell[a];
    if (step[a] == 0) continue;
    t_delta[a] = Num(step[a]) / d[a];
    t_max[a] = (Num(cell[a]) + Num(step[a] * 0.5) - p0[a]) / d[a];
  }
  if constexpr (Probe::on) {
    probe.step(L::setup, StepKind::init)
        .idx("step_x", step[0])
        .idx("step_y", step[1])
        .idx("step_z", step[2])
        .num("tDelta_x", t_delta[0])
        .num("tDelta_y", t_delta[1])
        .num("tDelta_z", t_delta[2])
        .idx("left_x", left[0])
        .idx("left_y", left[1])
        .idx("left_z", left[2]);
    probe.step(L::first_exit, StepKind::init).num("tMax_x", t_max[0]).num("tMax_y", t_max[1]).num("tMax_z", t_max[2]);
  }
  const std::int64_t bound = left[0] + left[1] + left[2];
  for (std::int64_t n = 0; n < bound && !(cell == last); ++n) {
    // The first axis (lowest index) among those with moves left and the least tMax gives t.
    int first = -1;
    for (int a = 0; a < 3; ++a)
      if (left[a] > 0 && (first < 0 || t_max[a] < t_max[first])) first = a;
    const Num t = t_max[first];
    if constexpr (Probe::on)
      probe.step(L::pick, StepKind::decide)
          .num("t", t)
          .num("tMax_x", t_max[0])
          .num("tMax_y", t_max[1])
          .num("tMax_z", t_max[2])
          .point(p0 + t * d);
    // Axes tied with t: a comparison, so a filtered type decides it surely or asks for exact.
    std::array<bool, 3> at_t{};
    for (int a = 0; a < 3; ++a) at_t[a] = a == first || (left[a] > 0 && !(t < t_max[a]));
    for (int dir : {1, -1}) {
      bool moved = false;
      for (int a = 0; a < 3; ++a) {
        if (!at_t[a] || step[a] != dir) continue;
        cell[a] += dir, --left[a];
        t_max[a] = t_max[a] + t_delta[a];
        moved = true;
      }
      if (moved) visit(dir > 0 ? L::visit_up : L::visit_down);
    }
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("cells", static_cast<std::int64_t>(out.size()));
}

}  // namespace sw::spatial
