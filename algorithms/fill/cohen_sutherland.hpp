// Cohen-Sutherland: a segment clipped to the closed axis-aligned window [min, max]. Each end gets
// a 4-bit outcode (which of the window's four boundary lines it lies strictly beyond); the segment
// is accepted when both codes are 0, rejected when they share a bit, and otherwise one end outside
// is moved to where the segment meets one boundary line, and the test repeats.
// Semantics: docs/fill/clipping.md.
#pragma once
#include <array>
#include <optional>
#include <string_view>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"

namespace sw::fill {

// The outcode bits: the end lies strictly left of x = min.x, right of x = max.x, below y = min.y,
// above y = max.y. A point on the window's boundary has code 0 (the window is closed).
enum OutcodeBit : int { kLeft = 1, kRight = 2, kBelow = 4, kAbove = 8 };

template <class Num> int outcode(const Vec2<Num>& p, const Vec2<Num>& lo, const Vec2<Num>& hi) {
  return (p.x < lo.x ? kLeft : 0) | (hi.x < p.x ? kRight : 0) | (p.y < lo.y ? kBelow : 0) | (hi.y < p.y ? kAbove : 0);
}

template <class Num> struct ClippedSegment {
  std::optional<std::array<Vec2<Num>, 2>> segment;  // none: the segment misses the window
  bool bound_hit = false;                           // the cut bound stopped the loop (rounded modes only)
};

struct CohenSutherland {
  static constexpr std::string_view id = "cohen-sutherland";
  static constexpr std::string_view summary = "Cohen-Sutherland: clip a segment to a closed window by outcodes";
#define SW_FILL_COHEN_SUTHERLAND(X) \
  X(codes, "c0 <- code(p0); c1 <- code(p1)       -- bits: 1 x < xmin, 2 x > xmax, 4 y < ymin, 8 y > ymax") \
  X(loop, "repeat (at most 4 cuts):") \
  X(accept, "    if c0 | c1 = 0: return [p0, p1]    -- both ends in the closed window") \
  X(reject, "    if c0 & c1 != 0: return nothing    -- both ends beyond the same boundary line") \
  X(cut_x, \
    "    k <- 0 if c0 != 0, else 1; b <- lowest bit of c_k; if b is 1 or 2: X <- xmin or xmax;" \
    " p_k <- (X, y0 + (y1 - y0) (X - x0) / (x1 - x0))") \
  X(cut_y, "    else: Y <- ymin or ymax; p_k <- (x0 + (x1 - x0) (Y - y0) / (y1 - y0), Y)") \
  X(recode, "    c_k <- code(p_k)")
  SW_LISTING("Cohen-Sutherland line clipping", SW_FILL_COHEN_SUTHERLAND)
#undef SW_FILL_COHEN_SUTHERLAND
};

// Clips p0 -> p1 to the window [lo, hi] (precondition: lo <= hi in both coordinates). The result
// keeps the direction: its first end is the one on p0's side.
template <NumberType Num, StepProbe Probe = NoProbe>
ClippedSegment<Num> cohen_sutherland(Vec2<Num> p0, Vec2<Num> p1, const Vec2<Num>& lo, const Vec2<Num>& hi, Probe& probe) {
  using L = CohenSutherland;
  std::array<Vec2<Num>, 2> p{p0, p1};
  std::array<int, 2> c{outcode(p0, lo, hi), outcode(p1, lo, hi)};
  if constexpr (Probe::on) {
    // The window, its four boundary lines (they cut the plane into the nine outcode regions),
    // drawn one window size plus 1 beyond it, and the input segment stay on the view. No
    // comparison here: a filtered trace must not decide anything the run did not.
    const Vec2<Num> reach = (hi - lo) + Vec2<Num>{Num(1), Num(1)};
    const Vec2<Num> f0 = lo - reach, f1 = hi + reach;
    probe.step(L::codes, StepKind::init).idx("c0", c[0]).idx("c1", c[1]);
    probe.rect(lo, hi).label("window").keep();
    using V = Vec2<Num>;
    probe.segment(V{lo.x, f0.y}, V{lo.x, f1.y})
        .label("x = xmin")
        .keep()
        .segment(V{hi.x, f0.y}, V{hi.x, f1.y})
        .label("x = xmax")
        .keep();
    probe.segment(V{f0.x, lo.y}, V{f1.x, lo.y})
        .label("y = ymin")
        .keep()
        .segment(V{f0.x, hi.y}, V{f1.x, hi.y})
        .label("y = ymax")
        .keep();
    probe.segment(p0, p1).label("segment").keep();
    probe.point(p0).label("p0").value(Num(c[0])).replace().point(p1).label("p1").value(Num(c[1])).replace();
  }
  // In exact arithmetic each end is cut at most twice (once on x, once on y; clipping.md), so the
  // fifth test accepts or rejects. The bound stops a rounded mode that keeps cutting near a corner.
  constexpr int kMaxCuts = 4;
  for (int cuts = 0;; ++cuts) {  // bounded: the reject test returns at cuts == kMaxCuts
    if ((c[0] | c[1]) == 0) {
      if constexpr (Probe::on)
        probe.step(L::accept, StepKind::hit).idx("c0", c[0]).idx("c1", c[1]).segment(p[0], p[1]).label("clipped").keep();
      return {p, false};
    }
    if ((c[0] & c[1]) != 0 || cuts == kMaxCuts) {
      const bool bound_hit = (c[0] & c[1]) == 0;  // only a rounded mode gets here
      if constexpr (Probe::on) {
        probe.step(L::reject, StepKind::miss).idx("c0", c[0]).idx("c1", c[1]);
        if (bound_hit) probe.idx("bound_hit", 1);
      }
      return {std::nullopt, bound_hit};
    }
    const int k = c[0] != 0 ? 0 : 1;
    const int bit = c[k] & -c[k];  // the lowest set bit
    const Vec2<Num> d = p[1] - p[0];
    auto record_cut = [&](auto line) {
      if constexpr (Probe::on)
        probe.step(line, StepKind::advance).idx("k", k).idx("b", bit).num("x", p[k].x).num("y", p[k].y).point(p[k]).label("cut");
    };
    if (bit == kLeft || bit == kRight) {
      const Num x = bit == kLeft ? lo.x : hi.x;
      p[k] = {x, p[0].y + d.y * (x - p[0].x) / d.x};
      record_cut(L::cut_x);
    } else {
      const Num y = bit == kBelow ? lo.y : hi.y;
      p[k] = {p[0].x + d.x * (y - p[0].y) / d.y, y};
      record_cut(L::cut_y);
    }
    c[k] = outcode(p[k], lo, hi);
    if constexpr (Probe::on) {
      probe.step(L::recode, StepKind::decide).idx("k", k).idx("c0", c[0]).idx("c1", c[1]);
      probe.point(p[k]).label(k == 0 ? "p0" : "p1").value(Num(c[k])).replace();
    }
  }
}

}  // namespace sw::fill
