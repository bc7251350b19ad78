// What tracing costs. The untraced algorithms (NoProbe) against hand-written plain loops with the
// same semantics, in the same run; the in-memory recorder per step; JSONL export steps per second.
//   build/bench/bench_probe --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include "catalog.hpp"
#include "trace_io.hpp"
#include "core/jsonl_probe.hpp"
#include "core/probe.hpp"
#include "lines/bresenham_line.hpp"
#include "lines/dda_line.hpp"

using namespace sw;

namespace {

template <class T> std::vector<std::array<Vec2<T>, 2>> segments(bool integer) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-2000, 2000), len(100, 400), ang(0, 6.283185307179586);
  std::vector<std::array<Vec2<T>, 2>> out;
  for (int i = 0; i < 1000; ++i) {
    double x = u(rng), y = u(rng), l = len(rng), a = ang(rng);
    double x1 = x + l * std::cos(a), y1 = y + l * std::sin(a);
    if (integer) x = std::round(x), y = std::round(y), x1 = std::round(x1), y1 = std::round(y1);
    out.push_back({Vec2<T>{T(x), T(y)}, Vec2<T>{T(x1), T(y1)}});
  }
  return out;
}

// The DDA written plainly, with dda_line's exact semantics (major axis, swap, start offset, bound).
bool hand_dda(Vec2<double> p0, Vec2<double> p1, std::vector<Pixel>& out) {
  double dx = p1.x - p0.x, dy = p1.y - p0.y;
  const bool x_major = std::fabs(dx) > std::fabs(dy);
  double a0 = x_major ? p0.x : p0.y, b0 = x_major ? p0.y : p0.x, a1 = x_major ? p1.x : p1.y;
  double da = x_major ? dx : dy, db = x_major ? dy : dx;
  if (da < 0) {
    a0 = x_major ? p1.x : p1.y, b0 = x_major ? p1.y : p1.x, a1 = x_major ? p0.x : p0.y;
    da = -da, db = -db;
  }
  if (da == 0) return true;
  const double m = db / da, first = std::ceil(a0), off = first - a0;
  double qa = a0 + off * 1.0, qb = b0 + off * m;
  const std::int64_t bound = static_cast<std::int64_t>(std::ceil(a1)) - static_cast<std::int64_t>(first) + 1;
  for (std::int64_t n = 0; n < bound; ++n) {
    if (!(qa < a1)) return true;
    const auto i = static_cast<std::int64_t>(std::floor(qa + 0.5)), j = static_cast<std::int64_t>(std::floor(qb + 0.5));
    out.push_back(x_major ? Pixel{i, j} : Pixel{j, i});
    qa += 1.0, qb += m;
  }
  return false;
}

// Bresenham written plainly on int64, with bresenham_line's semantics.
void hand_bresenham(Vec2<std::int64_t> p0, Vec2<std::int64_t> p1, std::vector<Pixel>& out) {
  const std::int64_t dx = p1.x - p0.x, dy = p1.y - p0.y;
  const bool x_major = std::llabs(dx) > std::llabs(dy);
  const std::int64_t A = std::llabs(x_major ? dx : dy), B = std::llabs(x_major ? dy : dx);
  const std::int64_t sa = (x_major ? dx : dy) > 0 ? 1 : -1, sb = ((x_major ? dy : dx) > 0) - ((x_major ? dy : dx) < 0);
  std::int64_t e = 2 * B - A, a = x_major ? p0.x : p0.y, b = x_major ? p0.y : p0.x;
  for (std::int64_t k = 0; k < A; ++k) {
    out.push_back(x_major ? Pixel{a, b} : Pixel{b, a});
    if (e > 0 || (e == 0 && sb > 0)) b += sb, e -= 2 * A;
    a += sa, e += 2 * B;
  }
}

template <class F> void pixels_loop(benchmark::State& state, F&& draw) {
  std::vector<Pixel> out;
  out.reserve(1 << 16);
  std::size_t pixels = 0;
  for (auto _ : state) {
    out.clear();
    draw(out);
    pixels += out.size();
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_pixel"] = benchmark::Counter(static_cast<double>(pixels), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_dda_hand_loop(benchmark::State& state) {
  const auto segs = segments<double>(false);
  pixels_loop(state, [&](auto& out) { for (const auto& s : segs) hand_dda(s[0], s[1], out); });
}
void BM_dda_untraced(benchmark::State& state) {
  const auto segs = segments<double>(false);
  NoProbe none;
  pixels_loop(state, [&](auto& out) { for (const auto& s : segs) lines::dda_line<double>(s[0], s[1], out, none); });
}
void BM_bresenham_hand_loop(benchmark::State& state) {
  const auto segs = segments<std::int64_t>(true);
  pixels_loop(state, [&](auto& out) { for (const auto& s : segs) hand_bresenham(s[0], s[1], out); });
}
void BM_bresenham_untraced(benchmark::State& state) {
  const auto segs = segments<std::int64_t>(true);
  NoProbe none;
  pixels_loop(state, [&](auto& out) { for (const auto& s : segs) lines::bresenham_line<std::int64_t>(s[0], s[1], out, none); });
}

// Recorder: ns per recorded step. Arg 0: a fresh recorder each time (growth and page faults
// included); arg 1: one recorder cleared and reused (the app's re-record on drag).
template <class Num> void BM_dda_recorder(benchmark::State& state) {
  const auto segs = segments<Num>(false);
  std::vector<Pixel> out;
  std::size_t steps = 0;
  Recorder<Num> reused;
  for (auto _ : state) {
    Recorder<Num> fresh;
    Recorder<Num>& rec = state.range(0) ? reused : fresh;
    rec.clear();
    for (const auto& s : segs) {
      out.clear();
      lines::dda_line<Num>(s[0], s[1], out, rec);
    }
    steps += rec.size();
    benchmark::DoNotOptimize(rec.size());
  }
  state.counters["ns_per_step"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// JSONL export to a file: steps per second (the stream is what `stepwise trace` writes).
template <class Num> void BM_dda_jsonl(benchmark::State& state) {
  const auto segs = segments<Num>(false);
  std::ofstream sink("/dev/null");
  std::vector<Pixel> out;
  std::size_t steps = 0;
  for (auto _ : state) {
    JsonlProbe<Num> probe(sink);
    for (const auto& s : segs) {
      out.clear();
      lines::dda_line<Num>(s[0], s[1], out, probe);
    }
    probe.finish();
    steps += probe.count();
  }
  state.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(BM_dda_hand_loop);
BENCHMARK(BM_dda_untraced);
BENCHMARK(BM_bresenham_hand_loop);
BENCHMARK(BM_bresenham_untraced);
BENCHMARK_TEMPLATE(BM_dda_recorder, double)->Arg(0)->Arg(1);
BENCHMARK_TEMPLATE(BM_dda_recorder, Rational)->Arg(0)->Arg(1);
BENCHMARK_TEMPLATE(BM_dda_jsonl, double);
BENCHMARK_TEMPLATE(BM_dda_jsonl, Rational);
BENCHMARK_MAIN();

// What the app pays to (re-)record a 10^6-step trace through the catalog: recorder + result.
static void BM_catalog_record_1M_steps(benchmark::State& state) {
  const sw::Algorithm& alg = sw::find_algorithm("dda-line");
  const sw::Run run = alg.open(sw::Json::parse(R"({"p0":[0.25,0.5],"p1":[499999.75,123456.5]})"), sw::Numeric::f64);
  std::size_t steps = 0;
  for (auto _ : state) {
    sw::Recorded rec = run.record();
    steps += rec.trace->size();
  }
  state.counters["steps"] = static_cast<double>(steps) / static_cast<double>(state.iterations());
  state.counters["ns_per_step"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_catalog_record_1M_steps)->Unit(benchmark::kMillisecond);

// `stepwise check` of a double dda-line trace of ~10^5 steps: µs per step (the goal is 10 or less).
static void BM_check_dda_double(benchmark::State& state) {
  const sw::Run run = sw::find_algorithm("dda-line").open(sw::Json::parse(R"({"p0":[0.25,0.5],"p1":[49999.75,12345.5]})"), sw::Numeric::f64);
  std::stringstream trace;
  sw::write_trace(run, trace);
  const std::string text = trace.str();
  std::size_t steps = 0;
  for (auto _ : state) {
    std::istringstream in(text);
    const sw::CheckReport rep = sw::check_trace(in);
    if (rep.status != 0) state.SkipWithError(rep.message.c_str());
    steps += rep.steps;
  }
  state.counters["us_per_step"] = benchmark::Counter(static_cast<double>(steps) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_check_dda_double)->Unit(benchmark::kMillisecond);
