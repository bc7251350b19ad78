// Exact specifications of the curve family, stated directly: every pixel is decided from the
// definition by exact integer or rational comparisons, never by stepping from the previous one.
// The algorithms in algorithms/curves/ are checked against these.
// Conventions: round(v) = floor(v + 1/2); a circle's octant O is the rows y = 0, 1, ... left of the
// centre while y <= (the row's distance from the centre), and the curve is O's 8 mirror images.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::oracle {

// The cubic y = a x^3 + b x^2 + c x + d, coeffs = {a, b, c, d}: for each integer x in [xs, xe),
// ascending, the pixel (x, round(y(x))) with y(x) evaluated exactly. Empty if xe <= xs.
// Precondition: every round(y(x)) fits in int64 (std::overflow_error otherwise).
std::vector<Pixel> poly_pixels(const std::array<Rational, 4>& coeffs, std::int64_t xs, std::int64_t xe);

// The midpoint circle: X(y) = the largest k >= 0 with k == 0 or (2k - 1)^2 < 4 (r^2 - y^2), i.e.
// round(sqrt(r^2 - y^2)) (no ties: the left side is odd, the right even). O = {(-X(y), y)} for
// y = 0, 1, ... while y <= X(y). Result: O's 8 images moved to (cx, cy), distinct, sorted by (x, y).
// Precondition: r >= 0 (empty otherwise) and cx +- r, cy +- r fit int64. The arithmetic is exact
// for any such r; the algorithms' own bound (r <= 2^22) is far inside it.
std::vector<Pixel> circle_midpoint_pixels(std::int64_t cx, std::int64_t cy, std::int64_t r);

// The interior border: the same with I(y) = floor(sqrt(r^2 - y^2)), the largest k >= 0 with
// k^2 <= r^2 - y^2, in place of X(y). Same preconditions.
std::vector<Pixel> circle_interior_pixels(std::int64_t cx, std::int64_t cy, std::int64_t r);

// The same two sets stated another way: every pixel of the box [-r-1, r+1]^2 around the centre is
// kept iff it is its row's pixel (|y| <= |x| == X(|y|)) or its column's (|x| <= |y| == X(|x|)),
// with X (resp. I) found by a linear scan over k. Quadratic in r: small radii only (tests).
std::vector<Pixel> circle_midpoint_brute_force(std::int64_t cx, std::int64_t cy, std::int64_t r);
std::vector<Pixel> circle_interior_brute_force(std::int64_t cx, std::int64_t cy, std::int64_t r);

// The implicit-curve walk on P(x, y) = sum c[i][j] x^i y^j (c[i][j] = 0 for i + j > 3), stated
// move by move with P and its partial derivatives evaluated exactly at each point (no difference
// table, nothing carried but the path). From the pixel p, with g = grad P(p):
//  - k = max_steps moves made: stop ("max_steps"); g = 0: stop ("singular");
//  - t = (-g_y, g_x); the major axis a is the one with the larger |t_a|, on a tie x iff
//    t_x t_y < 0; b the other; s_a = sign t_a; s_b = sign t_b, or -sign g_b when t_b = 0;
//  - A = p + s_a e_a, D = A + s_b e_b; the walk moves to D iff sign P((A + D) / 2) * s_b *
//    sign g_b < 0, else to A; the move counts;
//  - the new pixel is the start: stop ("closed"); already on the path: stop ("revisit").
// Returns the path (start first, each pixel once); `end`, if given, gets the reason and the moves.
struct ImplicitWalkEnd {
  std::string stopped;
  std::int64_t steps = 0;
};
std::vector<Pixel> implicit_walk_pixels(const std::array<std::array<Rational, 4>, 4>& c, Pixel start, std::int64_t max_steps,
                                        ImplicitWalkEnd* end = nullptr);

}  // namespace sw::oracle
