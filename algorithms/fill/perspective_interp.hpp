// Attributes across a triangle seen in perspective. The vertices are in clip space (x, y, z, w):
// the screen position is (x/w, y/w). The triangle is first clipped against w = w_near
// (clip_near.hpp), so nothing is ever divided by a w near zero or below it; the kept polygon is
// cut into one or two triangles, each filled by the double DDA (double_dda.hpp) under the
// family's sample rule. perspective-interp carries a/w and 1/w, which are linear on screen, and
// divides at each pixel (the implementor's guide's hyperbolic interpolation); affine-interp
// carries a itself, which is linear on screen only when w is the same at every vertex.
// Semantics: docs/fill/interpolation.md.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <span>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "fill/clip_near.hpp"
#include "fill/double_dda.hpp"
#include "fill/vary.hpp"

namespace sw::fill {

#define SW_FILL_INTERP(X, PROJECT, PLOT) \
  X(clip_edge, "for each edge P -> Q: d_P <- w_P - w_near, d_Q <- w_Q - w_near     -- w_near = 1") \
  X(clip_keep, "    if d_P >= 0: keep P") \
  X(clip_cut, "    if d_P d_Q < 0: keep P + t (Q - P), t <- d_P / (d_P - d_Q)  -- attributes too") \
  X(fan, "kept corners c_0 .. c_k-1 (k = 0, 3 or 4): triangles (c_0, c_1, c_2), (c_0, c_2, c_3)") \
  X(project, PROJECT) \
  X(sort, "    sort by y: b (bottom), m (middle), t (top)") \
  X(long_edge, "    edge c, b -> t: dq_c <- (t - b) / (t_y - b_y); q_c <- b + (ceil(b_y) - b_y) dq_c") \
  X(lower_edge, "    if m_y > b_y: edge a, b -> m: dq_a, q_a as for c") \
  X(lower_rows, "    while q_a,y < m_y:") \
  X(lower_span, "        span(q_a, q_c)") \
  X(lower_step, "        q_a <- q_a + dq_a; q_c <- q_c + dq_c") \
  X(upper_edge, "    if t_y > m_y: edge e, m -> t: dq_e, q_e as for c") \
  X(upper_rows, "    while q_e,y < t_y:") \
  X(upper_span, "        span(q_e, q_c)") \
  X(upper_step, "        q_e <- q_e + dq_e; q_c <- q_c + dq_c") \
  X(span_start, "span(l, r): order by x; if l_x < r_x: ds <- (r - l) / (r_x - l_x); s <- l + (ceil(l_x) - l_x) ds") \
  X(span_test, "    while s_x < r_x:") \
  X(plot, PLOT) \
  X(span_step, "        s <- s + ds") \
  X(done, "the triangles' pixels, merged into scanline order")

#define SW_FILL_PERSPECTIVE(X) \
  SW_FILL_INTERP(X, "each triangle: corner c -> (c_x/c_w, c_y/c_w), h <- c_attrs / c_w, q <- 1 / c_w", \
                 "        plot (round(s_x), round(s_y)) with attributes s_h / s_q; texel <- checker(a_0, a_1)")
#define SW_FILL_AFFINE(X) \
  SW_FILL_INTERP(X, "each triangle: corner c -> (c_x/c_w, c_y/c_w), h <- c_attrs     -- no 1/w", \
                 "        plot (round(s_x), round(s_y)) with attributes s_h; texel <- checker(a_0, a_1)")

struct PerspectiveInterp {
  static constexpr std::string_view id = "perspective-interp";
  static constexpr std::string_view summary =
      "Perspective-correct attributes: clip at w_near, interpolate a/w and 1/w on screen, divide per pixel";
  SW_LISTING("Perspective-correct (hyperbolic) interpolation", SW_FILL_PERSPECTIVE)
};
struct AffineInterp {
  static constexpr std::string_view id = "affine-interp";
  static constexpr std::string_view summary =
      "Affine attributes in perspective: clip at w_near, interpolate a itself on screen (no divide)";
  SW_LISTING("Affine (screen-linear) interpolation", SW_FILL_AFFINE)
};
#undef SW_FILL_AFFINE
#undef SW_FILL_PERSPECTIVE
#undef SW_FILL_INTERP

// What the walk carries (a Vary): the screen position and the values that are linear on screen,
// a_0 .. a_n-1 (a/w, or a for affine) and, for perspective, q = 1/w last.

// The colour a pixel shows in the views: a texture lookup of a checkerboard of unit squares at
// (a_0, a_1) (a_0 alone when n = 1): light where floor(a_0) + floor(a_1) is even, dark where odd.
// Read from the values rounded to double, so that it never asks a filtered number to decide.
template <class Num> Vec3<Num> checker_texel(std::span<const Num> a) {
  double sum = std::floor(num::to_double(a[0]));
  if (a.size() > 1) sum += std::floor(num::to_double(a[1]));
  if (std::fmod(std::fabs(sum), 2.0) == 0) return {Num(7) / Num(8), Num(7) / Num(8), Num(3) / Num(4)};
  return {Num(1) / Num(4), Num(3) / Num(8), Num(5) / Num(8)};
}

// The whole algorithm: clip, cut into triangles, project, fill each, merge the rows.
template <bool Persp, NumberType Num, StepProbe Probe = NoProbe>
void perspective_interp(const ClipTriangle<Num>& tri, FillResult<Num>& out, Probe& probe) {
  using L = std::conditional_t<Persp, PerspectiveInterp, AffineInterp>;
  const std::size_t n = tri.n;
  const ClipPolygon<Num> poly = clip_near<L>(tri, probe);
  if constexpr (Probe::on) {
    std::array<Vec2<Num>, 4> screen;
    for (std::size_t k = 0; k < poly.k; ++k) screen[k] = {poly.c[k].c[0] / poly.c[k].w(), poly.c[k].c[1] / poly.c[k].w()};
    probe.step(L::fan, StepKind::init)
        .idx("corners", std::int64_t(poly.k))
        .geo_list(GeoKind::polygon, std::span<const Vec2<Num>>(screen.data(), poly.k))
        .keep();
  }
  std::vector<std::size_t> firsts;  // where each triangle's pixels start
  for (std::size_t f = 0; f + 2 < poly.k; ++f) {
    std::array<Vary<Num>, 3> h;
    const std::array<std::size_t, 3> idx{0, f + 1, f + 2};
    for (int k = 0; k < 3; ++k) {
      const ClipVertex<Num>& c = poly.c[idx[k]];
      const Num q = Num(1) / c.w();
      h[k].p = {c.c[0] * q, c.c[1] * q};
      h[k].n = Persp ? n + 1 : n;
      for (std::size_t a = 0; a < n; ++a) h[k].a[a] = Persp ? c.a[a] * q : c.a[a];
      if constexpr (Persp) h[k].a[n] = q;
    }
    if constexpr (Probe::on) {
      static constexpr const char* sn[3] = {"s0", "s1", "s2"};
      static constexpr const char* hn[3] = {"h0", "h1", "h2"};
      auto& st = probe.step(L::project, StepKind::init).idx("triangle", std::int64_t(f));
      for (int k = 0; k < 3; ++k) st.vec(sn[k], h[k].p).list(hn[k], h[k].attrs());
    }
    firsts.push_back(out.pixels.size());
    // The triangle by the double DDA, plotting the n attributes at each pixel (perspective: h / q).
    double_dda<L, Dp0::sample>(
        h, Screen{}, {"q_h", "dq_h", "ds_h", false, false}, out, probe, [&](const Pixel& px, const Vary<Num>& s) {
          std::array<Num, kMaxAttrs> a{};
          for (std::size_t c = 0; c < n; ++c) a[c] = Persp ? s.a[c] / s.a[n] : s.a[c];
          out.pixels.push_back(px);
          out.values.insert(out.values.end(), a.begin(), a.begin() + n);
          if constexpr (Probe::on) {
            auto& st = probe.step(L::plot, StepKind::plot).idx("i", px.x).idx("j", px.y).list("h", s.attrs());
            const std::span<const Num> vals(a.data(), n);
            st.list("values", vals).colour("texel", checker_texel<Num>(vals)).pixel(px).point(s.p).label("s");
          }
        });
  }
  if (firsts.size() == 2 && firsts[1] > firsts[0] && firsts[1] < out.pixels.size()) {  // two triangles: merge by (j, i)
    std::vector<std::size_t> order(out.pixels.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      return std::pair(out.pixels[x].y, out.pixels[x].x) < std::pair(out.pixels[y].y, out.pixels[y].x);
    });
    FillResult<Num> merged;
    for (std::size_t i : order) {
      merged.pixels.push_back(out.pixels[i]);
      merged.values.insert(merged.values.end(), out.values.begin() + i * n, out.values.begin() + (i + 1) * n);
    }
    out = std::move(merged);
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("pixels", static_cast<std::int64_t>(out.pixels.size()));
}

}  // namespace sw::fill
