// Rasterization-time clipping (the implementor's guide, 1.8): the double-DDA triangle fill of
// triangle-dda, restricted to a screen of samples [i0, i1) x [j0, j1). The start offset dp0 does not
// stop at the first row of the triangle but jumps straight to the first row that is also on the
// screen, and each span's offset jumps straight to the first column on the screen; the row walk
// quits at the screen's top and each span at its right edge. Nothing off the screen is ever
// visited, so the work is bounded by the screen's size, however large the triangle is.
// Semantics: docs/fill/semantics.md (the samples) and docs/fill/raster-clip.md (the screen).
#pragma once
#include <string_view>
#include <utility>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "fill/double_dda.hpp"
#include "fill/vary.hpp"

namespace sw::fill {

#define SW_FILL_RASTER_CLIP(X) \
  X(sort, "sort the vertices by y: b (bottom), m (middle), t (top)") \
  X(screen, "screen: columns i0 <= i < i1, rows j0 <= j < j1; first(v, lo, hi) = min(max(ceil(v), lo), hi)") \
  X(long_edge, "edge c, b -> t: dq_c <- (t - b) / (t_y - b_y); j <- first(b_y, j0, j1); q_c <- b + (j - b_y) dq_c") \
  X(lower_edge, "if m_y > b_y: edge a, b -> m: dq_a; q_a <- b + (j - b_y) dq_a    -- dp0 to the first row on screen") \
  X(lower_rows, "while j < m_y and j < j1:               -- rows below m, up to the screen's top") \
  X(lower_span, "    span(q_a, q_c)") \
  X(lower_step, "    q_a <- q_a + dq_a; q_c <- q_c + dq_c; j <- j + 1") \
  X(upper_edge, "if t_y > m_y: edge e, m -> t: dq_e; q_e <- m + (j - m_y) dq_e    -- j = first(m_y, j0, j1)") \
  X(upper_rows, "while j < t_y and j < j1:               -- rows from m up, up to the screen's top") \
  X(upper_span, "    span(q_e, q_c)") \
  X(upper_step, "    q_e <- q_e + dq_e; q_c <- q_c + dq_c; j <- j + 1") \
  X(span_start, \
    "span(l, r): order l, r by x; if l_x < r_x: ds <- (r - l) / (r_x - l_x); i <- first(l_x, i0, i1); s <- l + (i - l_x) ds") \
  X(span_test, "    while i < r_x and i < i1:           -- up to the span's end or the screen's right edge") \
  X(plot, "    plot (i, j) with s's attributes") \
  X(span_step, "    s <- s + ds; i <- i + 1") \
  X(done, "done")

struct RasterClip {
  static constexpr std::string_view id = "raster-clip";
  static constexpr std::string_view summary =
      "Double-DDA triangle fill clipped at rasterization time: dp0 jumps to the screen, the walk stops at its edge";
  SW_LISTING("Rasterization-time clipping", SW_FILL_RASTER_CLIP)
};
#undef SW_FILL_RASTER_CLIP

template <NumberType Num, StepProbe Probe = NoProbe>
void raster_clip(Triangle<Num> v, const Screen& sc, FillResult<Num>& out, Probe& probe) {
  using L = RasterClip;
  double_dda<L, Dp0::screen>(std::move(v), sc, {"q_attrs", "dq_attrs", "ds_attrs"}, out, probe,
                             [&](const Pixel& px, const Vary<Num>& s) { plot_attrs<L>(px, s, out, probe); });
}

}  // namespace sw::fill
