// The implementor's guide's double-DDA triangle fill (Algorithm 1.2): DDA up the edges one row at
// a time, and on each row DDA across from the left edge to the right, carrying the attributes
// along. With the start offset dp0, every step lands on a sample point and the fill follows the
// family's rule exactly (docs/fill/semantics.md); without it (triangle-dda-no-offset, as the method
// is often presented) rows and spans start at the vertices, and neighbours overlap and leave gaps.
#pragma once
#include <string_view>
#include <type_traits>
#include <utility>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "fill/double_dda.hpp"
#include "fill/vary.hpp"

namespace sw::fill {

#define SW_FILL_TRIANGLE_DDA(X, START, SPAN_START) \
  X(sort, "sort the vertices by y: b (bottom), m (middle), t (top)") \
  X(long_edge, "edge c, b -> t: dq_c <- (t - b) / (t_y - b_y); " START("q_c", "b")) \
  X(lower_edge, "if m_y > b_y: edge a, b -> m: dq_a, q_a as for c") \
  X(lower_rows, "while q_a,y < m_y:                    -- rows below m") \
  X(lower_span, "    span(q_a, q_c)") \
  X(lower_step, "    q_a <- q_a + dq_a; q_c <- q_c + dq_c") \
  X(upper_edge, "if t_y > m_y: edge e, m -> t: dq_e, q_e as for c") \
  X(upper_rows, "while q_e,y < t_y:                    -- rows from m up") \
  X(upper_span, "    span(q_e, q_c)") \
  X(upper_step, "    q_e <- q_e + dq_e; q_c <- q_c + dq_c") \
  X(span_start, "span(l, r): order l, r by x; if l_x < r_x: ds <- (r - l) / (r_x - l_x); " SPAN_START) \
  X(span_test, "    while s_x < r_x:") \
  X(plot, "    plot (round(s_x), round(s_y)) with s's attributes") \
  X(span_step, "    s <- s + ds") \
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
  static constexpr std::string_view summary =
      "Double-DDA triangle fill without the start offset: the overlaps and gaps it causes";
  SW_LISTING("Double-DDA triangle fill, no start offset", SW_FILL_DDA_NO_OFFSET)
};
#undef SW_FILL_DDA_NO_OFFSET
#undef SW_FILL_DDA_OFFSET
#undef SW_FILL_NO_OFFSET
#undef SW_FILL_WITH_OFFSET
#undef SW_FILL_TRIANGLE_DDA

template <bool Offset, NumberType Num, StepProbe Probe = NoProbe>
void triangle_dda(Triangle<Num> v, FillResult<Num>& out, Probe& probe) {
  using L = std::conditional_t<Offset, TriangleDda, TriangleDdaNoOffset>;
  double_dda<L, Offset ? Dp0::sample : Dp0::none>(std::move(v), Screen{}, {"q_attrs", "dq_attrs", "ds_attrs"}, out, probe,
                                                  [&](const Pixel& px, const Vary<Num>& s) { plot_attrs<L>(px, s, out, probe); });
}

}  // namespace sw::fill
