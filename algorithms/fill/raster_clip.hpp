// Rasterization-time clipping (the implementor's guide, 1.8): the double-DDA triangle fill of
// triangle-dda, restricted to a screen of samples [i0, i1) x [j0, j1). The start offset dp0 does not
// stop at the first row of the triangle but jumps straight to the first row that is also on the
// screen, and each span's offset jumps straight to the first column on the screen; the row walk
// quits at the screen's top and each span at its right edge. Nothing off the screen is ever
// visited, so the work is bounded by the screen's size, however large the triangle is.
// Semantics: docs/fill/semantics.md (the samples) and docs/fill/raster-clip.md (the screen).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "fill/triangle_dda.hpp"
#include "fill/vary.hpp"

namespace sw::fill {

#define SW_FILL_RASTER_CLIP(X)                                                                                  \
  X(sort, "sort the vertices by y: b (bottom), m (middle), t (top)")                                           \
  X(screen, "screen: columns i0 <= i < i1, rows j0 <= j < j1; first(v, lo, hi) = min(max(ceil(v), lo), hi)")   \
  X(long_edge, "edge c, b -> t: dq_c <- (t - b) / (t_y - b_y); j <- first(b_y, j0, j1); q_c <- b + (j - b_y) dq_c") \
  X(lower_edge, "if m_y > b_y: edge a, b -> m: dq_a; q_a <- b + (j - b_y) dq_a    -- dp0 to the first row on screen") \
  X(lower_rows, "while j < m_y and j < j1:               -- rows below m, up to the screen's top")              \
  X(lower_span, "    span(q_a, q_c)")                                                                           \
  X(lower_step, "    q_a <- q_a + dq_a; q_c <- q_c + dq_c; j <- j + 1")                                         \
  X(upper_edge, "if t_y > m_y: edge e, m -> t: dq_e; q_e <- m + (j - m_y) dq_e    -- j = first(m_y, j0, j1)")   \
  X(upper_rows, "while j < t_y and j < j1:               -- rows from m up, up to the screen's top")            \
  X(upper_span, "    span(q_e, q_c)")                                                                           \
  X(upper_step, "    q_e <- q_e + dq_e; q_c <- q_c + dq_c; j <- j + 1")                                         \
  X(span_start, "span(l, r): order l, r by x; if l_x < r_x: ds <- (r - l) / (r_x - l_x); i <- first(l_x, i0, i1); s <- l + (i - l_x) ds") \
  X(span_test, "    while i < r_x and i < i1:           -- up to the span's end or the screen's right edge") \
  X(plot, "    plot (i, j) with s's attributes")                                                                 \
  X(span_step, "    s <- s + ds; i <- i + 1")                                                                    \
  X(done, "done")

struct RasterClip {
  static constexpr std::string_view id = "raster-clip";
  static constexpr std::string_view summary = "Double-DDA triangle fill clipped at rasterization time: dp0 jumps to the screen, the walk stops at its edge";
  SW_LISTING("Rasterization-time clipping", SW_FILL_RASTER_CLIP)
};
#undef SW_FILL_RASTER_CLIP

// The screen: the samples (i, j) with i0 <= i < i1 and j0 <= j < j1 (half-open, as the family's
// rows and spans are). Precondition: i0 < i1, j0 < j1, |i|, |j| < 2^53 (exact in double).
struct Screen {
  std::int64_t i0 = 0, j0 = 0, i1 = 0, j1 = 0;
};

// The first integer k >= v that is also in [lo, hi), or hi when there is none: min(max(ceil(v), lo), hi).
// Decided by comparisons before any rounding, so a coordinate far off the screen (or, in a rounded
// mode, an overflowed one) is never converted to an integer.
template <NumberType Num> std::int64_t first_on_screen(const Num& v, std::int64_t lo, std::int64_t hi) {
  if (!(Num(lo) < v)) return lo;
  if (!(v < Num(hi))) return hi;
  return num::ceil_int(v);
}

template <NumberType Num, StepProbe Probe = NoProbe>
void raster_clip(Triangle<Num> v, const Screen& sc, FillResult<Num>& out, Probe& probe) {
  using L = RasterClip;
  std::stable_sort(v.begin(), v.end(), [](const Vary<Num>& a, const Vary<Num>& b) { return a.p.y < b.p.y; });
  const Vary<Num>&b = v[0], &m = v[1], &t = v[2];
  if constexpr (Probe::on) {
    const std::array<Vec2<Num>, 3> corners{b.p, m.p, t.p};
    probe.step(L::sort, StepKind::init).vec("b", b.p).vec("m", m.p).vec("t", t.p).geo_list(GeoKind::polygon, std::span(corners)).keep();
    // The screen drawn as the union of its pixels' squares: [i0 - 1/2, i1 - 1/2) x [j0 - 1/2, j1 - 1/2).
    const Num h(0.5);
    probe.step(L::screen, StepKind::init).idx("i0", sc.i0).idx("j0", sc.j0).idx("i1", sc.i1).idx("j1", sc.j1)
        .rect({Num(Num(sc.i0) - h), Num(Num(sc.j0) - h)}, {Num(Num(sc.i1) - h), Num(Num(sc.j1) - h)}).label("screen").keep();
  }
  if (!(b.p.y < t.p.y)) {  // no height: no row
    if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("pixels", 0);
    return;
  }
  // The edge p0 -> p1 (p1_y > p0_y): its step per row, and its point on row j (dp0 = (j - p0_y) dq).
  auto start = [](const Vary<Num>& p0, const Vary<Num>& p1, std::int64_t j) {
    const Vary<Num> dq = (p1 - p0) / Num(p1.p.y - p0.p.y);
    return std::pair{p0 + Num(Num(j) - p0.p.y) * dq, dq};
  };
  auto record_edge = [&](auto line, const char* name, std::int64_t j, const Vary<Num>& q, const Vary<Num>& dq, const Vary<Num>& p0, const Vary<Num>& p1) {
    if constexpr (Probe::on)
      probe.step(line, StepKind::init).idx("j", j).vec("q", q.p).list("q_attrs", q.attrs()).vec("dq", dq.p).list("dq_attrs", dq.attrs())
          .segment(p0.p, p1.p).label(name).keep().point(q.p).label("q");
  };
  std::int64_t j = first_on_screen(b.p.y, sc.j0, sc.j1);  // the row: the first on screen at or above b
  auto long_edge = start(b, t, j);
  auto& qc = long_edge.first;  // references, not a structured binding: the lambdas below capture them
  const auto& dqc = long_edge.second;
  record_edge(L::long_edge, "c", j, qc, dqc, b, t);

  // One row's span between the edges' points l and r (either order): the samples i in [l_x, r_x)
  // that are also in [i0, i1).
  auto span = [&](Vary<Num> l, Vary<Num> r) {
    if (r.p.x < l.p.x) std::swap(l, r);
    if (!(l.p.x < r.p.x)) {
      if constexpr (Probe::on) probe.step(L::span_start, StepKind::decide).num("l_x", l.p.x).num("r_x", r.p.x).idx("empty", 1);
      return;
    }
    const Vary<Num> ds = (r - l) / Num(r.p.x - l.p.x);
    std::int64_t i = first_on_screen(l.p.x, sc.i0, sc.i1);  // the first column on screen at or right of l
    Vary<Num> s = l + Num(Num(i) - l.p.x) * ds;
    if constexpr (Probe::on)
      probe.step(L::span_start, StepKind::init).num("l_x", l.p.x).num("r_x", r.p.x).idx("empty", 0).idx("i", i).vec("s", s.p).list("ds_attrs", ds.attrs()).segment(l.p, r.p).label("span");
    for (; i < sc.i1 && Num(i) < r.p.x; ++i) {  // span_test: a loop header
      const Pixel px{i, j};
      out.pixels.push_back(px);
      out.values.insert(out.values.end(), s.a.begin(), s.a.begin() + s.n);
      if constexpr (Probe::on) {
        probe.step(L::plot, StepKind::plot).idx("i", i).idx("j", j).list("values", s.attrs()).pixel(px).point(s.p).label("s");
        if (s.n == 3) probe.colour("colour", Vec3<Num>{s.a[0], s.a[1], s.a[2]});  // three attributes: the pixel's colour in the views
      }
      s = s + ds;
      if constexpr (Probe::on) probe.step(L::span_step, StepKind::advance).idx("i", i + 1).vec("s", s.p).point(s.p).label("s");
    }
  };
  // The rows of one half: edge q from p0 to p1 against the long edge, from row j while j < p1_y and
  // j < j1. On entry j is first(p0_y, j0, j1): the lower half ends where the upper half begins.
  auto half = [&](auto edge_line, auto span_line, auto step_line, const char* name, const char* qname, const Vary<Num>& p0, const Vary<Num>& p1) {
    if (!(p0.p.y < p1.p.y)) {
      if constexpr (Probe::on) probe.step(edge_line, StepKind::decide).idx("flat", 1);
      return;
    }
    auto [q, dq] = start(p0, p1, j);
    record_edge(edge_line, name, j, q, dq, p0, p1);
    for (; j < sc.j1 && Num(j) < p1.p.y; ++j) {  // lower_rows, upper_rows: loop headers
      if constexpr (Probe::on) probe.step(span_line, StepKind::visit).idx("j", j).vec(qname, q.p).vec("q_c", qc.p).segment(q.p, qc.p).label("row");
      span(q, qc);
      q = q + dq;
      qc = qc + dqc;
      if constexpr (Probe::on) probe.step(step_line, StepKind::advance).idx("j", j + 1).vec(qname, q.p).vec("q_c", qc.p);
    }
  };
  half(L::lower_edge, L::lower_span, L::lower_step, "a", "q_a", b, m);
  half(L::upper_edge, L::upper_span, L::upper_step, "e", "q_e", m, t);
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("pixels", static_cast<std::int64_t>(out.pixels.size()));
}

}  // namespace sw::fill
