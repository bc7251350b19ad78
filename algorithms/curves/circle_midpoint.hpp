// The midpoint circle: the pixels nearest the circle along each row of the octant. It walks like
// circle-interior but tracks Q = 4 P(x + 1/2, y), the circle's polynomial at the midpoint between
// the current column and the next one toward the centre (times 4 to stay in integers). Q is odd,
// so it is never 0: there are no ties.
#pragma once
#include <string_view>
#include "curves/circle_walk.hpp"

namespace sw::curves {

struct CircleMidpoint {
  static constexpr std::string_view id = "circle-midpoint";
  static constexpr std::string_view summary = "Midpoint circle: the pixel nearest the circle on each row of the octant";
  static constexpr const char *kP = "Q", *kPx = "Qx", *kPy = "Qy";
#define SW_LINES_CIRCLE_MIDPOINT(X) \
  X(start, "(x, y) <- (-r, 0)                          -- the octant 0 <= y <= -x, left of the centre") \
  X(init, "Q <- 1 - 4r; Qx <- 8 - 8r; Qy <- 4          -- Q = 4 P(x + 1/2, y) and its steps; Qxx = Qyy = 8") \
  X(test, "while y <= -x:") \
  X(plot, "    plot (x, y) and its 7 mirror images, moved to the centre") \
  X(step_y, "    y <- y + 1; Q <- Q + Qy; Qy <- Qy + 8") \
  X(decide, "    if Q > 0:                              -- the midpoint is outside: x + 1 is nearer") \
  X(step_x, "        x <- x + 1; Q <- Q + Qx; Qx <- Qx + 8") \
  X(done, "done")
  SW_LISTING("Midpoint circle", SW_LINES_CIRCLE_MIDPOINT)
#undef SW_LINES_CIRCLE_MIDPOINT
};

template <NumberType Num, StepProbe Probe = NoProbe>
void circle_midpoint(const CircleInput& c, std::vector<Pixel>& out, Probe& probe) {
  const Num r(c.r);
  circle_octant_walk<CircleMidpoint, Num>(c, {Num(1) - Num(4) * r, Num(8) - Num(8) * r, Num(4), Num(8), Num(8)}, out, probe);
}

}  // namespace sw::curves
