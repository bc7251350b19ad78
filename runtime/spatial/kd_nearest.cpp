// kd-nearest in the catalog: the k nearest points, through a kd-tree that kd-build makes first,
// as a nested listing. Semantics: docs/spatial/kd.md.
#include <random>
#include "register.hpp"
#include "spatial/kd_common.hpp"
#include "spatial/kd_nearest.hpp"
#include "spatial_oracle.hpp"

namespace sw {
namespace {

using namespace kdspec;

struct NearestInput {
  PointSet pts;
  std::array<double, 3> q{};
  std::size_t k = 1;
};

template <class Num> struct NearestPrepared {
  std::vector<Vec2<Num>> p2;
  std::vector<Vec3<Num>> p3;
  Vec3<Num> q;
  std::size_t k = 1;
};

// The k nearest: ids by (d2, id), and d2 (exact mode: exactly).
struct NearestOutput {
  std::vector<std::int32_t> ids;
  std::vector<double> d2;
  std::vector<Rational> exact_d2;  // exact mode and the oracle
  std::size_t nodes_visited = 0, dist_tests = 0;
  // The same ids, and when both sides are exact, the same d2.
  friend bool operator==(const NearestOutput& x, const NearestOutput& y) {
    if (x.ids != y.ids) return false;
    return x.exact_d2.empty() || y.exact_d2.empty() || x.exact_d2 == y.exact_d2;
  }
};

// The search's own steps: at most every node popped, pruned or split (three steps), and every
// point measured and held (two).
std::size_t nearest_steps(std::size_t n, int dim) { return build_steps(n, dim) + 3 * kd_max_nodes(n) + 2 * n + 8; }

struct KdNearestSpec {
  static constexpr std::array hooks{Hook::handles, Hook::estimate_steps, Hook::error, Hook::canonical};
  using Algo = spatial::KdNearest;
  using Input = NearestInput;
  using Output = NearestOutput;
  static constexpr std::array views{View::tree, View::plane2d, View::orbit3d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example =
      R"({"points":[[1,1],[2,5],[3,2],[4,4],[5,1],[6,6],[7,3],[8,5],[8,1],[2,2],[6,3],[6,4],[1,6],[7,7]],"query":[5,3.5],"k":3})";
  static Input parse(const Json& j) {
    only_keys(j, {"points", "query", "k"}, "input");
    Input in;
    in.pts = parse_point_set(j["points"], "input.points");
    if (in.pts.dim == 2) {
      const auto q = parse_vec<2>(j["query"], "input.query");
      in.q = {q[0], q[1], 0};
    } else {
      in.q = parse_vec<3>(j["query"], "input.query");
    }
    in.k = static_cast<std::size_t>(parse_integer(j["k"], "input.k", 1, static_cast<std::int64_t>(in.pts.size())));
    return in;
  }
  static std::vector<Handle> handles() { return {{"/query", Handle::Kind::point2, 8, "q"}}; }
  template <class Num> static NearestPrepared<Num> prepare(const Input& in) {
    NearestPrepared<Num> p;
    for (const auto& a : in.pts.p2) p.p2.push_back(vec_from<Num, 2>(a));
    for (const auto& a : in.pts.p3) p.p3.push_back(vec_from<Num, 3>(a));
    p.q = vec_from<Num, 3>(in.q);
    p.k = in.k;
    return p;
  }
  template <class Num, class Probe> static Output compute(const NearestPrepared<Num>& p, Probe& probe) {
    const std::size_t n = p.p2.empty() ? p.p3.size() : p.p2.size();
    if constexpr (Probe::on) check_trace_budget(nearest_steps(n, p.p2.empty() ? 3 : 2), n, "input");
    const KdNearestResult<Num> r = p.p2.empty() ? kd_nearest<Num, 3>(p.p3, p.q, p.k, probe) : kd_nearest<Num, 2>(p.p2, Vec2<Num>{p.q.x, p.q.y}, p.k, probe);
    Output o;
    o.ids = r.ids, o.nodes_visited = r.nodes_visited, o.dist_tests = r.dist_tests;
    for (const Num& d : r.d2) o.d2.push_back(num::to_double(d));
    if constexpr (std::is_same_v<Num, Rational>) o.exact_d2 = r.d2;
    return o;
  }
  static std::size_t estimate_steps(const Input& in) { return nearest_steps(in.pts.size(), in.pts.dim); }
  static Json to_json(const Output& o) {
    Json d2 = Json::array();
    for (std::size_t i = 0; i < o.ids.size(); ++i) d2.push_back(o.exact_d2.empty() ? Json(o.d2[i]) : Json(o.exact_d2[i].get_str()));
    return {{"ids", o.ids}, {"d2", d2}, {"nodes_visited", o.nodes_visited}, {"dist_tests", o.dist_tests}};
  }
  static std::size_t ops(const Output&) { return 1; }
  static Json canonical(Json r) {
    r.erase("nodes_visited"), r.erase("dist_tests");
    return r;
  }
  // Wrong answers: the ranks whose id differs from the exact answer's.
  static constexpr std::string_view error_unit = "neighbours";
  static double error(const Output& got, const Output& exact) {
    double wrong = 0;
    for (std::size_t i = 0; i < exact.ids.size(); ++i) wrong += i >= got.ids.size() || got.ids[i] != exact.ids[i];
    return wrong;
  }
  static Output oracle(const Input& in) {
    std::vector<std::pair<Rational, std::int32_t>> r;
    if (in.pts.dim == 2) {
      std::vector<Vec2<Rational>> pts;
      for (const auto& a : in.pts.p2) pts.push_back(vec_from<Rational, 2>(a));
      r = oracle::k_nearest(pts, Vec2<Rational>{from_double<Rational>(in.q[0]), from_double<Rational>(in.q[1])}, in.k);
    } else {
      std::vector<Vec3<Rational>> pts;
      for (const auto& a : in.pts.p3) pts.push_back(vec_from<Rational, 3>(a));
      r = oracle::k_nearest(pts, vec_from<Rational, 3>(in.q), in.k);
    }
    Output o;
    for (const auto& [d, id] : r) o.ids.push_back(id), o.d2.push_back(d.get_d()), o.exact_d2.push_back(d);
    return o;
  }
  // 1000 points in 2D and in 3D, 8 queries each, k = 8 (each query builds its tree).
  static std::vector<BenchSet<Input>> bench_sets() {
    std::vector<BenchSet<Input>> sets;
    for (int dim : {2, 3}) {
      BenchSet<Input> s{dim == 2 ? "points2d-1000" : "points3d-1000", {}};
      const auto pts = random_points_for(20261204 + dim, 1000), qs = random_points_for(20261206 + dim, 8);
      for (const auto& q : qs) {
        Input in;
        in.pts.dim = dim, in.q = q, in.k = 8;
        for (const auto& p : pts) {
          if (dim == 2) in.pts.p2.push_back({p[0], p[1]});
          else in.pts.p3.push_back(p);
        }
        if (dim == 2) in.q[2] = 0;
        s.inputs.push_back(std::move(in));
      }
      sets.push_back(std::move(s));
    }
    return sets;
  }
};

SW_REGISTER(KdNearestSpec);

}  // namespace

}  // namespace sw
