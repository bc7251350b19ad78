// A window-space triangle's samples and depth plane, shared by the pipeline's raster algorithms.
// Coverage is the fill family's (triangle-edge and its tie rule); GL interpolates window depth
// (z/w) linearly in x and y, so depth at a sample is the plane through the vertices' (x, y, z).
#pragma once
#include <algorithm>
#include <array>
#include <vector>
#include "core/vec.hpp"
#include "fill/triangle_edge.hpp"

namespace sw::pipe {

template <class Num> struct DepthPlane {
  Num area2{};   // twice the signed area on the screen; 0: no plane (and no sample covered)
  Num zx{}, zy{};  // dz/dx and dz/dy
  Vec3<Num> a;     // the first vertex, where the plane is anchored
  Num at(const Num& x, const Num& y) const { return Num(a.z + zx * (x - a.x) + zy * (y - a.y)); }
};

// Precondition for zx, zy: area2 != 0 (they are left 0 otherwise).
template <class Num> DepthPlane<Num> depth_plane(const std::array<Vec3<Num>, 3>& v) {
  const Vec3<Num>&a = v[0], &b = v[1], &c = v[2];
  DepthPlane<Num> p;
  p.a = a;
  p.area2 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (p.area2 == Num(0)) return p;
  // Cramer's rule on z_b - z_a and z_c - z_a.
  p.zx = ((b.z - a.z) * (c.y - a.y) - (c.z - a.z) * (b.y - a.y)) / p.area2;
  p.zy = ((c.z - a.z) * (b.x - a.x) - (b.z - a.z) * (c.x - a.x)) / p.area2;
  return p;
}

// glPolygonOffset's o = factor max(|zx|, |zy|) + units r for a plane (r: the depth's resolvable step).
template <class Num> Num polygon_offset(const DepthPlane<Num>& p, const Num& factor, const Num& units, const Num& r) {
  return Num(factor * std::max(num::abs(p.zx), num::abs(p.zy)) + units * r);
}

// The samples triangle-edge covers in a width x height window, in its order (rows bottom up),
// into out (cleared first: a z-buffer reuses one vector for all its triangles).
template <class Num> void covered_samples(const std::array<Vec3<Num>, 3>& v, std::int64_t width, std::int64_t height, std::vector<Pixel>& out) {
  out.clear();
  NoProbe quiet;
  const std::array<Vec2<Num>, 3> xy{Vec2<Num>{v[0].x, v[0].y}, Vec2<Num>{v[1].x, v[1].y}, Vec2<Num>{v[2].x, v[2].y}};
  fill::triangle_edge<Num>(fill::EdgeTriangle<Num>{xy, Num(1), fill::SampleBox{0, width - 1, 0, height - 1}}, out, quiet);
}
template <class Num> std::vector<Pixel> covered_samples(const std::array<Vec3<Num>, 3>& v, std::int64_t width, std::int64_t height) {
  std::vector<Pixel> out;
  covered_samples(v, width, height, out);
  return out;
}

}  // namespace sw::pipe
