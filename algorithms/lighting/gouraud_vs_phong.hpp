// Gouraud against Phong shading on one triangle: the lighting model (shade.hpp) at the three
// vertices, interpolated over the pixels (Gouraud), against the model at every pixel from the
// interpolated position and normal (Phong). The pixels are the fill family's triangle-edge
// (half-space rasterizer, its tie rule: docs/fill/semantics.md), called as a nested listing, as is
// shade. Semantics: docs/lighting/shade.md.
#pragma once
#include <array>
#include <string_view>
#include <vector>
#include "fill/triangle_edge.hpp"
#include "lighting/shade.hpp"

namespace sw::lighting {

template <class Num> struct ShadedTriangle {
  std::array<Vec2<Num>, 3> xy;    // the vertices on the pixel grid (sample (i, j) is the point (i, j))
  std::array<Vec3<Num>, 3> p, n;  // their positions and normals for the lighting
  ShadeScene<Num> scene;          // eye, lights, material (its p and n unused)
  std::int64_t gap = 2;  // views: triangle-edge's coverage, then Gouraud, then Phong, left to right, this many pixels apart
};

template <class Num> struct GouraudPixel {
  Pixel px;
  Vec3<Num> gouraud, phong;
  bool defined = true;  // false: the interpolated normal is 0, or the point is the eye (no Phong colour)
};

template <class Num> struct GouraudVsPhongResult {
  std::array<Vec3<Num>, 3> vertex;  // shade at the vertices
  std::vector<GouraudPixel<Num>> pixels;
  Num max_diff{0};  // the largest |phong - gouraud| over channels and defined pixels
};

struct GouraudVsPhong {
  static constexpr std::string_view id = "gouraud-vs-phong";
  static constexpr std::string_view summary =
      "Gouraud (per vertex, interpolated) against Phong (per pixel) shading over triangle-edge";
#define SW_LIGHTING_GOURAUD_VS_PHONG(X) \
  X(vertices, "for each vertex k: c_k <- shade(P_k, N_k)                       -- nested: shade") \
  X(raster, "pixels <- triangle-edge(xy_0, xy_1, xy_2)                          -- nested: triangle-edge") \
  X(pixel, "for each pixel s: b_k <- E_k(s)/area2   (E_k: the edge opposite vertex k)") \
  X(gouraud, "    gouraud <- b_0 c_0 + b_1 c_1 + b_2 c_2") \
  X(undefined, "    if b.N = 0 or b.P = eye: no Phong colour (counted); next pixel") \
  X(phong, "    phong <- shade(b_0 P_0 + b_1 P_1 + b_2 P_2, b_0 N_0 + b_1 N_1 + b_2 N_2)   -- nested: shade") \
  X(diff, "    diff <- max_k |phong_k - gouraud_k|") \
  X(done, "done: the largest difference")
  SW_LISTING("Gouraud against Phong shading", SW_LIGHTING_GOURAUD_VS_PHONG)
#undef SW_LIGHTING_GOURAUD_VS_PHONG
};

template <class Num> Vec3<Num> blend(const std::array<Num, 3>& b, const std::array<Vec3<Num>, 3>& v) {
  return b[0] * v[0] + b[1] * v[1] + b[2] * v[2];
}

// Preconditions (validated): the vertex normals are not 0, the triangle's box is small (the runtime
// bounds it), shade's preconditions at the vertices.
template <NumberType Num, StepProbe Probe = NoProbe>
GouraudVsPhongResult<Num> gouraud_vs_phong(const ShadedTriangle<Num>& t, Probe& probe) {
  using L = GouraudVsPhong;
  GouraudVsPhongResult<Num> out;
  auto shade_at = [&](const Vec3<Num>& p, const Vec3<Num>& n) -> Vec3<Num> {
    ShadeScene<Num> s = t.scene;
    s.p = p, s.n = n;
    const auto call = nested<Shade>(probe);
    return shade(s, probe).rgb;
  };
  for (int k = 0; k < 3; ++k) {
    out.vertex[k] = shade_at(t.p[k], t.n[k]);
    if constexpr (Probe::on)
      probe.step(L::vertices, StepKind::init).idx("k", k).colour("c", out.vertex[k]).point(t.xy[k]).label("vertex").keep();
  }
  std::vector<Pixel> pixels;
  {
    const auto call = nested<fill::TriangleEdge>(probe);
    fill::triangle_edge(fill::EdgeTriangle<Num>{t.xy, Num(1)}, pixels, probe);
  }
  if constexpr (Probe::on) probe.step(L::raster, StepKind::init).idx("pixels", std::int64_t(pixels.size()));
  const auto& v = t.xy;
  const Num area2 = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
  auto edge = [&](const Vec2<Num>& a, const Vec2<Num>& b, const Vec2<Num>& s) {
    return (b.x - a.x) * (s.y - a.y) - (b.y - a.y) * (s.x - a.x);
  };
  const std::int64_t shift = [&] {
    std::int64_t lo = pixels.empty() ? 0 : pixels[0].x, hi = lo;
    for (const Pixel& p : pixels) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    return hi - lo + 1 + t.gap;
  }();
  for (const Pixel& px : pixels) {
    GouraudPixel<Num> g;
    g.px = px;
    const Vec2<Num> s{Num(px.x), Num(px.y)};
    const std::array<Num, 3> b{edge(v[1], v[2], s) / area2, edge(v[2], v[0], s) / area2, edge(v[0], v[1], s) / area2};
    if constexpr (Probe::on)
      probe.step(L::pixel, StepKind::advance).idx("i", px.x).idx("j", px.y).num("b0", b[0]).num("b1", b[1]).num("b2", b[2]);
    g.gouraud = blend(b, out.vertex);
    if constexpr (Probe::on) probe.step(L::gouraud, StepKind::plot).colour("colour", g.gouraud).pixel(Pixel{px.x + shift, px.y});
    const Vec3<Num> p = blend(b, t.p), n = blend(b, t.n);
    g.defined = !(n == Vec3<Num>{}) && (t.scene.eye_at_infinity || !(p == t.scene.eye));
    if (!g.defined) {
      if constexpr (Probe::on) probe.step(L::undefined, StepKind::miss).idx("i", px.x).idx("j", px.y);
      out.pixels.push_back(g);
      continue;
    }
    g.phong = shade_at(p, n);
    if constexpr (Probe::on) probe.step(L::phong, StepKind::plot).colour("colour", g.phong).pixel(Pixel{px.x + 2 * shift, px.y});
    Num d(0);
    for (int k = 0; k < 3; ++k) d = std::max(d, num::abs(g.phong[k] - g.gouraud[k]));
    out.max_diff = std::max(out.max_diff, d);
    if constexpr (Probe::on) probe.step(L::diff, StepKind::decide).num("diff", d).num("max_diff", out.max_diff);
    out.pixels.push_back(g);
  }
  if constexpr (Probe::on)
    probe.step(L::done, StepKind::done).idx("pixels", std::int64_t(out.pixels.size())).num("max_diff", out.max_diff);
  return out;
}

}  // namespace sw::lighting
