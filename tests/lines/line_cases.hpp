// Line inputs for the tests: seeded random segments (many exactly on the pixel lattice's ties)
// and the hard-case corpus of tests/cases/lines/hard.jsonl.
#pragma once
#include <fstream>
#include <random>
#include <string>
#include <vector>
#include "input.hpp"

namespace sw::testing {

// Exact floor and ceiling, written here so that the expectations share no helper with the
// algorithms (num::floor_int).
inline Rational floor_q(const Rational& v) {
  mpz_class f;
  mpz_fdiv_q(f.get_mpz_t(), v.get_num_mpz_t(), v.get_den_mpz_t());
  return Rational(f);
}
inline Rational ceil_q(const Rational& v) { return -floor_q(-v); }

// The axis a line steps along: x when |dx| > |dy|, else y (a 45-degree line steps in y).
inline int major_axis(const Vec2<Rational>& d) { return abs(d.x) > abs(d.y) ? 0 : 1; }

struct Segment {
  Vec2<Rational> p0, p1;
  std::string name;
  bool long_line = false;
};

// Coordinates on a 1/2 grid (centres and corners: ties everywhere), a 1/1024 grid, or any double;
// one in four is nudged by +-2^-45 or +-2^-40 (degenerate up to roundoff).
inline std::vector<Segment> random_segments(int count, bool integer_endpoints, std::uint64_t seed = 7) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> kind(0, 2), nudge(0, 7), base(-40, 40), delta(-12, 12);
  std::uniform_real_distribution<double> frac(0, 1);
  auto coord = [&](int b) -> Rational {
    if (integer_endpoints) return Rational(b);
    Rational v;
    switch (kind(rng)) {
      case 0: v = Rational(b) + Rational(static_cast<int>(frac(rng) * 2), 2); break;
      case 1: v = Rational(b) + Rational(static_cast<int>(frac(rng) * 1024), 1024); break;
      default: v = Rational(b) + num::to_rational(frac(rng)); break;
    }
    v.canonicalize();  // mpq_class(p, q) does not reduce, and comparisons assume reduced values
    const int n = nudge(rng);
    if (n == 0) v += num::to_rational(0x1p-45);
    if (n == 1) v -= num::to_rational(0x1p-45);
    if (n == 2) v += num::to_rational(0x1p-40);
    return v;
  };
  std::vector<Segment> out;
  for (int i = 0; i < count; ++i) {
    const int x = base(rng), y = base(rng);
    out.push_back({{coord(x), coord(y)}, {coord(x + delta(rng)), coord(y + delta(rng))}, "random " + std::to_string(i)});
  }
  return out;
}

// The documented corpus; every case but the long ones also runs reversed.
inline std::vector<Segment> hard_segments(bool integer_only) {
  std::ifstream f(std::string(SW_SOURCE_DIR) + "/tests/cases/lines/hard.jsonl");
  std::vector<Segment> out;
  std::string line;
  while (std::getline(f, line)) {
    if (line.empty() || line[0] == '#') continue;
    const Json j = Json::parse(line);
    Segment s{parse_point2(j["input"], "p0"), parse_point2(j["input"], "p1"), j["name"].get<std::string>(), j.value("long", false)};
    if (integer_only && (s.p0.x.get_den() != 1 || s.p0.y.get_den() != 1 || s.p1.x.get_den() != 1 || s.p1.y.get_den() != 1)) continue;
    out.push_back(s);
    if (!s.long_line) out.push_back({s.p1, s.p0, s.name + " (reversed)"});
  }
  return out;
}

}  // namespace sw::testing
