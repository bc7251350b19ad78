// Exact specifications of the line family, stated directly (no incremental stepping), on CGAL's
// GMP rationals. The algorithms in algorithms/lines/ are checked against these.
// Conventions (docs/lines/semantics.md): pixel (i, j) is [i-1/2, i+1/2) x [j-1/2, j+1/2); the
// segment p0 -> p1 holds p0 and not p1; round(v) = floor(v + 1/2); |dx| = |dy| steps rows.
#pragma once
#include <vector>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::oracle {

enum class Sampling {
  ascending,  // dda-line: major-axis integers k in [min(p0_a, p1_a), max(p0_a, p1_a)), ascending
  directed,   // bresenham-line: k from p0_a toward p1_a, p1_a excluded, in that order
};

// For each sampled major-axis integer k, the pixel whose square holds the segment's point at k.
// Evaluated directly for each k from the endpoints.
std::vector<Pixel> column_pixels(const Vec2<Rational>& p0, const Vec2<Rational>& p1, Sampling s);

// The same set by brute force: every pixel of the bounding box is tested for membership, then
// sorted into sampling order. Only for small boxes (tests cross-check the two statements).
std::vector<Pixel> column_pixels_brute_force(const Vec2<Rational>& p0, const Vec2<Rational>& p1, Sampling s);

// Does pixel c's half-open square meet the half-open segment [p0, p1)?
bool cell_meets_segment(const Vec2<Rational>& p0, const Vec2<Rational>& p1, Pixel c);

// The segment parameter at which it enters cell c (the infimum of the t it spends there), and
// whether that infimum is excluded. Precondition: cell_meets_segment.
struct Entry {
  Rational t;
  bool open;
};
Entry cell_entry(const Vec2<Rational>& p0, const Vec2<Rational>& p1, Pixel c);

// Every cell meeting the segment, in entry order: (t, closed before open). Column sweep: for each
// column, its t-interval bounds the rows to test.
std::vector<Pixel> walk_cells(const Vec2<Rational>& p0, const Vec2<Rational>& p1);
// The same by testing every cell of the bounding box (small boxes only).
std::vector<Pixel> walk_cells_brute_force(const Vec2<Rational>& p0, const Vec2<Rational>& p1);

}  // namespace sw::oracle
