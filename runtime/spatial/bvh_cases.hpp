// Generated meshes and rays for the BVH's bench sets, tests and peer bench: seeded random
// triangles, a grid mesh with shared vertices (rays through its edges and vertices), and rays.
#pragma once
#include <array>
#include <cmath>
#include <random>
#include "spatial/spatial_common.hpp"

namespace sw::spatial::cases {

// n triangles of size about `size` with vertices in [-1, 1]^3 (coordinates on a 2^-20 grid).
inline Mesh random_mesh(std::mt19937_64& rng, std::size_t n, double size = 0.2) {
  std::uniform_real_distribution<double> u(-1, 1), e(-size, size);
  auto grid = [](double x) { return std::ldexp(std::round(std::ldexp(x, 20)), -20); };
  Mesh m;
  for (std::size_t i = 0; i < n; ++i) {
    const std::array<double, 3> c{u(rng), u(rng), u(rng)};
    for (int k = 0; k < 3; ++k) m.v.push_back({grid(c[0] + e(rng)), grid(c[1] + e(rng)), grid(c[2] + e(rng))});
    const auto b = static_cast<std::int32_t>(3 * i);
    m.f.push_back({b, b + 1, b + 2});
  }
  return m;
}

// An nx x ny grid of unit squares in the plane z = h(x, y) (integer heights, so the mesh is not
// flat unless `flat`), two triangles per square, vertices shared.
inline Mesh grid_mesh(int nx, int ny, bool flat, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> h(-1, 1);
  Mesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.v.push_back({double(i), double(j), flat ? 0.0 : double(h(rng))});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::int32_t a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
      if ((i + j) % 2) m.f.push_back({a, b, d}), m.f.push_back({a, d, c});
      else m.f.push_back({a, b, c}), m.f.push_back({b, d, c});
    }
  return m;
}

// A ray from above the grid through a grid vertex, an edge midpoint or a random point on an edge
// (kind 0, 1, 2) of the grid mesh, with a random downward direction (exact doubles).
inline RayIn grid_ray(const Mesh& g, int nx, int ny, std::mt19937_64& rng, int kind) {
  std::uniform_int_distribution<int> ci(0, nx - 1), cj(0, ny - 1), dd(-8, 8), side(0, 2);
  std::uniform_int_distribution<int> frac(1, 15);
  const int i = ci(rng), j = cj(rng);
  auto vert = [&](int a, int b) { return g.v[static_cast<std::size_t>(b * (nx + 1) + a)]; };
  std::array<double, 3> p = vert(i, j);
  if (kind > 0) {  // on the cell's lower edge, left edge or diagonal (the triangulation's)
    const int s = side(rng);
    const bool odd = (i + j) % 2;
    const auto a = s == 2 && !odd ? vert(i + 1, j) : vert(i, j);
    const auto q = s == 0 ? vert(i + 1, j) : s == 1 ? vert(i, j + 1) : odd ? vert(i + 1, j + 1) : vert(i, j + 1);
    const double w = kind == 1 ? 0.5 : frac(rng) / 16.0;
    for (int k = 0; k < 3; ++k) p[k] = a[k] + w * (q[k] - a[k]);
  }
  RayIn r;
  r.d = {dd(rng) / 8.0, dd(rng) / 8.0, -1};
  for (int k = 0; k < 3; ++k) r.o[k] = p[k] - 4 * r.d[k];
  return r;
}

// A random ray: origin in [-1.5, 1.5]^3, direction toward a random point of [-1, 1]^3.
inline RayIn random_ray(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.5, 1.5), v(-1, 1);
  RayIn r;
  for (int k = 0; k < 3; ++k) r.o[k] = u(rng);
  for (int k = 0; k < 3; ++k) r.d[k] = v(rng) - r.o[k];
  if (r.d[0] == 0 && r.d[1] == 0 && r.d[2] == 0) r.d[2] = 1;
  return r;
}

}  // namespace sw::spatial::cases
