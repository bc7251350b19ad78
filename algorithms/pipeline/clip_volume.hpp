// Clipping a clip-space triangle to the view volume before the divide: Sutherland-Hodgman in
// homogeneous coordinates, against the near plane (z + w >= 0) and the four sides (|x|, |y| <= w).
// The far plane is at infinity (scene-raster's projection), so nothing beyond the near plane is
// cut away. Corners may be points at infinity (w = 0 in the world: a plane drawn to its horizon);
// a cut between two corners is their linear blend in clip space, which is the segment between
// them however far they are. Every kept corner satisfies the five inequalities, and that forces
// w > 0 (x = y = w = 0 only at the zero vector), so the divide is defined, and the kept polygon
// projects inside the viewport: no window coordinate grows beyond it.
// Semantics: docs/pipeline/semantics.md#scene-raster.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>
#include "core/probe.hpp"
#include "pipeline/camera.hpp"

namespace sw::pipe {

inline constexpr int kClipPlanes = 5;
inline constexpr int kMaxClipCorners = 3 + kClipPlanes;  // each plane adds at most one corner to a convex polygon

// A kept corner, and what the edge from it to the next corner lies on: the triangle's edge
// (0, 1, 2: from its corner k to k + 1) or a clip plane (-1). Coverage ties matter only on the
// triangle's own edges; the others are shared with a neighbour cut from the same triangle.
template <class Num> struct ClipCorner {
  Vec4<Num> c;
  int edge = -1;
};
template <class Num> struct ClippedPolygon {
  std::array<ClipCorner<Num>, kMaxClipCorners> v{};
  int k = 0;  // 0 (nothing kept) or 3 to kMaxClipCorners corners, in the triangle's cyclic order
};

inline constexpr const char* kClipPlaneNames[kClipPlanes] = {"near", "left", "right", "bottom", "top"};

// The signed distance of c from clip plane p, >= 0 inside.
template <class Num> Num clip_distance(int p, const Vec4<Num>& c) {
  switch (p) {
    case 0: return c.z + c.w;
    case 1: return c.x + c.w;
    case 2: return c.w - c.x;
    case 3: return c.y + c.w;
    default: return c.w - c.y;
  }
}

struct ClipVolume {
  static constexpr std::string_view id = "clip-volume";
  static constexpr std::string_view summary = "Clip a clip-space triangle to the view volume (near plane and four sides) before the divide";
#define SW_PIPELINE_CLIP_VOLUME(X) \
  X(plane, "for each plane p of near (z + w), left (x + w), right (w - x), bottom (y + w), top (w - y):") \
  X(edge, "    for each edge P -> Q of the polygon: dP <- p(P), dQ <- p(Q)      -- >= 0 inside") \
  X(keep, "        if dP >= 0: keep P") \
  X(cut, "        if dP, dQ have strictly opposite signs: keep P + dP/(dP - dQ) (Q - P)   -- on the plane") \
  X(empty, "    if fewer than 3 corners are left: nothing is kept; stop") \
  X(done, "the kept polygon: 3 to 8 corners, each with w > 0")
  SW_LISTING("Clip to the view volume", SW_PIPELINE_CLIP_VOLUME)
#undef SW_PIPELINE_CLIP_VOLUME
};

// first_plane > 0 skips the planes before it (1: the four sides only, the view pyramid from the eye).
template <NumberType Num, StepProbe Probe = NoProbe>
ClippedPolygon<Num> clip_volume(const std::array<Vec4<Num>, 3>& tri, Probe& probe, int first_plane = 0) {
  using L = ClipVolume;
  ClippedPolygon<Num> poly;
  for (int k = 0; k < 3; ++k) poly.v[k] = {tri[k], k};
  poly.k = 3;
  for (int p = first_plane; p < kClipPlanes; ++p) {
    if constexpr (Probe::on) probe.step(L::plane, StepKind::visit).idx("p", p);
    ClippedPolygon<Num> out;
    for (int e = 0; e < poly.k; ++e) {  // bounded: at most kMaxClipCorners edges
      const ClipCorner<Num>& P = poly.v[e];
      const ClipCorner<Num>& Q = poly.v[(e + 1) % poly.k];
      const Num dp = clip_distance(p, P.c), dq = clip_distance(p, Q.c);
      const bool keep = !(dp < Num(0));
      const bool cut = (dp < Num(0) && Num(0) < dq) || (Num(0) < dp && dq < Num(0));
      if constexpr (Probe::on) probe.step(L::edge, StepKind::decide).idx("e", e).num("dP", dp).num("dQ", dq).idx("keep", keep).idx("cut", cut);
      if (keep) {
        // P's outgoing edge is (part of) its old one, unless P lies on the plane and Q outside:
        // then the polygon follows the plane from P to where it enters again.
        out.v[out.k++] = {P.c, dq < Num(0) && !cut ? -1 : P.edge};
        if constexpr (Probe::on) {
          const std::array<Num, 4> cs{P.c.x, P.c.y, P.c.z, P.c.w};
          probe.step(L::keep, StepKind::advance).list("c", std::span<const Num>(cs));
        }
      }
      if (cut) {
        const Num s = dp / (dp - dq);
        const Vec4<Num> c{Num(P.c.x + s * (Q.c.x - P.c.x)), Num(P.c.y + s * (Q.c.y - P.c.y)), Num(P.c.z + s * (Q.c.z - P.c.z)),
                          Num(P.c.w + s * (Q.c.w - P.c.w))};
        // Entering (dP < 0): the new corner continues P's edge toward Q. Leaving: the polygon
        // follows the plane from here to where it enters again.
        out.v[out.k++] = {c, dp < Num(0) ? P.edge : -1};
        if constexpr (Probe::on) {
          const std::array<Num, 4> cs{c.x, c.y, c.z, c.w};
          probe.step(L::cut, StepKind::advance).num("s", s).list("c", std::span<const Num>(cs));
        }
      }
    }
    if (out.k < 3) {
      if constexpr (Probe::on) probe.step(L::empty, StepKind::miss).idx("corners", out.k);
      return {};
    }
    poly = out;
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("corners", poly.k);
  return poly;
}

}  // namespace sw::pipe
