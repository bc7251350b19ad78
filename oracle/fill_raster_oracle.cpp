#include "fill_raster_oracle.hpp"
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <cmath>
#include <stdexcept>
#include "cgal_bridge.hpp"

namespace sw::oracle {
namespace {

// Epick's filtered exact predicates when every coordinate is a double, the rational kernel otherwise.
using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
using Slow = ExactKernel;

// Counter-clockwise edge a -> c keeps the samples on it when it runs down (a left edge) or runs
// right along a row (a bottom edge): the sign of its edge function along the move (eps, eps^2).
template <class K> bool keeps_on_edge(const typename K::Point_2& a, const typename K::Point_2& c) {
  return c.y() < a.y() || (c.y() == a.y() && c.x() > a.x());
}

template <class K> std::vector<Pixel> samples(const std::array<Vec2<Rational>, 3>& t, const SampleWindow& w) {
  std::array<typename K::Point_2, 3> v{point<K>(t[0]), point<K>(t[1]), point<K>(t[2])};
  const CGAL::Orientation o = CGAL::orientation(v[0], v[1], v[2]);
  if (o == CGAL::COLLINEAR) return {};
  if (o == CGAL::RIGHT_TURN) std::swap(v[1], v[2]);
  std::array<bool, 3> keep{};
  for (int e = 0; e < 3; ++e) keep[e] = keeps_on_edge<K>(v[e], v[(e + 1) % 3]);
  std::vector<Pixel> out;
  for (std::int64_t j = w.j0; j < w.j1; ++j)
    for (std::int64_t i = w.i0; i < w.i1; ++i) {
      const typename K::Point_2 p(static_cast<double>(i), static_cast<double>(j));
      bool inside = true;
      for (int e = 0; e < 3 && inside; ++e) {
        const CGAL::Orientation s = CGAL::orientation(v[e], v[(e + 1) % 3], p);
        inside = s == CGAL::LEFT_TURN || (s == CGAL::COLLINEAR && keep[e]);
      }
      if (inside) out.push_back({i, j});
    }
  return out;
}

}  // namespace

std::vector<Pixel> triangle_samples_in_window(const std::array<Vec2<Rational>, 3>& t, const SampleWindow& w) {
  if (w.i1 <= w.i0 || w.j1 <= w.j0) return {};
  if (double(w.i1 - w.i0) * double(w.j1 - w.j0) > double(1 << 24)) throw std::invalid_argument("fill raster oracle: more than 2^24 samples in the window");
  if (std::abs(double(w.i0)) > 0x1p53 || std::abs(double(w.i1)) > 0x1p53 || std::abs(double(w.j0)) > 0x1p53 || std::abs(double(w.j1)) > 0x1p53)
    throw std::invalid_argument("fill raster oracle: a window coordinate beyond 2^53");
  bool doubles = true;
  for (const auto& p : t)
    for (int a = 0; a < 2; ++a) doubles = doubles && Rational(p[a].get_d()) == p[a];
  return doubles ? samples<Fast>(t, w) : samples<Slow>(t, w);
}

}  // namespace sw::oracle
