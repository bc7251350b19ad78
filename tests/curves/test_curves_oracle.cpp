// The curve family's exact oracle on its own: hand-derived sets, its per-row and brute-force
// statements against each other, and properties that follow from the definitions.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdlib>
#include <random>
#include <stdexcept>
#include <string>
#include "curves_oracle.hpp"

using namespace sw;
using Pixels = std::vector<Pixel>;
using Q = Rational;

namespace {

Pixels moved(Pixels px, std::int64_t dx, std::int64_t dy) {
  for (Pixel& p : px) p.x += dx, p.y += dy;
  return px;
}

}  // namespace

// X(y) is the largest k with (2k - 1)^2 < 4 (r^2 - y^2); rows stop at the first y > X(y).
TEST_CASE("curves oracle: midpoint circle by hand", "[oracle][curves]") {
  // r = 0: y = 0 gives 4D = 0, so X = 0 (the k == 0 clause) and 0 <= 0: O = {(0, 0)}.
  CHECK(oracle::circle_midpoint_pixels(0, 0, 0) == Pixels{{0, 0}});
  // r = 1: y = 0: 4D = 4 > 1 = 1^2, 9 > 4, X = 1. y = 1: 4D = 0, X = 0 < 1, stop. O = {(-1, 0)}.
  CHECK(oracle::circle_midpoint_pixels(0, 0, 1) == Pixels{{-1, 0}, {0, -1}, {0, 1}, {1, 0}});
  // r = 2: y = 0: 4D = 16, 3^2 = 9 < 16 < 25, X = 2. y = 1: 4D = 12, 9 < 12 < 25, X = 2.
  // y = 2: 4D = 0, X = 0, stop. O = {(-2, 0), (-2, 1)}: images (+-2, 0) (0, +-2) and
  // (+-2, +-1) (+-1, +-2), 12 pixels.
  CHECK(oracle::circle_midpoint_pixels(0, 0, 2) == Pixels{{-2, -1}, {-2, 0}, {-2, 1}, {-1, -2}, {-1, 2}, {0, -2},
                                                     {0, 2}, {1, -2}, {1, 2}, {2, -1}, {2, 0}, {2, 1}});
  // r = 3: y = 0: 4D = 36, 25 < 36 < 49, X = 3. y = 1: 4D = 32, 25 < 32, X = 3.
  // y = 2: 4D = 20, 9 < 20 < 25, X = 2 and 2 <= 2. y = 3: 4D = 0, stop.
  // O = {(-3, 0), (-3, 1), (-2, 2)}: 4 + 8 + 4 = 16 pixels.
  CHECK(oracle::circle_midpoint_pixels(0, 0, 3) == Pixels{{-3, -1}, {-3, 0}, {-3, 1}, {-2, -2}, {-2, 2}, {-1, -3},
                                                     {-1, 3}, {0, -3}, {0, 3}, {1, -3}, {1, 3}, {2, -2},
                                                     {2, 2}, {3, -1}, {3, 0}, {3, 1}});
  // r = 5: 4D = 100, 96, 84 for y = 0, 1, 2: all in (81, 121), X = 5. y = 3: 4D = 64 in (49, 81),
  // X = 4. y = 4: 4D = 36 in (25, 49), X = 3 < 4, stop. O = {(-5, 0..2), (-4, 3)}: 4 + 8 + 8 + 8.
  CHECK(oracle::circle_midpoint_pixels(0, 0, 5) ==
        Pixels{{-5, -2}, {-5, -1}, {-5, 0}, {-5, 1}, {-5, 2}, {-4, -3}, {-4, 3}, {-3, -4}, {-3, 4}, {-2, -5},
          {-2, 5}, {-1, -5}, {-1, 5}, {0, -5},  {0, 5},  {1, -5},  {1, 5},  {2, -5},  {2, 5},  {3, -4},
          {3, 4},  {4, -3},  {4, 3},  {5, -2},  {5, -1}, {5, 0},   {5, 1},  {5, 2}});
  // Moving the centre to (10, -4) moves every pixel of r = 1 by it.
  CHECK(oracle::circle_midpoint_pixels(10, -4, 1) == Pixels{{9, -4}, {10, -5}, {10, -3}, {11, -4}});
}

// I(y) is the largest k with k^2 <= r^2 - y^2.
TEST_CASE("curves oracle: interior circle by hand", "[oracle][curves]") {
  // r = 0: D = 0, I = 0, O = {(0, 0)}.
  CHECK(oracle::circle_interior_pixels(0, 0, 0) == Pixels{{0, 0}});
  // r = 1: y = 0: D = 1, I = 1. y = 1: D = 0, I = 0 < 1, stop.
  CHECK(oracle::circle_interior_pixels(0, 0, 1) == Pixels{{-1, 0}, {0, -1}, {0, 1}, {1, 0}});
  // r = 2: y = 0: D = 4, I = 2. y = 1: D = 3, I = 1 and 1 <= 1. y = 2: D = 0, stop.
  // O = {(-2, 0), (-1, 1)}: the diagonal (+-1, +-1) where the midpoint circle has (+-2, +-1).
  const Pixels r2{{-2, 0}, {-1, -1}, {-1, 1}, {0, -2}, {0, 2}, {1, -1}, {1, 1}, {2, 0}};
  CHECK(oracle::circle_interior_pixels(0, 0, 2) == r2);
  // r = 3: y = 0: D = 9, I = 3. y = 1: D = 8, I = 2 (4 <= 8 < 9). y = 2: D = 5, I = 2, 2 <= 2.
  // y = 3: D = 0, stop. O = {(-3, 0), (-2, 1), (-2, 2)}: 4 + 8 + 4 = 16 pixels.
  CHECK(oracle::circle_interior_pixels(0, 0, 3) == Pixels{{-3, 0}, {-2, -2}, {-2, -1}, {-2, 1}, {-2, 2}, {-1, -2},
                                                     {-1, 2}, {0, -3}, {0, 3}, {1, -2}, {1, 2}, {2, -2},
                                                     {2, -1}, {2, 1}, {2, 2}, {3, 0}});
  // A centre off the origin (and negative) only translates the set.
  CHECK(oracle::circle_interior_pixels(-3, 7, 2) == moved(r2, -3, 7));
  CHECK(oracle::circle_interior_pixels(-3, 7, -1).empty());  // r < 0: outside the precondition
}

TEST_CASE("curves oracle: per-row and brute-force circles agree for r up to 200", "[oracle][curves]") {
  for (std::int64_t r = 0; r <= 200; ++r) {
    INFO("r = " << r);
    REQUIRE(oracle::circle_midpoint_pixels(0, 0, r) == oracle::circle_midpoint_brute_force(0, 0, r));
    REQUIRE(oracle::circle_interior_pixels(0, 0, r) == oracle::circle_interior_brute_force(0, 0, r));
    REQUIRE(oracle::circle_midpoint_pixels(-7, 3, r) == oracle::circle_midpoint_brute_force(-7, 3, r));
    REQUIRE(oracle::circle_interior_pixels(-7, 3, r) == oracle::circle_interior_brute_force(-7, 3, r));
  }
}

// Properties, with (u, v) = (x - cx, y - cy), d2 = u^2 + v^2, and a pixel called flat if |v| <= |u|
// (it is then row |v|'s pixel: |u| = X(|v|), resp. I(|v|)), steep otherwise (column |u|'s).
// Midpoint: |u| = s + e with s = sqrt(r^2 - v^2) and |e| < 1/2, so d2 - r^2 = 2 e s + e^2 lies in
// (-s + 1/4, s + 1/4) once s >= 1/2 (for r >= 1 the octant never reaches r^2 - v^2 = 0), and s <= r:
// (2r - 1)^2 < 4 d2 < (2r + 1)^2, the centre lies strictly between the radii r - 1/2 and r + 1/2.
// Interior: u^2 <= r^2 - v^2 < (|u| + 1)^2: inside the disc, and the next pixel outward is not.
// Both: in the octant, row t + 1 moves 0 or 1 column toward the centre from row t: X (or I) never
// grows with t, and with t + 1 <= X(t + 1) the exact values differ by (2t + 1) / (s_t + s_t+1) < 1
// (both roots exceed t + 1/2), so the rounded (or floored) ones by at most 1: each octant is
// 8-connected.
namespace {

// The first property that fails, as text ("" if none). Checked pixel by pixel without REQUIRE, so
// that the ~10^6 checks stay fast.
std::string first_failure(const Pixels& px, std::int64_t cx, std::int64_t cy, std::int64_t r, bool midpoint) {
  if (px.empty()) return "empty";
  if (std::adjacent_find(px.begin(), px.end(), [](Pixel a, Pixel b) { return !(a < b); }) != px.end())
    return "not strictly sorted (unsorted or duplicated)";
  const auto has = [&](std::int64_t u, std::int64_t v) { return std::binary_search(px.begin(), px.end(), Pixel{cx + u, cy + v}); };
  const std::int64_t none = r + 1;  // no row's u can be r + 1
  std::vector<std::int64_t> octant(static_cast<std::size_t>(r + 1), none);  // octant[v]: u in 0 <= v <= -u
  for (const Pixel& p : px) {
    const std::int64_t u = p.x - cx, v = p.y - cy, au = std::abs(u), av = std::abs(v);
    const auto at = [&] { return " at (u, v) = (" + std::to_string(u) + ", " + std::to_string(v) + ")"; };
    if (au > r || av > r) return "outside the box" + at();
    // The two reflections u -> -u and u <-> v generate all 8 symmetries: closure under both suffices.
    if (!has(-u, v) || !has(v, u)) return "a mirror image is missing" + at();
    const std::int64_t d2 = u * u + v * v, lo = std::min(au, av), hi = std::max(au, av);
    if (midpoint && r >= 1) {
      if (!((2 * r - 1) * (2 * r - 1) < 4 * d2 && 4 * d2 < (2 * r + 1) * (2 * r + 1))) return "outside r +- 1/2" + at();
      // hi is the nearest integer to sqrt(r^2 - lo^2) along its row (or column).
      const std::int64_t four_d = 4 * (r * r - lo * lo);
      if (!((2 * hi - 1) * (2 * hi - 1) < four_d && four_d < (2 * hi + 1) * (2 * hi + 1))) return "not nearest" + at();
    } else if (!midpoint) {
      if (d2 > r * r) return "outside the disc" + at();
      if ((hi + 1) * (hi + 1) + lo * lo <= r * r) return "the next pixel outward is inside" + at();
    }
    if (0 <= v && v <= -u) {
      if (octant[static_cast<std::size_t>(v)] != none) return "two pixels in one octant row" + at();
      octant[static_cast<std::size_t>(v)] = u;
    }
  }
  // Rows 0 .. m are present and no others; each moves 0 or 1 column toward the centre.
  std::size_t m = 0;
  while (m + 1 < octant.size() && octant[m + 1] != none) ++m;
  if (octant[0] != -r) return "row 0 is not at -r";
  for (std::size_t t = m + 1; t < octant.size(); ++t)
    if (octant[t] != none) return "octant rows not contiguous";
  for (std::size_t t = 0; t < m; ++t)
    if (octant[t + 1] - octant[t] != 0 && octant[t + 1] - octant[t] != 1) return "a jump of more than one column";
  return "";
}

}  // namespace

TEST_CASE("curves oracle: circle properties for random radii", "[oracle][curves]") {
  std::mt19937_64 rng(20240611);
  for (int i = 0; i < 200; ++i) {
    const std::int64_t r = static_cast<std::int64_t>(rng() % 5001);
    const std::int64_t cx = static_cast<std::int64_t>(rng() % 2001) - 1000, cy = static_cast<std::int64_t>(rng() % 2001) - 1000;
    INFO("r = " << r << " centre " << cx << " " << cy);
    REQUIRE(first_failure(oracle::circle_midpoint_pixels(cx, cy, r), cx, cy, r, true) == "");
    REQUIRE(first_failure(oracle::circle_interior_pixels(cx, cy, r), cx, cy, r, false) == "");
  }
  // The smallest radius, at the origin.
  REQUIRE(first_failure(oracle::circle_midpoint_pixels(0, 0, 0), 0, 0, 0, true) == "");
  REQUIRE(first_failure(oracle::circle_interior_pixels(0, 0, 0), 0, 0, 0, false) == "");
}

TEST_CASE("curves oracle: cubic pixels by hand", "[oracle][curves]") {
  const auto poly = [](Q a, Q b, Q c, Q d, std::int64_t xs, std::int64_t xe) {
    return oracle::poly_pixels({a, b, c, d}, xs, xe);
  };
  // y = x^2 - 1 on [-2, 3): 4 - 1 = 3, 1 - 1 = 0, -1, 0, 3.
  CHECK(poly(0, 1, 0, -1, -2, 3) == Pixels{{-2, 3}, {-1, 0}, {0, -1}, {1, 0}, {2, 3}});
  // y = x / 2 on [-3, 4): -3/2 -1 -1/2 0 1/2 1 3/2, plus 1/2 and floored: -1 -1 0 0 1 1 2
  // (halves round up, also below zero: -1/2 -> 0, -3/2 -> -1).
  CHECK(poly(0, 0, Q(1, 2), 0, -3, 4) == Pixels{{-3, -1}, {-2, -1}, {-1, 0}, {0, 0}, {1, 1}, {2, 1}, {3, 2}});
  // Constants k + 1/2: 7/2 -> 4, -1/2 -> 0, -3/2 -> -1.
  CHECK(poly(0, 0, 0, Q(7, 2), 5, 6) == Pixels{{5, 4}});
  CHECK(poly(0, 0, 0, Q(-1, 2), 0, 1) == Pixels{{0, 0}});
  CHECK(poly(0, 0, 0, Q(-3, 2), 0, 1) == Pixels{{0, -1}});
  // Negative coefficients, y = -x^3 + 2x on [-2, 3): 8 - 4 = 4, 1 - 2 = -1, 0, -1 + 2 = 1, -8 + 4 = -4.
  CHECK(poly(-1, 0, 2, 0, -2, 3) == Pixels{{-2, 4}, {-1, -1}, {0, 0}, {1, 1}, {2, -4}});
  // Fractions, y = x^3 / 3 + 1/6 on [-2, 3): -8/3 + 1/6 = -5/2 -> -2 (a tie), -1/3 + 1/6 = -1/6 -> 0,
  // 1/6 -> 0, 1/3 + 1/6 = 1/2 -> 1 (a tie), 8/3 + 1/6 = 17/6 -> 3.
  CHECK(poly(Q("1/3"), 0, 0, Q("1/6"), -2, 3) == Pixels{{-2, -2}, {-1, 0}, {0, 0}, {1, 1}, {2, 3}});
  // y = x^2 / 4 - x / 5 on [-1, 2): 1/4 + 1/5 = 9/20 -> 0, 0, 1/4 - 1/5 = 1/20 -> 0.
  CHECK(poly(0, Q("1/4"), Q("-1/5"), 0, -1, 2) == Pixels{{-1, 0}, {0, 0}, {1, 0}});
  // Exactness: 1/2 - 10^-30 rounds down, 1/2 rounds up (doubles cannot tell these apart).
  CHECK(poly(0, 0, 0, Q("1/2") - Q("1/1000000000000000000000000000000"), 0, 1) == Pixels{{0, 0}});
  CHECK(poly(0, 0, 0, Q("1/2"), 0, 1) == Pixels{{0, 1}});
  // Large x: y = x^3 at 2^20 is 2^60, still an int64; at 2^22 it is 2^66, which is not.
  CHECK(poly(1, 0, 0, 0, 1 << 20, (1 << 20) + 1) == Pixels{{1 << 20, std::int64_t(1) << 60}});
  CHECK_THROWS_AS(poly(1, 0, 0, 0, 1 << 22, (1 << 22) + 1), std::overflow_error);
  // Empty ranges.
  CHECK(poly(1, 2, 3, 4, 3, 3).empty());
  CHECK(poly(1, 2, 3, 4, 3, -3).empty());
}
