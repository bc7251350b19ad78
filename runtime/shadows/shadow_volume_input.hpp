// shadow-volume's input, parsed once: the rasterized scene, one light, z-pass or z-fail, the
// scene's corners shared exactly (so that the silhouette is found), and the points the eye sees
// with their exact visibility (shadow-map's, map_input). The oracle counts, for each pixel's
// exact point, the casters whose open volume holds it, by segment-triangle tests in rationals.
// JSON: {"scene": ..., "size": [w, h], "stacks": n, "light": i, "method": "zfail" | "zpass"}
// Semantics: docs/shadows/semantics.md#shadow-volume.
#pragma once
#include <memory>
#include <vector>
#include "shadows/shadow_map_input.hpp"
#include "shadows/shadow_volume.hpp"

namespace sw::shadowspec {

struct VolumeInput {
  std::shared_ptr<const MapInput> seen;  // the scene, the light, the seen points and whether the light reaches each
  bool zfail = true;
  shadow::VolumeMesh<Rational> mesh;
  pipe::Vec4<Rational> light;  // w = 1 a point or spot light, w = 0 toward a directional one
};
struct VolumeInputRef {
  std::shared_ptr<const VolumeInput> p;
};
std::shared_ptr<const VolumeInput> volume_input(std::shared_ptr<const MapInput> seen, bool zfail);
// The scene's triangles over its corners, each corner once (exact), closed where a sphere's or a box's.
shadow::VolumeMesh<Rational> volume_mesh(const RasterScene& s);
// Light i as a homogeneous point: (position, 1), or (toward the light, 0) for a directional one.
pipe::Vec4<Rational> homogeneous_light(const RasterScene& s, std::size_t light);
VolumeInputRef parse_volume_input(const Json& j);

// Per pixel, row 0 at the top: the chosen count's verdict (-1: no surface, 0 shadowed, 1 lit), the
// exact visibility (-1, 0, 1), and both counts. Over the points whose surface faces the light:
// wrong_pass and wrong_fail count those where z-pass's and z-fail's verdicts differ from exact
// visibility; away, the points facing away.
struct VolumePixels {
  std::int64_t width = 0, height = 0;
  std::vector<int> lit, visible;
  std::vector<std::int64_t> zpass, zfail;
  std::int64_t wrong_pass = 0, wrong_fail = 0, away = 0;
  std::int64_t casters = 0, silhouette = 0, faces = 0, fragments = 0;
};
// The counts of the seen points' pixels (the rest stay 0) and the verdicts.
VolumePixels volume_pixels(const VolumeInput& in, std::vector<std::int64_t> zpass_top, std::vector<std::int64_t> zfail_top);
template <class Num> VolumePixels stencil_pixels(const VolumeInput& in, const shadow::StencilImage<Num>& img) {
  const std::int64_t w = in.seen->scene->width, h = in.seen->scene->height;
  std::vector<std::int64_t> p(std::size_t(w * h)), f(std::size_t(w * h));
  for (std::int64_t j = 0; j < h; ++j)
    for (std::int64_t i = 0; i < w; ++i) {  // rows bottom up to rows top down
      p[std::size_t(j * w + i)] = img.zpass[std::size_t((h - 1 - j) * w + i)], f[std::size_t(j * w + i)] = img.zfail[std::size_t((h - 1 - j) * w + i)];
    }
  VolumePixels o = volume_pixels(in, std::move(p), std::move(f));
  o.casters = img.casters, o.silhouette = img.silhouette, o.faces = img.faces, o.fragments = img.fragments;
  return o;
}
template <class Num> shadow::VolumeMesh<Num> mesh_in(const shadow::VolumeMesh<Rational>& m) {
  shadow::VolumeMesh<Num> out{{}, m.tris, m.closed};
  for (const auto& c : m.corners) out.corners.push_back({num::from_rational<Num>(c.x), num::from_rational<Num>(c.y), num::from_rational<Num>(c.z), num::from_rational<Num>(c.w)});
  return out;
}
// Drawn untraced in mode n (filtered: intervals, else exact rationals; fell_back says so).
VolumePixels stenciled(const VolumeInput& in, Numeric n, bool* fell_back = nullptr);
// The closed form: per pixel's exact point P, zfail = the casters whose open volume holds P just
// before it on the eye's ray, zpass = that less those holding the ray's start on the near plane.
VolumePixels volume_oracle(const VolumeInput& in);
Json volume_json(const VolumePixels& p);
std::size_t volume_steps(const VolumeInput& in);
std::vector<BenchSet<VolumeInputRef>> volume_sets();

}  // namespace sw::shadowspec
