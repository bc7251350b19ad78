// The point trees in the catalog: quadtree-build (2D points) and octree-build (3D points or
// triangles), registered here. Semantics, bounds and budgets: docs/spatial/point-trees.md.
#include <random>
#include "register.hpp"
#include "spatial/octree_build.hpp"
#include "spatial/quadtree_build.hpp"
#include "spatial/spatial_common.hpp"
#include "spatial_point_trees_oracle.hpp"

namespace sw {
namespace {

using spatial::CellTree;
using spatial::Mesh;
using spatial::TreeOutput;

// The octree's default reference budget (leaf entries), and the most an input may ask for.
constexpr std::int64_t kDefaultMaxRefs = std::int64_t{1} << 22;
constexpr std::int64_t kMaxMaxRefs = std::int64_t{1} << 24;

// A cell tree as the family's flat tree; budget_stops rides along (0 for the quadtree).
struct CellTreeOutput {
  TreeOutput tree;
  std::size_t budget_stops = 0;
  friend bool operator==(const CellTreeOutput& a, const CellTreeOutput& b) { return a.tree == b.tree && a.budget_stops == b.budget_stops; }
};

template <class Num, int D> CellTreeOutput to_output(const CellTree<Num, D>& t) {
  CellTreeOutput o;
  o.tree.dim = D;
  o.tree.bits = std::is_same_v<Num, float> ? 24 : 53;
  std::size_t refs = 0;
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    const auto& n = t.nodes[i];
    const std::int32_t id = spatial::add_node(o.tree, n.parent);  // children are appended after their parent
    spatial::set_bounds(o.tree, id, n.cell);
    if (n.first_child < 0) o.tree.nodes[i].prims = n.items, ++o.tree.leaves, refs += n.items.size();
  }
  o.tree.depth = t.depth;
  // A node: its bounds, parent and first child; a leaf entry: one 32-bit id.
  o.tree.bytes = t.nodes.size() * (2 * D * sizeof(double) + 8) + refs * 4;
  o.budget_stops = t.budget_stops;
  return o;
}

// The oracle's tree in the same form (exact bounds).
template <int D> CellTreeOutput from_spec(const oracle::CellSpecTree& t) {
  CellTreeOutput o;
  o.tree.dim = D;
  std::size_t refs = 0;
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    const auto& n = t.nodes[i];
    const std::int32_t id = spatial::add_node(o.tree, n.parent);
    spatial::Box<Rational, D> b;
    for (int a = 0; a < D; ++a) b.lo[a] = n.lo[a], b.hi[a] = n.hi[a];
    spatial::set_bounds(o.tree, id, b);
    if (n.children.empty()) o.tree.nodes[i].prims = n.items, ++o.tree.leaves, refs += n.items.size();
  }
  o.tree.depth = t.depth;
  o.tree.bytes = t.nodes.size() * (2 * D * sizeof(double) + 8) + refs * 4;
  o.budget_stops = t.budget_stops;
  return o;
}

Json output_json(const CellTreeOutput& o) {
  Json j = spatial::tree_json(o.tree);
  j["budget_stops"] = o.budget_stops;
  return j;
}
// Rounded modes are compared by structure: 1 if the tree differs from the exact one.
double tree_error(const CellTreeOutput& got, const CellTreeOutput& exact) { return got == exact ? 0 : 1; }

struct Params {
  std::size_t capacity = 4;
  int max_depth = 12;
  std::size_t max_refs = kDefaultMaxRefs;
};
Params parse_params(const Json& j, int depth_bound, int default_depth) {
  Params p;
  p.max_depth = default_depth;
  if (j.contains("capacity")) p.capacity = static_cast<std::size_t>(parse_integer(j["capacity"], "input.capacity", 1, 64));
  if (j.contains("max_depth")) p.max_depth = static_cast<int>(parse_integer(j["max_depth"], "input.max_depth", 1, depth_bound));
  if (j.contains("max_refs")) p.max_refs = static_cast<std::size_t>(parse_integer(j["max_refs"], "input.max_refs", 1, kMaxMaxRefs));
  return p;
}

// An upper bound on a cell tree build's steps: root and done; per split a split, a push and a visit
// of each child; per item placed a step. A level places at most the references it holds (n points;
// at most min(max_refs, 8^level n) triangle references), and a split places more than `capacity`.
std::size_t cell_tree_steps(std::size_t n, bool triangles, const Params& p, std::size_t children) {
  std::size_t placed = 0, refs = n;
  for (int level = 0; level < p.max_depth; ++level) {
    placed += refs;
    if (triangles) refs = std::min(p.max_refs, refs * children);
  }
  return (2 + children) * (placed / (p.capacity + 1)) + placed + 16;
}

template <int D> std::vector<std::array<double, D>> random_points(std::mt19937_64& rng, std::size_t n, bool clustered) {
  std::uniform_real_distribution<double> u(-100, 100);
  std::normal_distribution<double> g(0, 3);
  std::vector<std::array<double, D>> out(n);
  std::array<double, D> centre{};
  for (std::size_t i = 0; i < n; ++i) {
    if (clustered && i % 100 == 0)
      for (int a = 0; a < D; ++a) centre[a] = u(rng);
    for (int a = 0; a < D; ++a) out[i][a] = std::ldexp(std::round(std::ldexp(clustered ? centre[a] + g(rng) : u(rng), 10)), -10);
  }
  return out;
}

// ---- quadtree-build ----

struct QuadInput {
  std::vector<std::array<double, 2>> points;
  Params p;
};

struct QuadtreeBuildSpec {
  static constexpr std::array hooks{Hook::handles, Hook::error, Hook::estimate_steps};
  using Algo = spatial::QuadtreeBuild;
  using Input = QuadInput;
  using Output = CellTreeOutput;
  static constexpr std::array views{View::tree, View::plane2d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example =
      R"({"points":[[1,1],[3,2],[2,6],[6,6],[7,1],[5,3],[4,4],[6.5,5.5],[1.5,7],[2,2]],"capacity":2,"max_depth":4})";
  static Input parse(const Json& j) {
    only_keys_optional(j, {"points"}, {"capacity", "max_depth"}, "input");
    Input in{spatial::parse_points<2>(j["points"], "input.points"), parse_params(j, 24, 12)};
    // Each point is placed once per level: bound the work before running.
    if (in.points.size() * static_cast<std::size_t>(in.p.max_depth) > (std::size_t{1} << 25))
      throw InputError("input: points x max_depth = " + std::to_string(in.points.size() * in.p.max_depth) + ", more than the budget of 2^25");
    return in;
  }
  static std::vector<Handle> handles() {
    std::vector<Handle> h;
    for (int k = 0; k < 4; ++k) h.push_back({"/points/" + std::to_string(k), Handle::Kind::point2, 8, "p" + std::to_string(k)});
    return h;
  }
  template <class Num> struct Prepared {
    std::vector<Vec2<Num>> points;
    Params p;
  };
  template <class Num> static Prepared<Num> prepare(const Input& in) {
    Prepared<Num> out{{}, in.p};
    for (const auto& q : in.points) out.points.push_back(spatial::vec_from<Num, 2>(q));
    return out;
  }
  template <class Num, class Probe> static Output compute(const Prepared<Num>& in, Probe& probe) {
    return to_output(spatial::quadtree_build<Num>(in.points, in.p.capacity, in.p.max_depth, probe));
  }
  static Json to_json(const Output& o) { return output_json(o); }
  static std::size_t ops(const Output& o) { return o.tree.nodes.size(); }
  static constexpr std::string_view error_unit = "trees";
  static double error(const Output& got, const Output& exact) { return tree_error(got, exact); }
  // A visit per node and a place per point and level; a node per 4 placements at most, plus 4.
  static std::size_t estimate_steps(const Input& in) { return cell_tree_steps(in.points.size(), false, in.p, 4); }
  // Each cell's points found by testing every point (oracle/spatial_point_trees_oracle.*).
  static Output oracle(const Input& in) {
    std::vector<std::vector<Rational>> pts;
    for (const auto& p : in.points) pts.push_back({num::to_rational(p[0]), num::to_rational(p[1])});
    return from_spec<2>(oracle::point_cell_tree(pts, in.p.capacity, in.p.max_depth));
  }
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(20261126);
    BenchSet<Input> uniform{"uniform-2k", {}}, clustered{"clustered-2k", {}}, same{"identical-10k", {}};
    for (int s = 0; s < 10; ++s) uniform.inputs.push_back({random_points<2>(rng, 2000, false), {}});
    for (int s = 0; s < 10; ++s) clustered.inputs.push_back({random_points<2>(rng, 2000, true), {}});
    for (int s = 0; s < 2; ++s) same.inputs.push_back({std::vector<std::array<double, 2>>(10000, {1.5, -2.25}), {}});
    return {uniform, clustered, same};
  }
};

// ---- octree-build ----

struct OctInput {
  std::vector<std::array<double, 3>> points;  // or
  Mesh mesh;
  Params p;
};

struct OctreeBuildSpec {
  static constexpr std::array hooks{Hook::handles, Hook::error, Hook::estimate_steps};
  using Algo = spatial::OctreeBuild;
  using Input = OctInput;
  using Output = CellTreeOutput;
  static constexpr std::array views{View::tree, View::orbit3d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example =
      R"({"triangles":[[[0,0,0],[4,0,0],[0,4,0]],[[4,4,4],[0,4,4],[4,0,4]],[[0,0,4],[1,1,3],[0,2,4]],[[3,3,0],[4,3,1],[3,4,1]],[[2,2,2],[2,2,2],[2,2,2]]],"capacity":1,"max_depth":3})";
  static Input parse(const Json& j) {
    Input in;
    if (j.is_object() && j.contains("points")) {
      only_keys_optional(j, {"points"}, {"capacity", "max_depth", "max_refs"}, "input");
      in.points = spatial::parse_points<3>(j["points"], "input.points");
    } else {
      if (!j.is_object()) throw InputError("input: expected an object");
      only_keys_optional(j, {}, {"triangles", "mesh", "capacity", "max_depth", "max_refs"}, "input");
      in.mesh = spatial::parse_mesh(j, "input");
      if (in.mesh.size() == 0) throw InputError("input: the mesh has no triangles");
    }
    in.p = parse_params(j, 16, 8);
    if (!in.points.empty() && in.points.size() * static_cast<std::size_t>(in.p.max_depth) > (std::size_t{1} << 25))
      throw InputError("input: points x max_depth = " + std::to_string(in.points.size() * in.p.max_depth) + ", more than the budget of 2^25");
    return in;
  }
  static std::vector<Handle> handles() {
    std::vector<Handle> h;
    for (int k = 0; k < 3; ++k) h.push_back({"/triangles/0/" + std::to_string(k), Handle::Kind::point3, 1, "v" + std::to_string(k)});
    return h;
  }
  template <class Num> struct Prepared {
    spatial::OctreeItems<Num> items;
    Params p;
  };
  template <class Num> static Prepared<Num> prepare(const Input& in) {
    Prepared<Num> out{{}, in.p};
    for (const auto& q : in.points) out.items.points.push_back(spatial::vec_from<Num, 3>(q));
    for (std::size_t i = 0; i < in.mesh.size(); ++i) out.items.triangles.push_back(in.mesh.triangle<Num>(i));
    return out;
  }
  template <class Num, class Probe> static Output compute(const Prepared<Num>& in, Probe& probe) {
    return to_output(spatial::octree_build<Num>(in.items, in.p.capacity, in.p.max_depth, in.p.max_refs, probe));
  }
  static Json to_json(const Output& o) { return output_json(o); }
  static std::size_t ops(const Output& o) { return o.tree.nodes.size(); }
  static constexpr std::string_view error_unit = "trees";
  static double error(const Output& got, const Output& exact) { return tree_error(got, exact); }
  static std::size_t estimate_steps(const Input& in) {
    return in.points.empty() ? cell_tree_steps(in.mesh.size(), true, in.p, 8) : cell_tree_steps(in.points.size(), false, in.p, 8);
  }
  // Each cell's items found by testing every item: half-open for points, CGAL's closed
  // triangle-box overlap for triangles (independent of the listing's separating axis test).
  static Output oracle(const Input& in) {
    if (!in.points.empty()) {
      std::vector<std::vector<Rational>> pts;
      for (const auto& p : in.points) pts.push_back({num::to_rational(p[0]), num::to_rational(p[1]), num::to_rational(p[2])});
      return from_spec<3>(oracle::point_cell_tree(pts, in.p.capacity, in.p.max_depth, in.p.max_refs));
    }
    std::vector<oracle::Triangle3> tris;
    for (std::size_t i = 0; i < in.mesh.size(); ++i) tris.push_back(in.mesh.triangle<Rational>(i));
    return from_spec<3>(oracle::triangle_cell_tree(tris, in.p.capacity, in.p.max_depth, in.p.max_refs));
  }
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(20261127);
    BenchSet<Input> pts{"points-2k", {}}, tris{"triangles-500", {}};
    for (int s = 0; s < 10; ++s) pts.inputs.push_back({random_points<3>(rng, 2000, true), {}, {}});
    std::uniform_real_distribution<double> off(-2, 2);
    for (int s = 0; s < 10; ++s) {
      Input in;
      for (const auto& c : random_points<3>(rng, 500, false)) {
        in.mesh.f.push_back({static_cast<std::int32_t>(in.mesh.v.size()), static_cast<std::int32_t>(in.mesh.v.size() + 1), static_cast<std::int32_t>(in.mesh.v.size() + 2)});
        for (int v = 0; v < 3; ++v) in.mesh.v.push_back({c[0] + std::round(off(rng) * 64) / 64, c[1] + std::round(off(rng) * 64) / 64, c[2] + std::round(off(rng) * 64) / 64});
      }
      tris.inputs.push_back(std::move(in));
    }
    return {pts, tris};
  }
};

SW_REGISTER(QuadtreeBuildSpec);
SW_REGISTER(OctreeBuildSpec);

}  // namespace

}  // namespace sw
