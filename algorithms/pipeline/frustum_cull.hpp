// View-frustum culling of bounding volumes (spheres, axis-aligned and oriented boxes) against the
// six planes of the view volume, read off the rows of the world-to-clip matrix (Gribb and
// Hartmann's method). A volume entirely outside one plane is culled: conservative, it never culls
// a visible object, but it keeps some invisible ones near the volume's edges and corners. The
// sphere's test compares squares, so no square root enters it (docs/pipeline/semantics.md).
#pragma once
#include <array>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "pipeline/camera.hpp"

namespace sw::pipe {

// A bounding volume: a sphere (centre, radius), an axis-aligned box (min, max) or an oriented box
// (centre and three mutually orthogonal half-extent vectors).
template <class Num> struct Bounds {
  enum class Kind : std::uint8_t { sphere, aabb, obb } kind = Kind::sphere;
  Vec3<Num> c, lo, hi;      // sphere and obb: c; aabb: lo, hi
  Num r{};                  // sphere
  std::array<Vec3<Num>, 3> h;  // obb
};

// A plane a.x + d = 0; its positive side a.x + d > 0 faces into the view volume.
template <class Num> struct Plane4 {
  Vec3<Num> a;
  Num d{};
  Num at(const Vec3<Num>& x) const { return Num(dot(a, x) + d); }
};

enum class Cull : std::uint8_t { outside, straddles, inside };

struct FrustumCull {
  static constexpr std::string_view id = "frustum-cull";
  static constexpr std::string_view summary = "View-frustum culling of spheres, AABBs and OBBs against the six planes";
#define SW_LINES_FRUSTUM_CULL(X) \
  X(planes, "C <- P V; planes (a, d): C4+C1, C4-C1, C4+C2, C4-C2, C4+C3, C4-C3  -- a.x + d >= 0 inside (left ... far)") \
  X(object, "for each bounding volume: state <- inside") \
  X(sphere, "sphere (c, r), plane k: s <- a.c + d; outside if s < 0 and s^2 > r^2 |a|^2; inside if s >= 0 and s^2 >= r^2 |a|^2") \
  X(aabb, "box [lo, hi], plane k: c <- (lo + hi)/2, e <- (hi - lo)/2; rho <- |a.x| e.x + |a.y| e.y + |a.z| e.z; s <- a.c + d; outside if s < -rho; inside if s >= rho") \
  X(obb, "oriented box (c, h1, h2, h3), plane k: rho <- |a.h1| + |a.h2| + |a.h3|; s <- a.c + d; outside if s < -rho; inside if s >= rho") \
  X(culled, "outside one plane: culled, never visible") \
  X(kept, "kept: inside every plane, or straddling some (then maybe still invisible)")
  SW_LISTING("View-frustum culling", SW_LINES_FRUSTUM_CULL)
#undef SW_LINES_FRUSTUM_CULL
};

// The six planes, in the order left, right, bottom, top, near, far.
template <class Num> std::array<Plane4<Num>, 6> frustum_planes(const Mat4<Num>& C) {
  std::array<Plane4<Num>, 6> out;
  for (int k = 0; k < 6; ++k) {
    const Num sign = k % 2 == 0 ? Num(1) : Num(-1);
    const auto& row = C[k / 2];
    out[k] = {{Num(C[3][0] + sign * row[0]), Num(C[3][1] + sign * row[1]), Num(C[3][2] + sign * row[2])}, Num(C[3][3] + sign * row[3])};
  }
  return out;
}

// An axis-aligned box's half-extents as three vectors along the axes.
template <class Num> std::array<Vec3<Num>, 3> axis_halves(const Bounds<Num>& b) {
  const Vec3<Num> e = Num(Num(1) / Num(2)) * Vec3<Num>(b.hi - b.lo);
  return {Vec3<Num>{e.x, Num(0), Num(0)}, Vec3<Num>{Num(0), e.y, Num(0)}, Vec3<Num>{Num(0), Num(0), e.z}};
}

// Corner k of an oriented box: c + h_a where bit a of k is set, c - h_a where it is not.
template <class Num> Vec3<Num> obb_corner(const Bounds<Num>& b, int k) {
  Vec3<Num> p = b.c;
  for (int a = 0; a < 3; ++a) p = k >> a & 1 ? Vec3<Num>(p + b.h[a]) : Vec3<Num>(p - b.h[a]);
  return p;
}

template <NumberType Num, StepProbe Probe = NoProbe>
std::vector<Cull> frustum_cull(const Camera<Num>& cam, const std::vector<Bounds<Num>>& objects, Probe& probe) {
  using L = FrustumCull;
  using K = typename Bounds<Num>::Kind;
  const Frame<Num> fr = look_frame(cam.look);
  const auto planes = frustum_planes(product(projection_matrix(cam.proj), view_matrix(fr, cam.look.eye)));
  if constexpr (Probe::on) {
    auto& s = probe.step(L::planes, StepKind::init);
    const auto corner = frustum_corners(cam, fr);
    for (const auto& e : kFrustumEdges) {  // one label for the twelve edges keeps the view legible
      s.segment(corner[e[0]], corner[e[1]]).keep();
      if (&e == &kFrustumEdges[0]) s.label("frustum");
    }
  }
  using num::abs;  // with an Interval's own abs (found by argument-dependent lookup), which decides nothing
  std::vector<Cull> out(objects.size(), Cull::inside);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const Bounds<Num>& b = objects[i];
    Cull& state = out[i];
    if constexpr (Probe::on) {
      auto& s = probe.step(L::object, StepKind::advance).idx("i", std::int64_t(i));
      if (b.kind == K::sphere) s.sphere(b.c, b.r).label("sphere").keep();
      else if (b.kind == K::aabb) s.box(b.lo, b.hi).label("box").keep();
      else
        for (int k = 0; k < 8; ++k)  // its 12 edges: corners c +- h1 +- h2 +- h3 one sign apart
          for (int a = 0; a < 3; ++a)
            if (!(k >> a & 1)) {
              s.segment(obb_corner(b, k), obb_corner(b, k | 1 << a)).keep();
              if (k == 0 && a == 0) s.label("box");
            }
    }
    for (int k = 0; k < 6 && state != Cull::outside; ++k) {
      const Plane4<Num>& p = planes[k];
      bool outside = false, straddles = false;
      if (b.kind == K::sphere) {
        const Num s = p.at(b.c), s2 = s * s, r2a2 = b.r * b.r * dot(p.a, p.a);
        outside = s < Num(0) && r2a2 < s2;
        straddles = !(Num(0) <= s && r2a2 <= s2);  // not wholly on the inner side (a touch from outside straddles)
        if constexpr (Probe::on) probe.step(L::sphere, StepKind::decide).idx("k", k).num("s", s).num("r^2|a|^2", r2a2);
      } else {
        // A box by its centre and half-extents (an AABB's along the axes): its corner farthest
        // along a lies rho beyond the centre, and its nearest rho before it.
        const std::array<Vec3<Num>, 3> h = b.kind == K::obb ? b.h : axis_halves(b);
        const Vec3<Num> c = b.kind == K::obb ? b.c : Vec3<Num>(Num(Num(1) / Num(2)) * Vec3<Num>(b.lo + b.hi));
        const Num rho = Num(abs(dot(p.a, h[0])) + abs(dot(p.a, h[1])) + abs(dot(p.a, h[2]))), s = p.at(c);
        outside = s < Num(-rho);
        straddles = s < rho;
        if constexpr (Probe::on) probe.step(b.kind == K::obb ? L::obb : L::aabb, StepKind::decide).idx("k", k).num("s", s).num("rho", rho);
      }
      if (outside) state = Cull::outside;
      else if (straddles) state = Cull::straddles;
    }
    if constexpr (Probe::on) {
      if (state == Cull::outside) probe.step(L::culled, StepKind::miss).idx("culled", 1);
      else probe.step(L::kept, StepKind::hit).idx("culled", 0).idx("straddles", state == Cull::straddles);
    }
  }
  return out;
}

}  // namespace sw::pipe
