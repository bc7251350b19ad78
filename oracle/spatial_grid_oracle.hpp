// The 3D grid walk's specification, stated directly on GMP rationals, independently of
// algorithms/spatial/grid_traverse_3d.hpp. Semantics: docs/spatial/grid.md.
// Cell (i, j, k) is the half-open cube [i-1/2, i+1/2) x [j-1/2, j+1/2) x [k-1/2, k+1/2); the segment
// p0 -> p1 is the half-open set { p0 + t (p1 - p0) : 0 <= t < 1 } (empty when p0 = p1).
#pragma once
#include <array>
#include <cstdint>
#include <vector>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::oracle {

using GridCell = std::array<std::int64_t, 3>;

// Does cell c's half-open cube meet the half-open segment?
bool cube_meets_segment(const Vec3<Rational>& p0, const Vec3<Rational>& p1, const GridCell& c);

// Every cell meeting the segment, in entry order: by the entry parameter (the infimum of the t the
// segment spends in the cell), and at equal t a cell holding that point before one entered just
// after it. Swept by columns: the x-slab's t-interval bounds the y range, (x, y)'s bounds the z range.
std::vector<GridCell> grid_cells_3d(const Vec3<Rational>& p0, const Vec3<Rational>& p1);
// The same set by testing every cell of the segment's bounding box (small boxes only).
std::vector<GridCell> grid_cells_3d_brute_force(const Vec3<Rational>& p0, const Vec3<Rational>& p1);

}  // namespace sw::oracle
