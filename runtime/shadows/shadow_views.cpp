#include "shadows/shadow_views.hpp"
#include "shadows/shadow_volume.hpp"
#include <algorithm>
#include <cmath>
#include <optional>

namespace sw::shadowspec {

namespace {

using V3 = Vec3<Rational>;
using Vd = Vec3<double>;

Vd unit_of(const Vd& a) { return (1.0 / std::sqrt(dot(a, a))) * a; }
V3 exact_of(const Vd& a) { return {num::to_rational(a.x), num::to_rational(a.y), num::to_rational(a.z)}; }

// A view looking along -n from eye, its frame as double computes it (pipespec's tracer camera).
pipe::RasterCamera<Rational> view_along(const V3& eye, const Vd& n_dir, double half, std::int64_t size) {
  const Vd n = unit_of(n_dir);
  const Vd up = std::abs(n.y) > 0.9 ? Vd{1, 0, 0} : Vd{0, 1, 0};
  const Vd u = unit_of(cross(up, n)), v = cross(n, u);
  const Rational h = num::to_rational(half);
  return {eye, exact_of(u), exact_of(v), exact_of(n), Rational(1), {Rational(-h), h, Rational(-h), h}, Rational(1), size, size, false, Rational(0)};
}

// The orthographic box of a directional light (toward the light: `toward`): across the light, the
// finite corners' extent; along it, every surface the box's sides hold, each with a margin.
pipe::RasterCamera<Rational> box_view(const RasterScene& s, const V3& toward, std::int64_t size) {
  pipe::RasterCamera<Rational> c = view_along(V3{}, Vd{toward.x.get_d(), toward.y.get_d(), toward.z.get_d()}, 1, size);
  c.orthographic = true;
  // The frame's inverse gives a corner's (across, across, depth) coordinates.
  const Rational det = dot(c.u, cross(c.v, c.n));
  const V3 ru = Rational(1) / det * cross(c.v, c.n), rv = Rational(1) / det * cross(c.n, c.u), rn = Rational(1) / det * cross(c.u, c.v);
  std::optional<std::array<Rational, 4>> across;
  V3 lo, hi;
  for (const auto& t : s.tris)
    for (const auto& x : t.x) {
      if (x.w == 0) continue;
      const V3 p{x.x, x.y, x.z};
      const Rational a = dot(ru, p), b = dot(rv, p);
      if (!across) across = std::array<Rational, 4>{a, a, b, b};
      auto& w = *across;
      w[0] = std::min(w[0], a), w[1] = std::max(w[1], a), w[2] = std::min(w[2], b), w[3] = std::max(w[3], b);
    }
  if (!across) across = std::array<Rational, 4>{-1, 1, -1, 1};
  auto& w = *across;
  const Rational margin = std::max(w[1] - w[0], w[3] - w[2]) / 64 + 1;  // a box of no width gets one unit
  c.window = {Rational(w[0] - margin), Rational(w[1] + margin), Rational(w[2] - margin), Rational(w[3] + margin)};
  // Depth along -n from the origin: every corner the box's sides keep, at infinity or not.
  c.near = 0, c.far = 1;
  const pipe::Mat4<Rational> M = pipe::raster_matrix(c);
  std::optional<std::array<Rational, 2>> depth;
  NoProbe none;
  for (const auto& t : s.tris) {
    const pipe::ClippedPolygon<Rational> K =
        pipe::clip_volume<Rational>({pipe::apply(M, t.x[0]), pipe::apply(M, t.x[1]), pipe::apply(M, t.x[2])}, none, 1);
    for (int k = 0; k < K.k; ++k) {
      const pipe::Vec4<Rational>& v = K.v[k].c;
      if (v.w <= 0) continue;  // a direction along the light itself: depth without bound
      const Rational e = (v.z / v.w + 1) / 2;  // with near 0 and far 1, z_ndc = 2 e - 1
      if (!depth) depth = std::array<Rational, 2>{e, e};
      (*depth)[0] = std::min((*depth)[0], e), (*depth)[1] = std::max((*depth)[1], e);
    }
  }
  const auto [d0, d1] = depth.value_or(std::array<Rational, 2>{0, 1});
  const Rational dm = (d1 - d0) / 64 + 1;
  c.near = d0 - dm, c.far = d1 + dm;
  return c;
}

}  // namespace

LightViews light_views(const RasterScene& s, std::size_t light, std::int64_t size) {
  const lighting::Light<Rational>& li = s.scene->lights.at(light);
  LightViews out;
  if (li.type == lighting::LightType::directional) {
    out.views.push_back(box_view(s, li.where, size));
    return out;
  }
  out.position = li.where;
  const bool cone = li.type == lighting::LightType::spot && !li.cone.all && li.cone.degrees <= kSpotViewMaxDegrees;
  if (cone) {
    const double half = std::tan(li.cone.degrees.get_d() * 3.14159265358979323846 / 180);
    const Vd axis{li.spot_dir.x.get_d(), li.spot_dir.y.get_d(), li.spot_dir.z.get_d()};
    out.views.push_back(view_along(li.where, -1.0 * axis, half, size));
  } else {
    out.cube = true;
    for (int f = 0; f < 6; ++f) {  // +x, -x, +y, -y, +z, -z: the view looks along that axis
      Vd axis{};
      axis[f / 2] = f % 2 ? -1 : 1;
      out.views.push_back(view_along(li.where, -1.0 * axis, 1, size));
    }
  }
  for (auto& v : out.views) v.near = pipespec::near_plane(v, s.tris);
  return out;
}

std::vector<SeenPoint> seen_points(const RasterScene& s, const pipespec::RasterTruth& truth) {
  std::vector<SeenPoint> out;
  for (std::int64_t j = 0; j < s.height; ++j)
    for (std::int64_t i = 0; i < s.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j * s.width + i);
      const pipespec::PixelTruth& p = truth.px[k];
      if (p.object < 0) continue;
      const ray::Ray3<Rational> r = pipespec::pixel_ray(s.camera, i, j);
      out.push_back({k, V3(r.o + V3(p.t * r.d)), p.t, p.object, p.prim});
    }
  return out;
}

bool reaches(const RasterScene& s, std::size_t light, const SeenPoint& p) {
  const lighting::Light<Rational>& li = s.scene->lights.at(light);
  const bool directional = li.type == lighting::LightType::directional;
  const V3 d = directional ? li.where : V3(li.where - p.p);
  if (d == V3{}) return true;  // the light sits on the point
  // The segment leaves p's own surface: a flat one (a plane, a triangle, a mesh's triangle) is
  // not tested; a ray cannot meet its own plane again.
  const tracer::Leaving leaving{p.object, p.prim};
  // Directional: any t; 2^300 stands for infinity in rationals (no hit is that far).
  const Rational t_max = directional ? Rational(mpz_class(1) << 300) : Rational(1);
  NoProbe none;
  try {
    const ray::Ray3<Interval> r{to_num<Interval>(p.p), to_num<Interval>(d)};
    return !tracer::scene_hit(s.traced_iv, r, true, directional ? Interval(INFINITY) : Interval(1), leaving, none).hit;
  } catch (const Uncertain&) {
    return !tracer::scene_hit(s.traced, ray::Ray3<Rational>{p.p, d}, true, t_max, leaving, none).hit;
  }
}

// The window depth GL's answer has at a texel of view c: 1 - n/e in perspective (e = n + t d),
// t/(f - n) in orthographic, from where the texel's ray meets it.
Rational window_depth(const pipe::RasterCamera<Rational>& c, const Rational& t) {
  if (c.orthographic) return t / (c.far - c.near);
  return 1 - c.near / (c.near + t * c.dist);
}

// The slope of the plane through Y along e1, e2 in view c's window: max(|dz/dx|, |dz/dy|) from Y
// and two points a little along e1 and e2, each in front of the eye.
Rational window_slope(const pipe::Mat4<Rational>& M, const pipe::RasterCamera<Rational>& c, const Vec3<Rational>& Y, const Vec3<Rational>& e1, const Vec3<Rational>& e2) {
  auto window = [&](const Vec3<Rational>& p) {
    const pipe::Vec4<Rational> q = pipe::apply(M, pipe::Vec4<Rational>{p.x, p.y, p.z, Rational(1)});
    return Vec3<Rational>{Rational(-1, 2) + (q.x / q.w + 1) * c.width / 2, Rational(-1, 2) + (q.y / q.w + 1) * c.height / 2, (q.z / q.w + 1) / 2};
  };
  const pipe::Vec4<Rational> wy = pipe::apply(M, pipe::Vec4<Rational>{Y.x, Y.y, Y.z, Rational(1)});
  const pipe::Vec4<Rational> w1 = pipe::apply(M, pipe::Vec4<Rational>{e1.x, e1.y, e1.z, Rational(0)}), w2 = pipe::apply(M, pipe::Vec4<Rational>{e2.x, e2.y, e2.z, Rational(0)});
  const Rational eps = wy.w / (2 * (num::abs(w1.w) + num::abs(w2.w) + 1));
  // Any three points of the plane give its slopes; the area of their triangle on the screen is 0
  // only for a plane seen edge-on, which has no slope (and covers no texel).
  const std::array<Vec3<Rational>, 3> w{window(Y), window(Vec3<Rational>(Y + Vec3<Rational>(eps * e1))), window(Vec3<Rational>(Y + Vec3<Rational>(eps * e2)))};
  const Rational area2 = (w[1].x - w[0].x) * (w[2].y - w[0].y) - (w[1].y - w[0].y) * (w[2].x - w[0].x);
  if (area2 == 0) return 0;
  const Rational zx = ((w[1].z - w[0].z) * (w[2].y - w[0].y) - (w[2].z - w[0].z) * (w[1].y - w[0].y)) / area2;
  const Rational zy = ((w[2].z - w[0].z) * (w[1].x - w[0].x) - (w[1].z - w[0].z) * (w[2].x - w[0].x)) / area2;
  return std::max(num::abs(zx), num::abs(zy));
}

namespace {

// The signs that place the segment from X to L against triangle t: L's and X's side of its plane,
// and the line XL's turn about each edge. With R, a sign that is 0 at X is taken just before X
// (at X - e R: the sign of -R's, each test being linear in X).
struct SegmentSigns {
  int light = 0, here = 0;
  std::array<int, 3> edge{};
};
SegmentSigns segment_signs(const std::array<pipe::Vec4<Rational>, 3>& t, const pipe::Vec4<Rational>& L, const pipe::Vec4<Rational>& X,
                           const pipe::Vec4<Rational>* R) {
  auto at = [&](const pipe::Vec4<Rational>& a, const pipe::Vec4<Rational>& b, const pipe::Vec4<Rational>& c) {  // det[X a b c]
    const int s = exact_sign_of([&]<class Num>(std::type_identity<Num>) { return shadow::det4(v4_in<Num>(X), v4_in<Num>(a), v4_in<Num>(b), v4_in<Num>(c)); });
    if (s != 0 || !R) return s;
    return -exact_sign_of([&]<class Num>(std::type_identity<Num>) { return shadow::det4(v4_in<Num>(*R), v4_in<Num>(a), v4_in<Num>(b), v4_in<Num>(c)); });
  };
  SegmentSigns g;
  g.light = exact_sign_of([&]<class Num>(std::type_identity<Num>) { return shadow::det4(v4_in<Num>(L), v4_in<Num>(t[0]), v4_in<Num>(t[1]), v4_in<Num>(t[2])); });
  g.here = at(t[0], t[1], t[2]);
  for (int k = 0; k < 3; ++k) g.edge[std::size_t(k)] = at(L, t[std::size_t(k)], t[std::size_t((k + 1) % 3)]);
  return g;
}

// Through the relative interior: X off the plane on the far side from L, the line inside every edge.
bool inside(const SegmentSigns& g) {
  const auto& e = g.edge;
  return g.light != 0 && g.here != 0 && g.here != g.light && ((e[0] > 0 && e[1] > 0 && e[2] > 0) || (e[0] < 0 && e[1] < 0 && e[2] < 0));
}

}  // namespace

bool segment_crosses(const std::array<pipe::Vec4<Rational>, 3>& t, const pipe::Vec4<Rational>& L, const pipe::Vec4<Rational>& X, const pipe::Vec4<Rational>& R) {
  return inside(segment_signs(t, L, X, &R));
}

Meeting segment_meets(const std::array<pipe::Vec4<Rational>, 3>& t, const pipe::Vec4<Rational>& L, const pipe::Vec4<Rational>& X) {
  const SegmentSigns g = segment_signs(t, L, X, nullptr);
  if (g.light == 0 || g.here == g.light) return {};
  const auto& e = g.edge;
  return {inside(g), (e[0] >= 0 && e[1] >= 0 && e[2] >= 0) || (e[0] <= 0 && e[1] <= 0 && e[2] <= 0)};
}

}  // namespace sw::shadowspec
