// The half-space (edge function) triangle fill, the way GPUs rasterize: test every sample of the
// bounding box against the three edge functions, stepping them by their constant increments. A
// sample exactly on an edge is inside only on a left or bottom edge: the family's rule
// (docs/fill/semantics.md). In fixed point (int mode) coordinates are integers in units of
// 1/unit pixel, and every edge function is exact.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"

namespace sw::fill {

struct TriangleEdge {
  static constexpr std::string_view id = "triangle-edge";
  static constexpr std::string_view summary = "Half-space triangle fill: three edge functions tested at every sample of the box";
#define SW_FILL_TRIANGLE_EDGE(X) \
  X(orient, "area2 <- (b - a) x (c - a); if area2 = 0: stop; if area2 < 0: swap b, c   -- counter-clockwise") \
  X(edges, "for each edge p -> q: E(s) = (q - p) x (s - p), dE/di = -(q_y - p_y), dE/dj = q_x - p_x") \
  X(ties, "    on_edge_inside <- q_y < p_y, or q_y = p_y and q_x > p_x   -- a left or a bottom edge") \
  X(box, "box <- the samples between the vertices' least and greatest x and y, inside the scissor box") \
  X(rows, "for each row j of the box:") \
  X(row_start, "    E_k <- E_k at the row's first sample, for k = 0, 1, 2") \
  X(cols, "    for each column i of the box:") \
  X(test, "        if every E_k > 0, or E_k = 0 and on_edge_inside_k: plot (i, j)") \
  X(step, "        E_k <- E_k + dE_k/di                            -- one column right") \
  X(done, "done")
  SW_LISTING("Half-space triangle fill", SW_FILL_TRIANGLE_EDGE)
#undef SW_FILL_TRIANGLE_EDGE
};

// Vertices in units of 1/unit pixel: sample (i, j) is the point (i unit, j unit). unit = 1 except
// in fixed point. Precondition (validated): every edge function fits the number type.
// scissor: the samples [i0, i1] x [j0, j1] a raster target holds (GL's viewport or scissor box);
// samples outside it are never visited. Unbounded by default.
struct SampleBox {
  std::int64_t i0 = INT64_MIN / 4, i1 = INT64_MAX / 4, j0 = INT64_MIN / 4, j1 = INT64_MAX / 4;
};
template <class Num> struct EdgeTriangle {
  std::array<Vec2<Num>, 3> v;
  Num unit = Num(1);
  SampleBox scissor{};
};

inline constexpr const char* kEdgeNames[] = {"E0", "E1", "E2"};

template <NumberType Num, StepProbe Probe = NoProbe>
void triangle_edge(EdgeTriangle<Num> tri, std::vector<Pixel>& out, Probe& probe) {
  using L = TriangleEdge;
  Vec2<Num>&a = tri.v[0], &b = tri.v[1], &c = tri.v[2];
  const Num area2 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (area2 < Num(0)) std::swap(b, c);
  if constexpr (Probe::on) {
    const std::array<Vec2<Num>, 3> corners{a, b, c};
    probe.step(L::orient, StepKind::decide)
        .num("area2", area2)
        .idx("swapped", area2 < Num(0))
        .geo_list(GeoKind::polygon, std::span(corners))
        .keep();
  }
  if (area2 == Num(0)) {
    if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("pixels", 0);
    return;
  }
  std::array<Num, 3> di, dj;
  std::array<bool, 3> tie_inside;
  for (int k = 0; k < 3; ++k) {
    const Vec2<Num>& p = tri.v[k];
    const Vec2<Num>& q = tri.v[(k + 1) % 3];
    di[k] = -(q.y - p.y) * tri.unit;
    dj[k] = (q.x - p.x) * tri.unit;
    tie_inside[k] = q.y < p.y || (q.y == p.y && p.x < q.x);
    if constexpr (Probe::on) {
      probe.step(L::edges, StepKind::init)
          .idx("k", k)
          .num("dE_di", di[k])
          .num("dE_dj", dj[k])
          .segment(p, q)
          .label(kEdgeNames[k])
          .keep();
      probe.step(L::ties, StepKind::decide).idx("k", k).idx("on_edge_inside", tie_inside[k]);
    }
  }
  // The box's samples: ceil(min / unit) .. floor(max / unit) in each axis.
  auto lo = [&](int axis) { return num::ceil_div(std::min({a[axis], b[axis], c[axis]}), tri.unit); };
  auto hi = [&](int axis) { return num::floor_div(std::max({a[axis], b[axis], c[axis]}), tri.unit); };
  const std::int64_t i0 = std::max(lo(0), tri.scissor.i0), i1 = std::min(hi(0), tri.scissor.i1);
  const std::int64_t j0 = std::max(lo(1), tri.scissor.j0), j1 = std::min(hi(1), tri.scissor.j1);
  if constexpr (Probe::on) probe.step(L::box, StepKind::init).idx("i0", i0).idx("i1", i1).idx("j0", j0).idx("j1", j1);
  for (std::int64_t j = j0; j <= j1; ++j) {
    // E_k(s) = (q - p) x (s - p) at s = (i0, j) unit.
    std::array<Num, 3> e;
    for (int k = 0; k < 3; ++k) {
      const Vec2<Num>& p = tri.v[k];
      const Vec2<Num>& q = tri.v[(k + 1) % 3];
      e[k] = (q.x - p.x) * (Num(j) * tri.unit - p.y) - (q.y - p.y) * (Num(i0) * tri.unit - p.x);
    }
    if constexpr (Probe::on)
      probe.step(L::row_start, StepKind::advance).idx("j", j).num("E0", e[0]).num("E1", e[1]).num("E2", e[2]);
    for (std::int64_t i = i0; i <= i1; ++i) {
      bool inside = true;
      for (int k = 0; k < 3; ++k) inside = inside && (Num(0) < e[k] || (e[k] == Num(0) && tie_inside[k]));
      if (inside) out.push_back({i, j});
      if constexpr (Probe::on) {
        auto& s = probe.step(L::test, inside ? StepKind::plot : StepKind::decide)
                      .idx("i", i)
                      .idx("j", j)
                      .num("E0", e[0])
                      .num("E1", e[1])
                      .num("E2", e[2])
                      .idx("inside", inside);
        if (inside) s.pixel(Pixel{i, j});
      }
      for (int k = 0; k < 3; ++k) e[k] = e[k] + di[k];
      if constexpr (Probe::on) probe.step(L::step, StepKind::advance).num("E0", e[0]).num("E1", e[1]).num("E2", e[2]);
    }
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("pixels", static_cast<std::int64_t>(out.size()));
}

}  // namespace sw::fill
