// The kd-tree family in the catalog: kd-build here, kd-traverse and kd-nearest in kd_query.cpp.
// Semantics: docs/spatial/kd.md.
#include <cmath>
#include <random>
#include "register.hpp"
#include "spatial/kd_common.hpp"

namespace sw {

namespace kdspec {

PointSet parse_point_set(const Json& arr, const std::string& what) {
  if (!arr.is_array() || arr.empty() || !arr[0].is_array()) throw InputError(what + ": expected a non-empty array of points [x,y] or [x,y,z]");
  PointSet s;
  s.dim = static_cast<int>(arr[0].size());
  if (s.dim == 2) s.p2 = parse_points<2>(arr, what);
  else if (s.dim == 3) s.p3 = parse_points<3>(arr, what);
  else throw InputError(what + "[0]: expected 2 or 3 coordinates, got " + std::to_string(s.dim));
  return s;
}

void check_trace_budget(std::size_t steps, std::size_t n, const std::string& what) {
  if (steps > kTraceBudget)
    throw InputError(what + ": " + std::to_string(n) + " primitives, too many to trace (an estimated " + std::to_string(steps) +
                     " steps, beyond the bound of 2^26 for a trace); run it untraced");
}

}  // namespace kdspec

namespace {

using namespace kdspec;

struct BuildInput {
  bool points = false;  // else a mesh
  Mesh mesh;
  PointSet pts;
  int dim() const { return points ? pts.dim : 3; }
  std::size_t size() const { return points ? pts.size() : mesh.size(); }
};

template <class Num> struct BuildPrepared {
  bool points = false;
  int dim = 3;
  std::vector<Box<Num, 2>> b2;
  std::vector<Box<Num, 3>> b3;
};

// Random points in [-1, 1]^dim and random triangles of edge about 2/sqrt(n) in [-1, 1]^3, on
// the 2^-20 grid, seeded.
std::vector<std::array<double, 3>> random_points3(std::mt19937_64& rng, std::size_t n) {
  std::uniform_int_distribution<int> u(-(1 << 20), 1 << 20);
  std::vector<std::array<double, 3>> out(n);
  for (auto& p : out)
    for (double& x : p) x = std::ldexp(u(rng), -20);
  return out;
}
Mesh random_mesh(std::mt19937_64& rng, std::size_t n) {
  Mesh m;
  const double s = 2 / std::sqrt(static_cast<double>(n));
  std::uniform_real_distribution<double> e(-s, s);
  auto grid = [](double x) { return std::ldexp(std::round(std::ldexp(x, 20)), -20); };
  for (const auto& c : random_points3(rng, n)) {
    const auto base = static_cast<std::int32_t>(m.v.size());
    m.v.push_back(c);
    for (int k = 0; k < 2; ++k) m.v.push_back({c[0] + grid(e(rng)), c[1] + grid(e(rng)), c[2] + grid(e(rng))});
    m.f.push_back({base, base + 1, base + 2});
  }
  return m;
}

struct KdBuildSpec {
  static constexpr std::array hooks{Hook::handles, Hook::estimate_steps, Hook::canonical};
  static Json canonical(const Json& r) { return tree_canonical(r); }
  using Algo = spatial::KdBuild;
  using Input = BuildInput;
  using Output = TreeOutput;
  static constexpr std::array views{View::tree, View::plane2d, View::orbit3d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example =
      R"({"points":[[1,1],[2,5],[3,2],[4,4],[5,1],[6,6],[7,3],[8,5],[8,1],[2,2],[6,3],[6,4],[1,6],[7,7]]})";
  static Input parse(const Json& j) {
    Input in;
    if (j.is_object() && j.contains("points")) {
      only_keys(j, {"points"}, "input");
      in.points = true;
      in.pts = parse_point_set(j["points"], "input.points");
    } else {
      if (!j.is_object() || (j.contains("triangles") ? 1 : 0) + (j.contains("mesh") ? 1 : 0) != 1)
        throw InputError("input: expected exactly one of \"points\", \"triangles\" and \"mesh\"");
      only_keys(j, {j.contains("mesh") ? "mesh" : "triangles"}, "input");
      in.mesh = parse_mesh(j, "input");
    }
    return in;
  }
  static std::vector<Handle> handles() {
    std::vector<Handle> h;
    for (int k = 0; k < 4; ++k) h.push_back({"/points/" + std::to_string(k), Handle::Kind::point2, 8, "p" + std::to_string(k)});
    return h;
  }
  template <class Num> static BuildPrepared<Num> prepare(const Input& in) {
    BuildPrepared<Num> p;
    p.points = in.points, p.dim = in.dim();
    if (in.points && in.pts.dim == 2)
      for (const auto& a : in.pts.p2) p.b2.push_back(Box<Num, 2>::at(vec_from<Num, 2>(a)));
    else if (in.points)
      for (const auto& a : in.pts.p3) p.b3.push_back(Box<Num, 3>::at(vec_from<Num, 3>(a)));
    else
      for (std::size_t i = 0; i < in.mesh.size(); ++i) p.b3.push_back(triangle_bounds(in.mesh.triangle<Num>(i)));
    return p;
  }
  template <class Num, class Probe> static Output compute(const BuildPrepared<Num>& p, Probe& probe) {
    const std::size_t n = p.dim == 2 ? p.b2.size() : p.b3.size();
    if constexpr (Probe::on) check_trace_budget(build_steps(n, p.dim), n, "input");
    if (p.dim == 2) return tree_output(kd_build<Num, 2>(p.b2, true, probe));
    return tree_output(kd_build<Num, 3>(p.b3, p.points, probe));
  }
  static std::size_t estimate_steps(const Input& in) { return build_steps(in.size(), in.dim()); }
  static Json to_json(const Output& o) { return tree_json(o); }
  static std::size_t ops(const Output& o) { return o.nodes.size(); }
  // A build has no answer to compare but its invariants (tests/spatial/test_kd_build.cpp check
  // them exactly on every build): its oracle is its exact run.
  static Output oracle(const Input& in) {
    NoProbe none;
    return compute<Rational>(prepare<Rational>(in), none);
  }
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(20261201);
    BenchSet<Input> mesh{"mesh-500", {}}, p2{"points2d-1000", {}}, p3{"points3d-1000", {}};
    for (int s = 0; s < 4; ++s) {
      Input m;
      m.mesh = random_mesh(rng, 500);
      mesh.inputs.push_back(std::move(m));
      Input a, b;
      a.points = b.points = true;
      a.pts.dim = 2, b.pts.dim = 3;
      for (const auto& q : random_points3(rng, 1000)) a.pts.p2.push_back({q[0], q[1]}), b.pts.p3.push_back(q);
      p2.inputs.push_back(std::move(a)), p3.inputs.push_back(std::move(b));
    }
    return {mesh, p2, p3};
  }
};

SW_REGISTER(KdBuildSpec);

}  // namespace

namespace kdspec {
// Shared with kd_query.cpp's bench sets and with the benchmark.
Mesh random_mesh_for(std::uint64_t seed, std::size_t n) {
  std::mt19937_64 rng(seed);
  return random_mesh(rng, n);
}
std::vector<std::array<double, 3>> random_points_for(std::uint64_t seed, std::size_t n) {
  std::mt19937_64 rng(seed);
  return random_points3(rng, n);
}
}  // namespace kdspec

}  // namespace sw
