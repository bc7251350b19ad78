// Exact specifications of a BSP's fragments and of a painter's order, stated by brute force over
// all fragments and pairs on GMP rationals (CGAL in the .cpp), independently of any tree.
// Semantics: docs/spatial/bsp.md.
#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::oracle {

struct Seg2Q {
  Vec2<Rational> a, b;
};
struct FragmentQ {
  std::int32_t seg = -1;  // the input segment it is a piece of
  Vec2<Rational> a, b;
};

// Do the fragments exactly cover the segments? Every fragment lies on its segment and has positive
// length, and each segment is the union of its fragments, which overlap only at endpoints. Returns
// why not ("" when they do).
std::string fragments_cover(const std::vector<Seg2Q>& segs, const std::vector<FragmentQ>& frags);

// Is `order` a valid back-to-front order of the fragments seen from `eye`? Fragment i, drawn
// before j, must not hide part of j: there must be no open set of rays from the eye meeting both
// with i strictly nearer (the rays of zero measure, along a fragment's line through the eye, show
// no area). Checked for every pair from that definition by exact orientations: O(n^2).
struct OrderCheck {
  std::size_t violations = 0;  // pairs (i before j) with i hiding part of j
  std::size_t crossings = 0;   // of those, pairs whose interiors cross (no order of the two is valid)
  std::string first;           // the first such pair, or why `order` is not a permutation
};
OrderCheck painter_order(const Vec2<Rational>& eye, const std::vector<FragmentQ>& frags, const std::vector<std::int32_t>& order);

}  // namespace sw::oracle
