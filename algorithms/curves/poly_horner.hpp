// The baseline for poly-forward-diff: each pixel's y evaluated directly by Horner's rule, so no
// error is carried from one pixel to the next. Semantics: docs/curves/semantics.md.
#pragma once
#include "curves/poly_forward_diff.hpp"

namespace sw::curves {

struct PolyHorner {
  static constexpr std::string_view id = "poly-horner";
  static constexpr std::string_view summary = "Cubic y = P(x) evaluated afresh at each x by Horner's rule (the baseline)";
#define SW_LINES_POLY_HORNER(X) \
  X(test, "for x <- xs, xs + 1, ..., xe - 1:") \
  X(eval, "    y <- ((a x + b) x + c) x + d            -- three multiply-adds, nothing carried") \
  X(plot, "    plot (x, round(y))                      -- round(v) = floor(v + 1/2)") \
  X(done, "done")
  SW_LISTING("Cubic by Horner's rule", SW_LINES_POLY_HORNER)
#undef SW_LINES_POLY_HORNER
  // The algorithm itself, callable as PolyHorner{}(...): poly_horner below.
  template <NumberType Num, StepProbe Probe> void operator()(const Cubic<Num>& p, std::vector<Pixel>& out, Probe& probe) const;
};

template <NumberType Num, StepProbe Probe = NoProbe>
void poly_horner(const Cubic<Num>& p, std::vector<Pixel>& out, Probe& probe) {
  using L = PolyHorner;
  for (std::int64_t x = p.xs; x < p.xe; ++x) {  // bounded: xe - xs is validated
    const Num y = num::polynomial(p.c, Num(x));
    if constexpr (Probe::on) {
      auto& st = probe.step(L::eval, StepKind::advance).idx("x", x).num("y", y);
      if (x == p.xs) st.geo_list(GeoKind::polyline, curve_samples(p)).keep();  // the exact curve, once
    }
    const Pixel px{x, num::floor_int(y + Num(0.5))};
    out.push_back(px);
    if constexpr (Probe::on) probe.step(L::plot, StepKind::plot).idx("x", x).idx("j", px.y).pixel(px).point(Vec2<Num>{Num(x), y});
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done);
}

template <NumberType Num, StepProbe Probe>
void PolyHorner::operator()(const Cubic<Num>& p, std::vector<Pixel>& out, Probe& probe) const {
  poly_horner<Num>(p, out, probe);
}

}  // namespace sw::curves
