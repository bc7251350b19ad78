// Generated hard cases of the ray family, shared by the bench sets (rays.cpp), the tests and the
// Embree peer benchmark. Every value is a float, so all numeric modes see the same input.
#pragma once
#include <array>
#include <cstdint>
#include <vector>
#include "input.hpp"

namespace sw::rays {

using F3 = std::array<float, 3>;
struct FRay {
  F3 o, d;
  int ci = 0, cj = 0;  // grid rays: the cell nearest the aim point
};

// A tessellated, tilted, slightly bent n x n grid: vertex (i, j) is a float point; cell (i, j)
// holds triangles 2(j n + i) = (v00, v10, v11) and 2(j n + i) + 1 = (v00, v11, v01).
struct Grid {
  int n = 0;
  std::vector<F3> verts;                  // (n + 1)^2, index j (n + 1) + i
  std::vector<std::array<int, 3>> tris;   // 2 n^2
  std::array<F3, 3> triangle(int t) const { return {verts[tris[t][0]], verts[tris[t][1]], verts[tris[t][2]]}; }
};
Grid make_grid(int n, std::uint64_t seed);
// Rays from above aimed at `per_edge` random points of every shared (interior) edge, and at every
// interior vertex; each ray's float direction is the rounded aim, so it passes within rounding of
// the edge or vertex.
std::vector<FRay> grid_rays(const Grid& g, int per_edge, std::uint64_t seed);

Json ray_json(const FRay& r);
Json triangle_input(const FRay& r, const std::array<F3, 3>& tri);

// The hard sets of the four primitives (triangle, sphere, box, plane), as catalog inputs.
std::vector<Json> hard_inputs(const char* primitive, std::uint64_t seed);
// Random float inputs with roughly half hits.
std::vector<Json> random_inputs(const char* primitive, int count, std::uint64_t seed);

}  // namespace sw::rays
