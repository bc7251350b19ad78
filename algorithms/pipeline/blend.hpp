// Blending transparent triangles, in the order given and in painter's order (sorted far to near),
// through a depth buffer: GL's blend equation with glBlendFunc(GL_SRC_ALPHA,
// GL_ONE_MINUS_SRC_ALPHA), C = a_s C_s + (1 - a_s) C_d. The over operator does not commute, so
// the two orders give different pictures where transparent triangles overlap; with depth writes on,
// the given order also loses far fragments drawn after near ones (docs/pipeline/semantics.md).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "pipeline/depth_plane.hpp"

namespace sw::pipe {

template <class Num> struct BlendTriangle {
  std::array<Vec3<Num>, 3> v;  // window x, y and depth z in [0, 1]
  Vec3<Num> rgb;
  Num alpha{};
};

template <class Num> struct BlendImage {
  std::vector<Vec3<Num>> colour;  // row j at j * width
  std::int64_t fragments = 0, blended = 0;
};

struct Blend {
  static constexpr std::string_view id = "blend";
  static constexpr std::string_view summary = "Blending: GL's over operator in the given order and in painter's order, through a depth buffer";
#define SW_LINES_BLEND(X) \
  X(pass, "for each order (as given; then painter's): colour[all] <- background; depth[all] <- 1") \
  X(sort, "painter's order: sort far to near by the centroid's depth (z_a + z_b + z_c)/3, ties in the given order") \
  X(triangle, "for each triangle t in the order: its depth plane z(x, y) and the samples triangle-edge covers") \
  X(test, "for each sample (i, j): z <- z(i, j); pass <- z < depth[i, j]          -- GL_LESS") \
  X(blend, "if pass: colour[i, j] <- a_t C_t + (1 - a_t) colour[i, j]             -- GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA") \
  X(write, "    if depth writes are on: depth[i, j] <- z                            -- glDepthMask") \
  X(compare, "differ <- the pixels whose colours the two orders leave different")
  SW_LISTING("Blending", SW_LINES_BLEND)
#undef SW_LINES_BLEND
};

// The picture of `tris` drawn in `order` over `background`.
template <NumberType Num, StepProbe Probe>
BlendImage<Num> blend_pass(std::int64_t width, std::int64_t height, const std::vector<BlendTriangle<Num>>& tris,
                           const std::vector<std::size_t>& order, const Vec3<Num>& background, bool depth_write, Probe& probe) {
  using L = Blend;
  BlendImage<Num> img{std::vector<Vec3<Num>>(width * height, background)};
  std::vector<Num> depth(width * height, Num(1));
  for (std::size_t t : order) {
    const BlendTriangle<Num>& tri = tris[t];
    const DepthPlane<Num> plane = depth_plane(tri.v);
    if constexpr (Probe::on) probe.step(L::triangle, StepKind::advance).idx("t", std::int64_t(t)).num("alpha", tri.alpha).colour("C_t", tri.rgb);
    if (plane.area2 == Num(0)) continue;  // covers no sample
    for (const Pixel& s : covered_samples(tri.v, width, height)) {
      const std::size_t k = static_cast<std::size_t>(s.y * width + s.x);
      const Num z = plane.at(Num(s.x), Num(s.y));
      const bool pass = z < depth[k];
      ++img.fragments;
      if constexpr (Probe::on) probe.step(L::test, StepKind::decide).idx("i", s.x).idx("j", s.y).num("z", z).num("depth", depth[k]).idx("pass", pass);
      if (!pass) continue;
      img.colour[k] = Vec3<Num>(tri.alpha * tri.rgb) + Vec3<Num>(Num(Num(1) - tri.alpha) * img.colour[k]);
      ++img.blended;
      if constexpr (Probe::on) probe.step(L::blend, StepKind::plot).colour("colour", img.colour[k]).pixel(s);
      if (depth_write) {
        depth[k] = z;
        if constexpr (Probe::on) probe.step(L::write, StepKind::advance).num("depth", z);
      }
    }
  }
  return img;
}

template <class Num> struct BlendResult {
  BlendImage<Num> given, sorted;
  std::vector<std::size_t> painter;  // the sorted order
  std::int64_t differ = 0;
};

template <NumberType Num, StepProbe Probe = NoProbe>
BlendResult<Num> blend(std::int64_t width, std::int64_t height, const std::vector<BlendTriangle<Num>>& tris, const Vec3<Num>& background,
                       bool depth_write, Probe& probe) {
  using L = Blend;
  BlendResult<Num> out;
  std::vector<std::size_t> given(tris.size());
  std::iota(given.begin(), given.end(), std::size_t(0));
  if constexpr (Probe::on) probe.step(L::pass, StepKind::init).idx("order", 0);
  out.given = blend_pass(width, height, tris, given, background, depth_write, probe);
  out.painter = given;
  auto centroid = [&](std::size_t t) { return Num(tris[t].v[0].z + tris[t].v[1].z + tris[t].v[2].z); };
  std::stable_sort(out.painter.begin(), out.painter.end(), [&](std::size_t a, std::size_t b) { return centroid(b) < centroid(a); });
  if constexpr (Probe::on) {
    probe.step(L::pass, StepKind::init).idx("order", 1);
    std::vector<std::int64_t> order(out.painter.begin(), out.painter.end());
    probe.step(L::sort, StepKind::decide).ilist("painter", std::span<const std::int64_t>(order));  // at most 64 (kMaxListLength)
  }
  out.sorted = blend_pass(width, height, tris, out.painter, background, depth_write, probe);
  for (std::size_t k = 0; k < out.given.colour.size(); ++k) out.differ += !(out.given.colour[k] == out.sorted.colour[k]);
  if constexpr (Probe::on) probe.step(L::compare, StepKind::done).idx("differ", out.differ);
  return out;
}

}  // namespace sw::pipe
