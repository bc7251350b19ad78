// Shared by the BVH tests: meshes and rays as catalog inputs, a run of bvh-traverse judged by the
// brute-force exact oracle (oracle/spatial_oracle.hpp), and the structural invariants of a build
// read back exactly from its result.
#pragma once
#include <catch2/catch.hpp>
#include <map>
#include <string>
#include "catalog.hpp"
#include "spatial/bvh_build.hpp"
#include "spatial/bvh_cases.hpp"
#include "spatial/mesh_json.hpp"
#include "spatial_oracle.hpp"

namespace sw::testing::bvh {

using spatial::Mesh;
using spatial::RayIn;

using sw::testing::mesh_json;

inline Json query_json(const Mesh& m, const RayIn& r, bool any = false, double t_max = 0) {
  Json j = mesh_json(m);
  j["ray"] = {{"o", {r.o[0], r.o[1], r.o[2]}}, {"d", {r.d[0], r.d[1], r.d[2]}}};
  if (any) j["any"] = true, j["t_max"] = t_max;
  return j;
}

inline std::vector<oracle::Triangle3> exact_tris(const Mesh& m) {
  std::vector<oracle::Triangle3> out;
  for (std::size_t i = 0; i < m.size(); ++i) out.push_back(m.triangle<Rational>(i));
  return out;
}

// One query in mode n against the oracle: whether the answer is right (closest hit: hit, prim
// and, in exact mode, t; any hit: hit iff the closest hit has t < t_max, and the hit reported
// really is one before t_max).
inline bool judge(const Mesh& m, const std::vector<oracle::Triangle3>& tris, const RayIn& r, Numeric n, bool any = false, double t_max = 0, Json* out = nullptr) {
  const Json res = find_algorithm("bvh-traverse").open(query_json(m, r, any, t_max), n).run();
  if (out) *out = res;
  const Vec3<Rational> o = spatial::vec_from<Rational, 3>(r.o), d = spatial::vec_from<Rational, 3>(r.d);
  const oracle::ClosestHit want = oracle::closest_hit(o, d, tris);
  const bool hit = res.at("hit").get<bool>();
  if (any) {
    const bool want_hit = want.hit && want.r.t < num::to_rational(t_max);
    if (hit != want_hit) return false;
    if (!hit) return true;
    const oracle::RayResult got = oracle::ray_triangle(o, d, tris[res.at("prim").get<std::size_t>()]);
    return got.hit && got.t < num::to_rational(t_max);
  }
  if (hit != want.hit) return false;
  if (!hit) return true;
  if (res.at("prim").get<std::int32_t>() != want.prim) return false;
  return n != Numeric::exact || res.at("t").get<std::string>() == want.r.t.get_str();
}

// The invariants of a build result (tree_json), exactly: every node's box contains its
// children's boxes and its triangles' vertices, every triangle is in exactly one leaf, leaves hold
// at most 8 triangles and the depth is within the bound. Returns "" or what is wrong. A float
// build bounds the float-rounded vertices (what that mode computes with).
inline std::string tree_invariants(const Mesh& m, const Json& res, Numeric n = Numeric::exact) {
  const Json& tree = res.at("tree");
  auto q = [](const Json& v) { return parse_rational(v, "bound"); };
  auto inside = [&](const Json& node, const std::array<Rational, 3>& lo, const std::array<Rational, 3>& hi) {
    for (int k = 0; k < 3; ++k)
      if (lo[k] < q(node["lo"][k]) || q(node["hi"][k]) < hi[k]) return false;
    return true;
  };
  std::vector<int> seen(m.size(), 0);
  std::size_t leaves = 0, max_depth = 0;
  std::vector<std::size_t> depth(tree.size(), 0);
  for (std::size_t i = 0; i < tree.size(); ++i) {
    const Json& nd = tree[i];
    const std::string at = "node " + std::to_string(i);
    if (i > 0) depth[i] = depth[nd.at("parent").get<std::size_t>()] + 1;
    max_depth = std::max(max_depth, depth[i]);
    if (nd.contains("children")) {
      if (nd["children"].size() != 2) return at + ": not two children";
      for (const Json& c : nd["children"]) {
        const Json& ch = tree.at(c.get<std::size_t>());
        if (ch.at("parent").get<std::size_t>() != i) return at + ": a child's parent";
        if (!inside(nd, {q(ch["lo"][0]), q(ch["lo"][1]), q(ch["lo"][2])}, {q(ch["hi"][0]), q(ch["hi"][1]), q(ch["hi"][2])})) return at + ": a child's box is not inside";
      }
    } else {
      ++leaves;
      if (nd["prims"].empty() || nd["prims"].size() > static_cast<std::size_t>(spatial::kBvhMaxLeaf)) return at + ": leaf size " + std::to_string(nd["prims"].size());
      for (const Json& p : nd["prims"]) {
        const auto id = p.get<std::size_t>();
        if (id >= m.size()) return at + ": no such triangle";
        ++seen[id];
        const auto t = n == Numeric::f32 ? [&] {
          const auto f = m.triangle<float>(id);
          std::array<Vec3<Rational>, 3> q;
          for (int c = 0; c < 3; ++c) q[c] = {num::to_rational(double(f[c].x)), num::to_rational(double(f[c].y)), num::to_rational(double(f[c].z))};
          return q;
        }() : m.triangle<Rational>(id);
        for (const auto& v : t)
          if (!inside(nd, {v.x, v.y, v.z}, {v.x, v.y, v.z})) return at + ": triangle " + std::to_string(id) + " sticks out";
      }
    }
  }
  for (std::size_t i = 0; i < m.size(); ++i)
    if (seen[i] != 1) return "triangle " + std::to_string(i) + " is in " + std::to_string(seen[i]) + " leaves";
  if (res.at("leaves").get<std::size_t>() != leaves) return "the leaf count";
  if (res.at("depth").get<std::size_t>() != max_depth) return "the depth";
  if (max_depth > static_cast<std::size_t>(spatial::kBvhMaxDepth)) return "depth beyond the bound";
  return "";
}

}  // namespace sw::testing::bvh
