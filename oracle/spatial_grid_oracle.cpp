#include "spatial_grid_oracle.hpp"
#include <algorithm>

namespace sw::oracle {
namespace {

const Rational kHalf(1, 2);

// A set of parameters t: empty, or from lo to hi with each end open or closed.
struct Span {
  bool empty = false;
  Rational lo, hi;
  bool lo_open = false, hi_open = false;
};

Span meet(const Span& a, const Span& b) {
  if (a.empty || b.empty) return {true, 0, 0, false, false};
  Span s = a;
  if (b.lo > s.lo || (b.lo == s.lo && b.lo_open)) s.lo = b.lo, s.lo_open = b.lo_open;
  if (b.hi < s.hi || (b.hi == s.hi && b.hi_open)) s.hi = b.hi, s.hi_open = b.hi_open;
  s.empty = s.lo > s.hi || (s.lo == s.hi && (s.lo_open || s.hi_open));
  return s;
}

struct Seg {
  std::array<Rational, 3> p, d;
  Seg(const Vec3<Rational>& a, const Vec3<Rational>& b) {
    for (int k = 0; k < 3; ++k) p[k] = a[k], d[k] = Rational(b[k] - a[k]);
  }
  bool zero() const { return d[0] == 0 && d[1] == 0 && d[2] == 0; }
  // The t in [0, 1) whose point has axis-a coordinate in [c - 1/2, c + 1/2).
  Span slab(int a, std::int64_t c) const {
    const Span unit{false, 0, 1, false, true};
    const Rational lo = Rational(c) - kHalf, hi = Rational(c) + kHalf;
    if (d[a] == 0) return lo <= p[a] && p[a] < hi ? unit : Span{true, 0, 0, false, false};
    const Rational t_lo = (lo - p[a]) / d[a], t_hi = (hi - p[a]) / d[a];
    // Increasing: the face at lo is in, at hi out. Decreasing: the other way round.
    const Span s = d[a] > 0 ? Span{false, t_lo, t_hi, false, true} : Span{false, t_hi, t_lo, true, false};
    return meet(unit, s);
  }
  Span cube(const GridCell& c) const { return meet(meet(slab(0, c[0]), slab(1, c[1])), slab(2, c[2])); }
  // The cell indices (with a margin of one) of axis a over the closed parameter range [t0, t1].
  std::pair<std::int64_t, std::int64_t> range(int a, const Rational& t0, const Rational& t1) const {
    const Rational u = p[a] + t0 * d[a], v = p[a] + t1 * d[a];
    return {num::floor_int(Rational(std::min(u, v) + kHalf)) - 1, num::floor_int(Rational(std::max(u, v) + kHalf)) + 1};
  }
};

void sort_by_entry(std::vector<GridCell>& cells, const Seg& s) {
  std::vector<std::pair<Span, GridCell>> keyed;
  for (const GridCell& c : cells) keyed.push_back({s.cube(c), c});
  std::sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) {
    if (x.first.lo != y.first.lo) return x.first.lo < y.first.lo;
    return !x.first.lo_open && y.first.lo_open;
  });
  for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = keyed[i].second;
}

}  // namespace

bool cube_meets_segment(const Vec3<Rational>& p0, const Vec3<Rational>& p1, const GridCell& c) {
  const Seg s(p0, p1);
  return !s.zero() && !s.cube(c).empty;
}

std::vector<GridCell> grid_cells_3d(const Vec3<Rational>& p0, const Vec3<Rational>& p1) {
  const Seg s(p0, p1);
  std::vector<GridCell> out;
  if (s.zero()) return out;
  const auto [i0, i1] = s.range(0, 0, 1);
  for (std::int64_t i = i0; i <= i1; ++i) {
    const Span ti = s.slab(0, i);
    if (ti.empty) continue;
    const auto [j0, j1] = s.range(1, ti.lo, ti.hi);
    for (std::int64_t j = j0; j <= j1; ++j) {
      const Span tij = meet(ti, s.slab(1, j));
      if (tij.empty) continue;
      const auto [k0, k1] = s.range(2, tij.lo, tij.hi);
      for (std::int64_t k = k0; k <= k1; ++k)
        if (!meet(tij, s.slab(2, k)).empty) out.push_back({i, j, k});
    }
  }
  sort_by_entry(out, s);
  return out;
}

std::vector<GridCell> grid_cells_3d_brute_force(const Vec3<Rational>& p0, const Vec3<Rational>& p1) {
  const Seg s(p0, p1);
  std::vector<GridCell> out;
  if (s.zero()) return out;
  const auto [i0, i1] = s.range(0, 0, 1);
  const auto [j0, j1] = s.range(1, 0, 1);
  const auto [k0, k1] = s.range(2, 0, 1);
  for (std::int64_t i = i0; i <= i1; ++i)
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t k = k0; k <= k1; ++k)
        if (cube_meets_segment(p0, p1, {i, j, k})) out.push_back({i, j, k});
  sort_by_entry(out, s);
  return out;
}

}  // namespace sw::oracle
