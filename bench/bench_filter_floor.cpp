// What a filter of the once-written ray tests pays at least, next to the real one (Mag). A filter
// that certifies each decision of the algorithm as it is made must at least check each one;
// ChecksOnly does only that: plain double arithmetic, and at every decision one comparison of
// |a - b| with a constant (no error bound is tracked, so it is not sound: timing only, used
// nowhere else). It keeps Mag's branch-free num::select, so the control flow matches. A tight
// loop over the random sets of `stepwise bench`, without its output bookkeeping. Run:
//   build/bench/bench_filter_floor --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <cstring>
#include <string>
#include <vector>
#include "core/number.hpp"
#include "input.hpp"
#include "rays/ray_box.hpp"
#include "rays/ray_plane.hpp"
#include "rays/ray_sphere_geometric.hpp"
#include "rays/ray_sphere_quadratic.hpp"
#include "rays/ray_sphere_stable.hpp"
#include "rays/cases.hpp"

namespace sw {

struct ChecksOnly {
  double v = 0;
  ChecksOnly() = default;
  ChecksOnly(double x) : v(x) {}
  ChecksOnly(int x) : v(x) {}
  static inline thread_local bool flag = false;
  [[gnu::noinline, gnu::cold]] static void raise() { flag = true; }
  static void clear_uncertain() { flag = false; }
  static bool uncertain() { return flag; }
  [[gnu::always_inline]] static double checked(double d) {
    if (!(std::fabs(d) > 0x1p-900)) [[unlikely]] raise();
    return d;
  }
  [[gnu::always_inline]] friend ChecksOnly operator-(ChecksOnly a) { return -a.v; }
  [[gnu::always_inline]] friend ChecksOnly operator+(ChecksOnly a, ChecksOnly b) { return a.v + b.v; }
  [[gnu::always_inline]] friend ChecksOnly operator-(ChecksOnly a, ChecksOnly b) { return a.v - b.v; }
  [[gnu::always_inline]] friend ChecksOnly operator*(ChecksOnly a, ChecksOnly b) { return a.v * b.v; }
  [[gnu::always_inline]] friend ChecksOnly operator/(ChecksOnly a, ChecksOnly b) { return a.v / b.v; }
  [[gnu::always_inline]] friend ChecksOnly sqrt(ChecksOnly a) { return std::sqrt(a.v); }
  [[gnu::always_inline]] friend bool operator<(ChecksOnly a, ChecksOnly b) { return checked(a.v - b.v) < 0; }
  [[gnu::always_inline]] friend bool operator>(ChecksOnly a, ChecksOnly b) { return checked(a.v - b.v) > 0; }
  [[gnu::always_inline]] friend bool operator<=(ChecksOnly a, ChecksOnly b) { return checked(a.v - b.v) <= 0; }
  [[gnu::always_inline]] friend bool operator>=(ChecksOnly a, ChecksOnly b) { return checked(a.v - b.v) >= 0; }
  [[gnu::always_inline]] friend bool operator==(ChecksOnly a, ChecksOnly b) { return checked(a.v - b.v) == 0; }
  [[gnu::always_inline]] friend bool operator!=(ChecksOnly a, ChecksOnly b) { return checked(a.v - b.v) != 0; }
};

template <> struct NumericOf<ChecksOnly> { static constexpr Numeric value = Numeric::filtered; };

namespace num {
[[gnu::always_inline]] inline double to_double(ChecksOnly a) { return a.v; }
[[gnu::always_inline]] inline int sign(ChecksOnly a) {
  const double v = ChecksOnly::checked(a.v);
  return (v > 0) - (v < 0);
}
[[gnu::always_inline]] inline ChecksOnly select(bool c, ChecksOnly a, ChecksOnly b) {
  std::uint64_t x, y, m = -std::uint64_t(c);
  std::memcpy(&x, &a.v, 8), std::memcpy(&y, &b.v, 8);
  x = (x & m) | (y & ~m);
  double r;
  std::memcpy(&r, &x, 8);
  return r;
}
}  // namespace num

namespace {

enum Test { plane, box, geometric, quadratic, stable };

template <class N> struct Case {
  ray::Ray3<N> ray;
  Vec3<N> a, b;  // plane: p, n; box: min, max; sphere: a = centre
  N r;
};
struct Out {
  bool hit;
  double t, t_near, t_far;
};

Vec3<double> vec(const Json& obj, const char* key) { return to_num<double>(parse_point3(obj, key)); }

std::vector<Case<double>> random_set(Test t) {
  const char* prim = t == plane ? "plane" : t == box ? "box" : "sphere";
  std::vector<Case<double>> out;
  for (const Json& j : rays::random_inputs(prim, 10000, 20261122)) {
    Case<double> c{{vec(j["ray"], "o"), vec(j["ray"], "d")}, {}, {}, 0};
    if (t == plane) c.a = vec(j["plane"], "p"), c.b = vec(j["plane"], "n");
    else if (t == box) c.a = vec(j["box"], "min"), c.b = vec(j["box"], "max");
    else c.a = vec(j["sphere"], "c"), c.r = j["sphere"]["r"].get<double>();
    out.push_back(c);
  }
  return out;
}

template <class N> Vec3<N> conv(const Vec3<double>& v) { return {N(v.x), N(v.y), N(v.z)}; }

template <class N, Test T> [[gnu::always_inline]] inline Out one(const Case<N>& c) {
  NoProbe none;
  if constexpr (T == plane) {
    const auto h = ray::ray_plane<N>(c.ray, c.a, c.b, none);
    return {h.hit, num::to_double(h.t), 0, 0};
  } else if constexpr (T == box) {
    const auto h = ray::ray_box<N>(c.ray, c.a, c.b, none);
    return {h.hit, num::to_double(h.t), num::to_double(h.t_near), num::to_double(h.t_far)};
  } else if constexpr (T == geometric) {
    const auto h = ray::ray_sphere_geometric<N>(c.ray, c.a, c.r, none);
    return {h.hit, num::to_double(h.t), 0, 0};
  } else if constexpr (T == quadratic) {
    const auto h = ray::ray_sphere_quadratic<N>(c.ray, c.a, c.r, none);
    return {h.hit, num::to_double(h.t), 0, 0};
  } else {
    const auto h = ray::ray_sphere_stable<N>(c.ray, c.a, c.r, none);
    return {h.hit, num::to_double(h.t), 0, 0};
  }
}

template <class N, Test T> void BM_floor(benchmark::State& state) {
  std::vector<Case<N>> cases;
  for (const auto& c : random_set(T)) cases.push_back({{conv<N>(c.ray.o), conv<N>(c.ray.d)}, conv<N>(c.a), conv<N>(c.b), N(c.r)});
  std::vector<Out> outs(cases.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < cases.size(); ++i) {
      // As the filtered mode runs a case: clear the flag, run, look at the flag.
      if constexpr (requires { N::clear_uncertain(); }) N::clear_uncertain();
      outs[i] = one<N, T>(cases[i]);
      if constexpr (requires { N::uncertain(); })
        if (N::uncertain()) [[unlikely]] outs[i].hit = !outs[i].hit;
    }
    benchmark::DoNotOptimize(outs.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(cases.size()));
}

#define SW_FLOOR(T)                                                  \
  BENCHMARK_TEMPLATE(BM_floor, double, T)->Name("double/" #T);       \
  BENCHMARK_TEMPLATE(BM_floor, ChecksOnly, T)->Name("checks_only/" #T); \
  BENCHMARK_TEMPLATE(BM_floor, Mag, T)->Name("mag/" #T);
SW_FLOOR(plane)
SW_FLOOR(box)
SW_FLOOR(geometric)
SW_FLOOR(quadratic)
SW_FLOOR(stable)

}  // namespace
}  // namespace sw

BENCHMARK_MAIN();
