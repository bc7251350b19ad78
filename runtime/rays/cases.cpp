#include "rays/cases.hpp"
#include <cmath>
#include <random>

namespace sw::rays {
namespace {

using D3 = std::array<double, 3>;
F3 to_f(const D3& a) { return {float(a[0]), float(a[1]), float(a[2])}; }
D3 to_d(const F3& a) { return {a[0], a[1], a[2]}; }
D3 lerp(const D3& a, const D3& b, double s) { return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])}; }
Json arr(const F3& a) { return Json::array({double(a[0]), double(a[1]), double(a[2])}); }

struct Rng {
  std::mt19937_64 g;
  explicit Rng(std::uint64_t s) : g(s) {}
  double u(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g); }
  int i(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(g); }
  D3 box(double lo, double hi) { return {u(lo, hi), u(lo, hi), u(lo, hi)}; }
};

// A float ray from `o` aimed at `target` (the direction is rounded to float).
FRay aimed(const D3& o, const D3& target) {
  const F3 of = to_f(o);
  FRay r;
  r.o = of;
  r.d = to_f(D3{target[0] - of[0], target[1] - of[1], target[2] - of[2]});
  return r;
}

Json with(const FRay& r, const char* key, Json g) { return Json{{"ray", ray_json(r)}, {key, std::move(g)}}; }

}  // namespace

Json ray_json(const FRay& r) { return Json{{"o", arr(r.o)}, {"d", arr(r.d)}}; }
Json triangle_input(const FRay& r, const std::array<F3, 3>& t) { return with(r, "triangle", Json::array({arr(t[0]), arr(t[1]), arr(t[2])})); }

Grid make_grid(int n, std::uint64_t seed) {
  Rng rng(seed);
  Grid g;
  g.n = n;
  // Tilted axes with non-dyadic lengths, an offset origin and a gentle bend, so the float
  // vertices and the edge functions round in every way.
  const D3 origin{-137.31, 52.7, 11.13}, u{1.37, 0.11, 0.31}, v{-0.23, 1.29, 0.17};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double bend = 0.05 * std::sin(0.7 * i) * std::cos(0.5 * j) + rng.u(-1e-3, 1e-3);
      g.verts.push_back(to_f({origin[0] + i * u[0] + j * v[0], origin[1] + i * u[1] + j * v[1], origin[2] + i * u[2] + j * v[2] + bend}));
    }
  auto at = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      g.tris.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      g.tris.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return g;
}

std::vector<FRay> grid_rays(const Grid& g, int per_edge, std::uint64_t seed) {
  Rng rng(seed);
  const int n = g.n;
  auto vert = [&](int i, int j) { return to_d(g.verts[j * (n + 1) + i]); };
  std::vector<FRay> out;
  auto shoot = [&](const D3& target, int ci, int cj) {
    // From above the (upward-facing) grid, 2 to 20 units away, at up to ~60 degrees off vertical.
    const double h = rng.u(2, 20);
    const D3 o{target[0] + h * rng.u(-1.2, 1.2), target[1] + h * rng.u(-1.2, 1.2), target[2] + h};
    FRay r = aimed(o, target);
    r.ci = ci, r.cj = cj;
    out.push_back(r);
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < per_edge; ++k) {
        shoot(lerp(vert(i, j), vert(i + 1, j + 1), rng.u(0, 1)), i, j);                 // the cell's diagonal
        if (j > 0) shoot(lerp(vert(i, j), vert(i + 1, j), rng.u(0, 1)), i, j);          // the edge shared with the cell below
        if (i > 0) shoot(lerp(vert(i, j), vert(i, j + 1), rng.u(0, 1)), i, j);          // the edge shared with the cell to the left
      }
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i) shoot(vert(i, j), i, j);
  return out;
}

std::vector<Json> hard_inputs(const char* prim, std::uint64_t seed) {
  Rng rng(seed);
  const std::string p = prim;
  std::vector<Json> out;
  if (p == "triangle") {
    // The shared-edge crack (three.js #11449) and the pbrt-v4 sliver, then grid edge and vertex rays.
    FRay crack{{0, 0, 10}, {0.30458447f, 0.30458447f, -0.9024725f}};
    out.push_back(triangle_input(crack, {F3{-5, -5, 0}, F3{5, -5, 0}, F3{5, 5, 0}}));
    out.push_back(triangle_input(crack, {F3{-5, -5, 0}, F3{5, 5, 0}, F3{-5, 5, 0}}));
    FRay sliver{{-1081.47925f, 99.9999542f, 87.7701111f}, {-32.1072998f, -183.355865f, -144.607635f}};
    out.push_back(triangle_input(sliver, {F3{-1113.45459f, -79.049614f, -56.2431908f}, F3{-1113.45459f, -87.0922699f, -56.2431908f},
                                          F3{-1113.45459f, -79.2090149f, -56.2431908f}}));
    const Grid g = make_grid(8, seed);
    for (const FRay& r : grid_rays(g, 4, seed + 1))
      for (int dj = 0; dj <= 1; ++dj)
        for (int di = 0; di <= 1; ++di) {
          const int ci = std::min(r.ci + di, g.n - 1), cj = std::min(r.cj + dj, g.n - 1);
          for (int k = 0; k < 2; ++k) out.push_back(triangle_input(r, g.triangle(2 * (cj * g.n + ci) + k)));
        }
  } else if (p == "sphere") {
    // Unit spheres 1e4 .. 1e8 away, aimed at the limb (grazing), the centre, and just outside.
    for (double dist : {1e4, 1e5, 1e6, 1e7, 1e8})
      for (int k = 0; k < 200; ++k) {
        const D3 c{dist * rng.u(0.5, 1), dist * rng.u(-0.5, 0.5), dist * rng.u(-0.5, 0.5)};
        const F3 cf = to_f(c);
        const double off = (k % 4 == 0) ? 0 : rng.u(0.9, 1.1);
        FRay r = aimed(rng.box(-1, 1), {cf[0], cf[1] + off, cf[2]});
        out.push_back(with(r, "sphere", Json{{"c", arr(cf)}, {"r", 1}}));
      }
    // Tangent rays (exactly, along an axis at distance r), origins on the surface, inside.
    for (int k = 0; k < 200; ++k) {
      const float rad = std::ldexp(5.0f, rng.i(-3, 3));
      const F3 c = to_f(rng.box(-50, 50));
      FRay tangent{{c[0] - 3 * rad, c[1] + rad, c[2]}, {1, 0, 0}};
      out.push_back(with(tangent, "sphere", Json{{"c", arr(c)}, {"r", rad}}));
      FRay on{{c[0] + 0.6f * rad, c[1] + 0.8f * rad, c[2]}, to_f(rng.box(-1, 1))};  // 0.6 r, 0.8 r exact: r = 5 * 2^k
      out.push_back(with(on, "sphere", Json{{"c", arr(c)}, {"r", rad}}));
      FRay in{to_f({c[0] + rng.u(-0.5, 0.5) * rad, c[1], c[2]}), to_f(rng.box(-1, 1))};
      out.push_back(with(in, "sphere", Json{{"c", arr(c)}, {"r", rad}}));
    }
  } else if (p == "box") {
    // Axis-parallel rays with zero (and -0) components, origins on slab planes, rays along faces,
    // edges and through corners.
    for (int k = 0; k < 1000; ++k) {
      const F3 lo = to_f(rng.box(-10, 10));
      const F3 hi{lo[0] + float(rng.i(1, 4)), lo[1] + float(rng.i(1, 4)), lo[2] + float(rng.i(1, 4))};
      FRay r;
      for (int a = 0; a < 3; ++a) {
        const int pick = rng.i(0, 4);
        r.o[a] = pick == 0 ? lo[a] : pick == 1 ? hi[a] : float(rng.u(lo[a] - 3, hi[a] + 3));
      }
      const int zeros = rng.i(0, 2);
      for (int a = 0; a < 3; ++a) r.d[a] = a < zeros ? (rng.i(0, 1) ? -0.0f : 0.0f) : float(rng.i(-3, 3)) * 0.5f;
      if (r.d[0] == 0 && r.d[1] == 0 && r.d[2] == 0) r.d[2] = 1;
      if (k % 5 == 0) r = aimed(rng.box(-30, 30), to_d(k % 10 == 0 ? lo : hi));  // through a corner
      out.push_back(with(r, "box", Json{{"min", arr(lo)}, {"max", arr(hi)}}));
    }
  } else if (p == "plane") {
    // Nearly parallel rays (d . n ~ 2^-k), far origins, origins on the plane, parallel rays.
    for (int k = 0; k < 1000; ++k) {
      const F3 pp = to_f(rng.box(-100, 100));
      const F3 n = to_f(rng.box(-1, 1));
      D3 t{rng.u(-1, 1), rng.u(-1, 1), rng.u(-1, 1)};  // a tangent direction: t - (t.n / n.n) n, then tilted
      const double nn = double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2];
      const double tn = (t[0] * n[0] + t[1] * n[1] + t[2] * n[2]) / nn, tilt = std::ldexp(rng.u(-1, 1), -rng.i(5, 40));
      for (int a = 0; a < 3; ++a) t[a] = t[a] - tn * n[a] + tilt * n[a];
      const double far = k % 3 == 0 ? 1e8 : 10;
      FRay r{to_f({pp[0] + far * rng.u(-1, 1), pp[1] + far * rng.u(-1, 1), pp[2] + far * rng.u(-1, 1)}), to_f(t)};
      if (k % 10 == 0) r.o = pp;  // on the plane
      out.push_back(with(r, "plane", Json{{"p", arr(pp)}, {"n", arr(n)}}));
    }
  }
  return out;
}

std::vector<Json> random_inputs(const char* prim, int count, std::uint64_t seed) {
  Rng rng(seed);
  const std::string p = prim;
  std::vector<Json> out;
  for (int k = 0; k < count; ++k) {
    const D3 o = rng.box(-4, 4);
    if (p == "triangle") {
      const F3 a = to_f(rng.box(-1, 1)), b = to_f(rng.box(-1, 1)), c = to_f(rng.box(-1, 1));
      const double u = rng.u(-0.3, 1.1), v = rng.u(-0.3, 1.1);  // aim near the triangle: about half hit
      D3 target;
      for (int i = 0; i < 3; ++i) target[i] = a[i] + u * (b[i] - a[i]) + v * (c[i] - a[i]);
      out.push_back(triangle_input(aimed(o, target), {a, b, c}));
    } else if (p == "sphere") {
      const F3 c = to_f(rng.box(-1, 1));
      const float r = float(rng.u(0.2, 1.5));
      const D3 target{c[0] + rng.u(-1.5, 1.5) * r, c[1] + rng.u(-1.5, 1.5) * r, c[2] + rng.u(-1.5, 1.5) * r};
      out.push_back(with(aimed(rng.box(-8, 8), target), "sphere", Json{{"c", arr(c)}, {"r", r}}));
    } else if (p == "box") {
      const F3 lo = to_f(rng.box(-1, 0)), hi = to_f(rng.box(0, 1));
      out.push_back(with(aimed(o, rng.box(-1.5, 1.5)), "box", Json{{"min", arr(lo)}, {"max", arr(hi)}}));
    } else {
      const F3 pp = to_f(rng.box(-1, 1)), n = to_f(rng.box(-1, 1));
      out.push_back(with(FRay{to_f(o), to_f(rng.box(-1, 1))}, "plane", Json{{"p", arr(pp)}, {"n", arr(n)}}));
    }
  }
  return out;
}

}  // namespace sw::rays
