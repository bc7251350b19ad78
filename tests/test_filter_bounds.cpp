// The filtered types' declared error bounds against the errors they actually make (issue #16).
// The expressions are the ones the algorithms evaluate (dot, cross and triple products, differences
// of products, quotients, square roots; the line and curve families' slopes, tMax and
// forward-difference chains), on the project's random and hard sets, each evaluated at once in the
// filtered type and exactly: E is an mpq for + - * / and 300-bit MPFR for a square root
// (num::sqrt_of, 2^-300 relative, far below every bound here).
//
// Declared bounds:
//  - Mag: a value of index k has |v - E| <= gamma_k (1 + gamma_k) m, and a sign is decided when
//    |v| > kC m - 2^-1074 (the threshold), so |v - E| must stay below the threshold for any k
//    within kIndexBudget. "budget" is the worst case the budget allows: 1 + 2^-53 + ... summed 64
//    times rounds to even at every step and loses 64 u with m = 1, so it ties kC to the budget.
//  - Interval: each operation rounds its ends to nearest, then widens them by 2^-51 |end| + 2^-1021;
//    the rounding error (computed from the exact image of the operand intervals) must stay below the
//    widening, and every value must contain E.
// A row fails when its largest ratio error / bound exceeds 1 (unsound) or stays below 1 / its
// stated factor (too loose); the factors come from the measured table (print it with
// `sw_tests "[.filter-report]"`).
#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>
#include "core/functions.hpp"
#include "core/number.hpp"
#include "core/vec.hpp"
#include "filter_meter.hpp"
#include "lines/line_cases.hpp"
#include "rays/cases.hpp"

using namespace sw;

namespace {

using namespace sw::testing::filter;

// ---- The ray family's expressions (Mag is its first stage, Interval its second) ----

using D3 = std::array<double, 3>;
struct RayCase {
  D3 o, d;
  std::array<D3, 3> v{};  // triangle vertices; sphere: v[0] = c; box: min, max; plane: p, n
  double r = 0;
};

D3 d3(const Json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }
RayCase ray_case(const Json& j, const std::string& prim) {
  RayCase c{d3(j["ray"]["o"]), d3(j["ray"]["d"])};
  const Json& g = j[prim];
  if (prim == "triangle") c.v = {d3(g[0]), d3(g[1]), d3(g[2])};
  if (prim == "sphere") c.v[0] = d3(g["c"]), c.r = g["r"].get<double>();
  if (prim == "box") c.v = {d3(g["min"]), d3(g["max"]), D3{}};
  if (prim == "plane") c.v = {d3(g["p"]), d3(g["n"]), D3{}};
  return c;
}

template <class F> Vec3<Sh<F>> in3(const D3& a, Meter<F>& m) {
  Vec3<Sh<F>> v{a[0], a[1], a[2]};
  v.x.m = v.y.m = v.z.m = &m;
  return v;
}
template <class F> Sh<F> in1(double a, Meter<F>& m) {
  Sh<F> x(a);
  x.m = &m;
  return x;
}

// ray-plane: t = n.(p - o) / n.d.
template <class F> void plane(const RayCase& c, Meter<F>& m) {
  const auto o = in3(c.o, m), d = in3(c.d, m), p = in3(c.v[0], m), n = in3(c.v[1], m);
  const Sh<F> num = dot(n, p - o), den = dot(n, d);
  m.out("dot product", num), m.out("dot product", den);
  if (sgn(den.e) != 0) m.out("quotient", num / den);
}

// ray-sphere: the quadratic's coefficients and discriminant, Hearn-Baker's, the root and the
// Press et al. roots.
template <class F> void sphere(const RayCase& c, Meter<F>& m) {
  const auto o = in3(c.o, m), d = in3(c.d, m), ctr = in3(c.v[0], m);
  const Sh<F> rad = in1(c.r, m);
  const Vec3<Sh<F>> f = o - ctr;
  const Sh<F> a = dot(d, d), b = dot(f, d), r2 = rad * rad, cc = dot(f, f) - r2;
  m.out("dot product", a), m.out("dot product", b), m.out("product", r2), m.out("dot product", cc);
  m.out("difference of products", b * b - a * cc);
  const Sh<F> ba = b / a;
  m.out("quotient", ba);
  const Vec3<Sh<F>> l = f - ba * d;
  const Sh<F> disc = a * (r2 - dot(l, l));
  m.out("Hearn-Baker discriminant", disc);
  if (sgn(disc.e) < 0) return;
  const Sh<F> s = root(disc);
  m.out("square root", s);
  const Sh<F> q = sgn(b.e) < 0 ? s - b : -b - s;
  m.out("root formula", q);
  if (sgn(q.e) == 0) return;
  m.out("quotient", q / a), m.out("quotient", cc / q);
}

// ray-triangle: Moller-Trumbore's cross and triple products and quotients, and the watertight
// test's shear and edge functions.
template <class F> void triangle(const RayCase& c, Meter<F>& m) {
  const auto o = in3(c.o, m), d = in3(c.d, m), v0 = in3(c.v[0], m), v1 = in3(c.v[1], m), v2 = in3(c.v[2], m);
  const Vec3<Sh<F>> e1 = v1 - v0, e2 = v2 - v0, p = cross(d, e2), tv = o - v0, qv = cross(tv, e1);
  for (int k = 0; k < 3; ++k) m.out("difference of products", p[k]), m.out("difference of products", qv[k]);
  const Sh<F> det = dot(e1, p), un = dot(tv, p), vn = dot(d, qv), tn = dot(e2, qv);
  m.out("triple product", det), m.out("triple product", un), m.out("triple product", vn), m.out("triple product", tn);
  if (sgn(det.e) != 0) m.out("quotient", un / det), m.out("quotient", tn / det);
  // Watertight: kz the largest |d| component (exact on the inputs), shear, 2D edge functions.
  const int kz = num::max_axis(Vec3<double>{c.d[0], c.d[1], c.d[2]});
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (c.d[kz] < 0) std::swap(kx, ky);
  const Sh<F> sx = d[kx] / d[kz], sy = d[ky] / d[kz];
  m.out("quotient", sx), m.out("quotient", sy);
  std::array<Sh<F>, 3> x, y;
  for (int i = 0; i < 3; ++i) {
    const Vec3<Sh<F>> a = in3(c.v[i], m) - o;
    x[i] = a[kx] - sx * a[kz], y[i] = a[ky] - sy * a[kz];
  }
  for (int i = 0; i < 3; ++i) m.out("sheared edge function", x[(i + 2) % 3] * y[(i + 1) % 3] - y[(i + 2) % 3] * x[(i + 1) % 3]);
}

// ray-box: the slab distances (lo - o) / d for nonzero d.
template <class F> void box(const RayCase& c, Meter<F>& m) {
  const auto o = in3(c.o, m), d = in3(c.d, m), lo = in3(c.v[0], m), hi = in3(c.v[1], m);
  for (int k = 0; k < 3; ++k)
    if (c.d[k] != 0) m.out("quotient", (lo[k] - o[k]) / d[k]), m.out("quotient", (hi[k] - o[k]) / d[k]);
}

template <class F> void ray_expressions(const std::string& prim, const RayCase& c, Meter<F>& m) {
  if (prim == "plane") plane(c, m);
  else if (prim == "sphere") sphere(c, m);
  else if (prim == "triangle") triangle(c, m);
  else box(c, m);
}

// The ray sets: the bench's random set (float inputs), the same with full 53-bit significands
// (every double is a valid input), and the bench's hard set.
template <class F> void ray_sets(Meter<F>& m) {
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> jitter(-0x1p-25, 0x1p-25);
  auto widen = [&](D3& a) {
    for (double& x : a) x *= 1 + jitter(rng);
  };
  for (const std::string prim : {"plane", "sphere", "triangle", "box"}) {
    for (const Json& j : rays::random_inputs(prim.c_str(), 600, 20261122)) {
      RayCase c = ray_case(j, prim);
      m.set = "random";
      ray_expressions(prim, c, m);
      widen(c.o), widen(c.d);
      for (D3& v : c.v) widen(v);
      c.r *= 1 + jitter(rng);
      m.set = "random double";
      ray_expressions(prim, c, m);
    }
    const auto hard = rays::hard_inputs(prim.c_str(), 20261123);
    m.set = "hard";
    for (std::size_t i = 0; i < hard.size(); i += prim == "triangle" ? 5 : 1) ray_expressions(prim, ray_case(hard[i], prim), m);
  }
}

// 1 + 2^-53 + 2^-53 + ... with kIndexBudget sums: each rounds to even (down), so v = 1 while
// E = 1 + 64 u, and m rounds the same way: the error is 64 u m, the most the budget allows. Then
// the root of (63 such sums) - 1, whose v is 0 and E 63 u: the radicand's error is near the
// budget's, which is what the root's magnitude sqrt(kC m_x) / u is sized for.
template <class F> void budget(Meter<F>& m) {
  m.set = "budget";
  Sh<F> s = in1(1.0, m);
  for (int k = 0; k < Mag::kIndexBudget; ++k) s = s + in1(0x1p-53, m);
  m.out("sum chain at the index budget", s);
  Sh<F> t = in1(1.0, m);
  for (int k = 1; k < Mag::kIndexBudget; ++k) t = t + in1(0x1p-53, m);
  m.out("square root at the index budget", root(t - in1(1.0, m)));
}

// ---- The line and curve families' expressions (Interval is their filter) ----

Sh<Interval> in_q(const Rational& q, Meter<Interval>& m) { return {num::from_rational<Interval>(q), q, &m, true}; }
Rational ceil_q(const Rational& q) { return Rational(-num::floor_int(Rational(-q))); }

// dda-line's slope, first point and accumulated q; dda-grid-walk's tDelta, first tMax and the
// accumulated tMax. Integer parts (ceil, the start cell) are decided exactly, as the filter must.
void line(const testing::Segment& s, Meter<Interval>& m) {
  const Vec2<Sh<Interval>> p0{in_q(s.p0.x, m), in_q(s.p0.y, m)}, p1{in_q(s.p1.x, m), in_q(s.p1.y, m)};
  const Vec2<Sh<Interval>> d = p1 - p0;
  const int a = abs(d.x.e) > abs(d.y.e) ? 0 : 1;
  if (sgn(d[a].e) != 0) {
    const int dir = sgn(d[a].e);
    const Sh<Interval> slope = d[1 - a] / d[a];
    m.out("slope", slope);
    const Rational first = dir > 0 ? ceil_q(s.p0[a]) : ceil_q(s.p1[a]);
    const Vec2<Sh<Interval>>& start = dir > 0 ? p0 : p1;
    Sh<Interval> q = start[1 - a] + (Sh<Interval>(first.get_d()) - start[a]) * slope;
    m.out("DDA q", q);
    const Rational last = dir > 0 ? ceil_q(s.p1[a]) : ceil_q(s.p0[a]);
    for (Rational x = first + 1; x < last && x < first + 400; x += 1) m.out("DDA q (accumulated)", q = q + slope);
  }
  for (int k = 0; k < 2; ++k) {
    const int step = sgn(d[k].e);
    if (step == 0) continue;
    const Sh<Interval> t_delta = Sh<Interval>(step) / d[k];
    m.out("grid walk tDelta", t_delta);
    const double cell = double(num::floor_int(Rational(s.p0[k] + Rational(1, 2))));
    Sh<Interval> t_max = (Sh<Interval>(cell) + Sh<Interval>(step * 0.5) - p0[k]) / d[k];
    m.out("grid walk tMax", t_max);
    const std::int64_t n = std::min<std::int64_t>(num::floor_int(Rational(abs(d[k].e))) + 2, 400);
    for (std::int64_t i = 0; i < n; ++i) m.out("grid walk tMax (accumulated)", t_max = t_max + t_delta);
  }
}

// poly-forward-diff and poly-horner: P at xs..xs+3 by Horner, the difference table, and n steps
// of three additions; bezier-forward-diff's Bernstein weights at t = k/n and the point they give.
void curve(std::mt19937_64& rng, Meter<Interval>& m) {
  std::uniform_int_distribution<int> kind(0, 2), small(-64, 64), den(1, 97), xs_of(-30, 10);
  std::uniform_real_distribution<double> real(-2, 2);
  auto coeff = [&]() -> Rational {
    switch (kind(rng)) {
      case 0: return Rational(small(rng), 64);
      case 1: {
        Rational q(small(rng), den(rng));
        q.canonicalize();
        return q;
      }
      default: return Rational(real(rng));
    }
  };
  std::array<Sh<Interval>, 4> c;
  for (auto& x : c) x = in_q(coeff() / 16, m);
  const int xs = xs_of(rng);
  std::array<Sh<Interval>, 4> y;
  for (int k = 0; k < 4; ++k) {
    y[k] = num::polynomial(c, Sh<Interval>(xs + k));
    m.out("Horner", y[k]);
  }
  Sh<Interval> e0 = y[1] - y[0], e1 = y[2] - y[1], e2 = y[3] - y[2];
  Sh<Interval> d1 = e0, d2 = e1 - e0, yv = y[0];
  const Sh<Interval> d3 = (e2 - e1) - d2;
  for (int k = 0; k < 48; ++k) {
    yv = yv + d1, d1 = d1 + d2, d2 = d2 + d3;
    m.out("forward differences (accumulated)", yv);
  }
  std::array<Vec2<Sh<Interval>>, 4> p;
  for (auto& pt : p) pt = {in_q(coeff() * 8, m), in_q(coeff() * 8, m)};
  const int n = 3 + int(rng() % 40);
  for (int k = 0; k <= n; ++k) {
    const Sh<Interval> t = Sh<Interval>(k) / Sh<Interval>(n), s = Sh<Interval>(1) - t;
    const std::array<Sh<Interval>, 4> w = {s * s * s, Sh<Interval>(3) * s * s * t, Sh<Interval>(3) * s * t * t, t * t * t};
    Vec2<Sh<Interval>> q{Sh<Interval>(0), Sh<Interval>(0)};
    for (int i = 0; i < 4; ++i) q = q + w[i] * p[i];
    m.out("Bezier point", q.x), m.out("Bezier point", q.y);
  }
}

void line_curve_sets(Meter<Interval>& m) {
  m.set = "random";
  for (const auto& s : testing::random_segments(300, false, 11)) line(s, m);
  std::mt19937_64 rng(20261125);
  for (int k = 0; k < 150; ++k) curve(rng, m);
  m.set = "hard";
  for (const auto& s : testing::hard_segments(false)) line(s, m);
  // Inputs that are not doubles enter as the two neighbours of their rounding.
  m.set = "random";
  for (int k = 1; k < 1000; ++k) {
    Rational q(std::int64_t(rng() % 200001) - 100000, 1 + std::int64_t(rng() % 999));
    q.canonicalize();
    m.out("input", in_q(q, m));
  }
}

struct Measured {
  Table mag, interval;
};

Measured measure() {
  Meter<MagChecked> mag;
  ray_sets(mag);
  budget(mag);
  Meter<Interval> interval;
  ray_sets(interval);
  budget(interval);
  line_curve_sets(interval);
  return {mag.table, interval.table};
}

// The largest ratio each row must reach: its bound may be at most this factor above the largest
// error measured (`sw_tests "[.filter-report]"` prints the figures these come from; each factor
// leaves about 2x of room). Mag rows are against gamma_k (1 + gamma_k) m. Loose rows are loose by
// design: gamma_k is the worst case of k roundings, which long sums of products (Hearn-Baker's
// discriminant, the sheared edge functions) are far from; a quotient's m carries a factor 2 and 4
// more roundings; a root's magnitude is sized for a radicand whose error is at the budget, so the
// ray discriminants' roots sit 2^24 below their bound and the budget's root ties the bound instead.
struct Tightness {
  const char* row;
  double factor;
};
constexpr Tightness kMagTight[] = {
    {"op: sum", 2},
    {"op: difference", 2},
    {"op: product", 2},
    {"op: quotient", 16},               // measured 5.4
    {"op: square root", 0x1p25},        // measured 1.6e7 (2^23.9)
    {"product", 2},                     // measured 1.04 (random doubles; float products are exact)
    {"dot product", 4},                 // measured 1.5
    {"difference of products", 4},      // measured 1.5
    {"triple product", 16},             // measured 4.7
    {"quotient", 16},                   // measured 5.4
    {"square root", 0x1p25},            // measured 1.6e7
    {"root formula", 0x1p26},           // measured 2.7e7
    {"Hearn-Baker discriminant", 256},  // measured 111
    {"sheared edge function", 128},     // measured 40
    {"sum chain at the index budget", 1.001},
    {"square root at the index budget", 8},  // measured 4.3: the bound is u M_s, with gamma_3 for it
};
// Interval rows: an operation's rounding error is at most u |end| (half an ulp), its widening
// 2^-51 |end| = 4 u |end|: the widening is 4 times the worst rounding by design, so 5 fails a
// doubled widening.
constexpr Tightness kIntervalTight[] = {
    {"op: sum", 5}, {"op: difference", 5}, {"op: product", 5}, {"op: quotient", 5}, {"op: square root", 5},
};

void print(const char* type, const Table& t, bool with_c) {
  std::printf("%s\n  %-34s %-14s %8s %13s %13s %s\n", type, "row", "set", "count", "err/bound",
              with_c ? "err/threshold" : "|mid-E|/half", with_c ? "max k" : "");
  for (const auto& [row, sets] : t)
    for (const auto& [set, w] : sets) {
      std::printf("  %-34s %-14s %8ld %13.6g %13.6g", row.c_str(), set.c_str(), w.count, w.ratio, w.ratio_c);
      if (with_c) std::printf(" %5d", w.max_index);
      std::printf("\n");
    }
}

void check_table(const char* type, const Table& t, const Tightness* tight, std::size_t n_tight, bool with_c) {
  for (const auto& [row, sets] : t) {
    double worst = 0;
    for (const auto& [set, w] : sets) {
      INFO(type << " " << row << " on " << set << ": " << w.count << " values, largest error / bound " << w.ratio
                << (with_c ? ", / threshold " : ", |mid - E| / half width ") << w.ratio_c);
      CHECK(w.ratio <= 1);    // the bound holds
      CHECK(w.ratio_c <= 1);  // Mag: below the decision threshold; Interval: E inside
      worst = std::max(worst, w.ratio);
    }
    for (std::size_t i = 0; i < n_tight; ++i)
      if (row == tight[i].row) {
        INFO(type << " " << row << ": bound at most " << tight[i].factor << " times the largest error; measured " << 1 / worst);
        CHECK(worst * tight[i].factor >= 1);
      }
  }
}

}  // namespace

TEST_CASE("Filter bounds: Mag's and Interval's declared bounds hold and are tight on the algorithms' expressions",
          "[mag][interval]") {
  const Measured r = measure();
  check_table("Mag", r.mag, kMagTight, std::size(kMagTight), true);
  check_table("Interval", r.interval, kIntervalTight, std::size(kIntervalTight), false);
  // Every tightness row was measured (a renamed row would silently skip its check).
  for (const Tightness& t : kMagTight) CHECK(r.mag.count(t.row) == 1);
  for (const Tightness& t : kIntervalTight) CHECK(r.interval.count(t.row) == 1);
  // The budget's worst case reaches the decision threshold: kC is not loose by 2x.
  CHECK(r.mag.at("sum chain at the index budget").at("budget").ratio_c > 0.5);
}

TEST_CASE("Filter bounds: print the measured table", "[.filter-report]") {
  const Measured r = measure();
  print("Mag (MagChecked)", r.mag, true);
  print("Interval", r.interval, false);
}
