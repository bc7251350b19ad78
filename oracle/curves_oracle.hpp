// Exact specifications of the curve family, stated directly: every pixel is decided from the
// definition by exact integer or rational comparisons, never by stepping from the previous one.
// The algorithms in algorithms/curves/ are checked against these.
// Conventions: round(v) = floor(v + 1/2); a circle's octant O is the rows y = 0, 1, ... left of the
// centre while y <= (the row's distance from the centre), and the curve is O's 8 mirror images.
#pragma once
#include <array>
#include <cstdint>
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

}  // namespace sw::oracle
