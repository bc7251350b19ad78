// The exact specification of perspective-interp and affine-interp (docs/fill/interpolation.md), by
// brute force: the covered samples of the projected, clipped triangle (fill_oracle's exact
// orientation predicates), and at each the attribute values. Perspective: the clip-space
// barycentric coordinates of the ray through the sample, from a 3x3 rational linear system, so
// neither the clipping nor any interpolation on screen enters the values. Affine: the plane
// through the projected corners' attributes of the fan triangle that covers the sample.
#pragma once
#include <array>
#include <vector>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::oracle {

using ClipPoint = std::array<Rational, 4>;  // x, y, z, w

struct InterpSamples {
  std::vector<Pixel> pixels;    // scanline order
  std::vector<Rational> values; // n per pixel
};

// The polygon of the triangle's points with w >= w_near, in the triangle's cyclic order (0, 3 or
// 4 corners), with the attributes (n per corner) interpolated along the edges it cuts.
struct ClippedPolygon {
  std::vector<ClipPoint> corners;
  std::vector<std::vector<Rational>> attrs;
};
ClippedPolygon clip_w(const std::array<ClipPoint, 3>& v, const std::array<std::vector<Rational>, 3>& attrs, const Rational& w_near);

// The corners' screen positions (x/w, y/w). Precondition: every w > 0.
std::vector<Vec2<Rational>> project(const std::vector<ClipPoint>& corners);

// perspective-interp's result: covered samples and the perspective-correct attributes there.
InterpSamples perspective_samples(const std::array<ClipPoint, 3>& v, const std::array<std::vector<Rational>, 3>& attrs, const Rational& w_near);

// affine-interp's result: the same samples, and the attributes linear on screen over each fan
// triangle (c_0, c_1, c_2), (c_0, c_2, c_3) of the clipped polygon.
InterpSamples affine_samples(const std::array<ClipPoint, 3>& v, const std::array<std::vector<Rational>, 3>& attrs, const Rational& w_near);

// The perspective-correct value of f (one value per vertex) at screen point s: the barycentric
// coordinates b of the clip-space point on the triangle's plane that projects to s, sum b_k f_k.
// Precondition: the vertices (x, y, w) are linearly independent.
Rational perspective_at(const std::array<ClipPoint, 3>& v, const std::array<Rational, 3>& f, const Vec2<Rational>& s);

}  // namespace sw::oracle
