// Shared by the implicit-curve tests: cases, the walk in any mode and by the oracle, the corpus,
// and the closed forms (P, its partials, its forward differences) evaluated directly in Rational.
#pragma once
#include <catch2/catch.hpp>
#include <algorithm>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include "catalog.hpp"
#include "curves/implicit_curve.hpp"
#include "curves_oracle.hpp"
#include "input.hpp"
#include "step_values.hpp"

namespace sw::testing::implicit {

using Coeffs = std::array<std::array<Rational, 4>, 4>;

struct Case {
  Coeffs c;
  Pixel start;
  std::int64_t max_steps = 1;
};

struct Walk {
  std::vector<Pixel> pixels;
  std::string stopped;
  std::int64_t steps = 0;
  friend bool operator==(const Walk&, const Walk&) = default;
};

inline int degree_of(const Coeffs& c) {
  int d = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; i + j < 4; ++j)
      if (c[i][j] != 0) d = std::max(d, i + j);
  return d;
}

template <class Num> curves::ImplicitPoly<Num> poly(const Case& k) {
  curves::ImplicitPoly<Num> p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; i + j < 4; ++j) p.c[i][j] = num::from_rational<Num>(k.c[i][j]);
  p.start = k.start, p.max_steps = k.max_steps, p.degree = degree_of(k.c);
  return p;
}

template <class Num> Walk walk(const Case& k) {
  Walk w;
  NoProbe none;
  const curves::WalkEnd end = curves::implicit_curve<Num>(poly<Num>(k), w.pixels, none);
  w.stopped = curves::kWalkStopNames[static_cast<std::size_t>(end.stopped)];
  w.steps = end.steps;
  return w;
}

inline Walk oracle_walk(const Case& k) {
  oracle::ImplicitWalkEnd end;
  Walk w{oracle::implicit_walk_pixels(k.c, k.start, k.max_steps, &end), "", 0};
  w.stopped = end.stopped, w.steps = end.steps;
  return w;
}

// An input object of the corpus's form, read without the runtime's validation (the tests feed
// only valid inputs here).
inline Case case_of(const Json& in) {
  Case k;
  for (const Json& t : in.at("P")) k.c[t[1].get<int>()][t[2].get<int>()] = parse_rational(t[0], "term");
  k.start = {in.at("start")[0].get<std::int64_t>(), in.at("start")[1].get<std::int64_t>()};
  k.max_steps = in.at("max_steps").get<std::int64_t>();
  return k;
}

// The implicit-curve cases of the curves corpus, by name.
inline std::map<std::string, Json> corpus() {
  std::map<std::string, Json> out;
  std::ifstream f(std::string(SW_SOURCE_DIR) + "/tests/cases/curves/corpus.jsonl");
  std::string line;
  while (std::getline(f, line))
    if (!line.empty() && line[0] == '{') {
      const Json j = Json::parse(line);
      if (j.at("input").contains("P")) out[j.at("name").get<std::string>()] = j.at("input");
    }
  return out;
}

// --- The closed forms: P, its partials and its forward differences, directly in Rational. ---

inline Rational power(const Rational& b, int e) {
  Rational r = 1;
  for (int k = 0; k < e; ++k) r *= b;
  return r;
}
// (d/dx)^dx (d/dy)^dy P at (x, y), dx + dy <= 1.
inline Rational P(const Coeffs& c, const Rational& x, const Rational& y, int dx = 0, int dy = 0) {
  Rational s = 0;
  for (int i = dx; i < 4; ++i)
    for (int j = dy; i + j < 4; ++j) s += c[i][j] * (dx ? i : 1) * (dy ? j : 1) * power(x, i - dx) * power(y, j - dy);
  return s;
}
inline long binom(int n, int k) { return k == 0 || k == n ? 1 : binom(n - 1, k - 1) + binom(n - 1, k); }
// Du^m Dv^n Q at (u, v), Q(u, v) = P(u/2, v/2): the binomial sum over the corners.
inline Rational diff(const Coeffs& c, std::int64_t u, std::int64_t v, int m, int n) {
  Rational s = 0;
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j)
      s += ((m - i + n - j) % 2 ? -1 : 1) * binom(m, i) * binom(n, j) * P(c, ratio(u + i, 2), ratio(v + j, 2));
  return s;
}

inline Case random_case(std::mt19937_64& rng, int i) {
  const auto u = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  // Integer, dyadic (exact in every mode) or thirds (the filter's intervals are not points).
  const int den = std::array{1, 4, 3, 2}[i % 4];
  const int deg = 2 + i % 2;
  Case k;
  for (int a = 0; a <= deg; ++a)
    for (int b = 0; a + b <= deg; ++b)
      if (a + b > 0) k.c[a][b] = ratio(u(0, 2) ? u(-4, 4) : 0, den);
  if (degree_of(k.c) == 0) k.c[0][1] = 1;
  k.start = {u(-6, 6), u(-6, 6)};
  // The constant term puts the curve through the start, or within a little of it; one case in 8
  // starts far from it (P(start) up to 40).
  k.c[0][0] = -P(k.c, k.start.x, k.start.y) + (i % 8 == 5 ? ratio(u(-40, 40), 1) : ratio(u(-3, 3), u(1, 4)));
  k.max_steps = i % 8 < 2 ? u(1, 200) : u(1, 30);
  return k;
}

}  // namespace sw::testing::implicit
