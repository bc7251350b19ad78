// kd-traverse in the catalog: the closest hit of a ray in a mesh, through a kd-tree that kd-build
// makes first, as a nested listing. Semantics: docs/spatial/kd.md.
#include <random>
#include "register.hpp"
#include "spatial/kd_common.hpp"
#include "spatial/kd_traverse.hpp"
#include "spatial_oracle.hpp"

namespace sw {
namespace {

using namespace kdspec;

struct TraverseInput {
  Mesh mesh;
  RayIn ray;
};

template <class Num> struct TraversePrepared {
  std::vector<std::array<Vec3<Num>, 3>> tris;
  ray::Ray3<Num> ray;
};

// The traversal's own steps: at most every node visited (a visit, a decision and a move each,
// with the stack's boxes), and every reference tested (about 12 steps with the nested test).
std::size_t traverse_steps(std::size_t n) { return build_steps(n, 3) + 4 * kd_max_nodes(n) + 12 * 8 * n + 8; }

struct KdTraverseSpec {
  static constexpr std::array hooks{Hook::handles, Hook::estimate_steps, Hook::error, Hook::canonical, Hook::result_keys};
  using Algo = spatial::KdTraverse;
  static constexpr std::array result_keys{std::string_view("hit")};  // hit_json: always
  using Input = TraverseInput;
  using Output = HitOutput;
  static constexpr std::array views{View::tree, View::orbit3d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  // A 3 x 3 grid of unit squares, two triangles each, on z = 0, and a ray that crosses split planes.
  static inline const std::string example =
      R"({"triangles":[[[0,0,0],[1,0,0],[1,1,0]],[[0,0,0],[1,1,0],[0,1,0]],[[1,0,0],[2,0,0],[2,1,0]],[[1,0,0],[2,1,0],[1,1,0]],[[2,0,0],[3,0,0],[3,1,0]],[[2,0,0],[3,1,0],[2,1,0]],)"
      R"([[0,1,0],[1,1,0],[1,2,0]],[[0,1,0],[1,2,0],[0,2,0]],[[1,1,0],[2,1,0],[2,2,0]],[[1,1,0],[2,2,0],[1,2,0]],[[2,1,0],[3,1,0],[3,2,0]],[[2,1,0],[3,2,0],[2,2,0]],)"
      R"([[0,2,0],[1,2,0],[1,3,0]],[[0,2,0],[1,3,0],[0,3,0]],[[1,2,0],[2,2,0],[2,3,0]],[[1,2,0],[2,3,0],[1,3,0]],[[2,2,0],[3,2,0],[3,3,0]],[[2,2,0],[3,3,0],[2,3,0]]],"ray":{"o":[4,3.5,2],"d":[-2,-1.5,-2]}})";
  static Input parse(const Json& j) {
    if (!j.is_object() || (j.contains("triangles") ? 1 : 0) + (j.contains("mesh") ? 1 : 0) != 1)
      throw InputError("input: expected exactly one of \"triangles\" and \"mesh\", and \"ray\"");
    only_keys(j, {j.contains("mesh") ? "mesh" : "triangles", "ray"}, "input");
    return {parse_mesh(j, "input"), parse_ray(j["ray"], "input.ray")};
  }
  static std::vector<Handle> handles() { return {{"/ray/o", Handle::Kind::point3, 8, "o"}, {"/ray/d", Handle::Kind::direction3, 0, "o + d"}}; }
  template <class Num> static TraversePrepared<Num> prepare(const Input& in) {
    TraversePrepared<Num> p;
    for (std::size_t i = 0; i < in.mesh.size(); ++i) p.tris.push_back(in.mesh.triangle<Num>(i));
    p.ray = {vec_from<Num, 3>(in.ray.o), vec_from<Num, 3>(in.ray.d)};  // a -0.0 stays -0.0 (floats)
    return p;
  }
  template <class Num, class Probe> static Output compute(const TraversePrepared<Num>& p, Probe& probe) {
    if constexpr (Probe::on) check_trace_budget(traverse_steps(p.tris.size()), p.tris.size(), "input");
    const KdHit<Num> h = kd_traverse<Num>(p.tris, p.ray, probe);
    HitOutput o = make_hit<Num>(h.hit, h.prim, h.t, h.b);
    o.nodes_visited = h.nodes_visited, o.prim_tests = h.prim_tests;
    return o;
  }
  static std::size_t estimate_steps(const Input& in) { return traverse_steps(in.mesh.size()); }
  static Json to_json(const Output& o) { return hit_json(o); }
  static std::size_t ops(const Output&) { return 1; }
  static constexpr std::string_view error_unit = "ulps of t";
  static double error(const Output& got, const Output& exact) { return hit_error(got, exact); }
  // The answer without the walk's work counts (the oracle does no walk).
  static Json canonical(Json r) {
    r.erase("nodes_visited"), r.erase("prim_tests");
    return r;
  }
  static Output oracle(const Input& in) { return closest_hit_oracle(in.mesh, in.ray); }
  // Rays from outside a random mesh of 300 triangles towards random points in it (each query
  // builds its tree: the listing's cost).
  static std::vector<BenchSet<Input>> bench_sets() {
    const Mesh m = random_mesh_for(20261202, 300);
    std::mt19937_64 rng(20261203);
    std::uniform_real_distribution<double> u(-1, 1);
    BenchSet<Input> set{"mesh-300", {}};
    for (int i = 0; i < 12; ++i) {
      RayIn r{{u(rng) * 3, u(rng) * 3, 3}, {}};
      for (int k = 0; k < 3; ++k) r.d[k] = u(rng) - r.o[k];
      set.inputs.push_back({m, r});
    }
    return {set};
  }
};

SW_REGISTER(KdTraverseSpec);

}  // namespace

}  // namespace sw
