// Running perspective-interp and affine-interp directly in one number type, for the interp tests.
#pragma once
#include <array>
#include <random>
#include <vector>
#include "fill/fill_run.hpp"
#include "fill/perspective_interp.hpp"
#include "fill_interp_oracle.hpp"

namespace sw::testing {

struct ClipTri {
  std::array<oracle::ClipPoint, 3> v;
  std::array<std::vector<Rational>, 3> attrs;
};

template <class Num> fill::ClipTriangle<Num> to_clip_triangle(const ClipTri& t) {
  fill::ClipTriangle<Num> c;
  c.n = t.attrs[0].size();
  for (int k = 0; k < 3; ++k) {
    for (int a = 0; a < 4; ++a) c.v[k].c[a] = num::from_rational<Num>(t.v[k][a]);
    for (std::size_t i = 0; i < c.n; ++i) c.v[k].a[i] = num::from_rational<Num>(t.attrs[k][i]);
  }
  return c;
}

template <bool Persp, class Num, class Probe = NoProbe> fill::FillResult<Num> run_interp(const ClipTri& t, Probe&& probe = {}) {
  fill::FillResult<Num> r;
  fill::perspective_interp<Persp, Num>(to_clip_triangle<Num>(t), r, probe);
  return r;
}

template <bool Persp> oracle::InterpSamples interp_oracle(const ClipTri& t) {
  return Persp ? oracle::perspective_samples(t.v, t.attrs, Rational(fill::kWNear)) : oracle::affine_samples(t.v, t.attrs, Rational(fill::kWNear));
}

// A random clip-space triangle: w on the 1/4 grid in [-2, 4] (so vertices in front, on the near
// plane w = 1 and behind), x and y on the 1/4 grid in [-8, 8], n attributes on the 1/8 grid.
inline ClipTri random_clip_tri(std::mt19937_64& rng, std::size_t n) {
  ClipTri t;
  for (int k = 0; k < 3; ++k) {
    t.v[k] = {grid_coord(rng, -8, 8, 4), grid_coord(rng, -8, 8, 4), grid_coord(rng, -1, 1, 4), grid_coord(rng, -2, 4, 4)};
    for (std::size_t c = 0; c < n; ++c) t.attrs[k].push_back(grid_coord(rng, -4, 4, 8));
  }
  return t;
}

}  // namespace sw::testing
