// The zero set of f(x, y) over a window, by marching squares: what the curves' outlines draw for
// implicit curves and circles, evaluated in double from the exact coefficients.
#pragma once
#include <functional>
#include <vector>
#include "views.hpp"

namespace sw {

// Segments (two-point polylines) where f changes sign between the corners of a grid of about
// `cell` units over `window` (at most kMaxContourCells per side; a finer `cell` is coarsened).
// A corner with f = 0 counts as positive. Saddle cells join the corners by the centre's sign.
inline constexpr int kMaxContourCells = 1024;
std::vector<Polyline2> contour(const std::function<double(double, double)>& f, const Rect2& window, double cell);

}  // namespace sw
