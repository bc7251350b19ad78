// Scanline polygon fill with a global edge table and an active edge list: any polygon, self-
// intersecting or with holes (extra rings), filled by the even-odd or the nonzero winding rule.
// Each edge is a DDA in y (with the start offset onto its first row); on each row the active
// edges' crossings, sorted in x, bound the spans. Rows [y_low, y_high) and spans [x_k, x_k+1)
// are the family's half-open rule (docs/fill/semantics.md).
#pragma once
#include <algorithm>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"

namespace sw::fill {

struct ScanlinePolygon {
  static constexpr std::string_view id = "scanline-polygon";
  static constexpr std::string_view summary = "Scanline polygon fill: edge table, active edges, even-odd or nonzero winding";
#define SW_FILL_SCANLINE_POLYGON(X) \
  X(edge, "for each edge p -> q with p_y != q_y:      -- horizontal edges cross no row") \
  X(bucket, "    put it in the edge table at row ceil(y_low): x <- x at that row, dx <- per row, dir <- +1 up, -1 down") \
  X(first, "j <- the edge table's lowest row") \
  X(rows, "while the edge table or the active list holds an edge:") \
  X(add, "    move the edge table's edges of row j to the active list") \
  X(drop, "    drop the active edges with y_high <= j   -- rows [y_low, y_high)") \
  X(sort, "    sort the active list by x") \
  X(spans, "    w <- 0; for each active edge k in x order: w <- w + dir_k") \
  X(fill, "        if w is odd (even-odd) or w != 0 (nonzero): plot i = ceil(x_k) .. ceil(x_k+1) - 1") \
  X(advance, "    x <- x + dx for every active edge; j <- j + 1, or the next table row if none is active") \
  X(done, "done")
  SW_LISTING("Scanline polygon fill", SW_FILL_SCANLINE_POLYGON)
#undef SW_FILL_SCANLINE_POLYGON
};

enum class WindingRule { even_odd, nonzero };

template <class Num> struct Polygon {
  std::vector<std::vector<Vec2<Num>>> rings;  // each closed: the last vertex joins the first
  WindingRule rule = WindingRule::even_odd;
};

template <class Num> struct TableEdge {
  std::int64_t row;  // its first row, ceil(y_low)
  Num x, dx, y_high;
  int dir;
};

// A recorded list holds at most 64 entries: a longer active list shows its first 64.
template <class T> std::span<const T> shown(const std::vector<T>& v) {
  return std::span<const T>(v).first(std::min<std::size_t>(v.size(), 64));
}

// Appends the covered pixels in scanline order.
template <NumberType Num, StepProbe Probe = NoProbe>
void scanline_polygon(const Polygon<Num>& poly, std::vector<Pixel>& out, Probe& probe) {
  using L = ScanlinePolygon;
  std::vector<TableEdge<Num>> table;
  for (const auto& ring : poly.rings) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec2<Num>& p = ring[k];
      const Vec2<Num>& q = ring[(k + 1) % ring.size()];
      if constexpr (Probe::on) {
        probe.step(L::edge, StepKind::decide).vec("p", p).vec("q", q).idx("horizontal", p.y == q.y).segment(p, q);
        if (k == 0) probe.geo_list(GeoKind::polygon, std::span(ring)).keep();  // the ring, on its first edge's step
      }
      if (p.y == q.y) continue;
      const Vec2<Num>& lo = p.y < q.y ? p : q;
      const Vec2<Num>& hi = p.y < q.y ? q : p;
      const Num dx = (hi.x - lo.x) / (hi.y - lo.y);
      const std::int64_t row = num::ceil_int(lo.y);
      table.push_back({row, lo.x + (Num(row) - lo.y) * dx, dx, hi.y, p.y < q.y ? 1 : -1});
      if constexpr (Probe::on)
        probe.step(L::bucket, StepKind::init)
            .idx("row", row)
            .num("x", table.back().x)
            .num("dx", dx)
            .num("y_high", hi.y)
            .idx("dir", table.back().dir)
            .segment(lo, hi)
            .label(p.y < q.y ? "up" : "down")
            .keep();
    }
  }
  std::stable_sort(table.begin(), table.end(), [](const TableEdge<Num>& a, const TableEdge<Num>& b) { return a.row < b.row; });
  if (table.empty()) {
    if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("pixels", 0);
    return;
  }
  std::vector<TableEdge<Num>> active;
  std::size_t next = 0;
  std::int64_t j = table.front().row;
  if constexpr (Probe::on) probe.step(L::first, StepKind::init).idx("j", j);
  auto xs = [&] {
    std::vector<Num> v;
    for (const auto& e : active) v.push_back(e.x);
    return v;
  };
  // Each pass handles one row that holds an active edge: at most the rows spanned by the table.
  std::int64_t last_row = j;
  for (const auto& e : table) last_row = std::max(last_row, num::ceil_int(e.y_high));
  for (std::int64_t pass = 0; pass <= last_row - table.front().row && (next < table.size() || !active.empty()); ++pass) {
    for (; next < table.size() && table[next].row == j; ++next) active.push_back(table[next]);
    if constexpr (Probe::on)
      probe.step(L::add, StepKind::advance).idx("j", j).idx("active", static_cast<std::int64_t>(active.size()));
    std::erase_if(active, [&](const TableEdge<Num>& e) { return !(Num(j) < e.y_high); });
    if constexpr (Probe::on) probe.step(L::drop, StepKind::advance).idx("active", static_cast<std::int64_t>(active.size()));
    std::stable_sort(active.begin(), active.end(), [](const TableEdge<Num>& a, const TableEdge<Num>& b) { return a.x < b.x; });
    if constexpr (Probe::on) {
      std::vector<std::int64_t> dirs;
      for (const auto& e : active) dirs.push_back(e.dir);
      const auto x = xs();
      probe.step(L::sort, StepKind::advance).idx("j", j).list("x", shown(x)).ilist("dir", shown(dirs));
    }
    std::int64_t w = 0;
    for (std::size_t k = 0; k + 1 < active.size(); ++k) {
      w += active[k].dir;
      const bool inside = poly.rule == WindingRule::nonzero ? w != 0 : w % 2 != 0;
      const std::int64_t i0 = num::ceil_int(active[k].x), i1 = num::ceil_int(active[k + 1].x) - 1;
      if constexpr (Probe::on)
        probe.step(L::spans, StepKind::decide).idx("k", static_cast<std::int64_t>(k)).idx("w", w).idx("inside", inside);
      if (!inside || i1 < i0) continue;
      for (std::int64_t i = i0; i <= i1; ++i) out.push_back({i, j});
      if constexpr (Probe::on)
        probe.step(L::fill, StepKind::plot).num("x_l", active[k].x).num("x_r", active[k + 1].x).span(j, i0, i1);
    }
    for (auto& e : active) e.x = e.x + e.dx;
    j = active.empty() && next < table.size() ? table[next].row : j + 1;
    if constexpr (Probe::on) {
      const auto x = xs();
      probe.step(L::advance, StepKind::advance).idx("j", j).list("x", shown(x));
    }
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("pixels", static_cast<std::int64_t>(out.size()));
}

}  // namespace sw::fill
