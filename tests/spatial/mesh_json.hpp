// A triangle mesh as the spatial algorithms' JSON input: {"triangles": [[[x,y,z] x 3], ...]}.
#pragma once
#include "input.hpp"
#include "spatial/spatial_common.hpp"

namespace sw::testing {

inline Json mesh_json(const spatial::Mesh& m) {
  Json t = Json::array();
  for (const auto& f : m.f) {
    Json tri = Json::array();
    for (int c = 0; c < 3; ++c) tri.push_back({m.v[f[c]][0], m.v[f[c]][1], m.v[f[c]][2]});
    t.push_back(tri);
  }
  return {{"triangles", t}};
}

}  // namespace sw::testing
