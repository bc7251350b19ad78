// The pipeline family's shared input: a camera as GL takes it (gluLookAt, glFrustum or glOrtho,
// glViewport, glDepthRange), parsed once, exact. JSON (docs/pipeline/semantics.md):
//   "camera": {"eye": [x,y,z], "target": [x,y,z], "up": [x,y,z]},
//   "projection": {"perspective": [l,r,b,t,n,f]} or {"orthographic": [l,r,b,t,n,f]},
//   "viewport": [x, y, width, height], and optionally "depth_range": [dn, df] (default [0, 1]).
#pragma once
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>
#include "catalog.hpp"
#include "core/number.hpp"
#include "input.hpp"
#include "pipeline/camera.hpp"
#include "pipeline_oracle.hpp"

namespace sw::pipespec {

// Every coordinate, matrix entry and projection bound: |v| <= kCoordBound, with the curves' 64-bit
// bound on numerator and denominator.
inline constexpr double kCoordBound = 1e6;
inline constexpr std::int64_t kMaxViewport = 16384;  // GL's usual GL_MAX_VIEWPORT_DIMS
inline constexpr std::size_t kMaxPrimitives = 4096;  // points, triangles or volumes in one input

struct CameraInput {
  pipe::Camera<Rational> cam;
  // gluLookAt's frame is rational: its two lengths are. Exact and filtered modes need that
  // (admit_camera refuses them otherwise); reference mode takes the roots to 300 bits.
  bool rational_frame = false;
};

// Reads "camera", "projection", "viewport" and "depth_range" of j (the caller checks j's keys).
CameraInput parse_camera(const Json& j);
// Throws InputError when the mode cannot compute this camera exactly (filtered and exact need a
// rational frame).
void admit_camera(const CameraInput& c, Numeric n);
// A number within kCoordBound and the digit bound; `what` names it in errors.
Rational parse_coord(const Json& v, const std::string& what);
Vec3<Rational> parse_coord3(const Json& v, const std::string& what);

inline std::array<Rational, 3> arr_of(const Vec3<Rational>& v) { return {v.x, v.y, v.z}; }

// v on the grid of 2^-bits (truncated toward zero), exactly: the bench sets' seeded coordinates.
// Precondition: |v| 2^bits fits a long.
inline Rational on_grid(double v, int bits) { return Rational(static_cast<long>(std::ldexp(v, bits))) / Rational(static_cast<long>(1L << bits)); }

// The raster algorithms' error: the pixels whose ids differ.
inline double differing_ids(const std::vector<std::int64_t>& got, const std::vector<std::int64_t>& exact) {
  double wrong = 0;
  for (std::size_t i = 0; i < got.size() && i < exact.size(); ++i) wrong += got[i] != exact[i];
  return wrong;
}

// The samples of a window-space triangle's bounding box that lie in a width x height window: a
// bound on the fragments it makes, for the raster algorithms' step estimates.
double window_box_samples(const std::array<std::array<Rational, 3>, 3>& v, std::int64_t width, std::int64_t height);

template <class Num> pipe::Camera<Num> camera_as(const pipe::Camera<Rational>& c) {
  auto n = [](const Rational& q) { return num::from_rational<Num>(q); };
  pipe::Camera<Num> o;
  o.look = {to_num<Num>(c.look.eye), to_num<Num>(c.look.target), to_num<Num>(c.look.up)};
  o.proj = {c.proj.perspective, n(c.proj.l), n(c.proj.r), n(c.proj.b), n(c.proj.t), n(c.proj.n), n(c.proj.f)};
  o.view = {n(c.view.x), n(c.view.y), n(c.view.w), n(c.view.h), n(c.view.dn), n(c.view.df)};
  return o;
}

// A window and the triangles drawn in it, in window coordinates, as the raster algorithms take them:
//   "size": [width, height] (1 to kMaxWindowSide each),
//   "triangles": [{"v": [[x,y,z], [x,y,z], [x,y,z]], "id": k, "offset": [factor, units]}, ...]
// with |x|, |y| <= kWindowBound and depth z in [0, 1]; "offset" (glPolygonOffset) only where
// with_offset, ids (default: the index) distinct where distinct_ids. The caller checks j's keys.
inline constexpr std::int64_t kMaxWindowSide = 512;
inline constexpr double kWindowBound = 1e5;
struct WindowTriangles {
  std::int64_t width = 0, height = 0;
  std::vector<pipeline_oracle::DepthTriangle> tris;
};
WindowTriangles parse_window_triangles(const Json& j, std::size_t max_triangles, bool with_offset, bool distinct_ids);

// j[key]: a list of 1 to kMaxPrimitives items (`shape` names them in the error).
const Json& primitive_list(const Json& j, const char* key, const char* shape);

// Seeded random cameras with rational frames, looking at the origin from about `distance`, with a
// symmetric perspective frustum [-1,1]^2 at near n and far f, viewport w x h.
struct CameraGen {
  explicit CameraGen(std::uint64_t seed) : state(seed) {}
  CameraInput next(const Rational& distance, const Rational& n, const Rational& f, std::int64_t w, std::int64_t h);
  std::uint64_t state;
};

// A point of a random camera's view volume (window [-1,1]^2 at near 1), on a 2^-20 grid: depth d
// in [d0, d1], across (x, y) in [-1, 1]^2 of the window at that depth.
Vec3<Rational> volume_point(const CameraInput& c, std::mt19937_64& rng, double d0, double d1);

}  // namespace sw::pipespec
