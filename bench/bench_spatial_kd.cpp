// kd-tree speed: kd-build (SAH, O(N log N)) on 10^4, 10^5 and 10^6 generated triangles and
// points, in double, as ns per N log2 N and Mprims/s; and kd-nearest (k = 8) against nanoflann on
// the same points and queries, with the answers that differ counted and classified by the exact
// oracle on a subset (ties: the same distances in another order of ids). Prints the
// classification first, then times with Google Benchmark. Results: docs/spatial/kd.md.
#include <benchmark/benchmark.h>
#include <cmath>
#include <cstdio>
#include <map>
#include "spatial/kd_common.hpp"
#include "spatial/kd_nearest.hpp"
#include "spatial/kd_point_tree.hpp"
#include "spatial_oracle.hpp"
#if __has_include(<nanoflann.hpp>)
#include <nanoflann.hpp>
#define SW_HAVE_NANOFLANN 1
#endif

using namespace sw;
using namespace sw::spatial;

namespace {

const std::vector<Box<double, 3>>& triangle_bounds_of(std::size_t n) {
  static std::map<std::size_t, std::vector<Box<double, 3>>> cache;
  auto& b = cache[n];
  if (b.empty()) {
    const Mesh m = kdspec::random_mesh_for(7000 + n, n);
    for (std::size_t i = 0; i < m.size(); ++i) b.push_back(triangle_bounds(m.triangle<double>(i)));
  }
  return b;
}
template <int D> const std::vector<Box<double, D>>& point_bounds_of(std::size_t n) {
  static std::map<std::size_t, std::vector<Box<double, D>>> cache;
  auto& b = cache[n];
  if (b.empty())
    for (const auto& p : kdspec::random_points_for(8000 + n, n)) {
      VecN<double, D> v;
      for (int k = 0; k < D; ++k) v[k] = p[k];
      b.push_back(Box<double, D>::at(v));
    }
  return b;
}

template <int D> void report_build(benchmark::State& state, std::size_t n, const KdTree<double, D>& t) {
  const double nlogn = static_cast<double>(n) * std::log2(static_cast<double>(n));
  state.counters["Mprims/s"] = benchmark::Counter(static_cast<double>(n) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["ns/NlogN"] = benchmark::Counter(nlogn * 1e-9, static_cast<benchmark::Counter::Flags>(benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert));
  state.counters["nodes"] = static_cast<double>(t.nodes.size());
  state.counters["depth"] = static_cast<double>(t.depth);
  state.counters["refs/N"] = static_cast<double>(t.refs) / static_cast<double>(n);
}

void BM_KdBuildTriangles(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto& b = triangle_bounds_of(n);
  NoProbe none;
  KdTree<double, 3> t;
  for (auto _ : state) {
    t = kd_build<double, 3>(b, false, none);
    benchmark::DoNotOptimize(t.nodes.data());
  }
  report_build<3>(state, n, t);
}
template <int D> void BM_KdBuildPoints(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto& b = point_bounds_of<D>(n);
  NoProbe none;
  KdTree<double, D> t;
  for (auto _ : state) {
    t = kd_build<double, D>(b, true, none);
    benchmark::DoNotOptimize(t.nodes.data());
  }
  report_build<D>(state, n, t);
}
BENCHMARK(BM_KdBuildTriangles)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_KdBuildPoints<2>)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_KdBuildPoints<3>)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(1.0);

// kd-nearest against nanoflann: 10^5 points in [-1, 1]^3 (and their 2D projection), 10^4 queries,
// k = 8. Half the queries lie on the 2^-4 grid and half of the points too, so ties occur.
constexpr std::size_t kPoints = 100000, kQueries = 10000, kK = 8;

template <int D> struct NearestSet {
  std::vector<VecN<double, D>> pts, qs;
  KdTree<double, D> tree;    // kd-build's (the catalog's kd-nearest)
  KdTree<double, D> median;  // kd_point_tree's, 8 points a leaf (the photon map's)
  NearestSet() {
    const auto p = kdspec::random_points_for(9001, kPoints), q = kdspec::random_points_for(9002, kQueries);
    auto snap = [](double x, bool grid) { return grid ? std::round(x * 16) / 16 : x; };
    for (std::size_t i = 0; i < p.size(); ++i) {
      VecN<double, D> v;
      for (int k = 0; k < D; ++k) v[k] = snap(p[i][k], i % 2);
      pts.push_back(v);
    }
    for (std::size_t i = 0; i < q.size(); ++i) {
      VecN<double, D> v;
      for (int k = 0; k < D; ++k) v[k] = snap(q[i][k], i % 2);
      qs.push_back(v);
    }
    std::vector<Box<double, D>> b;
    for (const auto& v : pts) b.push_back(Box<double, D>::at(v));
    NoProbe none;
    tree = kd_build<double, D>(b, true, none);
    median = kd_point_tree<double, D>(pts, 8);
  }
};
template <int D> const NearestSet<D>& nearest_set() {
  static const NearestSet<D> s;
  return s;
}

// Our search on kd-build's tree (the catalog's) or on the median tree (kd_point_tree, the photon
// map's): the same answers, a shallower tree.
template <int D, bool Median> void BM_KdNearestOurs(benchmark::State& state) {
  const auto& s = nearest_set<D>();
  NoProbe none;
  std::size_t i = 0;
  for (auto _ : state) {
    const auto r = kd_nearest_tree<double, D>(Median ? s.median : s.tree, s.pts, s.qs[i++ % kQueries], kK, none);
    benchmark::DoNotOptimize(r.ids.data());
  }
  state.counters["queries/s"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_KdNearestOurs<2, false>)->Name("BM_KdNearestOurs<2>");
BENCHMARK(BM_KdNearestOurs<3, false>)->Name("BM_KdNearestOurs<3>");
BENCHMARK(BM_KdNearestOurs<2, true>)->Name("BM_KdNearestOursMedianTree<2>");
BENCHMARK(BM_KdNearestOurs<3, true>)->Name("BM_KdNearestOursMedianTree<3>");

#ifdef SW_HAVE_NANOFLANN
template <int D> struct Cloud {
  const std::vector<VecN<double, D>>* pts;
  std::size_t kdtree_get_point_count() const { return pts->size(); }
  double kdtree_get_pt(std::size_t i, std::size_t k) const { return (*pts)[i][static_cast<int>(k)]; }
  template <class B> bool kdtree_get_bbox(B&) const { return false; }
};
template <int D> using Flann = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud<D>>, Cloud<D>, D, std::uint32_t>;

template <int D> struct FlannSet {
  Cloud<D> cloud{&nearest_set<D>().pts};
  Flann<D> index{D, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10)};
};
template <int D> const FlannSet<D>& flann_set() {
  static const FlannSet<D> s;
  return s;
}

template <int D> void BM_KdNearestNanoflann(benchmark::State& state) {
  const auto& s = nearest_set<D>();
  const auto& f = flann_set<D>();
  std::size_t i = 0;
  std::array<std::uint32_t, kK> ids;
  std::array<double, kK> d2;
  for (auto _ : state) {
    const auto& q = s.qs[i++ % kQueries];
    const double qq[3] = {q[0], q[1], D > 2 ? q[D - 1] : 0.0};
    f.index.knnSearch(qq, kK, ids.data(), d2.data());
    benchmark::DoNotOptimize(ids.data());
  }
  state.counters["queries/s"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_KdNearestNanoflann<2>);
BENCHMARK(BM_KdNearestNanoflann<3>);

// Every query: do the id lists differ? On the first 300 queries, classify against the exact
// oracle: ours wrong, nanoflann wrong (a different set of distances), or a tie (the same
// distances, ids in another order or other ids at the k-th distance).
template <int D> void classify() {
  const auto& s = nearest_set<D>();
  const auto& f = flann_set<D>();
  NoProbe none;
  std::size_t differ = 0, ours_wrong = 0, flann_wrong = 0, ties = 0, checked = 0, trees_differ = 0;
  std::vector<VecN<Rational, D>> exact;
  for (const auto& p : s.pts) {
    VecN<Rational, D> v;
    for (int k = 0; k < D; ++k) v[k] = num::to_rational(p[k]);
    exact.push_back(v);
  }
  for (std::size_t i = 0; i < kQueries; ++i) {
    const auto& q = s.qs[i];
    const auto ours = kd_nearest_tree<double, D>(s.tree, s.pts, q, kK, none);
    const auto on_median = kd_nearest_tree<double, D>(s.median, s.pts, q, kK, none);
    trees_differ += on_median.ids != ours.ids || on_median.d2 != ours.d2;
    std::array<std::uint32_t, kK> ids;
    std::array<double, kK> d2;
    const double qq[3] = {q[0], q[1], D > 2 ? q[D - 1] : 0.0};
    f.index.knnSearch(qq, kK, ids.data(), d2.data());
    const std::vector<std::int32_t> theirs(ids.begin(), ids.end());
    if (theirs == ours.ids) continue;
    ++differ;
    if (checked >= 300) continue;
    ++checked;
    VecN<Rational, D> eq;
    for (int k = 0; k < D; ++k) eq[k] = num::to_rational(q[k]);
    const auto want = oracle::k_nearest(exact, eq, kK);
    std::vector<std::int32_t> want_ids;
    std::vector<Rational> want_d2;
    for (const auto& [d, id] : want) want_ids.push_back(id), want_d2.push_back(d);
    auto d2_of = [&](const std::vector<std::int32_t>& v) {
      std::vector<Rational> out;
      for (std::int32_t id : v) {
        Rational sum(0);
        for (int k = 0; k < D; ++k) sum += (exact[id][k] - eq[k]) * (exact[id][k] - eq[k]);
        out.push_back(sum);
      }
      std::sort(out.begin(), out.end());
      return out;
    };
    const bool ours_ok = ours.ids == want_ids, theirs_same_d2 = d2_of(theirs) == want_d2;
    ours_wrong += !ours_ok && d2_of(ours.ids) != want_d2;
    flann_wrong += !theirs_same_d2;
    ties += theirs_same_d2;
  }
  std::printf("kd-nearest %dD, %zu points, %zu queries, k = %zu: id lists differ from nanoflann's on %zu; of the first %zu of those, "
              "ours wrong %zu, nanoflann's distances wrong %zu, ties (same distances, other ids or order) %zu\n",
              D, kPoints, kQueries, kK, differ, checked, ours_wrong, flann_wrong, ties);
  std::printf("kd-nearest %dD: answers on kd-build's tree (depth %zu) and the median tree (depth %zu) differ on %zu queries\n", D,
              s.tree.depth, s.median.depth, trees_differ);
}
#endif

}  // namespace

int main(int argc, char** argv) {
#ifdef SW_HAVE_NANOFLANN
  classify<2>();
  classify<3>();
#else
  std::printf("nanoflann not found: install libnanoflann-dev for the peer comparison\n");
#endif
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
