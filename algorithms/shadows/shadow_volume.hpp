// Stencil shadow volumes (Crow 1977; Heidmann's z-pass, Carmack's z-fail), GL's way. Every
// triangle that faces the light casts a volume: itself as the near cap, its corners pushed to
// infinity away from the light as the far cap, and sides through its edges; where two casters share
// an edge in opposite turns the two sides cancel, so only the silhouette's sides are drawn. The
// volumes' faces are rasterized against the eye's depth buffer, each fragment counting +1 or -1 by
// the side it turns to the eye: z-pass counts the fragments in front of the visible surface, z-fail
// those at or behind it. A pixel is lit when its count is 0. z-pass counts from the near plane, so
// it is off by the volumes holding the eye; z-fail counts to infinity and is not, but needs the
// caps. Points at infinity are homogeneous (w = 0), which the infinite far plane keeps.
// Semantics: docs/shadows/semantics.md#shadow-volume.
#pragma once
#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>
#include "core/probe.hpp"
#include "pipeline/depth_plane.hpp"
#include "pipeline/scene_raster.hpp"

namespace sw::shadow {

// The scene's corners once each, and its triangles by corner index, so that shared edges are
// known exactly. closed: the triangle's object bounds a solid, wound counter-clockwise seen
// from outside (a sphere's or a box's triangles).
template <class Num> struct VolumeMesh {
  std::vector<pipe::Vec4<Num>> corners;
  std::vector<std::array<std::int32_t, 3>> tris;
  std::vector<char> closed;
};

// One face of a volume, outward. flip: drawn in the other turn (a near cap keeps its triangle's
// own order, so its depths equal the eye pass's bit for bit).
template <class Num> struct VolumeFace {
  std::array<pipe::Vec4<Num>, 3> x;
  bool flip = false;
};

// Per pixel (rows bottom up, GL's): the two counts, and the eye's depth buffer; the faces drawn.
template <class Num> struct StencilImage {
  pipe::DepthBuffer<Num> eye;
  std::vector<std::int64_t> zpass, zfail;
  std::vector<VolumeFace<Num>> faces_drawn;
  std::int64_t casters = 0, silhouette = 0, faces = 0, fragments = 0;
};

struct ShadowVolume {
  static constexpr std::string_view id = "shadow-volume";
  static constexpr std::string_view summary = "Shadow volumes: silhouettes extruded from the light, caps, a stencil count per pixel by z-pass and z-fail";
#define SW_SHADOWS_SHADOW_VOLUME(X) \
  X(depth, "D <- scene-raster from the eye: its depth buffer (GL_LESS), which the volumes' fragments are tested against") \
  X(caster, "for each triangle t = (a, b, c): s <- det[L a b c], homogeneous corners   -- > 0: t turns counter-clockwise seen from L") \
  X(turn, "    s = 0: edge-on to the light, no volume; s < 0: turned to (a, c, b), or none on a closed object (its lit half bounds that shadow)") \
  X(edges, "silhouette <- every caster's directed edges, (a, b) cancelling (b, a): each edge left, with its count m") \
  X(extrude, "each corner x: x' <- x - L as a point at infinity (w = 0); toward a directional light L: x' <- -L for every corner") \
  X(caps, "faces <- each caster's near cap (a, b, c) and its far cap (a', c', b')   -- outward: the near cap faces the light") \
  X(sides, "faces <- each silhouette edge (a, b), m times: (b, a, a') and (b, a', b')") \
  X(face, "for each face: c_k <- M x_k (the eye's matrix); clip-volume, divide and fan as scene-raster does") \
  X(cover, "    each window triangle: front <- it turns counter-clockwise (the other way for a turned near cap); its samples") \
  X(fragment, "    each sample (i, j) it covers: d <- its depth there, as the eye pass computes it") \
  X(zpass, "    z-pass: if d < D(i, j): pass(i, j) += front ? 1 : -1      -- GL_INCR_WRAP, GL_DECR_WRAP on depth pass") \
  X(zfail, "    z-fail: else fail(i, j) += front ? -1 : 1               -- on depth fail; it needs the caps") \
  X(lit, "each pixel with a surface: lit <- its count (pass or fail, as chosen) is 0") \
  X(done, "done: per pixel both counts")
  SW_LISTING("Shadow volume", SW_SHADOWS_SHADOW_VOLUME)
#undef SW_SHADOWS_SHADOW_VOLUME
};

// det[a b c d] of four homogeneous points, by rows: det[L a b c] = (L - a) . ((b - a) x (c - a))
// for points (w = 1), and L's way . ((b - a) x (c - a)) for a direction L (w = 0).
template <class Num> Num det4(const pipe::Vec4<Num>& a, const pipe::Vec4<Num>& b, const pipe::Vec4<Num>& c, const pipe::Vec4<Num>& d) {
  auto det3 = [](const Num& a0, const Num& a1, const Num& a2, const Num& b0, const Num& b1, const Num& b2, const Num& c0, const Num& c1, const Num& c2) {
    return Num(a0 * (b1 * c2 - b2 * c1) - a1 * (b0 * c2 - b2 * c0) + a2 * (b0 * c1 - b1 * c0));
  };
  return Num(a.x * det3(b.y, b.z, b.w, c.y, c.z, c.w, d.y, d.z, d.w) - a.y * det3(b.x, b.z, b.w, c.x, c.z, c.w, d.x, d.z, d.w) +
             a.z * det3(b.x, b.y, b.w, c.x, c.y, c.w, d.x, d.y, d.w) - a.w * det3(b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z));
}

// x pushed to infinity away from the light L (w = 1 a point, w = 0 a directional light's way).
template <class Num> pipe::Vec4<Num> extruded(const pipe::Vec4<Num>& x, const pipe::Vec4<Num>& L) {
  if (L.w == Num(0)) return {Num(-L.x), Num(-L.y), Num(-L.z), Num(0)};
  return {Num(x.x - x.w * L.x), Num(x.y - x.w * L.y), Num(x.z - x.w * L.z), Num(0)};
}

// For the 3D view: the finite corners' extent (at least 1), and where corner x is drawn: itself,
// or a point at infinity `reach` beyond `from` along it.
template <class Num> Num display_reach(const VolumeMesh<Num>& mesh) {
  std::optional<std::array<Num, 6>> box;  // least and greatest x, y, z
  for (const auto& x : mesh.corners)
    if (x.w != Num(0)) {
      const std::array<Num, 3> v{Num(x.x / x.w), Num(x.y / x.w), Num(x.z / x.w)};
      if (!box) box = std::array<Num, 6>{v[0], v[1], v[2], v[0], v[1], v[2]};
      for (std::size_t a = 0; a < 3; ++a) (*box)[a] = std::min((*box)[a], v[a]), (*box)[a + 3] = std::max((*box)[a + 3], v[a]);
    }
  if (!box) return Num(1);
  return std::max({Num(1), Num((*box)[3] - (*box)[0]), Num((*box)[4] - (*box)[1]), Num((*box)[5] - (*box)[2])});
}
template <class Num> Vec3<Num> shown_at(const pipe::Vec4<Num>& x, const Vec3<Num>& from, const Num& reach) {
  if (x.w != Num(0)) return {Num(x.x / x.w), Num(x.y / x.w), Num(x.z / x.w)};
  const Num n = std::max({num::abs(x.x), num::abs(x.y), num::abs(x.z)});
  return from + Num(reach / n) * Vec3<Num>{x.x, x.y, x.z};
}

// Precondition: L lies on no triangle. cam: the eye's (perspective, the far plane at infinity).
template <NumberType Num, StepProbe Probe = NoProbe>
StencilImage<Num> shadow_volume(const pipe::RasterCamera<Num>& cam, const std::vector<pipe::RasterTriangle<Num>>& tris,
                                const VolumeMesh<Num>& mesh, const pipe::Vec4<Num>& L, bool zfail, Probe& probe) {
  using S = ShadowVolume;
  StencilImage<Num> out;
  out.eye = [&] {
    const auto call = nested<pipe::SceneRaster>(probe);
    return pipe::scene_raster(cam, tris, probe).buffer;
  }();
  const std::size_t pixels = out.eye.depth.size();
  out.zpass.assign(pixels, 0), out.zfail.assign(pixels, 0);
  [[maybe_unused]] const Num reach = Probe::on ? display_reach(mesh) : Num(1);
  [[maybe_unused]] auto shown = [&](const pipe::Vec4<Num>& x, const Vec3<Num>& from) { return shown_at(x, from, reach); };
  if constexpr (Probe::on) {
    auto& st = probe.step(S::depth, StepKind::init).idx("passed", out.eye.passed).point(cam.eye).label("eye").keep();
    if (L.w != Num(0)) st.point(Vec3<Num>{Num(L.x / L.w), Num(L.y / L.w), Num(L.z / L.w)}).label("light").keep();
    for (const auto& t : tris) {
      const auto first = std::find_if(t.x.begin(), t.x.end(), [](const pipe::Vec4<Num>& x) { return x.w != Num(0); });
      if (first == t.x.end()) continue;
      const Vec3<Num> from = shown(*first, {});
      st.triangle(shown(t.x[0], from), shown(t.x[1], from), shown(t.x[2], from)).label("scene").keep();
    }
  }
  // The casters, turned to face the light; the directed edges' counts by their lower index first.
  std::vector<std::array<std::int32_t, 3>> casters;
  std::vector<char> turned;
  std::map<std::pair<std::int32_t, std::int32_t>, std::int64_t> edges;
  for (std::size_t t = 0; t < mesh.tris.size(); ++t) {
    std::array<std::int32_t, 3> k = mesh.tris[t];
    const Num s = det4(L, mesh.corners[std::size_t(k[0])], mesh.corners[std::size_t(k[1])], mesh.corners[std::size_t(k[2])]);
    if constexpr (Probe::on) probe.step(S::caster, StepKind::visit).idx("t", std::int64_t(t)).num("s", s);
    const bool edge_on = s == Num(0), away = s < Num(0);
    if (edge_on || (away && mesh.closed[t])) {
      if constexpr (Probe::on) probe.step(S::turn, StepKind::miss).idx("t", std::int64_t(t)).idx("edge_on", edge_on);
      continue;
    }
    if (away) std::swap(k[1], k[2]);
    if constexpr (Probe::on) probe.step(S::turn, StepKind::decide).idx("t", std::int64_t(t)).idx("turned", away);
    casters.push_back(k), turned.push_back(away);
    for (int e = 0; e < 3; ++e) {
      const std::int32_t a = k[std::size_t(e)], b = k[std::size_t((e + 1) % 3)];
      edges[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
    }
  }
  out.casters = std::int64_t(casters.size());
  std::vector<std::pair<std::array<std::int32_t, 2>, std::int64_t>> silhouette;
  for (const auto& [e, m] : edges)
    if (m != 0) silhouette.push_back({m > 0 ? std::array{e.first, e.second} : std::array{e.second, e.first}, m > 0 ? m : -m});
  out.silhouette = std::int64_t(silhouette.size());
  if constexpr (Probe::on) probe.step(S::edges, StepKind::init).idx("casters", out.casters).idx("edges", std::int64_t(edges.size())).idx("silhouette", out.silhouette);
  std::vector<pipe::Vec4<Num>> far(mesh.corners.size());
  for (std::size_t i = 0; i < far.size(); ++i) far[i] = extruded(mesh.corners[i], L);
  if constexpr (Probe::on) probe.step(S::extrude, StepKind::init).idx("corners", std::int64_t(far.size())).idx("directional", L.w == Num(0));
  auto at = [&](std::int32_t i) { return mesh.corners[std::size_t(i)]; };
  auto inf = [&](std::int32_t i) { return far[std::size_t(i)]; };
  std::vector<VolumeFace<Num>> faces;
  for (std::size_t c = 0; c < casters.size(); ++c) {
    const auto& k = casters[c];
    const bool t = turned[c];  // the near cap in the triangle's own order: (a, c, b) turned back
    faces.push_back({{at(k[0]), at(t ? k[2] : k[1]), at(t ? k[1] : k[2])}, bool(t)});
    faces.push_back({{inf(k[0]), inf(k[2]), inf(k[1])}, false});
  }
  // The 3D view draws the volumes of casters whose corners are all finite (a plane's wedges reach
  // infinity already).
  [[maybe_unused]] auto finite = [&](std::initializer_list<std::int32_t> ks) {
    return std::all_of(ks.begin(), ks.end(), [&](std::int32_t i) { return at(i).w != Num(0); });
  };
  [[maybe_unused]] auto shown_far = [&](std::int32_t i) { return shown(inf(i), shown(at(i), {})); };
  if constexpr (Probe::on) {
    auto& st = probe.step(S::caps, StepKind::init).idx("caps", std::int64_t(faces.size()));
    for (const auto& k : casters)
      if (finite({k[0], k[1], k[2]})) {
        st.triangle(shown(at(k[0]), {}), shown(at(k[1]), {}), shown(at(k[2]), {})).label("near cap").keep();
        st.triangle(shown_far(k[0]), shown_far(k[2]), shown_far(k[1])).label("far cap").keep();
      }
  }
  for (const auto& [e, m] : silhouette)
    for (std::int64_t r = 0; r < m; ++r) {
      faces.push_back({{at(e[1]), at(e[0]), inf(e[0])}, false});
      faces.push_back({{at(e[1]), inf(e[0]), inf(e[1])}, false});
    }
  out.faces = std::int64_t(faces.size());
  if constexpr (Probe::on) {
    auto& st = probe.step(S::sides, StepKind::init).idx("faces", out.faces);
    for (const auto& [e, m] : silhouette) {
      if (!finite({e[0], e[1]})) continue;
      const Vec3<Num> a = shown(at(e[0]), {}), b = shown(at(e[1]), {});
      st.triangle(b, a, shown_far(e[0])).label("side quad").keep();
      st.triangle(b, shown_far(e[0]), shown_far(e[1])).label("side quad").keep();
    }
  }
  const pipe::Mat4<Num> M = pipe::raster_matrix(cam);
  const pipe::Viewport<Num> vp = pipe::raster_viewport(cam);
  std::vector<Pixel> samples;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::array<pipe::Vec4<Num>, 3> c{pipe::apply(M, faces[f].x[0]), pipe::apply(M, faces[f].x[1]), pipe::apply(M, faces[f].x[2])};
    if constexpr (Probe::on) {
      auto& st = probe.step(S::face, StepKind::visit).idx("face", std::int64_t(f)).idx("flip", faces[f].flip);
      const char* names[3] = {"c0", "c1", "c2"};
      for (int k = 0; k < 3; ++k) {
        const std::array<Num, 4> cs{c[std::size_t(k)].x, c[std::size_t(k)].y, c[std::size_t(k)].z, c[std::size_t(k)].w};
        st.list(names[k], std::span<const Num>(cs));
      }
    }
    const pipe::ClippedPolygon<Num> K = [&] {
      const auto call = nested<pipe::ClipVolume>(probe);
      return pipe::clip_volume(c, probe);
    }();
    const std::array<Vec3<Num>, pipe::kMaxClipCorners> w = pipe::window_corners(vp, K);
    for (int k = 1; k + 1 < K.k; ++k) {
      const std::array<Vec3<Num>, 3> v{w[0], w[std::size_t(k)], w[std::size_t(k + 1)]};
      const pipe::DepthPlane<Num> plane = pipe::depth_plane(v);
      if (plane.area2 == Num(0)) continue;  // seen edge-on: no sample is covered
      const bool front = (Num(0) < plane.area2) != faces[f].flip;
      pipe::covered_samples(v, cam.width, cam.height, samples);
      if constexpr (Probe::on) {
        const std::array<Vec2<Num>, 3> xy{Vec2<Num>{v[0].x, v[0].y}, Vec2<Num>{v[1].x, v[1].y}, Vec2<Num>{v[2].x, v[2].y}};
        probe.step(S::cover, StepKind::advance).idx("front", front).num("area2", plane.area2).idx("samples", std::int64_t(samples.size())).geo_list(GeoKind::polygon, std::span(xy)).replace();
      }
      for (const Pixel& s : samples) {
        const std::size_t at_px = std::size_t(s.y * cam.width + s.x);
        const Num d = std::clamp(plane.at(Num(s.x), Num(s.y)), Num(0), Num(1));
        const Num& D = out.eye.depth[at_px];
        ++out.fragments;
        if constexpr (Probe::on) probe.step(S::fragment, StepKind::advance).idx("i", s.x).idx("j", s.y).num("d", d).num("D", D).pixel(s);
        if (d < D) {
          out.zpass[at_px] += front ? 1 : -1;
          if constexpr (Probe::on) probe.step(S::zpass, StepKind::decide).idx("pass", out.zpass[at_px]);
        } else {
          out.zfail[at_px] += front ? -1 : 1;
          if constexpr (Probe::on) probe.step(S::zfail, StepKind::decide).idx("fail", out.zfail[at_px]);
        }
      }
    }
  }
  if constexpr (Probe::on) {
    std::int64_t lit = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
      if (out.eye.id[i] < 0) continue;
      const std::int64_t count = zfail ? out.zfail[i] : out.zpass[i];
      lit += count == 0;
      const Pixel px{std::int64_t(i) % cam.width, std::int64_t(i) / cam.width};
      probe.step(S::lit, StepKind::plot).idx("i", px.x).idx("j", px.y).idx("count", count).idx("lit", count == 0).pixel(px).value(Num(count == 0)).keep();
    }
    probe.step(S::done, StepKind::done).idx("faces", out.faces).idx("fragments", out.fragments).idx("lit", lit);
  }
  out.faces_drawn = std::move(faces);
  return out;
}

}  // namespace sw::shadow
