// The exact specification of raster-clip: the samples a triangle covers (docs/fill/semantics.md)
// that lie on a screen, by brute force over the screen's samples only (so a triangle 10^6 times the
// screen costs the screen), with exact orientation predicates (CGAL). Independent of every fill
// algorithm and of oracle::triangle_samples' box walk.
#pragma once
#include <array>
#include <cstdint>
#include <vector>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::oracle {

// Half-open sample window: the samples (i, j) with i0 <= i < i1 and j0 <= j < j1.
struct SampleWindow {
  std::int64_t i0 = 0, j0 = 0, i1 = 0, j1 = 0;
};

// The samples of the window the triangle covers, in scanline order (j ascending, then i). Any
// vertex order; zero area covers nothing. Precondition: the window holds at most 2^24 samples.
std::vector<Pixel> triangle_samples_in_window(const std::array<Vec2<Rational>, 3>& t, const SampleWindow& w);

}  // namespace sw::oracle
