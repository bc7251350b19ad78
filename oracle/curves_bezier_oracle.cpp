#include "curves_bezier_oracle.hpp"
#include "cgal_bridge.hpp"
#include "lines_oracle.hpp"

namespace sw::oracle {

Vec2<Rational> bezier_point(const std::array<Vec2<Rational>, 4>& p, const Rational& t) {
  const Q tq = q(t), s = Q(1) - tq;
  const Q w[4] = {s * s * s, 3 * s * s * tq, 3 * s * tq * tq, tq * tq * tq};
  Q x(0), y(0);
  for (int i = 0; i < 4; ++i) {
    x += w[i] * q(p[i].x);
    y += w[i] * q(p[i].y);
  }
  return {r(x), r(y)};
}

std::vector<Pixel> bezier_pixels(const std::array<Vec2<Rational>, 4>& p, std::int64_t n) {
  std::vector<Pixel> out;
  for (std::int64_t k = 0; k < n; ++k) {
    Rational t0(k, n), t1(k + 1, n);
    t0.canonicalize(), t1.canonicalize();
    const auto seg = column_pixels(bezier_point(p, t0), bezier_point(p, t1), Sampling::ascending);
    out.insert(out.end(), seg.begin(), seg.end());
  }
  return out;
}

}  // namespace sw::oracle
