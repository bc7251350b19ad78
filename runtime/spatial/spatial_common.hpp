// What the spatial family's Specs share: the inputs (triangle meshes, inline or from OFF/OBJ files;
// points; segments; a ray), read as doubles, and the two result shapes every tree family returns:
// a ray query's closest hit and a built tree. Semantics: docs/spatial/semantics.md.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include "catalog.hpp"
#include "spatial/bounds.hpp"

namespace sw::oracle {
struct RayResult;
}

namespace sw::spatial {

// Coordinates beyond this are rejected, as in the rays family: double products of a few
// coordinates cannot overflow.
inline constexpr double kCoordBound = 1e15;
// The documented size bounds (docs/spatial/semantics.md): a mesh of at most this many triangles,
// a point set of at most this many points, and a mesh file of at most this many bytes.
inline constexpr std::size_t kMaxTriangles = std::size_t{1} << 21;
inline constexpr std::size_t kMaxPoints = std::size_t{1} << 21;
inline constexpr std::size_t kMaxMeshBytes = std::size_t{256} << 20;

// A coordinate: a JSON number or an exact string that is exactly a double (spatial inputs are
// doubles, so meshes, Embree and nanoflann see the same numbers), finite and within the bound.
double parse_coord(const Json& v, const std::string& what);
template <int D> std::array<double, D> parse_vec(const Json& v, const std::string& what);

// An indexed triangle mesh. Inline triangles become three vertices each; a file's shared vertices
// stay shared, so a ray through a shared edge meets the same two vertices in both triangles.
struct Mesh {
  std::vector<std::array<double, 3>> v;
  std::vector<std::array<std::int32_t, 3>> f;
  std::size_t size() const { return f.size(); }
  template <class Num> std::array<Vec3<Num>, 3> triangle(std::size_t i) const {
    std::array<Vec3<Num>, 3> t;
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) t[c][k] = num_from_double<Num>(v[f[i][c]][k]);
    return t;
  }
  template <class Num> static Num num_from_double(double x) {
    if constexpr (std::is_same_v<Num, Rational>) return num::to_rational(x);
    else return Num(x);
  }
};
// The input's "triangles" ([[[x,y,z] x3], ...]) or "mesh" (an .off or .obj file name): exactly
// one of them. Zero-area triangles are valid (they are never hit).
Mesh parse_mesh(const Json& input, const std::string& what);
// Reads an OFF or OBJ file (by its extension). Polygons are split into fans. Errors name the
// file and line.
Mesh read_mesh_file(const std::string& path);
// How many mesh files have been opened in this process (the parse-once tests read it).
std::uint64_t mesh_files_opened();

template <int D> std::vector<std::array<double, D>> parse_points(const Json& arr, const std::string& what);

struct RayIn {
  std::array<double, 3> o{}, d{};  // d != 0; a -0.0 component is kept
};
RayIn parse_ray(const Json& ray, const std::string& what);
template <class Num> Num from_double(double x) { return Mesh::num_from_double<Num>(x); }
template <class Num, int D> VecN<Num, D> vec_from(const std::array<double, D>& a) {
  VecN<Num, D> v;
  for (int k = 0; k < D; ++k) v[k] = from_double<Num>(a[k]);
  return v;
}

// A ray query's answer: the closest hit over all primitives (ties on t: the lowest primitive id).
struct HitOutput {
  bool hit = false;
  std::int32_t prim = -1;
  int bits = 53;  // significand bits of the mode (24 for float)
  double t = 0;
  std::array<double, 3> b{};
  std::shared_ptr<const oracle::RayResult> exact;  // exact mode: t and b exactly
  std::size_t nodes_visited = 0, prim_tests = 0;   // the traversal's work (not compared)
  // Hit, primitive, and when both sides are exact, t and b.
  friend bool operator==(const HitOutput& x, const HitOutput& y);
};
HitOutput make_exact_hit(bool hit, std::int32_t prim, const Rational& t, const std::array<Rational, 3>& b);
template <class Num> HitOutput make_hit(bool hit, std::int32_t prim, const Num& t, const std::array<Num, 3>& b) {
  if constexpr (std::is_same_v<Num, Rational>) {
    return make_exact_hit(hit, prim, t, b);
  } else {
    HitOutput o;
    o.hit = hit;
    o.bits = std::is_same_v<Num, float> ? 24 : 53;
    if (hit) o.prim = prim, o.t = num::to_double(t), o.b = {num::to_double(b[0]), num::to_double(b[1]), num::to_double(b[2])};
    return o;
  }
}
Json hit_json(const HitOutput& o);  // {"hit","t","prim","b","nodes_visited","prim_tests"}
// The oracle's closest hit over all of the mesh's triangles.
HitOutput closest_hit_oracle(const Mesh& m, const RayIn& r);
// t's error in ulps of the producing mode, at the exact t (0 for a miss on either side).
double hit_error(const HitOutput& got, const HitOutput& exact);

// A built tree, flat: node 0 is the root; a node's cell (kd-tree, quadtree, octree, BSP's region
// box) or bounding box (BVH) is lo..hi, dim values each. Leaves hold primitive (or point) ids.
struct TreeNode {
  std::int32_t parent = -1;
  std::vector<std::int32_t> children;  // empty for a leaf
  std::vector<std::int32_t> prims;     // a leaf's primitives
  std::int8_t axis = -1;               // the split axis, -1 if none
};
struct TreeOutput {
  int dim = 3, bits = 53;
  std::vector<TreeNode> nodes;
  std::vector<double> lo, hi;  // dim per node, as the mode computed them (exact: rounded)
  std::vector<Rational> exact_lo, exact_hi;  // exact mode only
  std::size_t leaves = 0, depth = 0, bytes = 0;
  double sah_cost = 0;
  // The same nodes, children and primitives, and when both sides are exact, the same bounds.
  friend bool operator==(const TreeOutput& x, const TreeOutput& y);
  // Node i's bound on axis k, exactly (a float or double bound is a rational too).
  Rational lo_at(std::size_t i, int k) const;
  Rational hi_at(std::size_t i, int k) const;
};
// Appends a node; its bounds are set with set_bounds.
std::int32_t add_node(TreeOutput& t, std::int32_t parent);
template <class Num, int D> void set_bounds(TreeOutput& t, std::int32_t node, const Box<Num, D>& b) {
  const std::size_t at = static_cast<std::size_t>(node) * D;
  if (t.lo.size() < at + D) t.lo.resize(at + D), t.hi.resize(at + D);
  if constexpr (std::is_same_v<Num, Rational>)
    if (t.exact_lo.size() < at + D) t.exact_lo.resize(at + D), t.exact_hi.resize(at + D);
  for (int k = 0; k < D; ++k) {
    t.lo[at + k] = num::to_double(b.lo[k]), t.hi[at + k] = num::to_double(b.hi[k]);
    if constexpr (std::is_same_v<Num, Rational>) t.exact_lo[at + k] = b.lo[k], t.exact_hi[at + k] = b.hi[k];
  }
}
// {"nodes","leaves","depth","sah_cost","bytes","tree":[{"parent","children"|"prims","lo","hi","axis"}...]}
Json tree_json(const TreeOutput& t);
// The tree as the oracle states it: without "bytes", the memory the mode's nodes take, which
// depends on the number type and is no part of the answer (`check` compares the rest).
inline Json tree_canonical(Json r) {
  if (r.is_object()) r.erase("bytes");
  return r;
}

}  // namespace sw::spatial
