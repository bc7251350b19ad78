// Exact specifications of the ray family, stated independently of algorithms/rays/ (on CGAL's GMP
// rationals and MPFR). Semantics (docs/rays/semantics.md): a hit is o + t d with t > 0 on the closed
// primitive; the smallest such t is reported (for the box and the sphere: the first surface point).
//  - triangle: exact orient3d of the ray's line against each edge, and of the origin against the
//    plane; a ray in the triangle's plane misses;
//  - sphere: the sign of r^2 |d|^2 - |f x d|^2 (f = o - c) with the sign conditions on the roots;
//  - box: exact slab intervals;  - plane: the exact sign of d . n.
#pragma once
#include <array>
#include <vector>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::oracle {

struct RayResult {
  bool hit = false;
  Rational t;                   // exact, or rounded to 128 bits when irrational (t_exact false)
  bool t_exact = true;
  std::array<Rational, 3> b;    // triangle: barycentric weights of v0, v1, v2
  Rational t_near, t_far;       // box: the ray's slab interval (reported on hits)
  std::vector<Rational> attr;   // triangle: the vertex attributes interpolated with b (if given)
};

// det [a; b; c] (rows), exactly: the scalar triple product a . (b x c).
Rational triple(const Vec3<Rational>& a, const Vec3<Rational>& b, const Vec3<Rational>& c);
// CGAL::orientation(p, q, r, s): the sign of det [q - p; r - p; s - p].
int orient3d(const Vec3<Rational>& p, const Vec3<Rational>& q, const Vec3<Rational>& r, const Vec3<Rational>& s);

// Precondition (validated by the runtime): d != 0; r > 0; lo <= hi; n != 0. A degenerate triangle misses.
RayResult ray_triangle(const Vec3<Rational>& o, const Vec3<Rational>& d, const std::array<Vec3<Rational>, 3>& v);
RayResult ray_sphere(const Vec3<Rational>& o, const Vec3<Rational>& d, const Vec3<Rational>& c, const Rational& r);
RayResult ray_box(const Vec3<Rational>& o, const Vec3<Rational>& d, const Vec3<Rational>& lo, const Vec3<Rational>& hi);
RayResult ray_plane(const Vec3<Rational>& o, const Vec3<Rational>& d, const Vec3<Rational>& p, const Vec3<Rational>& n);

// Spheres report an irrational t rounded to this many significant bits (nearest).
inline constexpr int kSphereTBits = 128;

}  // namespace sw::oracle
