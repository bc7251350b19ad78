// What every spatial tree shares: D-dimensional points and axis-aligned boxes over any number
// type, a box's surface measure for the surface area heuristic, and a primitive's bounds.
// Boxes are closed: [lo, hi] on every axis.
#pragma once
#include <array>
#include <type_traits>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::spatial {

template <class Num, int D> using VecN = std::conditional_t<D == 2, Vec2<Num>, Vec3<Num>>;

template <class Num, int D> struct Box {
  VecN<Num, D> lo, hi;
  // The box of one point.
  static Box at(const VecN<Num, D>& p) { return {p, p}; }
  void grow(const VecN<Num, D>& p) {
    for (int k = 0; k < D; ++k) {
      if constexpr (std::is_floating_point_v<Num>) {  // the same choice, as minsd/maxsd: no branch to mispredict
        lo[k] = p[k] < lo[k] ? p[k] : lo[k];
        hi[k] = hi[k] < p[k] ? p[k] : hi[k];
      } else {  // exact types: no copy of a coordinate onto itself
        if (p[k] < lo[k]) lo[k] = p[k];
        if (hi[k] < p[k]) hi[k] = p[k];
      }
    }
  }
  void grow(const Box& b) { grow(b.lo), grow(b.hi); }
  // The closed boxes share a point.
  bool meets(const Box& b) const {
    for (int k = 0; k < D; ++k)
      if (b.hi[k] < lo[k] || hi[k] < b.lo[k]) return false;
    return true;
  }
  bool contains(const VecN<Num, D>& p) const {
    for (int k = 0; k < D; ++k)
      if (p[k] < lo[k] || hi[k] < p[k]) return false;
    return true;
  }
  Num extent(int k) const { return hi[k] - lo[k]; }
  // The measure the SAH weighs a child by: half the surface area in 3D, half the perimeter in 2D.
  // (Halving changes no ratio of two measures, which is all the heuristic uses.)
  Num half_area() const {
    if constexpr (D == 2) return extent(0) + extent(1);
    else return extent(0) * extent(1) + extent(1) * extent(2) + extent(2) * extent(0);
  }
  int longest_axis() const {
    int a = 0;
    for (int k = 1; k < D; ++k)
      if (extent(a) < extent(k)) a = k;
    return a;
  }
};

template <class Num> Box<Num, 3> triangle_bounds(const std::array<Vec3<Num>, 3>& t) {
  Box<Num, 3> b = Box<Num, 3>::at(t[0]);
  b.grow(t[1]), b.grow(t[2]);
  return b;
}

}  // namespace sw::spatial
