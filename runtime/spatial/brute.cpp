// ray-triangles in the catalog: the brute-force closest hit with a chosen triangle test, the
// baseline of bvh-traverse and kd-traverse (same output, same ties, same oracle).
#include <memory>
#include <random>
#include "register.hpp"
#include "spatial/bvh_cases.hpp"
#include "spatial/ray_triangles.hpp"
#include "spatial/spatial_common.hpp"

namespace sw {
namespace {

using spatial::Mesh;
using spatial::RayIn;
using spatial::TriangleTest;

struct BruteInput {
  std::shared_ptr<const Mesh> mesh;
  RayIn ray;
  TriangleTest test = TriangleTest::watertight;
};

template <class Num> struct BrutePrepared {
  std::vector<std::array<Vec3<Num>, 3>> tris;
  ray::Ray3<Num> ray;
  TriangleTest test;
};

// Per triangle a visit, a nested test of at most 13 steps and a keep; a start and a done.
std::size_t brute_steps(std::size_t n) { return 15 * n + 2; }

struct RayTrianglesSpec {
  static constexpr std::array hooks{Hook::handles, Hook::estimate_steps, Hook::canonical, Hook::error, Hook::result_keys};
  using Algo = spatial::RayTriangles;
  static constexpr std::array result_keys{std::string_view("hit")};  // hit_json: always
  using Input = BruteInput;
  using Output = spatial::HitOutput;
  static constexpr std::array views{View::orbit3d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  // Two triangles sharing a diagonal, the ray aimed at it (lesson 05).
  static inline const std::string example =
      R"({"triangles":[[[-5,-5,0],[5,-5,0],[5,5,0]],[[-5,-5,0],[5,5,0],[-5,5,0]]],"test":"mt",)"
      R"("ray":{"o":[-1.9140625,1.91796875,11.66015625],"d":[5.49609375,1.6640625,-11.66015625]}})";
  static Input parse(const Json& j) {
    only_keys_optional(j, {"ray"}, {"triangles", "mesh", "test"}, "input");
    BruteInput in;
    in.mesh = std::make_shared<const Mesh>(spatial::parse_mesh(j, "input"));
    in.ray = spatial::parse_ray(require(j, "ray", "input"), "input.ray");
    if (j.contains("test")) {
      const Json& t = j["test"];
      if (t == "mt") in.test = TriangleTest::mt;
      else if (t == "barycentric") in.test = TriangleTest::barycentric;
      else if (t != "watertight") throw InputError("input.test: expected \"mt\", \"barycentric\" or \"watertight\"");
    }
    return in;
  }
  static std::vector<Handle> handles() { return {{"/ray/o", Handle::Kind::point3, 8, "o"}, {"/ray/d", Handle::Kind::direction3, 0, "o + d"}}; }
  template <class Num> static BrutePrepared<Num> prepare(const Input& in) {
    BrutePrepared<Num> p;
    for (std::size_t i = 0; i < in.mesh->size(); ++i) p.tris.push_back(in.mesh->triangle<Num>(i));
    p.ray.o = spatial::vec_from<Num, 3>(in.ray.o), p.ray.d = spatial::vec_from<Num, 3>(in.ray.d);  // keeps -0.0
    p.test = in.test;
    return p;
  }
  template <class Num, class Probe> static Output compute(const BrutePrepared<Num>& p, Probe& probe) {
    const spatial::TreeHit<Num> h = spatial::ray_triangles<Num>(p.tris, p.ray, p.test, probe);
    Output o = spatial::make_hit<Num>(h.hit, h.prim, h.t, h.b);
    o.prim_tests = h.prim_tests;
    return o;
  }
  static Json to_json(const Output& o) { return spatial::hit_json(o); }
  static Json canonical(const Json& r) {
    Json c = r;
    c.erase("nodes_visited"), c.erase("prim_tests");
    return c;
  }
  static constexpr std::string_view error_unit = "ulps of t";
  static double error(const Output& got, const Output& exact) { return spatial::hit_error(got, exact); }
  static std::size_t ops(const Output&) { return 1; }
  static std::size_t estimate_steps(const Input& in) { return brute_steps(in.mesh->size()); }
  static Output oracle(const Input& in) { return spatial::closest_hit_oracle(*in.mesh, in.ray); }
  // Small meshes (every triangle is tested): random triangles, and a grid with rays through its
  // edges and vertices, where a test that is not watertight loses rays.
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(20261126);
    BenchSet<Input> random{"random-100", {}}, grid{"grid-edges", {}};
    const auto rm = std::make_shared<const Mesh>(spatial::cases::random_mesh(rng, 100));
    const auto gm = std::make_shared<const Mesh>(spatial::cases::grid_mesh(8, 8, false, 11));
    for (int i = 0; i < 60; ++i) {
      const TriangleTest t = static_cast<TriangleTest>(i % 3);
      random.inputs.push_back({rm, spatial::cases::random_ray(rng), t});
      grid.inputs.push_back({gm, spatial::cases::grid_ray(*gm, 8, 8, rng, i % 3), t});
    }
    return {random, grid};
  }
};

SW_REGISTER(RayTrianglesSpec);

}  // namespace

}  // namespace sw
