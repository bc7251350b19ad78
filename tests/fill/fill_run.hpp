// Running the fills directly in one number type, for the fill tests.
#pragma once
#include <array>
#include <map>
#include <optional>
#include <random>
#include <vector>
#include "core/number.hpp"
#include "fill/scanline_polygon.hpp"
#include "fill/triangle_dda.hpp"
#include "fill/triangle_edge.hpp"
#include "input.hpp"

namespace sw::testing {

using Tri = std::array<Vec2<Rational>, 3>;
using Rings = std::vector<std::vector<Vec2<Rational>>>;

// Filtered mode: the Interval run, or nothing when a comparison was too close to call (the chain
// then runs exact).
template <class F> auto filtered(F f, std::size_t& uncertain) -> std::optional<decltype(f())> {
  try {
    return f();
  } catch (const Uncertain&) {
    ++uncertain;
    return std::nullopt;
  }
}

// How many times each sample is covered by the pieces.
using Cover = std::map<std::pair<std::int64_t, std::int64_t>, int>;
inline void add_cover(Cover& c, const std::vector<Pixel>& px) {
  for (Pixel p : px) ++c[{p.x, p.y}];
}

template <class Num, bool Offset = true, class Probe = NoProbe>
fill::FillResult<Num> run_dda(const Tri& t, const std::vector<std::array<Rational, 3>>& attrs = {}, Probe probe = {}) {
  fill::Triangle<Num> v;
  for (int k = 0; k < 3; ++k) {
    v[k].p = to_num<Num>(t[k]);
    v[k].n = attrs.size();
    for (std::size_t c = 0; c < attrs.size(); ++c) v[k].a[c] = num::from_rational<Num>(attrs[c][k]);
  }
  fill::FillResult<Num> r;
  fill::triangle_dda<Offset, Num>(v, r, probe);
  return r;
}

template <class Num> std::vector<Pixel> run_edge(const Tri& t) {
  fill::EdgeTriangle<Num> e{{to_num<Num>(t[0]), to_num<Num>(t[1]), to_num<Num>(t[2])}, Num(1)};
  std::vector<Pixel> out;
  NoProbe none;
  fill::triangle_edge<Num>(e, out, none);
  return out;
}

// int mode: vertices on the 1/256 grid, in fixed point.
inline std::vector<Pixel> run_edge_fixed(const Tri& t) {
  fill::EdgeTriangle<std::int64_t> e{{}, 256};
  for (int k = 0; k < 3; ++k) e.v[k] = {num::floor_int(Rational(t[k].x * 256)), num::floor_int(Rational(t[k].y * 256))};
  std::vector<Pixel> out;
  NoProbe none;
  fill::triangle_edge<std::int64_t>(e, out, none);
  return out;
}

template <class Num> std::vector<Pixel> run_scanline(const Rings& rings, fill::WindingRule rule) {
  fill::Polygon<Num> p{{}, rule};
  for (const auto& r : rings) {
    p.rings.emplace_back();
    for (const auto& v : r) p.rings.back().push_back(to_num<Num>(v));
  }
  std::vector<Pixel> out;
  NoProbe none;
  fill::scanline_polygon<Num>(p, out, none);
  return out;
}

// A coordinate on the 1/`den` grid in [lo, hi]: coarse grids put many vertices and edges exactly on samples.
inline Rational grid_coord(std::mt19937_64& rng, long lo, long hi, long den) {
  return Rational(std::uniform_int_distribution<long>(lo * den, hi * den)(rng)) / den;
}

}  // namespace sw::testing
