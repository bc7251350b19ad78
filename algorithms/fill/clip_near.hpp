// Clipping a clip-space (homogeneous) triangle against the plane w = w_near before anything is
// divided by w: Sutherland-Hodgman against one plane. What is kept is the convex polygon of the
// triangle's points with w >= w_near: nothing, a triangle, or a quadrilateral. The perspective
// fills (perspective_interp.hpp) run it first. Semantics: docs/fill/interpolation.md.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "fill/vary.hpp"

namespace sw::fill {

// The near plane w = w_near = 1. Screen positions are (x/w, y/w) in pixels, so w = 1 is where
// clip space and the screen coincide: what is kept projects into the box of its own clip x, y,
// and nothing is ever magnified (docs/fill/interpolation.md says why not a tiny epsilon).
inline constexpr std::int64_t kWNear = 1;
template <class Num> Num w_near() { return Num(kWNear); }

// A clip-space vertex: (x, y, z, w) and its n attribute values (n is the triangle's).
template <class Num> struct ClipVertex {
  std::array<Num, 4> c{};
  std::array<Num, kMaxAttrs> a{};
  Num w() const { return c[3]; }
};

template <class Num> struct ClipTriangle {
  std::array<ClipVertex<Num>, 3> v;
  std::size_t n = 0;  // attributes per vertex, 1..kMaxAttrs
};

// The kept polygon: k = 0, 3 or 4 corners, in the triangle's own cyclic order.
template <class Num> struct ClipPolygon {
  std::array<ClipVertex<Num>, 4> c;
  std::size_t k = 0;
};

// The point P + t (Q - P), attributes included: attributes are linear in clip space.
template <class Num> ClipVertex<Num> clip_lerp(const ClipVertex<Num>& p, const ClipVertex<Num>& q, const Num& t, std::size_t n) {
  ClipVertex<Num> r;
  for (int a = 0; a < 4; ++a) r.c[a] = p.c[a] + t * (q.c[a] - p.c[a]);
  for (std::size_t a = 0; a < n; ++a) r.a[a] = p.a[a] + t * (q.a[a] - p.a[a]);
  return r;
}

// Sutherland-Hodgman against w >= w_near, one step per edge and per kept corner. L names the
// listing lines clip_edge, clip_keep and clip_cut.
template <class L, NumberType Num, StepProbe Probe> ClipPolygon<Num> clip_near(const ClipTriangle<Num>& t, Probe& probe) {
  ClipPolygon<Num> out;
  const Num wn = w_near<Num>();
  // A kept corner's step: its clip coordinates, its attributes and where it lands on screen.
  [[maybe_unused]] auto corner = [&](auto& step, const ClipVertex<Num>& c, std::size_t k) {
    const Vec2<Num> s{c.c[0] / c.w(), c.c[1] / c.w()};
    step.idx("k", std::int64_t(k))
        .list("c", std::span<const Num>(c.c))
        .list("c_attrs", std::span<const Num>(c.a.data(), t.n))
        .point(s)
        .label("c")
        .keep();
  };
  for (std::size_t e = 0; e < 3; ++e) {
    const ClipVertex<Num>& p = t.v[e];
    const ClipVertex<Num>& q = t.v[(e + 1) % 3];
    const Num dp = p.w() - wn, dq = q.w() - wn;
    const bool keep = !(dp < Num(0));
    const bool cut = (dp < Num(0) && Num(0) < dq) || (Num(0) < dp && dq < Num(0));
    if constexpr (Probe::on)
      probe.step(L::clip_edge, StepKind::decide)
          .idx("P", std::int64_t(e))
          .num("d_P", dp)
          .num("d_Q", dq)
          .idx("keep", keep)
          .idx("cut", cut);
    if (keep) {
      out.c[out.k] = p;
      if constexpr (Probe::on) corner(probe.step(L::clip_keep, StepKind::visit), p, out.k);
      ++out.k;
    }
    if (cut) {
      const Num s = dp / (dp - dq);
      out.c[out.k] = clip_lerp(p, q, s, t.n);
      if constexpr (Probe::on) corner(probe.step(L::clip_cut, StepKind::init).num("t", s), out.c[out.k], out.k);
      ++out.k;
    }
  }
  return out;
}

}  // namespace sw::fill
