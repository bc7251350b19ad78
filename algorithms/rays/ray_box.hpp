// The slab test (Kay-Kajiya): the ray's t-interval inside each axis slab, intersected. A zero
// direction component (+0.0 or -0.0) is tested explicitly: the ray then holds every t of that slab
// or none, decided by the origin's coordinate. So no 1/0 = inf and no 0 * inf = NaN can arise, an
// origin exactly on a slab plane counts as inside it, and exact rationals run the same code.
#pragma once
#include <array>
#include <string_view>
#include "core/probe.hpp"
#include "rays/ray_common.hpp"

namespace sw::ray {

template <class Num> struct BoxHit {
  bool hit = false;
  Num t{}, t_near{}, t_far{};  // t: the first surface point with t > 0
};

struct RayBox {
  static constexpr std::string_view id = "ray-box";
  static constexpr std::string_view summary = "Ray-box slab test, exact for zero and -0 direction components";
#define SW_LINES_RAY_BOX(X) \
  X(init, "t_near <- -inf; t_far <- +inf") \
  X(axis, "for each axis k:") \
  X(flat, "    if d_k = 0:                                -- parallel to the slab (+0 or -0)") \
  X(outside, "        if o_k < min_k or o_k > max_k: miss; else next axis") \
  X(slab, "    t1 <- (min_k - o_k) / d_k; t2 <- (max_k - o_k) / d_k") \
  X(order, "    if d_k < 0: swap t1, t2                    -- min_k <= max_k, so then t1 >= t2") \
  X(clip, "    t_near <- max(t_near, t1); t_far <- min(t_far, t2)") \
  X(empty, "if t_near > t_far: miss                        -- the slab intervals do not overlap") \
  X(exit, "if t_far <= 0: miss                            -- the box is behind") \
  X(hit, "hit: t <- t_near if t_near > 0, else t_far     -- origin inside: the exit point")
  SW_LISTING("Slab test", SW_LINES_RAY_BOX)
#undef SW_LINES_RAY_BOX
  // The algorithm itself, callable as RayBox{}(...): ray_box below.
  template <NumberType Num, StepProbe Probe>
  BoxHit<Num> operator()(const Ray3<Num>& r, const Vec3<Num>& lo, const Vec3<Num>& hi, Probe& probe) const;
};

template <NumberType Num, StepProbe Probe = NoProbe>
[[gnu::always_inline]] inline BoxHit<Num> ray_box(const Ray3<Num>& r, const Vec3<Num>& lo, const Vec3<Num>& hi, Probe& probe) {
  using L = RayBox;
  BoxHit<Num> out;
  if constexpr (Probe::on) probe.step(L::init, StepKind::init).ray(r.o, r.d).keep().box(lo, hi).keep();
  bool bounded = false;  // false while t_near and t_far are still -inf and +inf
  Num tn{}, tf{};
#pragma GCC unroll 3
  for (int k = 0; k < 3; ++k) {
    // One decision gives both the parallel case and the swap: min_k <= max_k, so the sign of d_k
    // orders t1 and t2, and the rounded quotients keep that order (rounding is monotonic).
    const int d_sign = num::sign(r.d[k]);
    if (d_sign == 0) {
      const bool out_of_slab = r.o[k] < lo[k] || r.o[k] > hi[k];
      if constexpr (Probe::on) probe.step(L::flat, StepKind::decide).idx("k", k).idx("out", out_of_slab);
      if (out_of_slab) {
        if constexpr (Probe::on) probe.step(L::outside, StepKind::miss);
        return out;
      }
      continue;
    }
    // The selections are branch-free (num::select): which way they go depends on the data.
    const Num ta = (lo[k] - r.o[k]) / r.d[k], tb = (hi[k] - r.o[k]) / r.d[k];
    const bool flip = d_sign < 0;
    const Num t1 = num::select(flip, tb, ta), t2 = num::select(flip, ta, tb);
    if (!bounded) {
      tn = t1, tf = t2, bounded = true;
    } else {
      tn = num::select(t1 > tn, t1, tn);
      tf = num::select(t2 < tf, t2, tf);
    }
    if constexpr (Probe::on) {
      static constexpr const char* slab[3] = {"x slab", "y slab", "z slab"};
      probe.step(L::clip, StepKind::advance)
          .idx("k", k)
          .num("t1", t1)
          .num("t2", t2)
          .num("t_near", tn)
          .num("t_far", tf)
          .segment(Vec3<Num>(r.o + t1 * r.d), Vec3<Num>(r.o + t2 * r.d))
          .label(slab[k])
          .keep()
          .segment(Vec3<Num>(r.o + tn * r.d), Vec3<Num>(r.o + tf * r.d))
          .label("[t_near, t_far]")
          .value(tf - tn)
          .replace();
    }
  }
  // d != 0, so some axis bounded the interval.
  out.t_near = tn, out.t_far = tf;
  const Num zero(0);
  const bool empty = tn > tf, behind = !(tf > zero);
  out.hit = !empty & !behind;
  out.t = num::select(tn > zero, tn, tf);
  if constexpr (Probe::on) {
    if (empty) probe.step(L::empty, StepKind::miss);
    else if (behind) probe.step(L::exit, StepKind::miss);
    else probe.step(L::hit, StepKind::hit).num("t", out.t).point(Vec3<Num>(r.o + out.t * r.d)).label("hit");
  }
  return out;
}

template <NumberType Num, StepProbe Probe>
[[gnu::always_inline]] inline BoxHit<Num> RayBox::operator()(const Ray3<Num>& r, const Vec3<Num>& lo, const Vec3<Num>& hi,
                                                             Probe& probe) const {
  return ray_box<Num>(r, lo, hi, probe);
}

}  // namespace sw::ray
