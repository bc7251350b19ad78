// The octant walk shared by circle-interior and circle-midpoint (the guide's Algorithm 1.3 and its
// midpoint variant): start at (-r, 0), step y up one row at a time through the octant
// 0 <= y <= -x, and move x one column toward the centre whenever the tracked value of the circle's
// polynomial says the walk left the disc. Each octant pixel is plotted with its 8 mirror images.
// Semantics and the guide's two slips (the loop test and the midpoint start values):
// docs/curves/semantics.md.
#pragma once
#include <array>
#include <cstdint>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"

namespace sw::curves {

// Centre and radius, integers. Precondition (validated): 0 <= r <= 2^22, |cx|, |cy| <= 2^24.
struct CircleInput {
  std::int64_t cx = 0, cy = 0, r = 0;
};

// The start of the walk: P and its first and (constant) second differences at (-r, 0).
template <class Num> struct OctantStart { Num p, px, py, pxx, pyy; };

// The 8 mirror images of the octant point (x, y) about the centre, each once.
inline int mirror_images(const CircleInput& c, std::int64_t x, std::int64_t y, std::array<Pixel, 8>& img) {
  const std::array<Pixel, 8> all = {Pixel{x, y}, {-x, y}, {x, -y}, {-x, -y}, {y, x}, {-y, x}, {y, -x}, {-y, -x}};
  int n = 0;
  for (const Pixel& p : all) {
    const Pixel q{c.cx + p.x, c.cy + p.y};
    bool seen = false;
    for (int k = 0; k < n; ++k) seen |= img[k] == q;
    if (!seen) img[n++] = q;
  }
  return n;
}

// L is the algorithm's listing (start, init, test, plot, step_y, decide, step_x, done) and names
// the tracked value and its steps (kP, kPx, kPy) as the listing does.
template <class L, NumberType Num, StepProbe Probe>
void circle_octant_walk(const CircleInput& c, OctantStart<Num> s, std::vector<Pixel>& out, Probe& probe) {
  std::int64_t x = -c.r, y = 0;
  if constexpr (Probe::on)
    probe.step(L::start, StepKind::init).idx("x", x).idx("y", y).circle(Vec2<Num>{Num(c.cx), Num(c.cy)}, Num(c.r)).keep();
  if constexpr (Probe::on) probe.step(L::init, StepKind::init).num(L::kP, s.p).num(L::kPx, s.px).num(L::kPy, s.py);
  std::array<Pixel, 8> img;
  // Each pass moves y up by one and the octant holds at most r + 1 rows: bounded.
  while (y <= -x) {
    const int n = mirror_images(c, x, y, img);
    out.insert(out.end(), img.begin(), img.begin() + n);
    if constexpr (Probe::on) {
      auto& st = probe.step(L::plot, StepKind::plot).idx("x", x).idx("y", y).num(L::kP, s.p);
      for (int k = 0; k < n; ++k) st.pixel(img[k]);
    }
    ++y;
    s.p = s.p + s.py;
    s.py = s.py + s.pyy;
    if constexpr (Probe::on) probe.step(L::step_y, StepKind::advance).idx("y", y).num(L::kP, s.p).num(L::kPy, s.py);
    const bool inward = s.p > Num(0);
    if constexpr (Probe::on) {  // the two candidates on the row, coloured by the sign that decides between them
      const Vec2<Num> stay{Num(c.cx + x), Num(c.cy + y)}, inner{Num(c.cx + x + 1), Num(c.cy + y)};
      probe.step(L::decide, StepKind::decide).num(L::kP, s.p).idx("inward", inward).segment(stay, inner).label(L::kP).value(s.p);
    }
    if (inward) {
      ++x;
      s.p = s.p + s.px;
      s.px = s.px + s.pxx;
      if constexpr (Probe::on) probe.step(L::step_x, StepKind::advance).idx("x", x).num(L::kP, s.p).num(L::kPx, s.px);
    }
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("x", x).idx("y", y);
}

}  // namespace sw::curves
