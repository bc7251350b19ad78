#include "curves/outlines.hpp"
#include <algorithm>
#include <cmath>
#include "contour.hpp"

namespace sw::curves {

std::vector<Polyline2> cubic_outline(const std::array<Rational, 4>& c, std::int64_t xs, std::int64_t xe, const Rect2& w, double cell) {
  const double a = std::max(w.x0, double(xs)), b = std::min(w.x1, double(xe - 1));
  if (!(b > a)) return {};
  const double k[4] = {c[0].get_d(), c[1].get_d(), c[2].get_d(), c[3].get_d()};
  const int n = std::clamp(static_cast<int>((b - a) / std::max(cell, 1e-9)), 1, 8192);
  Polyline2 line;
  for (int i = 0; i <= n; ++i) {
    const double x = a + (b - a) * i / n;
    line.push_back({x, ((k[0] * x + k[1]) * x + k[2]) * x + k[3]});
  }
  return {line};
}

std::vector<Polyline2> circle_outline(std::int64_t cx, std::int64_t cy, std::int64_t r, const Rect2& w, double cell) {
  const double x0 = double(cx), y0 = double(cy), rr = double(r), m = rr + 2 * cell;
  if (w.x1 < x0 - m || w.x0 > x0 + m || w.y1 < y0 - m || w.y0 > y0 + m) return {};
  // Only the part of the window near the circle's box is searched.
  const Rect2 box{std::max(w.x0, x0 - m), std::max(w.y0, y0 - m), std::min(w.x1, x0 + m), std::min(w.y1, y0 + m)};
  return contour([&](double x, double y) { return (x - x0) * (x - x0) + (y - y0) * (y - y0) - rr * rr; }, box, cell);
}

std::vector<Polyline2> implicit_outline(const std::array<std::array<Rational, 4>, 4>& c, const Rect2& w, double cell) {
  std::array<std::array<double, 4>, 4> k{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; i + j < 4; ++j) k[i][j] = c[i][j].get_d();
  return contour([&](double x, double y) {
    double sum = 0, xi = 1;
    for (int i = 0; i < 4; ++i, xi *= x) {
      double yj = 1;
      for (int j = 0; i + j < 4; ++j, yj *= y) sum += k[i][j] * xi * yj;
    }
    return sum;
  }, w, cell);
}

std::vector<Polyline2> bezier_outline(const std::array<Vec2<Rational>, 4>& p, double cell) {
  std::array<std::array<double, 2>, 4> q;
  double length = 0;
  for (int i = 0; i < 4; ++i) q[i] = {p[i].x.get_d(), p[i].y.get_d()};
  for (int i = 0; i < 3; ++i) length += std::hypot(q[i + 1][0] - q[i][0], q[i + 1][1] - q[i][1]);
  const int n = std::clamp(static_cast<int>(length / std::max(cell, 1e-9)), 16, 8192);
  Polyline2 line;
  for (int s = 0; s <= n; ++s) {
    const double t = double(s) / n, u = 1 - t;
    const double b[4] = {u * u * u, 3 * u * u * t, 3 * u * t * t, t * t * t};
    std::array<double, 2> pt{0, 0};
    for (int i = 0; i < 4; ++i) pt[0] += b[i] * q[i][0], pt[1] += b[i] * q[i][1];
    line.push_back(pt);
  }
  return {line};
}

}  // namespace sw::curves
