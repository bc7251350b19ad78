// Shared by the pipeline family's tests: an input's exact numbers read straight from its JSON, its
// camera, the inputs of an algorithm (example, corpus, seeded cameras) and the frustum edges' check.
#pragma once
#include <catch2/catch.hpp>
#include <algorithm>
#include <random>
#include <string>
#include "catalog.hpp"
#include "core/number.hpp"
#include "core/vec.hpp"
#include "corpus.hpp"
#include "input.hpp"
#include "pipeline/camera.hpp"
#include "pipeline_oracle.hpp"
#include "step_values.hpp"

namespace sw::testing::pipeline {

namespace po = sw::pipeline_oracle;

// An exact number of an input: a JSON number (a double, exactly) or a "p/q" string.
inline Rational q_of(const Json& v) {
  if (!v.is_string()) return num::to_rational(v.get<double>());
  Rational r(v.get<std::string>());
  r.canonicalize();
  return r;
}
inline Vec3<Rational> point_of(const Json& v) { return {q_of(v[0]), q_of(v[1]), q_of(v[2])}; }

using V3 = std::array<Rational, 3>;
inline V3 arr(const Vec3<Rational>& v) { return {v.x, v.y, v.z}; }
inline Vec3<Rational> vec(const V3& a) { return {a[0], a[1], a[2]}; }

inline void check_vec(StepValues& sv, const std::string& name, const V3& want) {
  for (int k = 0; k < 3; ++k) CHECK(sv[name + "." + "xyz"[k]] == want[k]);
}

// An input's window-space triangles ("triangles" of the z-buffer, depth-sort), read exactly.
inline std::vector<po::DepthTriangle> window_triangles_of(const Json& j) {
  std::vector<po::DepthTriangle> out;
  for (const Json& t : j["triangles"]) {
    po::DepthTriangle d;
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) d.v[k][a] = q_of(t["v"][k][a]);
    d.id = t.value("id", std::int64_t(out.size()));
    if (t.contains("offset")) d.factor = q_of(t["offset"][0]), d.units = q_of(t["offset"][1]);
    out.push_back(d);
  }
  return out;
}

// The inputs of one algorithm: its example, its corpus cases and `random` seeded variations of
// the example's camera made by `vary`.
inline std::vector<Json> inputs_of(std::string_view id) {
  std::vector<Json> out{Json::parse(find_algorithm(id).example)};
  for (const Json& j : corpus("pipeline"))
    if (j.contains("camera") && j.contains(id == "transform" ? "points" : id == "backface-cull" ? "triangles" : "objects")) out.push_back(j);
  // Seeded cameras with rational frames: eyes at Pythagorean offsets from the target.
  std::mt19937_64 rng(std::hash<std::string_view>{}(id));
  const std::array<std::array<int, 3>, 6> eyes{{{0, 3, 4}, {3, 0, 4}, {4, 3, 0}, {0, -4, 3}, {0, 5, 12}, {-12, 0, 5}}};
  for (const auto& e : eyes) {
    Json j = out[0];
    const int scale = 1 + static_cast<int>(rng() % 3);
    j["camera"]["eye"] = {e[0] * scale, e[1] * scale, e[2] * scale};
    j["camera"]["target"] = {0, 0, 0};
    j["camera"]["up"] = {0, 1, 0};
    out.push_back(j);
  }
  return out;
}

inline pipe::Camera<Rational> camera_of(const Json& j) {
  // The runtime's parse (via the catalog) is the one under test elsewhere; here the camera is read
  // straight from the JSON, exactly.
  auto q = [](const Json& v) { return q_of(v); };
  auto v3 = [&](const Json& v) { return Vec3<Rational>{q(v[0]), q(v[1]), q(v[2])}; };
  pipe::Camera<Rational> c;
  c.look = {v3(j["camera"]["eye"]), v3(j["camera"]["target"]), v3(j["camera"]["up"])};
  const bool persp = j["projection"].contains("perspective");
  const Json& b = persp ? j["projection"]["perspective"] : j["projection"]["orthographic"];
  c.proj = {persp, q(b[0]), q(b[1]), q(b[2]), q(b[3]), q(b[4]), q(b[5])};
  const Json& v = j["viewport"];
  c.view = {q(v[0]), q(v[1]), q(v[2]), q(v[3]), Rational(0), Rational(1)};
  if (j.contains("depth_range")) c.view.dn = q(j["depth_range"][0]), c.view.df = q(j["depth_range"][1]);
  return c;
}


// A segment3 item whose two ends are corners of the oracle's view volume.
inline void check_frustum_edges(StepGeometry& g, const po::Camera& cam) {
  const auto corners = po::corners(cam);
  for (int e = 0; e < 12; ++e) {
    GeoItem& item = g.take(GeoKind::segment3);
    CHECK(item.label == (e == 0 ? "frustum" : ""));
    CHECK(item.life == "keep");
    for (int end = 0; end < 2; ++end) {
      const V3 p{item.values[3 * end], item.values[3 * end + 1], item.values[3 * end + 2]};
      CHECK(std::find(corners.begin(), corners.end(), p) != corners.end());
    }
  }
}


}  // namespace sw::testing::pipeline
