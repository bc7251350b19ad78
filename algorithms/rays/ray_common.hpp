// Shared pieces of the ray family: the ray type and the exact-mode root that keeps sphere roots
// free of cancellation. Square roots and the other functions are the core's (core/functions.hpp). Semantics: docs/rays/semantics.md.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include "core/functions.hpp"
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::ray {

template <class Num> struct Ray3 {
  Vec3<Num> o, d;  // the ray is o + t d, t > 0; d != 0 (validated)
};

// p + s*sqrt(q) for s = +1 or -1 and q >= 0, and whether it is exact. Float types evaluate it as
// written (that is the naive formula's behaviour under test). Exact mode avoids the cancellation
// when p and s*sqrt(q) have opposite signs by using (p^2 - q) / (p - s*sqrt(q)), so the result
// keeps its precision and its sign is exact (p^2 - q is exact).
template <class Num> num::Rooted<Num> add_root(const Num& p, int s, const Num& q) {
  const num::Rooted<Num> r = num::root(q);
  if constexpr (std::is_same_v<Num, Rational>) {
    if (r.exact || sgn(p) * s >= 0) return {p + s * r.value, r.exact};
    return {(p * p - q) / (p - s * r.value), false};
  } else {
    return {num::select(s > 0, p + r.value, p - r.value), false};
  }
}

// A triangle test's scene, kept on the view: the ray, the triangle and its named vertices. `step`
// is what the probe's step() returned (a summarised callee's steps go elsewhere).
template <class Step, class Num> void record_triangle_scene(Step& step, const Ray3<Num>& r, const std::array<Vec3<Num>, 3>& v) {
  step.ray(r.o, r.d).keep().triangle(v[0], v[1], v[2]).keep();
  step.point(v[0]).label("v0").keep().point(v[1]).label("v1").keep().point(v[2]).label("v2").keep();
}

}  // namespace sw::ray
