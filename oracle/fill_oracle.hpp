// The exact specification of the fill family's covered samples (docs/fill/semantics.md), by brute
// force over the bounding box's samples with exact orientation predicates (CGAL). Independent of
// every fill algorithm: no DDA, no edge table, no incremental evaluation.
#pragma once
#include <array>
#include <vector>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::oracle {

enum class FillRule { even_odd, nonzero };

// The samples (i, j) the triangle covers, in scanline order (j ascending, then i). Any vertex
// order; a triangle of zero area covers nothing. Precondition: its bounding box holds at most
// 2^24 samples.
std::vector<Pixel> triangle_samples(const std::array<Vec2<Rational>, 3>& t);

// The winding number of sample (i, j) for the closed rings: crossings of the non-horizontal edges
// with rows [min y, max y) at or left of the sample, +1 going up, -1 going down.
std::int64_t winding_number(const std::vector<std::vector<Vec2<Rational>>>& rings, Pixel sample);

// The samples the rings cover under the rule, in scanline order. Precondition as above.
std::vector<Pixel> polygon_samples(const std::vector<std::vector<Vec2<Rational>>>& rings, FillRule rule);

// The linear function with values f[k] at the triangle's vertices t[k], at sample s: the
// barycentric combination, by Cramer's rule. Precondition: the triangle has nonzero area.
Rational linear_at(const std::array<Vec2<Rational>, 3>& t, const std::array<Rational, 3>& f, Pixel s);

}  // namespace sw::oracle
