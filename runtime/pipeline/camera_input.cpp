// The pipeline family's camera input (camera_input.hpp).
#include "pipeline/camera_input.hpp"
#include <algorithm>
#include <cmath>
#include <set>
#include "core/functions.hpp"

namespace sw::pipespec {

Rational parse_coord(const Json& v, const std::string& what) {
  Rational q = parse_rational(v, what);
  check_bound(q, kCoordBound, what);
  check_digits(q, what);
  return q;
}

Vec3<Rational> parse_coord3(const Json& v, const std::string& what) {
  if (!v.is_array() || v.size() != 3) throw InputError(what + ": expected [x, y, z]");
  return {parse_coord(v[0], what + "[0]"), parse_coord(v[1], what + "[1]"), parse_coord(v[2], what + "[2]")};
}

namespace {

template <std::size_t N> std::array<Rational, N> parse_coords(const Json& v, const std::string& what, const char* shape) {
  if (!v.is_array() || v.size() != N) throw InputError(what + ": expected " + shape);
  std::array<Rational, N> out;
  for (std::size_t k = 0; k < N; ++k) out[k] = parse_coord(v[k], what + "[" + std::to_string(k) + "]");
  return out;
}

bool is_square(const Rational& x) { return num::root(x).exact; }

}  // namespace

CameraInput parse_camera(const Json& j) {
  CameraInput in;
  pipe::Camera<Rational>& c = in.cam;
  const Json& look = require(j, "camera", "input");
  if (!look.is_object()) throw InputError("input.camera: expected {\"eye\": [x,y,z], \"target\": [x,y,z], \"up\": [x,y,z]}");
  only_keys(look, {"eye", "target", "up"}, "input.camera");
  c.look = {parse_coord3(look["eye"], "input.camera.eye"), parse_coord3(look["target"], "input.camera.target"),
            parse_coord3(look["up"], "input.camera.up")};
  const Vec3<Rational> f = c.look.target - c.look.eye, side = cross(f, c.look.up);
  if (dot(f, f) == 0) throw InputError("input.camera: target equals eye, so the camera looks nowhere");
  if (dot(side, side) == 0) throw InputError("input.camera.up: parallel to target - eye (or zero), so the camera has no up");
  in.rational_frame = is_square(dot(f, f)) && is_square(dot(side, side));

  const Json& p = require(j, "projection", "input");
  if (!p.is_object() || p.size() != 1 || !(p.contains("perspective") || p.contains("orthographic")))
    throw InputError("input.projection: expected {\"perspective\": [l,r,b,t,n,f]} or {\"orthographic\": [l,r,b,t,n,f]}");
  c.proj.perspective = p.contains("perspective");
  const std::string pw = c.proj.perspective ? "input.projection.perspective" : "input.projection.orthographic";
  const auto b = parse_coords<6>(p.begin().value(), pw, "[left, right, bottom, top, near, far]");
  c.proj.l = b[0], c.proj.r = b[1], c.proj.b = b[2], c.proj.t = b[3], c.proj.n = b[4], c.proj.f = b[5];
  if (!(c.proj.l < c.proj.r)) throw InputError(pw + ": left must be less than right");
  if (!(c.proj.b < c.proj.t)) throw InputError(pw + ": bottom must be less than top");
  if (!(c.proj.n < c.proj.f)) throw InputError(pw + ": near must be less than far");
  if (c.proj.perspective && !(c.proj.n > 0)) throw InputError(pw + ": near must be positive in perspective");

  const auto v = parse_coords<4>(require(j, "viewport", "input"), "input.viewport", "[x, y, width, height]");
  for (int k = 0; k < 4; ++k)
    if (v[k].get_den() != 1) throw InputError("input.viewport[" + std::to_string(k) + "]: " + v[k].get_str() + " is not an integer");
  for (int k = 2; k < 4; ++k)
    if (v[k] < 1 || v[k] > kMaxViewport)
      throw InputError("input.viewport[" + std::to_string(k) + "]: " + v[k].get_str() + " is outside [1, " + std::to_string(kMaxViewport) + "]");
  c.view = {v[0], v[1], v[2], v[3], Rational(0), Rational(1)};
  if (j.contains("depth_range")) {
    const auto d = parse_coords<2>(j["depth_range"], "input.depth_range", "[near, far]");
    for (int k = 0; k < 2; ++k)
      if (d[k] < 0 || d[k] > 1) throw InputError("input.depth_range[" + std::to_string(k) + "]: " + d[k].get_str() + " is outside [0, 1]");
    c.view.dn = d[0], c.view.df = d[1];
  }
  return in;
}

void admit_camera(const CameraInput& c, Numeric n) {
  if ((n == Numeric::filtered || n == Numeric::exact) && !c.rational_frame)
    throw InputError(std::string("input.camera: ") + std::string(numeric_name(n)) +
                     " mode needs |target - eye| and |(target - eye) x up| rational (an axis-aligned or Pythagorean camera); "
                     "this camera's are irrational: use reference mode");
}

const Json& primitive_list(const Json& j, const char* key, const char* shape) {
  const Json& list = require(j, key, "input");
  if (!list.is_array() || list.empty() || list.size() > kMaxPrimitives)
    throw InputError(std::string("input.") + key + ": expected a list of 1 to " + std::to_string(kMaxPrimitives) + " " + shape);
  return list;
}

Vec3<Rational> volume_point(const CameraInput& c, std::mt19937_64& rng, double d0, double d1) {
  std::uniform_real_distribution<double> depth(d0, d1), across(-1, 1);
  auto q = [](double v) { return on_grid(v, 20); };
  const pipe::Frame<Rational> fr = pipe::look_frame(c.cam.look);
  const double d = depth(rng);
  return c.cam.look.eye + q(d) * fr.f + q(across(rng) * d) * fr.s + q(across(rng) * d) * fr.u;
}

double window_box_samples(const std::array<std::array<Rational, 3>, 3>& v, std::int64_t width, std::int64_t height) {
  auto span = [&](int a, std::int64_t side) {
    const Rational lo = std::min({v[0][a], v[1][a], v[2][a]}), hi = std::max({v[0][a], v[1][a], v[2][a]});
    const double l = std::max(0.0, std::ceil(lo.get_d())), h = std::min(double(side - 1), std::floor(hi.get_d()));
    return std::max(0.0, h - l + 1);
  };
  return span(0, width) * span(1, height);
}

WindowTriangles parse_window_triangles(const Json& j, std::size_t max_triangles, bool with_offset, bool distinct_ids) {
  WindowTriangles out;
  const Json& size = require(j, "size", "input");
  if (!size.is_array() || size.size() != 2) throw InputError("input.size: expected [width, height]");
  out.width = parse_integer(size[0], "input.size[0]", 1, kMaxWindowSide);
  out.height = parse_integer(size[1], "input.size[1]", 1, kMaxWindowSide);
  const Json& ts = require(j, "triangles", "input");
  if (!ts.is_array() || ts.empty() || ts.size() > max_triangles)
    throw InputError("input.triangles: expected a list of 1 to " + std::to_string(max_triangles) + " triangles");
  const std::string shape = with_offset ? R"({"v": [[x,y,z],[x,y,z],[x,y,z]], "id": k, "offset": [factor, units]})" : R"({"v": [[x,y,z],[x,y,z],[x,y,z]], "id": k})";
  std::set<std::int64_t> ids;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const std::string what = "input.triangles[" + std::to_string(i) + "]";
    const Json& t = ts[i];
    if (!t.is_object()) throw InputError(what + ": expected " + shape);
    if (with_offset) only_keys_optional(t, {"v"}, {"id", "offset"}, what);
    else only_keys_optional(t, {"v"}, {"id"}, what);
    pipeline_oracle::DepthTriangle d;
    if (!t["v"].is_array() || t["v"].size() != 3) throw InputError(what + ".v: expected three vertices [x, y, z]");
    for (int k = 0; k < 3; ++k) {
      const std::string w = what + ".v[" + std::to_string(k) + "]";
      d.v[k] = arr_of(parse_coord3(t["v"][k], w));
      for (int a = 0; a < 2; ++a) check_bound(d.v[k][a], kWindowBound, w + "[" + std::to_string(a) + "]");
      if (d.v[k][2] < 0 || d.v[k][2] > 1) throw InputError(w + "[2]: depth " + d.v[k][2].get_str() + " is outside [0, 1] (clip first)");
    }
    d.id = t.contains("id") ? parse_integer(t["id"], what + ".id", 0, 1 << 20) : std::int64_t(i);
    if (distinct_ids && !ids.insert(d.id).second)
      throw InputError(t.contains("id") ? what + ".id: " + std::to_string(d.id) + " is already another triangle's"
                                        : what + ": its default id " + std::to_string(d.id) + " (its index) is already another triangle's");
    if (t.contains("offset")) {
      const Json& o = t["offset"];
      if (!o.is_array() || o.size() != 2) throw InputError(what + ".offset: expected [factor, units] (glPolygonOffset)");
      d.factor = parse_coord(o[0], what + ".offset[0]"), d.units = parse_coord(o[1], what + ".offset[1]");
    }
    out.tris.push_back(d);
  }
  return out;
}

CameraInput CameraGen::next(const Rational& distance, const Rational& n, const Rational& f, std::int64_t w, std::int64_t h) {
  auto small = [this] {  // a small integer in [-4, 4] (splitmix64)
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return static_cast<long>((z ^ (z >> 31)) % 9) - 4;
  };
  long a = small(), b = small(), cq = small(), d = small();
  if (a == 0 && b == 0 && cq == 0 && d == 0) a = 1;  // the zero quaternion is no rotation
  // A rational rotation from the quaternion (a, b, c, d): its columns are rational unit vectors.
  const Rational q2(a * a + b * b + cq * cq + d * d);
  const Vec3<Rational> col_y{Rational(2 * (b * cq - a * d)) / q2, Rational(a * a - b * b + cq * cq - d * d) / q2, Rational(2 * (cq * d + a * b)) / q2};
  const Vec3<Rational> col_z{Rational(2 * (b * d + a * cq)) / q2, Rational(2 * (cq * d - a * b)) / q2, Rational(a * a - b * b - cq * cq + d * d) / q2};
  CameraInput in;
  in.cam.look = {distance * col_z, Vec3<Rational>{}, col_y};  // looks along -col_z at the origin
  in.cam.proj = {true, Rational(-1), Rational(1), Rational(-1), Rational(1), n, f};
  in.cam.view = {Rational(0), Rational(0), Rational(w), Rational(h), Rational(0), Rational(1)};
  in.rational_frame = true;
  return in;
}

}  // namespace sw::pipespec
