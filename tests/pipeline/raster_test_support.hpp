// Shared by the scene-raster tests: the brute-force clip, an exact statement of clip-volume's result
// that shares no code with it.
#pragma once
#include <algorithm>
#include <array>
#include <vector>
#include "pipeline/camera.hpp"

namespace sw::testing::raster {

using V4 = pipe::Vec4<Rational>;

inline bool same(const V4& a, const V4& b) { return a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w; }

// Distance from clip plane p, >= 0 inside: near, left, right, bottom, top, written out here.
inline Rational plane_distance(int p, const V4& v) {
  const Rational d[5] = {v.z + v.w, v.x + v.w, v.w - v.x, v.y + v.w, v.w - v.y};
  return d[p];
}

// The view volume's part of a clip-space triangle, planes [first, 5), by brute force: the points
// sum_k l_k c_k with l >= 0, l_0 + l_1 + l_2 = 1, inside the planes, are a polygon in (l_1, l_2);
// its corners are where two of the boundary lines meet inside all of them. Empty below 3 corners.
inline std::vector<V4> brute_clip(const std::array<V4, 3>& c, int first = 0) {
  std::vector<std::array<Rational, 3>> h{{0, 1, 0}, {0, 0, 1}, {1, -1, -1}};  // each a0 + a1 l1 + a2 l2 >= 0
  for (int p = first; p < 5; ++p) {
    const Rational d0 = plane_distance(p, c[0]);
    h.push_back({d0, plane_distance(p, c[1]) - d0, plane_distance(p, c[2]) - d0});
  }
  std::vector<V4> out;
  for (std::size_t a = 0; a < h.size(); ++a)
    for (std::size_t b = a + 1; b < h.size(); ++b) {
      const Rational det = h[a][1] * h[b][2] - h[a][2] * h[b][1];
      if (det == 0) continue;
      const Rational l1 = (h[b][0] * h[a][2] - h[a][0] * h[b][2]) / det, l2 = (h[a][0] * h[b][1] - h[b][0] * h[a][1]) / det;
      bool in = true;
      for (const auto& x : h) in = in && x[0] + x[1] * l1 + x[2] * l2 >= 0;
      const Rational l0 = 1 - l1 - l2;
      const V4 v{l0 * c[0].x + l1 * c[1].x + l2 * c[2].x, l0 * c[0].y + l1 * c[1].y + l2 * c[2].y, l0 * c[0].z + l1 * c[1].z + l2 * c[2].z,
                 l0 * c[0].w + l1 * c[1].w + l2 * c[2].w};
      if (in && std::none_of(out.begin(), out.end(), [&](const V4& o) { return same(o, v); })) out.push_back(v);
    }
  if (out.size() < 3) out.clear();
  return out;
}

}  // namespace sw::testing::raster
