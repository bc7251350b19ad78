// The guide's Algorithm 1.3: the interior border of a circle, the outermost pixels whose centres
// lie inside or on it, with integers only. P tracks x^2 + y^2 - r^2 at the current pixel.
#pragma once
#include <string_view>
#include "curves/circle_walk.hpp"

namespace sw::curves {

struct CircleInterior {
  static constexpr std::string_view id = "circle-interior";
  static constexpr std::string_view summary = "Circle's interior border (the guide's Algorithm 1.3): centres inside or on it";
  static constexpr const char *kP = "P", *kPx = "Px", *kPy = "Py";
#define SW_LINES_CIRCLE_INTERIOR(X) \
  X(start, "(x, y) <- (-r, 0)                          -- the octant 0 <= y <= -x, left of the centre") \
  X(init, "P <- 0; Px <- 1 - 2r; Py <- 1              -- P = x^2 + y^2 - r^2 and its steps; Pxx = Pyy = 2") \
  X(test, "while y <= -x:") \
  X(plot, "    plot (x, y) and its 7 mirror images, moved to the centre") \
  X(step_y, "    y <- y + 1; P <- P + Py; Py <- Py + 2") \
  X(decide, "    if P > 0:                              -- the pixel centre left the disc") \
  X(step_x, "        x <- x + 1; P <- P + Px; Px <- Px + 2") \
  X(done, "done")
  SW_LISTING("Circle, interior border", SW_LINES_CIRCLE_INTERIOR)
#undef SW_LINES_CIRCLE_INTERIOR
};

template <NumberType Num, StepProbe Probe = NoProbe>
void circle_interior(const CircleInput& c, std::vector<Pixel>& out, Probe& probe) {
  const Num r(c.r);
  circle_octant_walk<CircleInterior, Num>(c, {Num(0), Num(1) - Num(2) * r, Num(1), Num(2), Num(2)}, out, probe);
}

}  // namespace sw::curves
