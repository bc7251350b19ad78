// The BVH in the catalog: bvh-build (binned SAH) and bvh-traverse (closest hit, or any hit for
// shadow rays), registered here. Semantics, bounds and ties: docs/spatial/bvh.md.
#include <cmath>
#include <memory>
#include <optional>
#include <random>
#include "register.hpp"
#include "rays_oracle.hpp"
#include "spatial/bvh_cases.hpp"
#include "spatial/bvh_traverse.hpp"
#include "spatial/spatial_common.hpp"

namespace sw {
namespace {

using spatial::Mesh;
using spatial::RayIn;

// The trace budget: inputs whose step estimate passes 2^26 are refused (a recorded step costs
// about 100 bytes). Untraced runs obey it too, so that every valid input can also be traced.
constexpr std::size_t kTraceBudget = std::size_t{1} << 26;

struct BvhInput {
  std::shared_ptr<const Mesh> mesh;
  RayIn ray;
  bool has_ray = false, any = false;
  double t_max = 0;
};

// Steps of a build: bounds, root, done, and per node (at most 2n - 1) a pop, three bins and
// three sweeps, a decide and a split or leaf.
std::size_t build_steps(std::size_t n) { return 9 * (2 * n) + 3; }
// A traversal adds per node its pop, the children's boxes (two nested slab tests of at most 7
// steps) and a push; per triangle a test (nested, at most 13 steps) and a keep.
std::size_t traverse_steps(std::size_t n) { return build_steps(n) + 18 * (2 * n) + 15 * n + 4; }

void check_budget(std::size_t steps, const std::string& what) {
  if (steps > kTraceBudget)
    throw InputError(what + ": about " + std::to_string(steps) + " steps, more than the trace budget of 2^26 (fewer triangles)");
}

template <class Num> struct Prepared {
  std::vector<std::array<Vec3<Num>, 3>> tris;
  ray::Ray3<Num> ray;
  spatial::BvhQuery<Num> q;
};

template <class Num> Prepared<Num> prepare_mesh(const BvhInput& in) {
  Prepared<Num> p;
  p.tris.reserve(in.mesh->size());
  for (std::size_t i = 0; i < in.mesh->size(); ++i) p.tris.push_back(in.mesh->triangle<Num>(i));
  if (in.has_ray) {
    p.ray.o = spatial::vec_from<Num, 3>(in.ray.o), p.ray.d = spatial::vec_from<Num, 3>(in.ray.d);  // keeps -0.0
    p.q.any = in.any, p.q.t_max = spatial::from_double<Num>(in.t_max);
  }
  return p;
}

// The build as the shared tree shape; the SAH cost in doubles, relative to the root's area (the
// build's costs: 2 per inner node, 1 per triangle): inner nodes 2 A(node)/A(root), leaves n A(leaf)/A(root).
template <class Num> spatial::TreeOutput tree_output(const spatial::Bvh<Num>& b) {
  spatial::TreeOutput t;
  t.bits = std::is_same_v<Num, float> ? 24 : 53;
  for (std::size_t i = 0; i < b.nodes.size(); ++i) {
    const auto& nd = b.nodes[i];
    (void)spatial::add_node(t, nd.parent);  // ids in order: node i is i
    spatial::set_bounds<Num, 3>(t, static_cast<std::int32_t>(i), nd.box);
    if (nd.left < 0) t.nodes[i].prims.assign(b.order.begin() + nd.first, b.order.begin() + nd.first + nd.count);
    t.nodes[i].axis = nd.axis;
  }
  t.leaves = b.leaves, t.depth = b.depth;
  t.bytes = b.nodes.size() * sizeof(spatial::BvhNode<Num>) + b.order.size() * sizeof(std::int32_t);
  auto area = [&](std::size_t i) {
    const double* lo = &t.lo[3 * i];
    const double* hi = &t.hi[3 * i];
    const double e[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
  };
  const double root = area(0);
  double cost = 0;
  for (std::size_t i = 0; i < b.nodes.size(); ++i) {
    const double a = root > 0 ? area(i) / root : 1;  // a root of no area (all triangles on a line): counts only
    cost += b.nodes[i].left < 0 ? a * b.nodes[i].count : spatial::kBvhTraversalCost * a;
  }
  t.sah_cost = cost;
  return t;
}

BvhInput parse_common(const Json& j, bool with_ray) {
  if (with_ray) only_keys_optional(j, {"ray"}, {"triangles", "mesh", "any", "t_max"}, "input");
  else only_keys_optional(j, {}, {"triangles", "mesh"}, "input");
  BvhInput in;
  in.mesh = std::make_shared<const Mesh>(spatial::parse_mesh(j, "input"));
  if (!with_ray) {
    check_budget(build_steps(in.mesh->size()), "input");
    return in;
  }
  check_budget(traverse_steps(in.mesh->size()), "input");
  in.ray = spatial::parse_ray(require(j, "ray", "input"), "input.ray");
  in.has_ray = true;
  if (j.contains("any")) {
    if (!j["any"].is_boolean()) throw InputError("input.any: expected true or false");
    in.any = j["any"].get<bool>();
  }
  if (in.any) {
    if (!j.contains("t_max")) throw InputError("input.t_max: required with \"any\": true (the shadow ray's length)");
    in.t_max = spatial::parse_coord(j["t_max"], "input.t_max");
    if (!(in.t_max > 0)) throw InputError("input.t_max: must be > 0");
  } else if (j.contains("t_max")) {
    throw InputError("input.t_max: only with \"any\": true");
  }
  return in;
}

std::shared_ptr<const Mesh> shared(Mesh m) { return std::make_shared<const Mesh>(std::move(m)); }

struct BvhBuildSpec {
  static constexpr std::array hooks{Hook::estimate_steps, Hook::step_cost, Hook::canonical};
  static Json canonical(const Json& r) { return spatial::tree_canonical(r); }
  using Algo = spatial::BvhBuild;
  using Input = BvhInput;
  using Output = spatial::TreeOutput;
  static constexpr std::array views{View::tree, View::orbit3d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  // Two rows of a height field, a thin sliver, and three identical triangles (no centroid spread).
  static inline const std::string example =
      R"({"triangles":[[[0,0,0],[1,0,0],[0,1,0]],[[1,0,0],[1,1,1],[0,1,0]],[[1,0,0],[2,0,1],[1,1,1]],[[2,0,1],[2,1,0],[1,1,1]],)"
      R"([[0,1,0],[1,1,1],[0,2,1]],[[1,1,1],[1,2,0],[0,2,1]],[[4,0,0],[4,2,0],[4,1,0.5]],)"
      R"([[6,6,6],[7,6,6],[6,7,6]],[[6,6,6],[7,6,6],[6,7,6]],[[6,6,6],[7,6,6],[6,7,6]]]})";
  static Input parse(const Json& j) { return parse_common(j, false); }
  template <class Num> static Prepared<Num> prepare(const Input& in) { return prepare_mesh<Num>(in); }
  template <class Num, class Probe> static Output compute(const Prepared<Num>& p, Probe& probe) {
    return tree_output(spatial::bvh_build<Num>(p.tris, probe));
  }
  static Json to_json(const Output& o) { return spatial::tree_json(o); }
  static std::size_t ops(const Output& o) {
    std::size_t n = 0;
    for (const auto& nd : o.nodes) n += nd.prims.size();
    return n;
  }
  static std::size_t estimate_steps(const Input& in) { return build_steps(in.mesh->size()); }
  // Budget units a step costs (measured, docs/cli.md: the largest accepted input within 10 s).
  static std::size_t step_cost(Numeric n) { return n == Numeric::filtered || n == Numeric::exact ? 5 : 1; }
  // The tree is defined by the algorithm: the oracle is its exact run. The independent checks are
  // the structural invariants (tests/spatial/test_bvh.cpp: boxes bound, every triangle in one leaf).
  static Output oracle(const Input& in) {
    NoProbe none;
    return compute<Rational>(prepare<Rational>(in), none);
  }
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(20261201);
    BenchSet<Input> random{"random-2k", {}}, grid{"grid-32", {}}, same{"identical-1k", {}};
    for (int i = 0; i < 4; ++i) random.inputs.push_back({shared(spatial::cases::random_mesh(rng, 2000)), {}, false, false, 0});
    grid.inputs.push_back({shared(spatial::cases::grid_mesh(32, 32, false, 7)), {}, false, false, 0});
    Mesh m;
    m.v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.f.assign(1000, {0, 1, 2});
    same.inputs.push_back({shared(std::move(m)), {}, false, false, 0});
    return {random, grid, same};
  }
};

// A query's answer, and whether it was an any-hit query (then only hit or miss is compared).
struct TraverseOutput {
  spatial::HitOutput h;
  bool any = false;
  friend bool operator==(const TraverseOutput& x, const TraverseOutput& y) {
    if (x.any || y.any) return x.h.hit == y.h.hit;
    return x.h == y.h;
  }
};

struct BvhTraverseSpec {
  static constexpr std::array hooks{Hook::handles, Hook::estimate_steps, Hook::step_cost, Hook::canonical, Hook::error, Hook::result_keys};
  using Algo = spatial::BvhTraverse;
  static constexpr std::array result_keys{std::string_view("hit")};  // hit_json: always
  using Input = BvhInput;
  using Output = TraverseOutput;
  static constexpr std::array views{View::orbit3d, View::tree};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  // A ray through the shared vertex (1, 1, 1) of four triangles: the lowest id wins the tie.
  static inline const std::string example =
      R"({"triangles":[[[0,0,0],[1,0,0],[0,1,0]],[[1,0,0],[1,1,1],[0,1,0]],[[1,0,0],[2,0,1],[1,1,1]],[[2,0,1],[2,1,0],[1,1,1]],)"
      R"([[0,1,0],[1,1,1],[0,2,1]],[[1,1,1],[1,2,0],[0,2,1]],[[4,0,0],[4,2,0],[4,1,0.5]],[[0,0,-2],[3,0,-2],[0,3,-2]]],)"
      R"("ray":{"o":[1,1,4],"d":[0,-0.0,-1]}})";
  static Input parse(const Json& j) { return parse_common(j, true); }
  static std::vector<Handle> handles() { return {{"/ray/o", Handle::Kind::point3, 8, "o"}, {"/ray/d", Handle::Kind::direction3, 0, "o + d"}}; }
  template <class Num> static Prepared<Num> prepare(const Input& in) { return prepare_mesh<Num>(in); }
  template <class Num, class Probe> static Output compute(const Prepared<Num>& p, Probe& probe) {
    const spatial::BvhHit<Num> h = spatial::bvh_traverse<Num>(p.tris, p.ray, p.q, probe);
    Output o{spatial::make_hit<Num>(h.hit, h.prim, h.t, h.b), p.q.any};
    o.h.nodes_visited = h.nodes_visited, o.h.prim_tests = h.prim_tests;
    return o;
  }
  static Json to_json(const Output& o) {
    Json j = spatial::hit_json(o.h);
    if (o.any) j["any"] = true;
    return j;
  }
  // What the oracle states: the hit (any hit: only whether there is one), not the work done.
  static Json canonical(const Json& r) {
    Json c = r;
    c.erase("nodes_visited"), c.erase("prim_tests");
    if (c.value("any", false)) c.erase("t"), c.erase("prim"), c.erase("b");
    return c;
  }
  static constexpr std::string_view error_unit = "ulps of t";
  static double error(const Output& got, const Output& exact) { return got.any ? 0.0 : spatial::hit_error(got.h, exact.h); }
  static std::size_t ops(const Output&) { return 1; }
  static std::size_t estimate_steps(const Input& in) { return traverse_steps(in.mesh->size()); }
  // Budget units a step costs (measured, docs/cli.md: the largest accepted input within 10 s).
  static std::size_t step_cost(Numeric n) { return n == Numeric::filtered || n == Numeric::exact ? 2 : 1; }
  // The brute-force closest hit over all triangles; any hit: whether it lies before t_max.
  static Output oracle(const Input& in) {
    Output o{spatial::closest_hit_oracle(*in.mesh, in.ray), in.any};
    if (in.any && o.h.hit && !(o.h.exact->t < num::to_rational(in.t_max))) o.h = spatial::make_exact_hit(false, -1, Rational(0), {});
    return o;
  }
  // Each input builds its BVH, so the sets are small meshes: random triangles with random rays,
  // a grid with rays through its edges and vertices, and shadow rays. Exact queries take about
  // 40 ms each, so a quick bench takes the first 10 queries of each set.
  static std::vector<BenchSet<Input>> bench_sets(BenchSize size) {
    std::mt19937_64 rng(20261202);
    BenchSet<Input> random{"random-500", {}}, grid{"grid-edges", {}}, shadow{"any-hit", {}};
    const auto rm = shared(spatial::cases::random_mesh(rng, 500));
    const auto gm = shared(spatial::cases::grid_mesh(16, 16, false, 11));
    for (int i = 0; i < (size == BenchSize::quick ? 10 : 40); ++i) {
      random.inputs.push_back({rm, spatial::cases::random_ray(rng), true, false, 0});
      grid.inputs.push_back({gm, spatial::cases::grid_ray(*gm, 16, 16, rng, i % 3), true, false, 0});
      shadow.inputs.push_back({rm, spatial::cases::random_ray(rng), true, true, 0.5});
    }
    return {random, grid, shadow};
  }
};

SW_REGISTER(BvhBuildSpec);
SW_REGISTER(BvhTraverseSpec);

}  // namespace

}  // namespace sw
