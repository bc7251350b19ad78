// raster-clip on triangles far larger than the screen, against the same triangles clipped to the
// screen first (Sutherland-Hodgman, exactly, outside the timed loop) and filled as a fan with
// triangle-dda: the bar is raster-clip within 2x of the pre-clipped fill. Double,
// untraced, a 256 x 256 screen; each triangle's edges cross the screen (its covered set is a
// clipped piece, not the whole screen). Run:
//   build/bench/bench_raster_clip --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <random>
#include <algorithm>
#include <cstdio>
#include <vector>
#include "fill/raster_clip.hpp"
#include "fill/sutherland_hodgman.hpp"
#include "fill/triangle_dda.hpp"
#include "input.hpp"

namespace sw {
namespace {

constexpr std::int64_t kSide = 256;
const fill::Screen kScreen{0, 0, kSide, kSide};
using Tri = std::array<Vec2<Rational>, 3>;

// Triangles `scale` times the screen's width, each with one edge through two random points on the
// screen (so the fill is a clipped piece), on the 1/256 grid.
std::vector<Tri> triangles(double scale, int count) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(scale) + 7);
  std::uniform_int_distribution<long> on(0, kSide * 256), dir(-kSide * 256, kSide * 256);
  std::vector<Tri> out;
  const long K = static_cast<long>(scale);
  auto grid = [](long n) -> Rational { return Rational(n) / 256; };
  while (static_cast<int>(out.size()) < count) {
    const Vec2<Rational> p{grid(on(rng)), grid(on(rng))}, q{grid(on(rng)), grid(on(rng))};
    if (p == q) continue;
    const Vec2<Rational> a{Rational(p.x + K * (p.x - q.x)), Rational(p.y + K * (p.y - q.y))}, b{Rational(q.x + K * (q.x - p.x)), Rational(q.y + K * (q.y - p.y))};
    const Vec2<Rational> c{grid(dir(rng) * K), grid(dir(rng) * K)};
    out.push_back({a, b, c});
  }
  return out;
}

fill::Triangle<double> to_double(const Tri& t) {
  fill::Triangle<double> v;
  for (int k = 0; k < 3; ++k) v[k].p = to_num<double>(t[k]);
  return v;
}

// The triangle clipped exactly to the screen's pixel squares [-1/2, 256 - 1/2]^2 (no sample lies
// on their edges), as a fan of double triangles.
std::vector<fill::Triangle<double>> preclipped_fan(const Tri& t) {
  const Rational lo(-1, 2), hi(2 * kSide - 1, 2);
  const std::vector<Vec2<Rational>> window{{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
  NoProbe none;
  const auto poly = fill::sutherland_hodgman<Rational>({t[0], t[1], t[2]}, window, none);
  std::vector<fill::Triangle<double>> fan;
  for (std::size_t k = 1; k + 1 < poly.size(); ++k) fan.push_back(to_double({poly[0], poly[k], poly[k + 1]}));
  return fan;
}

void BM_RasterClip(benchmark::State& state) {
  std::vector<fill::Triangle<double>> in;
  for (const Tri& t : triangles(static_cast<double>(state.range(0)), 64)) in.push_back(to_double(t));
  std::size_t pixels = 0;
  for (auto _ : state) {
    for (const auto& t : in) {
      fill::FillResult<double> r;
      NoProbe none;
      fill::raster_clip<double>(t, kScreen, r, none);
      pixels += r.pixels.size();
      benchmark::DoNotOptimize(r.pixels.data());
    }
  }
  state.counters["px/s"] = benchmark::Counter(static_cast<double>(pixels), benchmark::Counter::kIsRate);
}

void BM_PreclippedFan(benchmark::State& state) {
  std::vector<std::vector<fill::Triangle<double>>> in;
  for (const Tri& t : triangles(static_cast<double>(state.range(0)), 64)) in.push_back(preclipped_fan(t));
  std::size_t pixels = 0;
  for (auto _ : state) {
    for (const auto& fan : in)
      for (const auto& t : fan) {
        fill::FillResult<double> r;
        NoProbe none;
        fill::triangle_dda<true, double>(t, r, none);
        pixels += r.pixels.size();
        benchmark::DoNotOptimize(r.pixels.data());
      }
  }
  state.counters["px/s"] = benchmark::Counter(static_cast<double>(pixels), benchmark::Counter::kIsRate);
}

// Both fill the same samples (the clipped fan tiles the triangle's samples on the screen), up to
// double's rounding: the count of triangles where they differ goes to stderr.
[[maybe_unused]] const bool kSame = [] {
  int differ = 0;
  for (const Tri& t : triangles(1000000, 64)) {
    fill::FillResult<double> a;
    NoProbe none;
    fill::raster_clip<double>(to_double(t), kScreen, a, none);
    std::vector<Pixel> b;
    for (const auto& f : preclipped_fan(t)) {
      fill::FillResult<double> r;
      fill::triangle_dda<true, double>(f, r, none);
      b.insert(b.end(), r.pixels.begin(), r.pixels.end());
    }
    std::sort(a.pixels.begin(), a.pixels.end());
    std::sort(b.begin(), b.end());
    differ += a.pixels != b;
  }
  std::fprintf(stderr, "raster-clip and the pre-clipped fan differ on %d of 64 triangles 10^6 x the screen (double)\n", differ);
  return true;
}();

}  // namespace

// Screen-sized (1x), 10^3 and 10^6 times the screen's width.
BENCHMARK(BM_RasterClip)->Arg(1)->Arg(1000)->Arg(1000000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PreclippedFan)->Arg(1)->Arg(1000)->Arg(1000000)->Unit(benchmark::kMicrosecond);

}  // namespace sw

BENCHMARK_MAIN();
