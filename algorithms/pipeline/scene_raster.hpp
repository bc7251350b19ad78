// A scene drawn by rasterization, GL's way: every triangle through one matrix to clip space,
// clipped to the view volume (clip-volume), divided, mapped to the window and fanned into
// triangles, then drawn through the z-buffer (z-buffer) with GL_LESS in the scene's order.
// The camera is the ray tracer's: its frame B = [u v n] (u right, v up, n toward the eye) is
// inverted, not transposed, so that for any basis the eye-space direction of the tracer's ray
// through image point (wu, wv) is exactly (wu, wv, -d). In exact arithmetic a pixel centre then
// sees through this projection what the tracer's ray through it meets: the visibility identity
// (docs/pipeline/semantics.md#scene-raster).
#pragma once
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "pipeline/camera.hpp"
#include "pipeline/clip_volume.hpp"
#include "pipeline/z_buffer.hpp"

namespace sw::pipe {

// Preconditions: u, v, n independent; window[0] < window[1], window[2] < window[3]; 0 < near;
// orthographic: near < far.
template <class Num> struct RasterCamera {
  Vec3<Num> eye, u, v, n;
  Num dist{};                 // the view plane's distance d
  std::array<Num, 4> window{};  // [umin, umax, vmin, vmax] on the view plane (orthographic: in eye space)
  Num near{};                 // the near plane's eye depth
  std::int64_t width = 1, height = 1;
  // glOrtho instead of the perspective (a directional light's view), depth linear from near to
  // far; eye may then lie anywhere on the light's side, and depth may be negative.
  bool orthographic = false;
  Num far{};
};

// World corners, homogeneous: w = 1, or w = 0 for a point at infinity (a plane's wedge).
template <class Num> struct RasterTriangle {
  std::array<Vec4<Num>, 3> x;
  std::int32_t object = 0, prim = 0;  // the scene object and its triangle
};

template <class Num> struct RasterImage {
  DepthBuffer<Num> buffer;                         // rows bottom up (GL's); ids index `drawn`
  std::vector<std::array<std::int32_t, 2>> drawn;  // per window triangle: its object and prim
  std::int64_t culled = 0, cut = 0;                // triangles with nothing in the view volume; triangles the clip cut
};

struct SceneRaster {
  static constexpr std::string_view id = "scene-raster";
  static constexpr std::string_view summary = "A ray-tracer scene rasterized: clip-space transform, clipping, divide, viewport, z-buffer";
#define SW_PIPELINE_SCENE_RASTER(X) \
  X(view, "V <- (B^-1, -B^-1 eye), B = [u v n] the camera's frame          -- eye space: right, up, toward the eye") \
  X(project, "P <- glFrustum(the view-plane window scaled to the near plane n), far plane at infinity (glOrtho: near to far); M <- P V") \
  X(corners, "for each triangle of the objects, in id order: c_k <- M x_k      -- x_k homogeneous: w = 0 at infinity") \
  X(clip, "    K <- clip-volume(c_0, c_1, c_2); if nothing is kept: next triangle") \
  X(divide, "    each corner of K: (x, y, depth) <- viewport((c_x, c_y, c_z)/c_w)   -- sample (i, j) is GL's pixel centre") \
  X(fan, "    fan K into window triangles (K_0, K_i, K_i+1), each drawn as the triangle's object") \
  X(draw, "z-buffer(every window triangle in order; GL_LESS, clear depth 1)") \
  X(done, "each pixel shows the object of the fragment that passed last there, or none")
  SW_LISTING("Scene rasterizer", SW_PIPELINE_SCENE_RASTER)
#undef SW_PIPELINE_SCENE_RASTER
};

// The world-to-clip matrix M = P V of the camera.
template <class Num> Mat4<Num> raster_matrix(const RasterCamera<Num>& c) {
  // B^-1 by rows: (v x n, n x u, u x v) / det B.
  const Num det = dot(c.u, cross(c.v, c.n));
  const std::array<Vec3<Num>, 3> rows{(Num(1) / det) * cross(c.v, c.n), (Num(1) / det) * cross(c.n, c.u), (Num(1) / det) * cross(c.u, c.v)};
  Mat4<Num> V = identity<Num>();
  for (int k = 0; k < 3; ++k) V[k] = {rows[k].x, rows[k].y, rows[k].z, Num(-dot(rows[k], c.eye))};
  if (c.orthographic) return product(projection_matrix(Projection<Num>{false, c.window[0], c.window[1], c.window[2], c.window[3], c.near, c.far}), V);
  const Num s = c.near / c.dist;
  return product(infinite_projection_matrix(Num(c.window[0] * s), Num(c.window[1] * s), Num(c.window[2] * s), Num(c.window[3] * s), c.near), V);
}

// The camera's viewport: it puts sample (i, j), GL's pixel centre (i + 1/2, j + 1/2), at the
// point (i, j), with depth in [0, 1].
template <class Num> Viewport<Num> raster_viewport(const RasterCamera<Num>& c) {
  const Num half = Num(1) / Num(2);
  return {Num(-half), Num(-half), Num(c.width), Num(c.height), Num(0), Num(1)};
}

// A clipped polygon's corners divided and mapped to the window (its corners have w > 0).
template <class Num> std::array<Vec3<Num>, kMaxClipCorners> window_corners(const Viewport<Num>& vp, const ClippedPolygon<Num>& K) {
  std::array<Vec3<Num>, kMaxClipCorners> w;
  for (int k = 0; k < K.k; ++k) {
    const Vec4<Num>& q = K.v[k].c;
    w[k] = to_window(vp, Vec3<Num>{Num(q.x / q.w), Num(q.y / q.w), Num(q.z / q.w)});
  }
  return w;
}

// offset: glPolygonOffset(factor, units) on every triangle; bits: the depth buffer's (0: depth in
// Num). A shadow map's pass sets them; a picture draws with neither.
template <class Num> struct DepthSettings {
  Num factor{}, units{};
  int bits = 0;
};

template <NumberType Num, StepProbe Probe = NoProbe>
RasterImage<Num> scene_raster(const RasterCamera<Num>& cam, const std::vector<RasterTriangle<Num>>& tris, Probe& probe,
                              const DepthSettings<Num>& depth = {}) {
  using L = SceneRaster;
  const Mat4<Num> M = raster_matrix(cam);
  if constexpr (Probe::on) {
    probe.step(L::view, StepKind::init).vec("u", cam.u).vec("v", cam.v).vec("n", cam.n).vec("eye", cam.eye);
    std::array<Num, 16> m;
    for (int i = 0; i < 16; ++i) m[i] = M[i / 4][i % 4];
    probe.step(L::project, StepKind::init).num("near", cam.near).list("M", std::span<const Num>(m));
  }
  const Viewport<Num> vp = raster_viewport(cam);
  RasterImage<Num> out;
  std::vector<DepthTriangle<Num>> window;
  for (const RasterTriangle<Num>& t : tris) {
    const std::array<Vec4<Num>, 3> c{apply(M, t.x[0]), apply(M, t.x[1]), apply(M, t.x[2])};
    if constexpr (Probe::on) {
      auto& st = probe.step(L::corners, StepKind::visit).idx("object", t.object).idx("prim", t.prim);
      const char* names[3] = {"c0", "c1", "c2"};
      for (int k = 0; k < 3; ++k) {
        const std::array<Num, 4> cs{c[k].x, c[k].y, c[k].z, c[k].w};
        st.list(names[k], std::span<const Num>(cs));
      }
    }
    const ClippedPolygon<Num> K = [&] {
      const auto call = nested<ClipVolume>(probe);
      return clip_volume(c, probe);
    }();
    const bool cut = K.k != 3 || K.v[0].edge != 0 || K.v[1].edge != 1 || K.v[2].edge != 2;
    if constexpr (Probe::on) probe.step(L::clip, K.k == 0 ? StepKind::miss : StepKind::decide).idx("corners", K.k).idx("cut", cut && K.k > 0);
    if (K.k == 0) {
      ++out.culled;
      continue;
    }
    out.cut += cut;
    const std::array<Vec3<Num>, kMaxClipCorners> w = window_corners(vp, K);
    if constexpr (Probe::on) {
      std::array<Vec2<Num>, kMaxClipCorners> xy;
      for (int k = 0; k < K.k; ++k) xy[k] = {w[k].x, w[k].y};
      probe.step(L::divide, StepKind::advance).idx("corners", K.k).geo_list(GeoKind::polygon, std::span<const Vec2<Num>>(xy.data(), K.k)).label("K").replace();
    }
    for (int k = 1; k + 1 < K.k; ++k) {
      window.push_back({{w[0], w[k], w[k + 1]}, std::int64_t(out.drawn.size()), depth.factor, depth.units});
      out.drawn.push_back({t.object, t.prim});
    }
    if constexpr (Probe::on) probe.step(L::fan, StepKind::advance).idx("triangles", K.k - 2).idx("drawn", std::int64_t(out.drawn.size()));
  }
  if constexpr (Probe::on) probe.step(L::draw, StepKind::init).idx("triangles", std::int64_t(window.size()));
  out.buffer = [&] {
    const auto call = nested<ZBuffer>(probe);
    return z_buffer(cam.width, cam.height, window, depth.bits, DepthFunc::less, Num(1), probe);
  }();
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("passed", out.buffer.passed).idx("culled", out.culled).idx("cut", out.cut);
  return out;
}

}  // namespace sw::pipe
