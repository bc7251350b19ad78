// Running raster-clip directly in one number type, and the random cases of its tests.
#pragma once
#include <array>
#include <random>
#include <vector>
#include "fill/fill_run.hpp"
#include "fill/raster_clip.hpp"

namespace sw::testing {

template <class Num>
fill::FillResult<Num> run_clip(const Tri& t, const fill::Screen& s, const std::vector<std::array<Rational, 3>>& attrs = {}) {
  fill::Triangle<Num> v;
  for (int k = 0; k < 3; ++k) {
    v[k].p = to_num<Num>(t[k]);
    v[k].n = attrs.size();
    for (std::size_t c = 0; c < attrs.size(); ++c) v[k].a[c] = num::from_rational<Num>(attrs[c][k]);
  }
  fill::FillResult<Num> r;
  NoProbe none;
  fill::raster_clip<Num>(v, s, r, none);
  return r;
}

inline bool on_screen(const fill::Screen& s, Pixel p) { return s.i0 <= p.x && p.x < s.i1 && s.j0 <= p.y && p.y < s.j1; }

// The pixels of `all` (in scanline order) that lie on the screen, in the same order.
inline std::vector<Pixel> restrict_to(const std::vector<Pixel>& all, const fill::Screen& s) {
  std::vector<Pixel> out;
  for (Pixel p : all)
    if (on_screen(s, p)) out.push_back(p);
  return out;
}

// A triangle K times as wide as the screen (K >= 1) with one edge through two points near the
// screen, so that the edge crosses it; the third vertex far off in a random direction. Exact: the
// edge's line is the one through p and q.
inline Tri huge_crossing(std::mt19937_64& rng, const fill::Screen& s, long K, long den) {
  const long w = std::max(s.i1 - s.i0, s.j1 - s.j0);
  const Vec2<Rational> c{Rational(s.i0 + s.i1) / 2, Rational(s.j0 + s.j1) / 2};
  const Vec2<Rational> p{c.x + grid_coord(rng, -w, w, den), c.y + grid_coord(rng, -w, w, den)};
  Vec2<Rational> q{c.x + grid_coord(rng, -w, w, den), c.y + grid_coord(rng, -w, w, den)};
  if (q == p) q.x += 1;
  const Vec2<Rational> a{p.x + K * (p.x - q.x), p.y + K * (p.y - q.y)}, b{q.x + K * (q.x - p.x), q.y + K * (q.y - p.y)};
  const Vec2<Rational> far{c.x + grid_coord(rng, -w, w, 1) * K, c.y + grid_coord(rng, -w, w, 1) * K};
  return {a, b, far};
}

}  // namespace sw::testing
