#include "contour.hpp"
#include <algorithm>
#include <cmath>

namespace sw {

std::vector<Polyline2> contour(const std::function<double(double, double)>& f, const Rect2& w, double cell) {
  std::vector<Polyline2> out;
  const double width = w.x1 - w.x0, height = w.y1 - w.y0;
  if (!(width > 0 && height > 0 && cell > 0)) return out;
  const int nx = std::clamp(static_cast<int>(std::ceil(width / cell)), 1, kMaxContourCells);
  const int ny = std::clamp(static_cast<int>(std::ceil(height / cell)), 1, kMaxContourCells);
  const double dx = width / nx, dy = height / ny;
  auto X = [&](int i) { return w.x0 + dx * i; };
  auto Y = [&](int j) { return w.y0 + dy * j; };
  std::vector<double> below(nx + 1), above(nx + 1);
  for (int i = 0; i <= nx; ++i) below[i] = f(X(i), Y(0));
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i <= nx; ++i) above[i] = f(X(i), Y(j + 1));
    for (int i = 0; i < nx; ++i) {
      // Corners counter-clockwise from the lower left; edge k runs from corner k to corner k + 1.
      const double v[4] = {below[i], below[i + 1], above[i + 1], above[i]};
      const std::array<double, 2> p[4] = {{X(i), Y(j)}, {X(i + 1), Y(j)}, {X(i + 1), Y(j + 1)}, {X(i), Y(j + 1)}};
      int mask = 0;
      // A branch, not (v[k] >= 0) << k: GCC 12 with -fsanitize=undefined -O2 computes that as 15.
      for (int k = 0; k < 4; ++k)
        if (v[k] >= 0) mask |= 1 << k;
      if (mask == 0 || mask == 15) continue;
      auto cross = [&](int k) {  // where f is 0 on edge k, by linear interpolation
        const int m = (k + 1) % 4;
        const double t = std::clamp(v[k] / (v[k] - v[m]), 0.0, 1.0);
        return std::array<double, 2>{p[k][0] + t * (p[m][0] - p[k][0]), p[k][1] + t * (p[m][1] - p[k][1])};
      };
      std::array<int, 4> edges{};
      int n = 0;
      for (int k = 0; k < 4; ++k)
        if (((mask >> k) & 1) != ((mask >> ((k + 1) % 4)) & 1)) edges[n++] = k;
      if (n == 2) {
        out.push_back({cross(edges[0]), cross(edges[1])});
      } else {  // a saddle: four crossings; pair them so the centre's side stays connected
        const bool centre = f(X(i) + dx / 2, Y(j) + dy / 2) >= 0;
        const bool first_positive = (mask & 1) != 0;
        if (centre == first_positive) out.push_back({cross(0), cross(1)}), out.push_back({cross(2), cross(3)});
        else out.push_back({cross(3), cross(0)}), out.push_back({cross(1), cross(2)});
      }
    }
    std::swap(below, above);
  }
  return out;
}

}  // namespace sw
