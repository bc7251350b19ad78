// The implementor's guide's double-DDA triangle fill (Algorithm 1.2): DDA up the edges one row at
// a time, and on each row DDA across from the left edge to the right, carrying the attributes
// along. With the start offset dp0, every step lands on a sample point and the fill follows the
// family's rule exactly (docs/fill/semantics.md); without it (triangle-dda-no-offset, as the method
// is often presented) rows and spans start at the vertices, and neighbours overlap and leave gaps.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "fill/vary.hpp"

namespace sw::fill {

#define SW_FILL_TRIANGLE_DDA(X, START, SPAN_START)                                                          \
  X(sort, "sort the vertices by y: b (bottom), m (middle), t (top)")                                        \
  X(long_edge, "edge c, b -> t: dq_c <- (t - b) / (t_y - b_y); " START("q_c", "b"))                          \
  X(lower_edge, "if m_y > b_y: edge a, b -> m: dq_a, q_a as for c")                                          \
  X(lower_rows, "while q_a,y < m_y:                    -- rows below m")                                     \
  X(lower_span, "    span(q_a, q_c)")                                                                        \
  X(lower_step, "    q_a <- q_a + dq_a; q_c <- q_c + dq_c")                                                  \
  X(upper_edge, "if t_y > m_y: edge e, m -> t: dq_e, q_e as for c")                                          \
  X(upper_rows, "while q_e,y < t_y:                    -- rows from m up")                                   \
  X(upper_span, "    span(q_e, q_c)")                                                                        \
  X(upper_step, "    q_e <- q_e + dq_e; q_c <- q_c + dq_c")                                                  \
  X(span_start, "span(l, r): order l, r by x; if l_x < r_x: ds <- (r - l) / (r_x - l_x); " SPAN_START)      \
  X(span_test, "    while s_x < r_x:")                                                                       \
  X(plot, "    plot (round(s_x), round(s_y)) with s's attributes")                                           \
  X(span_step, "    s <- s + ds")                                                                            \
  X(done, "done")

#define SW_FILL_WITH_OFFSET(q, p) q " <- " p " + (ceil(" p "_y) - " p "_y) dq    -- start offset dp0: the first row"
#define SW_FILL_NO_OFFSET(q, p) q " <- " p "                       -- no start offset"
#define SW_FILL_DDA_OFFSET(X) SW_FILL_TRIANGLE_DDA(X, SW_FILL_WITH_OFFSET, "s <- l + (ceil(l_x) - l_x) ds")
#define SW_FILL_DDA_NO_OFFSET(X) SW_FILL_TRIANGLE_DDA(X, SW_FILL_NO_OFFSET, "s <- l")

struct TriangleDda {
  static constexpr std::string_view id = "triangle-dda";
  static constexpr std::string_view summary = "Double-DDA triangle fill: up the edges, across the rows, with the start offset";
  SW_LISTING("Double-DDA triangle fill", SW_FILL_DDA_OFFSET)
};
struct TriangleDdaNoOffset {
  static constexpr std::string_view id = "triangle-dda-no-offset";
  static constexpr std::string_view summary = "Double-DDA triangle fill without the start offset: the overlaps and gaps it causes";
  SW_LISTING("Double-DDA triangle fill, no start offset", SW_FILL_DDA_NO_OFFSET)
};
#undef SW_FILL_DDA_NO_OFFSET
#undef SW_FILL_DDA_OFFSET
#undef SW_FILL_NO_OFFSET
#undef SW_FILL_WITH_OFFSET
#undef SW_FILL_TRIANGLE_DDA

// Three vertices with their attributes (all with the same count n <= kMaxAttrs).
template <class Num> using Triangle = std::array<Vary<Num>, 3>;

// The covered pixels in scanline order and, per pixel, its n attribute values.
template <class Num> struct FillResult {
  std::vector<Pixel> pixels;
  std::vector<Num> values;
};

template <bool Offset, NumberType Num, StepProbe Probe = NoProbe>
void triangle_dda(Triangle<Num> v, FillResult<Num>& out, Probe& probe) {
  using L = std::conditional_t<Offset, TriangleDda, TriangleDdaNoOffset>;
  std::stable_sort(v.begin(), v.end(), [](const Vary<Num>& a, const Vary<Num>& b) { return a.p.y < b.p.y; });
  const Vary<Num>&b = v[0], &m = v[1], &t = v[2];
  if constexpr (Probe::on) {
    const std::array<Vec2<Num>, 3> corners{b.p, m.p, t.p};
    probe.step(L::sort, StepKind::init).vec("b", b.p).vec("m", m.p).vec("t", t.p).geo_list(GeoKind::polygon, std::span(corners)).keep();
  }
  // The start of an edge p0 -> p1 (p1_y > p0_y): its step per row, and its point on the first row.
  auto start = [](const Vary<Num>& p0, const Vary<Num>& p1) {
    const Vary<Num> dq = (p1 - p0) / Num(p1.p.y - p0.p.y);
    if constexpr (Offset) return std::pair{p0 + Num(Num(num::ceil_int(p0.p.y)) - p0.p.y) * dq, dq};
    else return std::pair{p0, dq};
  };
  auto record_edge = [&](auto line, const char* name, const Vary<Num>& q, const Vary<Num>& dq, const Vary<Num>& p0, const Vary<Num>& p1) {
    if constexpr (Probe::on) probe.step(line, StepKind::init).vec("q", q.p).list("q_attrs", q.attrs()).vec("dq", dq.p).list("dq_attrs", dq.attrs()).segment(p0.p, p1.p).label(name).keep().point(q.p).label("q");
  };
  if (!(b.p.y < t.p.y)) {  // no height: no row
    if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("pixels", 0);
    return;
  }
  auto long_edge = start(b, t);
  auto& qc = long_edge.first;  // references, not a structured binding: the lambdas below capture them
  const auto& dqc = long_edge.second;
  record_edge(L::long_edge, "c", qc, dqc, b, t);

  // One row's span between the edges' points l and r (either order), sampled at the integers in [l_x, r_x).
  auto span = [&](Vary<Num> l, Vary<Num> r) {
    if (r.p.x < l.p.x) std::swap(l, r);
    if (!(l.p.x < r.p.x)) {
      if constexpr (Probe::on) probe.step(L::span_start, StepKind::decide).num("l_x", l.p.x).num("r_x", r.p.x).idx("empty", 1);
      return;
    }
    const Vary<Num> ds = (r - l) / Num(r.p.x - l.p.x);
    Vary<Num> s = l;
    if constexpr (Offset) s = l + Num(Num(num::ceil_int(l.p.x)) - l.p.x) * ds;
    if constexpr (Probe::on) probe.step(L::span_start, StepKind::init).num("l_x", l.p.x).num("r_x", r.p.x).idx("empty", 0).vec("s", s.p).list("ds_attrs", ds.attrs()).segment(l.p, r.p).label("span");
    const std::int64_t bound = num::ceil_int(r.p.x) - num::floor_int(l.p.x) + 2;  // samples in [l_x, r_x), plus a stall pass
    for (std::int64_t k = 0; k < bound && s.p.x < r.p.x; ++k) {
      const Pixel px{num::floor_int(Num(s.p.x + Num(0.5))), num::floor_int(Num(s.p.y + Num(0.5)))};
      out.pixels.push_back(px);
      out.values.insert(out.values.end(), s.a.begin(), s.a.begin() + s.n);
      if constexpr (Probe::on) {
        probe.step(L::plot, StepKind::plot).idx("i", px.x).idx("j", px.y).list("values", s.attrs()).pixel(px).point(s.p).label("s");
        if (s.n == 3) probe.colour("colour", Vec3<Num>{s.a[0], s.a[1], s.a[2]});  // three attributes: the pixel's colour in the views
      }
      s = s + ds;
      if constexpr (Probe::on) probe.step(L::span_step, StepKind::advance).vec("s", s.p).point(s.p).label("s");
    }
  };
  // The rows of one half: edge q from p0 to p1 against the long edge, while q_y < p1_y.
  auto half = [&](auto edge_line, auto span_line, auto step_line, const char* name, const char* qname, const Vary<Num>& p0, const Vary<Num>& p1) {
    if (!(p0.p.y < p1.p.y)) {
      if constexpr (Probe::on) probe.step(edge_line, StepKind::decide).idx("flat", 1);
      return;
    }
    auto [q, dq] = start(p0, p1);
    record_edge(edge_line, name, q, dq, p0, p1);
    const std::int64_t bound = num::ceil_int(p1.p.y) - num::floor_int(p0.p.y) + 2;
    for (std::int64_t k = 0; k < bound && q.p.y < p1.p.y; ++k) {
      if constexpr (Probe::on) probe.step(span_line, StepKind::visit).vec(qname, q.p).vec("q_c", qc.p).segment(q.p, qc.p).label("row");
      span(q, qc);
      q = q + dq;
      qc = qc + dqc;
      if constexpr (Probe::on) probe.step(step_line, StepKind::advance).vec(qname, q.p).vec("q_c", qc.p);
    }
  };
  half(L::lower_edge, L::lower_span, L::lower_step, "a", "q_a", b, m);  // lower_rows, upper_rows: loop headers
  half(L::upper_edge, L::upper_span, L::upper_step, "e", "q_e", m, t);
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("pixels", static_cast<std::int64_t>(out.pixels.size()));
}

}  // namespace sw::fill
