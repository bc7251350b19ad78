// The 3D grid walk in the catalog: grid-traverse-3d (registered here).
// Semantics, bounds and ties: docs/spatial/grid.md.
#include <algorithm>
#include <random>
#include <set>
#include "register.hpp"
#include "spatial/grid_traverse_3d.hpp"
#include "spatial/spatial_common.hpp"
#include "spatial_grid_oracle.hpp"

namespace sw {
namespace {

using spatial::Cell3;

// |coordinate| <= 2^30: cell indices and their halves are exact in double, and a float input's
// cell index is exact too (x - floor(x) is exact). The walk's cells are bounded before it runs.
constexpr double kGridCoordBound = 1073741824.0;
constexpr std::int64_t kMaxGridMoves = std::int64_t{1} << 22;

struct GridInput {
  std::array<double, 3> p0{}, p1{};
};

// The moves the walk makes, |last - first| summed over the axes, computed exactly from the ends.
std::int64_t grid_moves(const GridInput& in) {
  std::int64_t n = 0;
  for (int a = 0; a < 3; ++a) {
    const Rational x0 = num::to_rational(in.p0[a]), x1 = num::to_rational(in.p1[a]);
    const std::int64_t first = spatial::cell_index(x0, false);
    const std::int64_t last = x0 < x1 ? spatial::cell_index(x1, true) : x1 < x0 ? spatial::cell_index(x1, false) : first;
    n += last < first ? first - last : last - first;
  }
  return n;
}

struct GridOutput {
  std::vector<Cell3> cells;
  friend bool operator==(const GridOutput&, const GridOutput&) = default;
};

std::array<double, 3> parse_grid_point(const Json& j, const char* key) {
  const std::string what = std::string("input.") + key;
  const auto p = spatial::parse_vec<3>(require(j, key, "input"), what);
  for (int a = 0; a < 3; ++a)
    if (std::abs(p[a]) > kGridCoordBound) throw InputError(what + "[" + std::to_string(a) + "]: |coordinate| is more than the grid's bound 2^30");
  return p;
}

GridInput random_segment(std::mt19937_64& rng, double len) {
  std::uniform_real_distribution<double> c(-64, 64), u(-len, len);
  auto grid = [](double x) { return std::ldexp(std::floor(std::ldexp(x, 8)), -8); };  // 1/256 steps: ties happen
  GridInput in;
  for (int a = 0; a < 3; ++a) in.p0[a] = grid(c(rng)), in.p1[a] = grid(in.p0[a] + u(rng));
  return in;
}

struct GridTraverse3dSpec {
  static constexpr std::array hooks{Hook::handles, Hook::error, Hook::estimate_steps, Hook::table_lines};
  using Algo = spatial::GridTraverse3d;
  using Input = GridInput;
  using Output = GridOutput;
  static constexpr std::array views{View::orbit3d, View::table};
  static constexpr std::array<std::string_view, 2> table_lines{"start", "pick"};  // a row per move
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"p0":[0.25,-0.5,0.75],"p1":[4.5,2.5,-1.5]})";
  static Input parse(const Json& j) {
    only_keys(j, {"p0", "p1"}, "input");
    Input in{parse_grid_point(j, "p0"), parse_grid_point(j, "p1")};
    const std::int64_t moves = grid_moves(in);
    if (moves > kMaxGridMoves)
      throw InputError("input: the segment crosses " + std::to_string(moves) + " cell faces, more than the budget of 2^22");
    return in;
  }
  static std::vector<Handle> handles() { return {{"/p0", Handle::Kind::point3, 2, "p0"}, {"/p1", Handle::Kind::point3, 2, "p1"}}; }
  template <class Num> static std::array<Vec3<Num>, 2> prepare(const Input& in) {
    return {Vec3<Num>{spatial::from_double<Num>(in.p0[0]), spatial::from_double<Num>(in.p0[1]), spatial::from_double<Num>(in.p0[2])},
            Vec3<Num>{spatial::from_double<Num>(in.p1[0]), spatial::from_double<Num>(in.p1[1]), spatial::from_double<Num>(in.p1[2])}};
  }
  template <class Num, class Probe> static Output compute(const std::array<Vec3<Num>, 2>& p, Probe& probe) {
    Output o;
    spatial::grid_traverse_3d<Num>(p[0], p[1], o.cells, probe);
    return o;
  }
  static Json to_json(const Output& o) {
    Json cells = Json::array();
    for (const Cell3& c : o.cells) cells.push_back({c.i, c.j, c.k});
    return {{"count", o.cells.size()}, {"cells", std::move(cells)}};
  }
  static std::size_t ops(const Output& o) { return o.cells.size(); }
  // Cells in one list and not the other; 1 if the sets agree but the order does not.
  static constexpr std::string_view error_unit = "cells";
  static double error(const Output& got, const Output& exact) {
    std::set<Cell3> a(got.cells.begin(), got.cells.end()), b(exact.cells.begin(), exact.cells.end());
    std::vector<Cell3> diff;
    std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(diff));
    return !diff.empty() ? static_cast<double>(diff.size()) : got.cells == exact.cells ? 0 : 1;
  }
  // A pick step per move and at most two visits, plus the set-up steps.
  static std::size_t estimate_steps(const Input& in) { return 3 * static_cast<std::size_t>(grid_moves(in)) + 8; }
  static Output oracle(const Input& in) {
    Output o;
    const auto q = [](const std::array<double, 3>& p) { return Vec3<Rational>{num::to_rational(p[0]), num::to_rational(p[1]), num::to_rational(p[2])}; };
    for (const auto& c : oracle::grid_cells_3d(q(in.p0), q(in.p1))) o.cells.push_back({c[0], c[1], c[2]});
    return o;
  }
  // Random segments on the 1/256 grid, short and long; and axis-parallel ones through edges.
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(20261125);
    BenchSet<Input> short_set{"len8", {}}, long_set{"len64", {}}, edges{"on-edges", {}};
    for (int i = 0; i < 2000; ++i) short_set.inputs.push_back(random_segment(rng, 8));
    for (int i = 0; i < 300; ++i) long_set.inputs.push_back(random_segment(rng, 64));
    for (int i = 0; i < 1000; ++i) {
      GridInput in = random_segment(rng, 16);
      in.p0[i % 3] = in.p1[i % 3] = std::floor(in.p0[i % 3]) + 0.5;  // in a face plane, along it
      in.p0[(i + 1) % 3] = std::floor(in.p0[(i + 1) % 3]) + 0.5;
      edges.inputs.push_back(in);
    }
    return {short_set, long_set, edges};
  }
};

SW_REGISTER(GridTraverse3dSpec);

}  // namespace

}  // namespace sw
