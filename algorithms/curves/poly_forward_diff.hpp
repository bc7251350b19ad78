// The implementor's guide's DDA for polynomials: y = a x^3 + b x^2 + c x + d plotted at each
// integer x in [xs, xe) from a difference table, with additions only. Semantics:
// docs/curves/semantics.md (the guide's listing adds the third difference to itself; we add it
// to the second, as the table requires).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/functions.hpp"
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"

namespace sw::curves {

// A cubic and the integer range it is plotted on. Precondition (validated): xs <= xe and every
// |P(x)| on the range fits the mode (docs/curves/semantics.md has the bound).
template <class Num> struct Cubic {
  std::array<Num, 4> c;  // a, b, c, d
  std::int64_t xs = 0, xe = 0;
};


// Points on the curve for the canvas: n + 1 samples from xs to xe, n = 8 per column, at most 512.
template <class Num> std::vector<Vec2<Num>> curve_samples(const Cubic<Num>& p) {
  const std::int64_t n = std::clamp<std::int64_t>(8 * (p.xe - p.xs), 1, 512);
  std::vector<Vec2<Num>> pts;
  for (std::int64_t k = 0; k <= n; ++k) {
    const Num x = Num(p.xs) + Num(p.xe - p.xs) * Num(k) / Num(n);
    pts.push_back({x, num::polynomial(p.c, x)});
  }
  return pts;
}

struct PolyForwardDiff {
  static constexpr std::string_view id = "poly-forward-diff";
  static constexpr std::string_view summary = "Cubic y = P(x) by a forward-difference table: three additions per pixel";
#define SW_LINES_POLY_FORWARD_DIFF(X) \
  X(samples, "y_k <- P(xs + k) for k = 0, 1, 2, 3          -- four samples start the table") \
  X(table, "d1 <- y_1 - y_0; d2 <- (y_2 - y_1) - d1; d3 <- ((y_3 - y_2) - (y_2 - y_1)) - d2   -- d3 = 6a") \
  X(start, "x <- xs; y <- y_0") \
  X(test, "while x < xe:") \
  X(plot, "    plot (x, round(y))                      -- round(v) = floor(v + 1/2)") \
  X(step, "    x <- x + 1; y <- y + d1; d1 <- d1 + d2; d2 <- d2 + d3   -- lowest first, each with the old next") \
  X(done, "done")
  SW_LISTING("Cubic by forward differences", SW_LINES_POLY_FORWARD_DIFF)
#undef SW_LINES_POLY_FORWARD_DIFF
  // The algorithm itself, callable as PolyForwardDiff{}(...): poly_forward_diff below.
  template <NumberType Num, StepProbe Probe> void operator()(const Cubic<Num>& p, std::vector<Pixel>& out, Probe& probe) const;
};

template <NumberType Num, StepProbe Probe = NoProbe>
void poly_forward_diff(const Cubic<Num>& p, std::vector<Pixel>& out, Probe& probe) {
  using L = PolyForwardDiff;
  std::array<Num, 4> y;
  for (int k = 0; k < 4; ++k) y[k] = num::polynomial(p.c, Num(p.xs) + Num(k));
  if constexpr (Probe::on)
    probe.step(L::samples, StepKind::init)
        .num("y0", y[0])
        .num("y1", y[1])
        .num("y2", y[2])
        .num("y3", y[3])
        .geo_list(GeoKind::polyline, curve_samples(p))
        .keep();
  const Num e0 = y[1] - y[0], e1 = y[2] - y[1], e2 = y[3] - y[2];
  Num d1 = e0, d2 = e1 - e0;
  const Num d3 = e2 - e1 - d2;
  if constexpr (Probe::on) probe.step(L::table, StepKind::init).num("d1", d1).num("d2", d2).num("d3", d3);
  Num yv = y[0];
  std::int64_t x = p.xs;
  if constexpr (Probe::on) probe.step(L::start, StepKind::init).idx("x", x).num("y", yv);
  for (; x < p.xe; ++x) {  // bounded: xe - xs is validated
    const Pixel px{x, num::floor_int(yv + Num(0.5))};
    out.push_back(px);
    if constexpr (Probe::on)
      probe.step(L::plot, StepKind::plot).idx("x", x).num("y", yv).idx("j", px.y).pixel(px).point(Vec2<Num>{Num(x), yv});
    yv = yv + d1;
    d1 = d1 + d2;
    d2 = d2 + d3;
    if constexpr (Probe::on) probe.step(L::step, StepKind::advance).idx("x", x + 1).num("y", yv).num("d1", d1).num("d2", d2);
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("x", x);
}

template <NumberType Num, StepProbe Probe>
void PolyForwardDiff::operator()(const Cubic<Num>& p, std::vector<Pixel>& out, Probe& probe) const {
  poly_forward_diff<Num>(p, out, probe);
}

}  // namespace sw::curves
