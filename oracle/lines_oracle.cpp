#include "lines_oracle.hpp"
#include <algorithm>
#include <optional>
#include "cgal_bridge.hpp"

namespace sw::oracle {
namespace {

std::int64_t floor_q(const Q& x) { return num::floor_int(r(x)); }
const Q kHalf(1, 2);

struct Seg {
  Q p[2], d[2];
  Seg(const Vec2<Rational>& a, const Vec2<Rational>& b)
      : p{q(a.x), q(a.y)}, d{q(b.x) - q(a.x), q(b.y) - q(a.y)} {}
  int major() const { return CGAL::abs(d[0]) > CGAL::abs(d[1]) ? 0 : 1; }
};

// Is integer k one of the sampled major-axis positions?
bool sampled(const Seg& s, int a, const Q& k, Sampling mode) {
  const Q lo = s.p[a], hi = s.p[a] + s.d[a];
  if (mode == Sampling::ascending) return std::min(lo, hi) <= k && k < std::max(lo, hi);
  return s.d[a] > 0 ? (lo <= k && k < hi) : (hi < k && k <= lo);
}

// Pixel of the segment's point at major coordinate k (the point's minor value, rounded).
Pixel pixel_at(const Seg& s, int a, std::int64_t k) {
  const Q v = s.p[1 - a] + (Q(k) - s.p[a]) * s.d[1 - a] / s.d[a];
  const std::int64_t j = floor_q(v + kHalf);
  return a == 0 ? Pixel{k, j} : Pixel{j, k};
}

void sort_samples(std::vector<Pixel>& px, const Seg& s, int a, Sampling mode) {
  const bool descending = mode == Sampling::directed && s.d[a] < 0;
  std::sort(px.begin(), px.end(), [&](Pixel u, Pixel v) {
    const auto ku = a == 0 ? u.x : u.y, kv = a == 0 ? v.x : v.y;
    return descending ? ku > kv : ku < kv;
  });
}

// A parameter interval with open or closed ends; `all` is the whole line.
struct TInterval {
  bool empty = false, all = true;
  Q lo, hi;
  bool lo_open = false, hi_open = false;
  static TInterval none() {
    TInterval t;
    t.empty = true;
    return t;
  }
};

TInterval intersect(TInterval a, const TInterval& b) {
  if (a.empty || b.empty) return TInterval::none();
  if (b.all) return a;
  if (a.all) return b;
  if (b.lo > a.lo) a.lo = b.lo, a.lo_open = b.lo_open;
  else if (b.lo == a.lo) a.lo_open = a.lo_open || b.lo_open;
  if (b.hi < a.hi) a.hi = b.hi, a.hi_open = b.hi_open;
  else if (b.hi == a.hi) a.hi_open = a.hi_open || b.hi_open;
  if (a.lo > a.hi || (a.lo == a.hi && (a.lo_open || a.hi_open))) a.empty = true;
  return a;
}

// The t at which the point p + t d has coordinate a in [c - 1/2, c + 1/2).
TInterval slab(const Seg& s, int a, std::int64_t c) {
  const Q lo = Q(c) - kHalf, hi = Q(c) + kHalf;
  if (s.d[a] == 0) return (lo <= s.p[a] && s.p[a] < hi) ? TInterval{} : TInterval::none();
  TInterval t;
  t.all = false;
  const Q t_lo = (lo - s.p[a]) / s.d[a], t_hi = (hi - s.p[a]) / s.d[a];
  if (s.d[a] > 0) t.lo = t_lo, t.hi = t_hi, t.lo_open = false, t.hi_open = true;
  else t.lo = t_hi, t.hi = t_lo, t.lo_open = true, t.hi_open = false;
  return t;
}

TInterval unit_segment() {
  TInterval t;
  t.all = false;
  t.lo = 0, t.hi = 1, t.hi_open = true;
  return t;
}

TInterval cell_interval(const Seg& s, Pixel c) {
  return intersect(intersect(unit_segment(), slab(s, 0, c.x)), slab(s, 1, c.y));
}

void sort_by_entry(std::vector<Pixel>& cells, const Seg& s) {
  std::vector<std::pair<TInterval, Pixel>> keyed;
  for (Pixel c : cells) keyed.push_back({cell_interval(s, c), c});
  std::sort(keyed.begin(), keyed.end(), [](const auto& u, const auto& v) {
    if (u.first.lo != v.first.lo) return u.first.lo < v.first.lo;
    return !u.first.lo_open && v.first.lo_open;
  });
  for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = keyed[i].second;
}

// Pixel-index range covered by a value range [lo, hi] (closed, so it errs on the side of more).
std::pair<std::int64_t, std::int64_t> index_range(const Q& a, const Q& b) {
  return {floor_q(std::min(a, b) + kHalf) - 1, floor_q(std::max(a, b) + kHalf) + 1};
}

}  // namespace

std::vector<Pixel> column_pixels(const Vec2<Rational>& p0, const Vec2<Rational>& p1, Sampling mode) {
  const Seg s(p0, p1);
  const int a = s.major();
  std::vector<Pixel> out;
  if (s.d[a] == 0) return out;
  const auto [k0, k1] = index_range(s.p[a], s.p[a] + s.d[a]);
  for (std::int64_t k = k0; k <= k1; ++k)
    if (sampled(s, a, Q(k), mode)) out.push_back(pixel_at(s, a, k));
  sort_samples(out, s, a, mode);
  return out;
}

std::vector<Pixel> column_pixels_brute_force(const Vec2<Rational>& p0, const Vec2<Rational>& p1, Sampling mode) {
  const Seg s(p0, p1);
  const int a = s.major();
  std::vector<Pixel> out;
  if (s.d[a] == 0) return out;
  const auto [x0, x1] = index_range(s.p[0], s.p[0] + s.d[0]);
  const auto [y0, y1] = index_range(s.p[1], s.p[1] + s.d[1]);
  for (std::int64_t i = x0; i <= x1; ++i)
    for (std::int64_t j = y0; j <= y1; ++j) {
      const std::int64_t k = a == 0 ? i : j, m = a == 0 ? j : i;
      if (!sampled(s, a, Q(k), mode)) continue;
      // The point of the segment at major coordinate k lies in the minor half-open range of m.
      const Q v = s.p[1 - a] + (Q(k) - s.p[a]) * s.d[1 - a] / s.d[a];
      if (Q(m) - kHalf <= v && v < Q(m) + kHalf) out.push_back({i, j});
    }
  sort_samples(out, s, a, mode);
  return out;
}

bool cell_meets_segment(const Vec2<Rational>& p0, const Vec2<Rational>& p1, Pixel c) {
  return !cell_interval(Seg(p0, p1), c).empty;
}

Entry cell_entry(const Vec2<Rational>& p0, const Vec2<Rational>& p1, Pixel c) {
  const TInterval t = cell_interval(Seg(p0, p1), c);
  return {r(t.lo), t.lo_open};
}

std::vector<Pixel> walk_cells(const Vec2<Rational>& p0, const Vec2<Rational>& p1) {
  const Seg s(p0, p1);
  std::vector<Pixel> out;
  if (s.d[0] == 0 && s.d[1] == 0) return out;
  const auto [x0, x1] = index_range(s.p[0], s.p[0] + s.d[0]);
  for (std::int64_t i = x0; i <= x1; ++i) {
    const TInterval col = intersect(unit_segment(), slab(s, 0, i));
    if (col.empty) continue;
    const auto [y0, y1] = index_range(s.p[1] + col.lo * s.d[1], s.p[1] + col.hi * s.d[1]);
    for (std::int64_t j = y0; j <= y1; ++j)
      if (!cell_interval(s, {i, j}).empty) out.push_back({i, j});
  }
  sort_by_entry(out, s);
  return out;
}

std::vector<Pixel> walk_cells_brute_force(const Vec2<Rational>& p0, const Vec2<Rational>& p1) {
  const Seg s(p0, p1);
  std::vector<Pixel> out;
  if (s.d[0] == 0 && s.d[1] == 0) return out;
  const auto [x0, x1] = index_range(s.p[0], s.p[0] + s.d[0]);
  const auto [y0, y1] = index_range(s.p[1], s.p[1] + s.d[1]);
  for (std::int64_t i = x0; i <= x1; ++i)
    for (std::int64_t j = y0; j <= y1; ++j)
      if (cell_meets_segment(p0, p1, {i, j})) out.push_back({i, j});
  sort_by_entry(out, s);
  return out;
}

}  // namespace sw::oracle
