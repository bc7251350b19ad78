// Shared by the clipper tests (test_clip_segment.cpp, test_clip_polygon.cpp): the corpus cases of
// one algorithm, exact points from JSON, and seeded small rationals that hit corners and edges often.
#pragma once
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>
#include "catalog.hpp"
#include "core/number.hpp"
#include "fill_clip_oracle.hpp"
#include "step_values.hpp"

namespace sw::testing::clip {

using oracle::Polygon2;
using Q = Rational;

// Whether an interval result encloses the exact value.
inline bool within(const Interval& v, const Q& exact) { return num::to_rational(v.lo()) <= exact && exact <= num::to_rational(v.hi()); }

struct Case {
  std::string name;
  Json input;
};

// The catalog example, then the corpus lines of tests/cases/fill/clip.jsonl for this algorithm.
inline std::vector<Case> corpus_cases(std::string_view algorithm) {
  std::vector<Case> out{{"example", Json::parse(find_algorithm(algorithm).example)}};
  std::ifstream in(std::filesystem::path(SW_SOURCE_DIR) / "tests" / "cases" / "fill" / "clip.jsonl");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] != '{') continue;
    const Json j = Json::parse(line);
    if (j.at("algorithm") == algorithm) out.push_back({j.at("name").get<std::string>(), j.at("input")});
  }
  return out;
}

inline Vec2<Q> point_of(const Json& v) { return {parse_rational(v[0], "x"), parse_rational(v[1], "y")}; }
inline Polygon2 points_of(const Json& a) {
  Polygon2 p;
  for (const Json& v : a) p.push_back(point_of(v));
  return p;
}

inline Q cross(const Vec2<Q>& a, const Vec2<Q>& b, const Vec2<Q>& v) { return (b.x - a.x) * (v.y - a.y) - (b.y - a.y) * (v.x - a.x); }

// Small rationals: halves on a short range, so that ends, vertices and corners coincide often.
struct SmallRng {
  std::mt19937_64 rng;
  std::int64_t pick(std::int64_t lo, std::int64_t hi) { return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng); }
  Q half(std::int64_t lo, std::int64_t hi) { return ratio(pick(2 * lo, 2 * hi), 2); }
  Vec2<Q> point(std::int64_t lo, std::int64_t hi) { return {half(lo, hi), half(lo, hi)}; }
  // A double-exact value with 20 fraction bits: filtered mode mostly decides these.
  Q dyadic(double lo, double hi) {
    return num::to_rational(std::ldexp(std::floor(std::ldexp(std::uniform_real_distribution<double>(lo, hi)(rng), 20)), -20));
  }
};

}  // namespace sw::testing::clip
