// The curves' exact definitions drawn under their pixels (the outline view hook, views.hpp):
// polylines in world coordinates over a window, computed in double from the exact input.
#pragma once
#include <array>
#include <cstdint>
#include "core/number.hpp"
#include "core/vec.hpp"
#include "views.hpp"

namespace sw::curves {

// y = c0 x^3 + c1 x^2 + c2 x + c3 over the plotted columns [xs, xe - 1] within the window.
std::vector<Polyline2> cubic_outline(const std::array<Rational, 4>& c, std::int64_t xs, std::int64_t xe, const Rect2& w, double cell);
// The circle's zero set (x - cx)^2 + (y - cy)^2 - r^2 = 0, by marching squares: exact at any zoom.
std::vector<Polyline2> circle_outline(std::int64_t cx, std::int64_t cy, std::int64_t r, const Rect2& w, double cell);
// sum c[i][j] x^i y^j = 0 over the window, by marching squares.
std::vector<Polyline2> implicit_outline(const std::array<std::array<Rational, 4>, 4>& c, const Rect2& w, double cell);
// The cubic Bezier in Bernstein form, t in [0, 1], points about `cell` apart.
std::vector<Polyline2> bezier_outline(const std::array<Vec2<Rational>, 4>& p, double cell);

}  // namespace sw::curves
