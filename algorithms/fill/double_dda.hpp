// The double DDA that triangle-dda, triangle-dda-no-offset, raster-clip, perspective-interp and
// affine-interp share (the implementor's guide, Algorithm 1.2): sort the vertices by y, DDA up the
// edges one row at a time (q <- q + dq), and on each row DDA across from the left edge to the
// right (s <- s + ds), carrying the attributes along (a Vary). Each caller keeps its own listing L:
// the lines sort, long_edge, lower_edge, lower_span, lower_step, upper_edge, upper_span, upper_step,
// span_start, plot (the caller's plot()), span_step and done, and screen for Dp0::screen.
// Semantics: docs/fill/semantics.md, docs/fill/raster-clip.md.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "fill/vary.hpp"

namespace sw::fill {

// Three vertices with their attributes (all with the same count n <= kMaxAttrs).
template <class Num> using Triangle = std::array<Vary<Num>, 3>;

// The covered pixels in scanline order and, per pixel, its n attribute values.
template <class Num> struct FillResult {
  std::vector<Pixel> pixels;
  std::vector<Num> values;
};

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

// Where the walk starts each edge and each span: the start offset dp0.
enum class Dp0 {
  none,    // at the edge's lower vertex and the span's left end (triangle-dda-no-offset)
  sample,  // at the first row, and the first column, of samples (ceil)
  screen,  // at the first row, and column, of samples on the screen; the walk stops at its edges
};

// What the callers record differently: the names of the attribute lists, and whether the sorted
// triangle and the edges stay on the view (Life::keep) and the walk ends with a `done` step.
struct DdaRecord {
  const char *q, *dq, *ds;
  bool keep = true, done = true;
};

// Fills triangle v by the double DDA from Start, calling plot(pixel, s) at each sample s
// (plot records L::plot). `sc` is read only for Dp0::screen.
template <class L, Dp0 Start, NumberType Num, StepProbe Probe, class Plot>
void double_dda(Triangle<Num> v, const Screen& sc, const DdaRecord& rec, FillResult<Num>& out, Probe& probe, Plot&& plot) {
  constexpr bool kScreen = Start == Dp0::screen;
  std::stable_sort(v.begin(), v.end(), [](const Vary<Num>& a, const Vary<Num>& b) { return a.p.y < b.p.y; });
  const Vary<Num>&b = v[0], &m = v[1], &t = v[2];
  if constexpr (Probe::on) {
    const std::array<Vec2<Num>, 3> corners{b.p, m.p, t.p};
    auto& st = probe.step(L::sort, StepKind::init)
                   .vec("b", b.p)
                   .vec("m", m.p)
                   .vec("t", t.p)
                   .geo_list(GeoKind::polygon, std::span(corners));
    if (rec.keep) st.keep();
    if constexpr (kScreen) {
      // The screen drawn as the union of its pixels' squares: [i0 - 1/2, i1 - 1/2) x [j0 - 1/2, j1 - 1/2).
      const Num h(0.5);
      probe.step(L::screen, StepKind::init)
          .idx("i0", sc.i0)
          .idx("j0", sc.j0)
          .idx("i1", sc.i1)
          .idx("j1", sc.j1)
          .rect({Num(sc.i0) - h, Num(sc.j0) - h}, {Num(sc.i1) - h, Num(sc.j1) - h})
          .label("screen")
          .keep();
    }
  }
  if (!(b.p.y < t.p.y)) {  // no height: no row
    if constexpr (Probe::on)
      if (rec.done) probe.step(L::done, StepKind::done).idx("pixels", 0);
    return;
  }
  std::int64_t j = kScreen ? first_on_screen(b.p.y, sc.j0, sc.j1) : 0;  // Dp0::screen: the row, the first on screen at or above b
  // The edge p0 -> p1 (p1_y > p0_y): its step per row, and its point on the first row.
  auto start = [&](const Vary<Num>& p0, const Vary<Num>& p1) {
    const Vary<Num> dq = (p1 - p0) / (p1.p.y - p0.p.y);
    if constexpr (Start == Dp0::none) return std::pair{p0, dq};
    else if constexpr (Start == Dp0::sample) return std::pair{p0 + (Num(num::ceil_int(p0.p.y)) - p0.p.y) * dq, dq};
    else return std::pair{p0 + (Num(j) - p0.p.y) * dq, dq};
  };
  auto record_edge = [&](auto line, const char* name, const Vary<Num>& q, const Vary<Num>& dq, const Vary<Num>& p0,
                         const Vary<Num>& p1) {
    if constexpr (Probe::on) {
      auto& st = probe.step(line, StepKind::init);
      if constexpr (kScreen) st.idx("j", j);
      st.vec("q", q.p).list(rec.q, q.attrs()).vec("dq", dq.p).list(rec.dq, dq.attrs()).segment(p0.p, p1.p).label(name);
      if (rec.keep) st.keep();
      st.point(q.p).label("q");
    }
  };
  auto long_edge = start(b, t);
  auto& qc = long_edge.first;  // references, not a structured binding: the lambdas below capture them
  const auto& dqc = long_edge.second;
  record_edge(L::long_edge, "c", qc, dqc, b, t);

  // One row's span between the edges' points l and r (either order), sampled at the integers in
  // [l_x, r_x) (Dp0::screen: those also in [i0, i1)).
  auto span = [&](Vary<Num> l, Vary<Num> r) {
    if (r.p.x < l.p.x) std::swap(l, r);
    if (!(l.p.x < r.p.x)) {
      if constexpr (Probe::on) probe.step(L::span_start, StepKind::decide).num("l_x", l.p.x).num("r_x", r.p.x).idx("empty", 1);
      return;
    }
    const Vary<Num> ds = (r - l) / (r.p.x - l.p.x);
    std::int64_t i =
        kScreen ? first_on_screen(l.p.x, sc.i0, sc.i1) : 0;  // Dp0::screen: the first column on screen at or right of l
    Vary<Num> s = l;
    if constexpr (Start == Dp0::sample) s = l + (Num(num::ceil_int(l.p.x)) - l.p.x) * ds;
    if constexpr (kScreen) s = l + (Num(i) - l.p.x) * ds;
    if constexpr (Probe::on) {
      auto& st = probe.step(L::span_start, StepKind::init).num("l_x", l.p.x).num("r_x", r.p.x).idx("empty", 0);
      if constexpr (kScreen) st.idx("i", i);
      st.vec("s", s.p).list(rec.ds, ds.attrs()).segment(l.p, r.p).label("span");
    }
    auto sample = [&](const Pixel& px) {
      plot(px, s);
      s = s + ds;
      if constexpr (Probe::on) {
        auto& st = probe.step(L::span_step, StepKind::advance);
        if constexpr (kScreen) st.idx("i", i + 1);
        st.vec("s", s.p).point(s.p).label("s");
      }
    };
    if constexpr (kScreen) {
      for (; i < sc.i1 && Num(i) < r.p.x; ++i) sample(Pixel{i, j});  // span_test: a loop header
    } else {
      const std::int64_t bound = num::ceil_int(r.p.x) - num::floor_int(l.p.x) + 2;  // samples in [l_x, r_x), plus a stall pass
      for (std::int64_t k = 0; k < bound && s.p.x < r.p.x; ++k)
        sample(Pixel{num::floor_int(s.p.x + Num(0.5)), num::floor_int(s.p.y + Num(0.5))});
    }
  };
  // The rows of one half: edge q from p0 to p1 against the long edge, while q_y < p1_y (Dp0::screen:
  // from row j while j < p1_y and j < j1; on entry j is first(p0_y, j0, j1), so the lower half ends
  // where the upper half begins).
  auto half = [&](auto edge_line, auto span_line, auto step_line, const char* name, const char* qname, const Vary<Num>& p0,
                  const Vary<Num>& p1) {
    if (!(p0.p.y < p1.p.y)) {
      if constexpr (Probe::on) probe.step(edge_line, StepKind::decide).idx("flat", 1);
      return;
    }
    auto edge = start(p0, p1);
    auto& q = edge.first;
    const auto& dq = edge.second;
    record_edge(edge_line, name, q, dq, p0, p1);
    auto row = [&] {
      if constexpr (Probe::on) {
        auto& st = probe.step(span_line, StepKind::visit);
        if constexpr (kScreen) st.idx("j", j);
        st.vec(qname, q.p).vec("q_c", qc.p).segment(q.p, qc.p).label("row");
      }
      span(q, qc);
      q = q + dq;
      qc = qc + dqc;
      if constexpr (Probe::on) {
        auto& st = probe.step(step_line, StepKind::advance);
        if constexpr (kScreen) st.idx("j", j + 1);
        st.vec(qname, q.p).vec("q_c", qc.p);
      }
    };
    if constexpr (kScreen) {
      for (; j < sc.j1 && Num(j) < p1.p.y; ++j) row();  // lower_rows, upper_rows: loop headers
    } else {
      const std::int64_t bound = num::ceil_int(p1.p.y) - num::floor_int(p0.p.y) + 2;
      for (std::int64_t k = 0; k < bound && q.p.y < p1.p.y; ++k) row();
    }
  };
  half(L::lower_edge, L::lower_span, L::lower_step, "a", "q_a", b, m);
  half(L::upper_edge, L::upper_span, L::upper_step, "e", "q_e", m, t);
  if constexpr (Probe::on)
    if (rec.done) probe.step(L::done, StepKind::done).idx("pixels", static_cast<std::int64_t>(out.pixels.size()));
}

// The plot of triangle-dda and raster-clip: the pixel with s's attributes (three: its colour in the views).
template <class L, NumberType Num, StepProbe Probe>
void plot_attrs(const Pixel& px, const Vary<Num>& s, FillResult<Num>& out, Probe& probe) {
  out.pixels.push_back(px);
  out.values.insert(out.values.end(), s.a.begin(), s.a.begin() + s.n);
  if constexpr (Probe::on) {
    auto& st = probe.step(L::plot, StepKind::plot)
                   .idx("i", px.x)
                   .idx("j", px.y)
                   .list("values", s.attrs())
                   .pixel(px)
                   .point(s.p)
                   .label("s");
    if (s.n == 3) st.colour("colour", Vec3<Num>{s.a[0], s.a[1], s.a[2]});
  }
}

}  // namespace sw::fill
