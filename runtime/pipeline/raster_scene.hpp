// A ray-tracer scene as the rasterizer takes it (scene-raster, `stepwise scene raster`), built once
// and exact: the tracer's camera as its double arithmetic computes it, the near plane, and every
// object's triangles (a sphere tessellated by the documented rule, a box's twelve, a plane's four
// wedges reaching infinity). The same triangles, as the tracer's objects, are what the exact ray
// cast of the visibility identity meets (raster_truth.hpp). Rules: docs/pipeline/semantics.md#scene-raster.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>
#include "core/number.hpp"
#include "input.hpp"
#include "pipeline/scene_raster.hpp"
#include "tracer/scene.hpp"

namespace sw::pipespec {

// A sphere's tessellation: `stacks` bands of latitude and 2 stacks slices of longitude.
inline constexpr int kDefaultStacks = 12, kMinStacks = 2, kMaxStacks = 256;

struct RasterOptions {
  std::int64_t width = 0, height = 0;  // 0: the scene's resolution
  int stacks = kDefaultStacks;
};

// An object's triangles: tris[first, first + count).
struct RasterObject {
  tracer::ObjectKind kind = tracer::ObjectKind::sphere;
  std::int32_t first = 0, count = 0;
};

struct RasterScene {
  std::shared_ptr<const tracer::Scene> scene;
  std::int64_t width = 1, height = 1;
  int stacks = kDefaultStacks;
  pipe::RasterCamera<Rational> camera;
  std::vector<pipe::RasterTriangle<Rational>> tris;
  std::vector<RasterObject> objects;
  // Per triangle, the shading normal at each corner (unit): a sphere's radial, a mesh's averaged
  // over the faces at the vertex, else the face's; a plane's wedges carry the plane's normal.
  std::vector<std::array<Vec3<double>, 3>> normals;
  // The same triangles as the ray tracer's objects, in rationals and in intervals: spheres and
  // boxes become meshes, planes stay planes. Their BVHs share one topology, built in double.
  tracer::TraceObjects<Rational> traced;
  tracer::TraceObjects<Interval> traced_iv;
};

// Throws InputError for a camera the rasterizer cannot take (fisheye, cylindrical) or a bad size.
std::shared_ptr<const RasterScene> raster_scene(std::shared_ptr<const tracer::Scene> s, const RasterOptions& o);

inline Vec3<double> to_double3(const Vec3<Rational>& v) { return {v.x.get_d(), v.y.get_d(), v.z.get_d()}; }

// A triangle's prim as the results name it: the triangle's index in its object, -1 for a plane's.
inline std::int32_t named_prim(const RasterScene& s, std::int32_t object, std::int32_t prim) {
  return s.objects[static_cast<std::size_t>(object)].kind == tracer::ObjectKind::plane ? -1 : prim;
}

template <class Num> pipe::RasterCamera<Num> camera_in(const pipe::RasterCamera<Rational>& c) {
  auto n = [](const Rational& q) { return num::from_rational<Num>(q); };
  return {to_num<Num>(c.eye), to_num<Num>(c.u), to_num<Num>(c.v), to_num<Num>(c.n), n(c.dist),
          {n(c.window[0]), n(c.window[1]), n(c.window[2]), n(c.window[3])}, n(c.near), c.width, c.height, c.orthographic, n(c.far)};
}
template <class Num> std::vector<pipe::RasterTriangle<Num>> triangles_in(const std::vector<pipe::RasterTriangle<Rational>>& tris) {
  std::vector<pipe::RasterTriangle<Num>> out(tris.size());
  auto n = [](const Rational& q) { return num::from_rational<Num>(q); };
  for (std::size_t i = 0; i < tris.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const pipe::Vec4<Rational>& x = tris[i].x[k];
      out[i].x[k] = {n(x.x), n(x.y), n(x.z), n(x.w)};
    }
    out[i].object = tris[i].object, out[i].prim = tris[i].prim;
  }
  return out;
}

// A perspective camera's near plane: half the least eye depth of any surface inside its view
// pyramid (the four sides' clip of every triangle), so that the near plane cuts nothing the
// pyramid holds; the view plane's distance d when it holds nothing. A polygon that reaches the eye
// holds it, so it is seen edge-on and covers no sample: it does not count.
Rational near_plane(pipe::RasterCamera<Rational> cam, const std::vector<pipe::RasterTriangle<Rational>>& tris);

// The exact ray of pixel (i, j), row 0 at the top, from the near plane: its origin is where the
// tracer's ray through the pixel's centre crosses eye depth `near`, so its hits at t > 0 are those
// the rasterizer keeps.
ray::Ray3<Rational> pixel_ray(const pipe::RasterCamera<Rational>& c, std::int64_t i, std::int64_t j);

// The raster's result in the tracer's orientation (row 0 at the top): per pixel the object
// (-1: none) and its prim (named_prim), and the window depth (1 where nothing was drawn).
struct RasterPixels {
  std::int64_t width = 0, height = 0;
  std::vector<std::int32_t> objects, prims;
  std::vector<double> depth;
  std::int64_t drawn = 0, culled = 0, cut = 0, fragments = 0, passed = 0;
};
template <class Num> RasterPixels raster_pixels(const RasterScene& s, const pipe::RasterImage<Num>& img) {
  RasterPixels o{s.width, s.height, {}, {}, {}, std::int64_t(img.drawn.size()), img.culled, img.cut, img.buffer.fragments, img.buffer.passed};
  const std::size_t n = static_cast<std::size_t>(s.width * s.height);
  o.objects.assign(n, -1), o.prims.assign(n, -1), o.depth.assign(n, 1.0);
  for (std::int64_t j = 0; j < s.height; ++j)
    for (std::int64_t i = 0; i < s.width; ++i) {
      const std::size_t from = static_cast<std::size_t>((s.height - 1 - j) * s.width + i), to = static_cast<std::size_t>(j * s.width + i);
      const std::int64_t id = img.buffer.id[from];
      o.depth[to] = num::to_double(img.buffer.depth[from]);
      if (id < 0) continue;
      const auto& d = img.drawn[static_cast<std::size_t>(id)];
      o.objects[to] = d[0], o.prims[to] = named_prim(s, d[0], d[1]);
    }
  return o;
}

// f(std::type_identity<Num>{}) in mode n: float, double, exact, or filtered (intervals, and exact
// rationals when they cannot decide; fell_back then says so). what names the algorithm in the
// error for another mode.
template <class F> auto in_mode(Numeric n, std::string_view what, bool* fell_back, F&& f) {
  if (fell_back) *fell_back = false;
  switch (n) {
    case Numeric::f32: return f(std::type_identity<float>{});
    case Numeric::f64: return f(std::type_identity<double>{});
    case Numeric::filtered:
      try {
        return f(std::type_identity<Interval>{});
      } catch (const Uncertain&) {
        if (fell_back) *fell_back = true;
        return f(std::type_identity<Rational>{});
      }
    case Numeric::exact: return f(std::type_identity<Rational>{});
    default: throw InputError(std::string(what) + " runs on float, double, filtered and exact, not '" + std::string(numeric_name(n)) + "'");
  }
}

// The scene drawn untraced in mode n: float, double, exact, or filtered (intervals, and exact
// rationals when they cannot decide; fell_back then says so).
RasterPixels draw(const RasterScene& s, Numeric n, bool* fell_back = nullptr);

}  // namespace sw::pipespec
