// kd-nearest against the brute-force exact k nearest (oracle::k_nearest, ties by id): random
// points in 2D and 3D, grids full of ties and duplicates, queries on split planes, every k from 1
// to N on a small set. Filtered and exact: 0 wrong; float and double counted.
#include <catch2/catch.hpp>
#include "kd_support.hpp"
#include "spatial/kd_point_tree.hpp"

using namespace sw;
using namespace sw::testing::kd;

namespace {

template <int D> struct PointScene {
  std::vector<VecN<float, D>> pf;
  std::vector<VecN<double, D>> pd;
  std::vector<VecN<Interval, D>> pi;
  std::vector<VecN<Q, D>> pq;
  KdTree<float, D> kf;
  KdTree<double, D> kdd;
  std::optional<KdTree<Interval, D>> ki;
  KdTree<Q, D> kq;
  std::size_t fallbacks = 0;
  template <class Num> static KdTree<Num, D> tree(const std::vector<VecN<Num, D>>& p) {
    std::vector<Box<Num, D>> b;
    for (const auto& x : p) b.push_back(Box<Num, D>::at(x));
    NoProbe none;
    return kd_build<Num, D>(b, true, none);
  }
  explicit PointScene(const std::vector<std::array<double, D>>& pts) {
    for (const auto& a : pts) pf.push_back(vec_from<float, D>(a)), pd.push_back(vec_from<double, D>(a)), pi.push_back(vec_from<Interval, D>(a)), pq.push_back(vec_from<Q, D>(a));
    kf = tree<float>(pf), kdd = tree<double>(pd), kq = tree<Q>(pq);
    try {
      ki = tree<Interval>(pi);
    } catch (const Uncertain&) {
    }
  }
  // The ids in (d2, id) order, and the exact d2 where the mode is exact.
  std::pair<std::vector<std::int32_t>, std::vector<Q>> run(Numeric n, const std::array<double, D>& q, std::size_t k) {
    NoProbe none;
    auto ids = [](const auto& r) { return std::pair<std::vector<std::int32_t>, std::vector<Q>>{r.ids, {}}; };
    switch (n) {
      case Numeric::f32: return ids(kd_nearest_tree<float, D>(kf, pf, vec_from<float, D>(q), k, none));
      case Numeric::f64: return ids(kd_nearest_tree<double, D>(kdd, pd, vec_from<double, D>(q), k, none));
      case Numeric::filtered:
        if (ki) {
          try {
            return ids(kd_nearest_tree<Interval, D>(*ki, pi, vec_from<Interval, D>(q), k, none));
          } catch (const Uncertain&) {
          }
        }
        ++fallbacks;
        [[fallthrough]];
      default: {
        const auto r = kd_nearest_tree<Q, D>(kq, pq, vec_from<Q, D>(q), k, none);
        return {r.ids, r.d2};
      }
    }
  }
};

template <int D> void query(PointScene<D>& sc, const std::type_identity_t<std::array<double, D>>& q, std::size_t k, std::array<std::size_t, 4>& wrong) {
  const auto want = oracle::k_nearest(sc.pq, vec_from<Q, D>(q), k);
  std::vector<std::int32_t> ids;
  std::vector<Q> d2;
  for (const auto& [d, i] : want) ids.push_back(i), d2.push_back(d);
  const Numeric modes[] = {Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  for (int m = 0; m < 4; ++m) {
    const auto got = sc.run(modes[m], q, k);
    wrong[m] += got.first != ids;
    if (m >= 2) {
      INFO(numeric_name(modes[m]) << " k " << k << " q " << q[0] << "," << q[1]);
      CHECK(got.first == ids);
      if (m == 3) CHECK(got.second == d2);
    }
  }
}

template <int D> std::vector<std::array<double, D>> points(std::mt19937_64& rng, int n, int bits, double dup) {
  std::vector<std::array<double, D>> out;
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < n; ++i) {
    if (i > 0 && u(rng) < dup) {
      out.push_back(out[std::uniform_int_distribution<int>(0, i - 1)(rng)]);
      continue;
    }
    std::array<double, D> p;
    for (double& x : p) x = grid_coord(rng, -4, 4, bits);
    out.push_back(p);
  }
  return out;
}

template <int D> void run_dim(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::array<std::size_t, 4> wrong{};
  std::size_t queries = 0;
  for (const auto& [bits, dup] : {std::pair{30, 0.0}, std::pair{1, 0.25}}) {  // continuous; a grid with ties and duplicates
    PointScene<D> sc(points<D>(rng, 400, bits, dup));
    for (int i = 0; i < 120; ++i, ++queries) {
      std::array<double, D> q;
      for (double& x : q) x = grid_coord(rng, -5, 5, i % 2 ? 2 : 20);
      query(sc, q, std::size_t{1} + static_cast<std::size_t>(i % 3 == 0 ? 8 : i % 17), wrong);
    }
    for (const auto& [k, p] : split_planes<D>(sc.kq)) {  // queries on split planes
      std::array<double, D> q;
      for (double& x : q) x = grid_coord(rng, -4, 4, 2);
      q[k] = p.get_d();
      query(sc, q, 8, wrong), ++queries;
    }
    WARN(D << "D, " << (bits == 1 ? "grid with ties" : "random") << " points, " << queries << " queries so far: wrong float " << wrong[0] << ", double "
           << wrong[1] << " (filtered fell back to exact " << sc.fallbacks << " times here)");
  }
  CHECK(wrong[2] == 0);
  CHECK(wrong[3] == 0);
}

}  // namespace

TEST_CASE("kd-nearest: random points and grids of ties in 2D and 3D against the exact k nearest", "[spatial][spatial-kd]") {
  run_dim<2>(31);
  run_dim<3>(32);
}

TEST_CASE("kd-nearest: every k on a small set with duplicates, identical points, and the catalog run", "[spatial][spatial-kd]") {
  std::mt19937_64 rng(33);
  std::array<std::size_t, 4> wrong{};
  PointScene<2> sc(points<2>(rng, 24, 0, 0.3));
  for (std::size_t k = 1; k <= 24; ++k) query(sc, {0.5, -0.5}, k, wrong);
  PointScene<3> same(std::vector<std::array<double, 3>>(500, {1, 2, 3}));  // one leaf; ties by id
  query(same, {0, 0, 0}, 7, wrong);
  CHECK(wrong[2] + wrong[3] == 0);
  const Algorithm& a = find_algorithm("kd-nearest");
  const Json in = Json::parse(a.example);
  const Json want = a.open(in).oracle();
  for (Numeric n : {Numeric::f64, Numeric::filtered, Numeric::exact}) CHECK(a.open(in, n).run()["ids"] == want["ids"]);
  CHECK(a.open(in, Numeric::exact).run()["d2"] == want["d2"]);
  check_refused(a, {R"({"points":[[0,0],[1,1]],"query":[0,0],"k":0})", R"({"points":[[0,0],[1,1]],"query":[0,0],"k":3})",
                    R"({"points":[[0,0],[1,1]],"query":[0,0,0],"k":1})", R"({"points":[[0,0],[1,1]],"query":[0,0],"k":1.5})",
                    R"({"points":[[0,0],[1,1]],"query":[0,"nan"],"k":1})"});
}

// kd_point_tree (median splits, the photon map's): kd-nearest on it gives the exact k nearest in
// exact mode, and in double the very answer it gives on kd-build's tree (the search's answer does
// not depend on the tree), on random points and on grids full of ties and duplicates.
template <int D> void run_point_tree(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  NoProbe none;
  for (const auto& [bits, dup] : {std::pair{30, 0.0}, std::pair{1, 0.25}, std::pair{0, 0.5}}) {
    PointScene<D> sc(points<D>(rng, 300, bits, dup));
    for (const std::int32_t leaf : {1, 3, 8}) {
      const KdTree<Q, D> tq = kd_point_tree<Q, D>(sc.pq, leaf);
      const KdTree<double, D> td = kd_point_tree<double, D>(sc.pd, leaf);
      CHECK(td.depth <= 10);  // log2(300) + 1: median splits halve every range
      for (int i = 0; i < 60; ++i) {
        std::array<double, D> q;
        for (double& x : q) x = grid_coord(rng, -5, 5, i % 2 ? 1 : 20);
        const std::size_t k = std::size_t{1} + static_cast<std::size_t>(i % 13) * 7;
        const auto want = oracle::k_nearest(sc.pq, vec_from<Q, D>(q), k);
        std::vector<std::int32_t> ids;
        std::vector<Q> d2;
        for (const auto& [d, id] : want) ids.push_back(id), d2.push_back(d);
        const auto exact = kd_nearest_tree<Q, D>(tq, sc.pq, vec_from<Q, D>(q), k, none);
        INFO(D << "D leaf " << leaf << " k " << k);
        CHECK(exact.ids == ids);
        CHECK(exact.d2 == d2);
        const auto on_median = kd_nearest_tree<double, D>(td, sc.pd, vec_from<double, D>(q), k, none);
        const auto on_sah = kd_nearest_tree<double, D>(sc.kdd, sc.pd, vec_from<double, D>(q), k, none);
        CHECK(on_median.ids == on_sah.ids);
        CHECK(on_median.d2 == on_sah.d2);
      }
    }
  }
}

TEST_CASE("kd-nearest on the median point tree: the exact k nearest, and double's answer on kd-build's tree", "[spatial][spatial-kd]") {
  run_point_tree<2>(41);
  run_point_tree<3>(42);
}
