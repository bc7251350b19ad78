#include "fill_oracle.hpp"
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <algorithm>
#include <stdexcept>
#include "cgal_bridge.hpp"

namespace sw::oracle {
namespace {

// Exact orientation either way: Epick's filtered predicates when every coordinate is a double
// (the common case, and 100x faster), the rational kernel otherwise.
using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
using Slow = ExactKernel;

bool all_doubles(const std::vector<std::vector<Vec2<Rational>>>& rings) {
  for (const auto& ring : rings)
    for (const auto& v : ring)
      for (int a = 0; a < 2; ++a)
        if (Rational(v[a].get_d()) != v[a]) return false;
  return true;
}

struct Box {
  std::int64_t i0, i1, j0, j1;  // samples i0..i1, j0..j1
};

Box sample_box(const std::vector<std::vector<Vec2<Rational>>>& rings) {
  Rational lo[2], hi[2];
  bool first = true;
  for (const auto& ring : rings)
    for (const auto& v : ring)
      for (int a = 0; a < 2; ++a) {
        if (first || v[a] < lo[a]) lo[a] = v[a];
        if (first || v[a] > hi[a]) hi[a] = v[a];
        if (a == 1) first = false;
      }
  const Box b{num::ceil_int(lo[0]), num::floor_int(hi[0]), num::ceil_int(lo[1]), num::floor_int(hi[1])};
  if (!first && b.i1 >= b.i0 && b.j1 >= b.j0 && double(b.i1 - b.i0 + 1) * double(b.j1 - b.j0 + 1) > double(1 << 24))
    throw std::invalid_argument("fill oracle: more than 2^24 samples in the box");
  return b;
}

// Winding number by exact crossing counts: the edge a->b crosses row y = p.y when
// min(a.y, b.y) <= p.y < max(a.y, b.y), and the crossing is at or left of p when p is on or right of
// the directed edge taken upward.
template <class K> std::int64_t winding(const std::vector<std::vector<typename K::Point_2>>& rings, const typename K::Point_2& p) {
  std::int64_t w = 0;
  for (const auto& ring : rings)
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const auto& a = ring[k];
      const auto& b = ring[(k + 1) % ring.size()];
      if (a.y() == b.y()) continue;
      const bool up = a.y() < b.y();
      const auto& lo = up ? a : b;
      const auto& hi = up ? b : a;
      if (!(lo.y() <= p.y() && p.y() < hi.y())) continue;
      if (CGAL::orientation(lo, hi, p) != CGAL::LEFT_TURN) w += up ? 1 : -1;
    }
  return w;
}

template <class K> std::vector<Pixel> polygon_samples_in(const std::vector<std::vector<Vec2<Rational>>>& rings, FillRule rule) {
  std::vector<std::vector<typename K::Point_2>> pts;
  for (const auto& ring : rings) {
    pts.emplace_back();
    for (const auto& v : ring) pts.back().push_back(point<K>(v));
  }
  const Box b = sample_box(rings);
  std::vector<Pixel> out;
  for (std::int64_t j = b.j0; j <= b.j1; ++j)
    for (std::int64_t i = b.i0; i <= b.i1; ++i) {
      const std::int64_t w = winding<K>(pts, typename K::Point_2(static_cast<double>(i), static_cast<double>(j)));
      if (rule == FillRule::nonzero ? w != 0 : (w % 2 != 0)) out.push_back({i, j});
    }
  return out;
}

// Sample p is covered when it is left of each counter-clockwise edge a->b, or on it and the edge is a
// left edge (going down) or a bottom edge (horizontal, going right): the sign of the edge function
// along the move (eps, eps^2).
template <class K> std::vector<Pixel> triangle_samples_in(const std::array<Vec2<Rational>, 3>& t) {
  std::array<typename K::Point_2, 3> v{point<K>(t[0]), point<K>(t[1]), point<K>(t[2])};
  const CGAL::Orientation o = CGAL::orientation(v[0], v[1], v[2]);
  if (o == CGAL::COLLINEAR) return {};
  if (o == CGAL::RIGHT_TURN) std::swap(v[1], v[2]);
  const Box b = sample_box({{t[0], t[1], t[2]}});
  std::vector<Pixel> out;
  for (std::int64_t j = b.j0; j <= b.j1; ++j)
    for (std::int64_t i = b.i0; i <= b.i1; ++i) {
      const typename K::Point_2 p(static_cast<double>(i), static_cast<double>(j));
      bool inside = true;
      for (int e = 0; e < 3 && inside; ++e) {
        const auto& a = v[e];
        const auto& c = v[(e + 1) % 3];
        switch (CGAL::orientation(a, c, p)) {
          case CGAL::LEFT_TURN: break;
          case CGAL::RIGHT_TURN: inside = false; break;
          default: inside = c.y() < a.y() || (c.y() == a.y() && c.x() > a.x());
        }
      }
      if (inside) out.push_back({i, j});
    }
  return out;
}

}  // namespace

std::vector<Pixel> triangle_samples(const std::array<Vec2<Rational>, 3>& t) {
  return all_doubles({{t[0], t[1], t[2]}}) ? triangle_samples_in<Fast>(t) : triangle_samples_in<Slow>(t);
}

std::int64_t winding_number(const std::vector<std::vector<Vec2<Rational>>>& rings, Pixel s) {
  const Vec2<Rational> p{Rational(s.x), Rational(s.y)};
  auto convert = [&]<class K>(K) {
    std::vector<std::vector<typename K::Point_2>> pts;
    for (const auto& ring : rings) {
      pts.emplace_back();
      for (const auto& v : ring) pts.back().push_back(point<K>(v));
    }
    return winding<K>(pts, point<K>(p));
  };
  return all_doubles(rings) ? convert(Fast{}) : convert(Slow{});
}

Rational linear_at(const std::array<Vec2<Rational>, 3>& t, const std::array<Rational, 3>& f, Pixel s) {
  const Vec2<Rational> p{Rational(s.x), Rational(s.y)};
  auto area2 = [](const Vec2<Rational>& a, const Vec2<Rational>& b, const Vec2<Rational>& c) {
    return Rational((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  };
  const Rational whole = area2(t[0], t[1], t[2]);
  if (whole == 0) throw std::invalid_argument("fill oracle: linear_at on a triangle of zero area");
  return Rational((area2(p, t[1], t[2]) * f[0] + area2(t[0], p, t[2]) * f[1] + area2(t[0], t[1], p) * f[2]) / whole);
}

std::vector<Pixel> polygon_samples(const std::vector<std::vector<Vec2<Rational>>>& rings, FillRule rule) {
  return all_doubles(rings) ? polygon_samples_in<Fast>(rings, rule) : polygon_samples_in<Slow>(rings, rule);
}

}  // namespace sw::oracle
