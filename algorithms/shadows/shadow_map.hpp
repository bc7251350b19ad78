// Shadow mapping (Williams 1978), GL's way: a depth map drawn from the light (scene-raster from the
// light's view, into a fixed-point depth buffer), then every visible point's depth from the light
// against the map: lit when its reference, less a constant bias and a slope-scaled one, is at most
// the stored depth (GL_COMPARE_REF_TO_TEXTURE with GL_LEQUAL). The slope is the point's own
// surface's, max(|dz/dx|, |dz/dy|) in the light's window, as glPolygonOffset measures it; it is
// applied to the reference, not in the light's pass, so that the map keeps the nearest surface at
// every texel (an offset per triangle can reorder two near surfaces). Percentage-closer filtering
// takes the fraction of the k x k texels around the point's own that pass. A spot light has one
// perspective view (its cone), a point light the six faces of a cube, a directional light an
// orthographic box. Semantics: docs/shadows/semantics.md#shadow-map.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "pipeline/depth_plane.hpp"
#include "pipeline/scene_raster.hpp"

namespace sw::shadow {

template <class Num> struct MapParams {
  int bits = 24;   // the map's depth bits (0: depth in Num)
  Num bias{};      // subtracted from each point's reference depth
  Num slope{};     // times the point's depth slope, subtracted too
  int pcf = 1;     // k x k taps, k odd
};

// A point the eye sees, and two directions along its surface (for its slope).
template <class Num> struct MapPoint {
  Vec3<Num> p, e1, e2;
};

// Per point: `lit` from its own texel, `fraction` of the k x k taps that pass (1 when no view holds
// it: nothing drawn from the light can shadow it there), the view and texel it fell in, the depth
// stored there and its reference depth, biased.
template <class Num> struct MapLookup {
  bool lit = true, outside = true;
  Num fraction = Num(1), stored{}, ref{};
  int view = -1;
  std::int64_t i = 0, j = 0;
};

struct ShadowMap {
  static constexpr std::string_view id = "shadow-map";
  static constexpr std::string_view summary = "Shadow map: the light's depth map (scene-raster from the light), each point's depth against it, bias, PCF";
#define SW_SHADOWS_SHADOW_MAP(X) \
  X(pass, "for each view of the light (a spot: its cone; a point light: six cube faces; directional: a box):") \
  X(draw, "    its depth map <- scene-raster from the light, into the map's depth bits") \
  X(point, "for each visible point P: v <- the view holding P (a point light: the face of P - L's largest axis)") \
  X(project, "    (x, y, d) <- P through v's matrix, the divide and the viewport: d is P's depth from the light") \
  X(outside, "    if (x, y) lies off the map: lit, since nothing drawn from the light covers it") \
  X(texel, "    (i, j) <- (floor(x + 1/2), floor(y + 1/2)), the texel holding P; D <- the map there (fixed point: D / (2^bits - 1))") \
  X(slope, "    s <- max(|dz/dx|, |dz/dy|) of P's own plane in v's window   -- glPolygonOffset's slope, of the receiver") \
  X(compare, "    lit <- d - bias - slope s <= D          -- GL_COMPARE_REF_TO_TEXTURE, GL_LEQUAL") \
  X(pcf, "    fraction <- the share of the k x k texels around (i, j), inside the map, whose depth passes the same test") \
  X(done, "done: per point lit and its fraction")
  SW_LISTING("Shadow map", SW_SHADOWS_SHADOW_MAP)
#undef SW_SHADOWS_SHADOW_MAP
};

// The view of a point light's cube holding P: the face of P - L's largest axis (ties: x, then y),
// faces ordered +x, -x, +y, -y, +z, -z.
template <class Num> int cube_face(const Vec3<Num>& d) {
  const Num ax = num::abs(d.x), ay = num::abs(d.y), az = num::abs(d.z);
  if (!(ax < ay) && !(ax < az)) return d.x < Num(0) ? 1 : 0;
  if (!(ay < az)) return d.y < Num(0) ? 3 : 2;
  return d.z < Num(0) ? 5 : 4;
}

// views: one, or a point light's six faces (cube: then the face of P - light holds P).
// The slope of the plane through P along e1, e2 in the window of the view with matrix M (w x h):
// the plane's depth at P and at two points a little along e1 and e2 (still in front of the eye).
template <class Num> Num window_slope(const pipe::Mat4<Num>& M, std::int64_t w, std::int64_t h, const MapPoint<Num>& q) {
  const Num half = Num(1) / Num(2);
  auto window = [&](const pipe::Vec4<Num>& c) {
    return Vec3<Num>{Num(-half + (c.x / c.w + Num(1)) * Num(w) * half), Num(-half + (c.y / c.w + Num(1)) * Num(h) * half), Num((c.z / c.w + Num(1)) * half)};
  };
  const pipe::Vec4<Num> c = pipe::apply(M, pipe::Vec4<Num>{q.p.x, q.p.y, q.p.z, Num(1)});
  const pipe::Vec4<Num> d1 = pipe::apply(M, pipe::Vec4<Num>{q.e1.x, q.e1.y, q.e1.z, Num(0)}), d2 = pipe::apply(M, pipe::Vec4<Num>{q.e2.x, q.e2.y, q.e2.z, Num(0)});
  const Num eps = c.w / (Num(2) * (num::abs(d1.w) + num::abs(d2.w) + Num(1)));  // keeps w > 0
  auto moved = [&](const pipe::Vec4<Num>& d) { return pipe::Vec4<Num>{Num(c.x + eps * d.x), Num(c.y + eps * d.y), Num(c.z + eps * d.z), Num(c.w + eps * d.w)}; };
  const pipe::DepthPlane<Num> plane = pipe::depth_plane<Num>({window(c), window(moved(d1)), window(moved(d2))});
  return std::max(num::abs(plane.zx), num::abs(plane.zy));
}

template <NumberType Num, StepProbe Probe = NoProbe>
std::vector<MapLookup<Num>> shadow_map(const std::vector<pipe::RasterCamera<Num>>& views, bool cube, const Vec3<Num>& light,
                                       const std::vector<pipe::RasterTriangle<Num>>& tris, const std::vector<MapPoint<Num>>& points,
                                       const MapParams<Num>& p, Probe& probe) {
  using L = ShadowMap;
  std::vector<pipe::DepthBuffer<Num>> maps;
  std::vector<pipe::Mat4<Num>> M;
  for (std::size_t v = 0; v < views.size(); ++v) {
    if constexpr (Probe::on) probe.step(L::pass, StepKind::visit).idx("view", std::int64_t(v)).num("near", views[v].near);
    maps.push_back([&] {
      const auto call = nested<pipe::SceneRaster>(probe);
      return pipe::scene_raster(views[v], tris, probe, pipe::DepthSettings<Num>{Num(0), Num(0), p.bits}).buffer;
    }());
    M.push_back(pipe::raster_matrix(views[v]));
    if constexpr (Probe::on) probe.step(L::draw, StepKind::init).idx("view", std::int64_t(v)).idx("passed", maps.back().passed);
  }
  const Num scale = p.bits == 0 ? Num(1) : Num(std::int64_t(1) << p.bits) - Num(1);
  const Num half = Num(1) / Num(2);
  std::vector<MapLookup<Num>> out(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    MapLookup<Num>& r = out[k];
    const Vec3<Num>& P = points[k].p;
    const int v = cube ? cube_face(Vec3<Num>(P - light)) : 0;
    const pipe::RasterCamera<Num>& cam = views[static_cast<std::size_t>(v)];
    if constexpr (Probe::on) probe.step(L::point, StepKind::visit).idx("k", std::int64_t(k)).idx("view", v).point(P).label("P");
    const pipe::Vec4<Num> c = pipe::apply(M[static_cast<std::size_t>(v)], pipe::Vec4<Num>{P.x, P.y, P.z, Num(1)});
    const Num x = Num(-half + (c.x / c.w + Num(1)) * Num(cam.width) * half), y = Num(-half + (c.y / c.w + Num(1)) * Num(cam.height) * half);
    const Num d = Num((c.z / c.w + Num(1)) * half);
    if constexpr (Probe::on) probe.step(L::project, StepKind::advance).num("x", x).num("y", y).num("d", d);
    const std::int64_t i = num::floor_int(Num(x + half)), j = num::floor_int(Num(y + half));
    if (!(Num(0) < c.w) || i < 0 || j < 0 || i >= cam.width || j >= cam.height) {
      if constexpr (Probe::on) probe.step(L::outside, StepKind::miss).idx("lit", 1);
      continue;
    }
    const pipe::DepthBuffer<Num>& map = maps[static_cast<std::size_t>(v)];
    auto stored = [&](std::int64_t a, std::int64_t b) { return Num(map.depth[static_cast<std::size_t>(b * cam.width + a)] / scale); };
    const Num D = stored(i, j);
    r.outside = false, r.view = v, r.i = i, r.j = j;
    if constexpr (Probe::on) probe.step(L::texel, StepKind::init).idx("i", i).idx("j", j).num("D", D).pixel(Pixel{i, j});
    const Num slope = p.slope == Num(0) ? Num(0) : window_slope(M[static_cast<std::size_t>(v)], cam.width, cam.height, points[k]);
    if constexpr (Probe::on) probe.step(L::slope, StepKind::advance).num("s", slope);
    const Num ref = Num(d - p.bias - p.slope * slope);
    r.lit = !(D < ref), r.stored = D, r.ref = ref;
    if constexpr (Probe::on) probe.step(L::compare, StepKind::decide).num("ref", ref).num("D", D).idx("lit", r.lit);
    const std::int64_t h = p.pcf / 2;
    std::int64_t taps = 0, pass = 0;
    for (std::int64_t b = std::max<std::int64_t>(0, j - h); b <= std::min<std::int64_t>(cam.height - 1, j + h); ++b)
      for (std::int64_t a = std::max<std::int64_t>(0, i - h); a <= std::min<std::int64_t>(cam.width - 1, i + h); ++a)
        ++taps, pass += !(stored(a, b) < ref);
    r.fraction = Num(pass) / Num(taps);
    if constexpr (Probe::on) probe.step(L::pcf, StepKind::advance).idx("taps", taps).idx("pass", pass).num("fraction", r.fraction);
  }
  if constexpr (Probe::on) {
    std::int64_t lit = 0;
    for (const auto& r : out) lit += r.lit;
    probe.step(L::done, StepKind::done).idx("points", std::int64_t(points.size())).idx("lit", lit);
  }
  return out;
}

}  // namespace sw::shadow
