// Projective (planar) shadows (Blinn 1988), GL's way: the scene is drawn, every occluder is
// squashed onto the receiver's plane by one matrix, S = (P . L) I - L P^T, which sends each point
// to where the ray from the light L through it meets the plane P (n . x + d = 0, P = (n, d)), and
// the squashed polygons are drawn over the receiver. They lie exactly in its plane, so their
// depths tie with its depths: GL_LESS drops them, GL_LEQUAL keeps them where the arithmetic is
// exact, and rounding decides in between (z-fighting); glPolygonOffset pulls them forward. A
// stencil of the receiver's pixels keeps them on it and darkens each pixel once. Only the part of
// an occluder between the plane and the light can shadow the plane, so each triangle is cut to
// that slab first; the receiver shadows nothing on itself.
// Semantics: docs/shadows/semantics.md#projective-shadow.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "pipeline/depth_plane.hpp"
#include "pipeline/scene_raster.hpp"

namespace sw::shadow {

template <class Num> struct ProjectiveParams {
  bool lequal = false;    // GL_LEQUAL, else GL_LESS
  Num factor{}, units{};  // glPolygonOffset on the shadow polygons
  bool stencil = true;    // keep them on the receiver's pixels, each pixel darkened once
};

// Per pixel (rows bottom up): shadowed, and the fragments that decided it.
template <class Num> struct ProjectiveImage {
  pipe::DepthBuffer<Num> eye;
  std::vector<std::int64_t> objects;  // the object seen (-1: none)
  std::vector<char> shadowed;
  std::int64_t occluders = 0, polygons = 0, fragments = 0, ties = 0, passed = 0, off_receiver = 0, doubled = 0;
};

struct ProjectiveShadow {
  static constexpr std::string_view id = "projective-shadow";
  static constexpr std::string_view summary = "Projective shadows: occluders squashed onto a plane by one matrix, drawn over it with a depth tie, offset and stencil";
#define SW_SHADOWS_PROJECTIVE_SHADOW(X) \
  X(depth, "D, id <- scene-raster from the eye") \
  X(matrix, "S <- (P . L) I - L P^T     -- sends X to where the ray from L through X meets the plane P") \
  X(stencil, "stencil(i, j) <- 1 where the receiver is what the eye sees, else 0") \
  X(occluder, "for each triangle t of another object, not in the plane: K <- its part with P . X >= 0 and w(S X) >= 0   -- between the plane and the light") \
  X(project, "    the shadow polygon S K, fanned into triangles: each through the eye's matrix, clip-volume, the divide") \
  X(offset, "    o <- factor max(|zx|, |zy|) + units r, its window plane's slopes   -- glPolygonOffset") \
  X(fragment, "    each sample (i, j) it covers: d <- its depth there + o") \
  X(test, "    pass <- d < D(i, j) (GL_LESS) or d <= D(i, j) (GL_LEQUAL), and stencil(i, j) = 1 if the stencil is on") \
  X(darken, "    if pass: shadowed(i, j) <- yes; stencil(i, j) <- 2, so that it is darkened once") \
  X(done, "done: per pixel shadowed")
  SW_LISTING("Projective shadow", SW_SHADOWS_PROJECTIVE_SHADOW)
#undef SW_SHADOWS_PROJECTIVE_SHADOW
};

template <class Num> Num dot4(const pipe::Vec4<Num>& a, const pipe::Vec4<Num>& b) { return Num(a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w); }

// The planar shadow matrix of plane P and light L (a point w = 1, toward a directional one w = 0).
template <class Num> pipe::Mat4<Num> shadow_matrix(const pipe::Vec4<Num>& P, const pipe::Vec4<Num>& L) {
  const Num pl = dot4(P, L);
  const std::array<Num, 4> l{L.x, L.y, L.z, L.w}, p{P.x, P.y, P.z, P.w};
  pipe::Mat4<Num> S;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) S[std::size_t(r)][std::size_t(c)] = Num((r == c ? pl : Num(0)) - l[std::size_t(r)] * p[std::size_t(c)]);
  return S;
}

// A polygon's part where every f . X >= 0 (Sutherland-Hodgman, homogeneous points).
template <class Num> std::vector<pipe::Vec4<Num>> clip_half_spaces(std::vector<pipe::Vec4<Num>> poly, const std::vector<pipe::Vec4<Num>>& fs) {
  for (const auto& f : fs) {
    std::vector<pipe::Vec4<Num>> out;
    for (std::size_t e = 0; e < poly.size(); ++e) {
      const pipe::Vec4<Num>&P = poly[e], &Q = poly[(e + 1) % poly.size()];
      const Num dp = dot4(f, P), dq = dot4(f, Q);
      if (!(dp < Num(0))) out.push_back(P);
      if ((dp < Num(0) && Num(0) < dq) || (Num(0) < dp && dq < Num(0))) {
        const Num s = dp / (dp - dq);
        out.push_back({Num(P.x + s * (Q.x - P.x)), Num(P.y + s * (Q.y - P.y)), Num(P.z + s * (Q.z - P.z)), Num(P.w + s * (Q.w - P.w))});
      }
    }
    if (out.size() < 3) return {};
    poly = std::move(out);
  }
  return poly;
}

// Preconditions: P . L > 0 (the light on the plane's positive side); receiver is an object whose
// triangles lie in P.
template <NumberType Num, StepProbe Probe = NoProbe>
ProjectiveImage<Num> projective_shadow(const pipe::RasterCamera<Num>& cam, const std::vector<pipe::RasterTriangle<Num>>& tris, std::int32_t receiver,
                                       const pipe::Vec4<Num>& P, const pipe::Vec4<Num>& L, const ProjectiveParams<Num>& p, Probe& probe) {
  using Lines = ProjectiveShadow;
  ProjectiveImage<Num> out;
  const pipe::RasterImage<Num> img = [&] {
    const auto call = nested<pipe::SceneRaster>(probe);
    return pipe::scene_raster(cam, tris, probe);
  }();
  out.eye = img.buffer;
  const std::size_t pixels = out.eye.depth.size();
  out.objects.assign(pixels, -1), out.shadowed.assign(pixels, 0);
  for (std::size_t i = 0; i < pixels; ++i)
    if (out.eye.id[i] >= 0) out.objects[i] = img.drawn[std::size_t(out.eye.id[i])][0];
  if constexpr (Probe::on) probe.step(Lines::depth, StepKind::init).idx("passed", out.eye.passed);
  const pipe::Mat4<Num> S = shadow_matrix(P, L);
  if constexpr (Probe::on) {
    std::array<Num, 16> m;
    for (int i = 0; i < 16; ++i) m[std::size_t(i)] = S[std::size_t(i / 4)][std::size_t(i % 4)];
    probe.step(Lines::matrix, StepKind::init).num("PL", dot4(P, L)).list("S", std::span<const Num>(m));
  }
  std::vector<std::uint8_t> stencil(pixels, 0);
  std::int64_t on = 0;
  for (std::size_t i = 0; i < pixels; ++i) stencil[i] = out.objects[i] == receiver, on += stencil[i];
  if constexpr (Probe::on) probe.step(Lines::stencil, StepKind::init).idx("receiver", receiver).idx("pixels", on);
  // w(S X) = (P . L) X.w - L.w (P . X): the row of S that gives w.
  const pipe::Vec4<Num> w_row{S[3][0], S[3][1], S[3][2], S[3][3]};
  const pipe::Mat4<Num> M = pipe::raster_matrix(cam);
  const pipe::Viewport<Num> vp = pipe::raster_viewport(cam);
  const Num r = Num(1) / Num(std::int64_t(1) << 24);
  std::vector<Pixel> samples;
  for (const pipe::RasterTriangle<Num>& t : tris) {
    if (t.object == receiver) continue;
    // A triangle in the plane itself shadows nothing of it; the rest is cut to the slab.
    const bool in_plane = dot4(P, t.x[0]) == Num(0) && dot4(P, t.x[1]) == Num(0) && dot4(P, t.x[2]) == Num(0);
    const std::vector<pipe::Vec4<Num>> K = in_plane ? std::vector<pipe::Vec4<Num>>{} : clip_half_spaces<Num>({t.x[0], t.x[1], t.x[2]}, {P, w_row});
    if constexpr (Probe::on) probe.step(Lines::occluder, K.empty() ? StepKind::miss : StepKind::visit).idx("object", t.object).idx("prim", t.prim).idx("corners", std::int64_t(K.size()));
    if (K.empty()) continue;
    ++out.occluders;
    std::vector<pipe::Vec4<Num>> shadow;
    for (const auto& x : K) shadow.push_back(pipe::apply(S, x));
    for (std::size_t k = 1; k + 1 < shadow.size(); ++k) {
      const std::array<pipe::Vec4<Num>, 3> c{pipe::apply(M, shadow[0]), pipe::apply(M, shadow[k]), pipe::apply(M, shadow[k + 1])};
      const pipe::ClippedPolygon<Num> C = [&] {
        const auto call = nested<pipe::ClipVolume>(probe);
        return pipe::clip_volume(c, probe);
      }();
      const std::array<Vec3<Num>, pipe::kMaxClipCorners> w = pipe::window_corners(vp, C);
      if constexpr (Probe::on) {
        std::array<Vec2<Num>, pipe::kMaxClipCorners> xy;
        for (int q = 0; q < C.k; ++q) xy[std::size_t(q)] = {w[std::size_t(q)].x, w[std::size_t(q)].y};
        probe.step(Lines::project, StepKind::advance).idx("corners", C.k).geo_list(GeoKind::polygon, std::span<const Vec2<Num>>(xy.data(), std::size_t(C.k))).label("S K").replace();
      }
      for (int q = 1; q + 1 < C.k; ++q) {
        const std::array<Vec3<Num>, 3> v{w[0], w[std::size_t(q)], w[std::size_t(q + 1)]};
        const pipe::DepthPlane<Num> plane = pipe::depth_plane(v);
        if (plane.area2 == Num(0)) continue;
        ++out.polygons;
        const Num o = pipe::polygon_offset(plane, p.factor, p.units, r);
        if constexpr (Probe::on) probe.step(Lines::offset, StepKind::advance).num("zx", plane.zx).num("zy", plane.zy).num("o", o);
        pipe::covered_samples(v, cam.width, cam.height, samples);
        for (const Pixel& s : samples) {
          const std::size_t at = std::size_t(s.y * cam.width + s.x);
          const Num d = std::clamp(Num(plane.at(Num(s.x), Num(s.y)) + o), Num(0), Num(1));
          const Num& D = out.eye.depth[at];
          ++out.fragments;
          out.ties += d == D;
          if constexpr (Probe::on) probe.step(Lines::fragment, StepKind::advance).idx("i", s.x).idx("j", s.y).num("d", d).num("D", D).pixel(s);
          const bool depth_ok = p.lequal ? !(D < d) : d < D;
          const bool pass = depth_ok && (!p.stencil || stencil[at] == 1);
          if constexpr (Probe::on) probe.step(Lines::test, StepKind::decide).idx("depth", depth_ok).idx("stencil", stencil[at]).idx("pass", pass);
          if (!pass) continue;
          ++out.passed;
          out.off_receiver += out.objects[at] != receiver;
          out.doubled += out.shadowed[at] != 0;
          out.shadowed[at] = 1, stencil[at] = 2;
          if constexpr (Probe::on) probe.step(Lines::darken, StepKind::plot).pixel(s).value(Num(1)).keep();
        }
      }
    }
  }
  if constexpr (Probe::on) {
    std::int64_t dark = 0;
    for (char c : out.shadowed) dark += c;
    probe.step(Lines::done, StepKind::done).idx("shadowed", dark).idx("ties", out.ties).idx("fragments", out.fragments);
  }
  return out;
}

}  // namespace sw::shadow
