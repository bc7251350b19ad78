// The exact specification of bezier-forward-diff: the curve points B(k/n) from the Bernstein form,
// each joined to the next by the lines family's DDA specification (oracle::column_pixels).
#pragma once
#include <array>
#include <cstdint>
#include <vector>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::oracle {

// B(t) = sum over i of C(3, i) (1 - t)^(3 - i) t^i P_i, exactly.
Vec2<Rational> bezier_point(const std::array<Vec2<Rational>, 4>& p, const Rational& t);

// For k = 0 .. n-1, the pixels of the half-open segment B(k/n) -> B((k+1)/n) under dda-line's
// semantics (major-axis integers in [min, max), ascending), concatenated. Precondition: n >= 1.
std::vector<Pixel> bezier_pixels(const std::array<Vec2<Rational>, 4>& p, std::int64_t n);

}  // namespace sw::oracle
