// The ray-triangle tests, step by step: every variable and geometry item an exact step of
// ray-triangle-barycentric, -mt and -watertight records, against closed forms of
// docs/rays/semantics.md written from the input (see test_ray_steps.cpp for the inputs and the
// replay). The closed forms: with a, b, c = v0 - o, v1 - o, v2 - o and n = (v1 - v0) x (v2 - v0),
// the signed volumes w0 = d.(b x c), w1 = d.(c x a), w2 = d.(a x b) sum to d.n, and where d.n != 0
// the line meets the plane at t = n.a / d.n with barycentric weights b_i = w_i / d.n (the edge
// opposite v_i is where b_i = 0).
//
// Listing lines no step records, by design: barycentric `edges` (the normal step shows the
// scene), mt `pvec`, `inv`, `tvec` and `qvec` (intermediate vectors), watertight `retry` (float
// mode only).
#include <catch2/catch.hpp>
#include "catalog.hpp"
#include "ray_steps.hpp"
#include "rays/cases.hpp"
#include "rays_oracle.hpp"

using namespace sw;
using namespace sw::testing::rays;
using sw::testing::ratio;
using K = StepKind;

namespace {

struct TriForms {
  V3 n, a;
  std::array<Q, 3> w;
  Q dn, na;  // d.n and n.a
  std::array<VV, 3> v;
};
TriForms tri_forms(const Parsed& p) {
  TriForms f;
  f.n = crossq(sub(p.v[1], p.v[0]), sub(p.v[2], p.v[0]));
  const V3 a = sub(p.v[0], p.o), b = sub(p.v[1], p.o), c = sub(p.v[2], p.o);
  f.a = a;
  f.w = {dotq(p.d, crossq(b, c)), dotq(p.d, crossq(c, a)), dotq(p.d, crossq(a, b))};
  f.dn = dotq(p.d, f.n), f.na = dotq(f.n, a);
  CHECK(f.w[0] + f.w[1] + f.w[2] == f.dn);
  for (int i = 0; i < 3; ++i) f.v[i] = lift(p.v[i]);
  return f;
}

struct Outcome {
  bool hit = false;
  Q t;
  std::array<Q, 3> b;
};

VV at(const Parsed& p, const Q& t) { return lift(p.o) + Val(t) * lift(p.d); }

// Every test keeps the ray, the triangle and its named vertices from its first step.
ExpectedStep& scene(ExpectedStep& s, const Parsed& p, const TriForms& f) {
  s.item2(GeoKind::ray3, lift(p.o), lift(p.d)).keep();
  s.item(GeoKind::triangle3, {f.v[0].x, f.v[0].y, f.v[0].z, f.v[1].x, f.v[1].y, f.v[1].z, f.v[2].x, f.v[2].y, f.v[2].z}).keep();
  return s.point(f.v[0]).label("v0").keep().point(f.v[1]).label("v1").keep().point(f.v[2]).label("v2").keep();
}

// ray-triangle-barycentric: den = n.d; the plane's t; P = o + t d; k the axis of the largest
// |n_k| (the first on ties); beta, gamma = b1, b2 of P; outside iff some b_i < 0.
Outcome barycentric_expected(const Parsed& p, Expected& e) {
  using L = ray::RayTriangleBarycentric;
  const TriForms f = tri_forms(p);
  scene(e.step(L::normal, K::init).vec("nx", "ny", "nz", lift(f.n)), p, f);
  e.step(L::denom, K::decide).var("den", f.dn);
  if (sgn(f.dn) == 0) {
    e.step(L::denom, K::miss);
    return {};
  }
  const Q t = f.na / f.dn;
  e.step(L::t, K::decide).var("t", t);
  if (sgn(t) <= 0) {
    e.step(L::t, K::miss);
    return {};
  }
  e.step(L::point, K::advance).point(at(p, t)).label("p").keep();
  const Q ax = abs(f.n.x), ay = abs(f.n.y), az = abs(f.n.z);
  e.step(L::drop, K::decide).flag("k", ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2);
  const std::array<Q, 3> b = {f.w[0] / f.dn, f.w[1] / f.dn, f.w[2] / f.dn};
  e.step(L::solve, K::decide)
      .var("beta", b[1])
      .var("gamma", b[2])
      .segment(f.v[2], f.v[0])
      .label("beta")
      .valued(b[1])
      .segment(f.v[0], f.v[1])
      .label("gamma")
      .valued(b[2])
      .segment(f.v[1], f.v[2])
      .label("1 - beta - gamma")
      .valued(b[0]);
  if (sgn(b[0]) < 0 || sgn(b[1]) < 0 || sgn(b[2]) < 0) {
    e.step(L::inside, K::miss);
    return {};
  }
  e.step(L::hit, K::hit).var("b0", b[0]).point(at(p, t)).label("hit");
  return {true, t, b};
}

// ray-triangle-mt: det = e1.(d x e2) = -d.n; u = b1 (miss outside [0, 1]); v = b2 (miss if v < 0
// or b0 = 1 - u - v < 0); the plane's t.
Outcome mt_expected(const Parsed& p, Expected& e) {
  using L = ray::RayTriangleMT;
  const TriForms f = tri_forms(p);
  scene(e.step(L::edges, K::init), p, f);
  e.step(L::det, K::decide).var("det", Q(-f.dn));
  if (sgn(f.dn) == 0) {
    e.step(L::det, K::miss);
    return {};
  }
  const std::array<Q, 3> b = {f.w[0] / f.dn, f.w[1] / f.dn, f.w[2] / f.dn};
  e.step(L::u, K::decide).var("u", b[1]).segment(f.v[2], f.v[0]).label("u").valued(b[1]);
  if (sgn(b[1]) < 0 || b[1] > 1) {
    e.step(L::u, K::miss);
    return {};
  }
  e.step(L::v, K::decide)
      .var("v", b[2])
      .segment(f.v[0], f.v[1])
      .label("v")
      .valued(b[2])
      .segment(f.v[1], f.v[2])
      .label("1 - u - v")
      .valued(b[0]);
  if (sgn(b[2]) < 0 || sgn(b[0]) < 0) {
    e.step(L::v, K::miss);
    return {};
  }
  const Q t = f.na / f.dn;
  e.step(L::t, K::decide).var("t", t);
  if (sgn(t) <= 0) {
    e.step(L::t, K::miss);
    return {};
  }
  e.step(L::hit, K::hit).var("b0", b[0]).point(at(p, t)).label("hit");
  return {true, t, b};
}

// ray-triangle-watertight: kz the axis of the largest |d_k| (first on ties), (kx, ky) the next two,
// swapped when d_kz < 0; the shear takes P to P_k - (d_k / d_kz) P_kz. The frame is an even
// permutation when d_kz > 0 and odd otherwise, so the 2D edge functions are -w_i / |d_kz|, their
// sum det = -d.n / |d_kz|, and T = -n.a / |d_kz| (t = T / det).
Outcome watertight_expected(const Parsed& p, Expected& e) {
  using L = ray::RayTriangleWatertight;
  const TriForms f = tri_forms(p);
  const Q adx = abs(p.d.x), ady = abs(p.d.y), adz = abs(p.d.z);
  const int kz = adx >= ady && adx >= adz ? 0 : ady >= adz ? 1 : 2;
  int kx = (kz + 1) % 3, ky = (kz + 2) % 3;
  if (sgn(p.d[kz]) < 0) std::swap(kx, ky);
  scene(e.step(L::axes, K::init).flag("kx", kx).flag("ky", ky).flag("kz", kz), p, f);
  const Q dz = p.d[kz], m = abs(dz);
  e.step(L::shear, K::init).var("Sx", Q(p.d[kx] / dz)).var("Sy", Q(p.d[ky] / dz)).var("Sz", Q(1 / dz));
  const VV o = lift(p.o);
  e.step(L::translate, K::init).segment(o, f.v[0]).label("A").segment(o, f.v[1]).label("B").segment(o, f.v[2]).label("C");
  auto sheared = [&](int i, int k) {
    const V3 r = sub(p.v[i], p.o);
    return Q(r[k] - p.d[k] / dz * r[kz]);
  };
  e.step(L::project, K::init)
      .var("Ax", sheared(0, kx))
      .var("Ay", sheared(0, ky))
      .var("Bx", sheared(1, kx))
      .var("By", sheared(1, ky))
      .var("Cx", sheared(2, kx))
      .var("Cy", sheared(2, ky));
  const std::array<Q, 3> uvw = {-f.w[0] / m, -f.w[1] / m, -f.w[2] / m};
  e.step(L::edges, K::decide)
      .var("U", uvw[0])
      .var("V", uvw[1])
      .var("W", uvw[2])
      .segment(f.v[1], f.v[2])
      .label("U")
      .valued(uvw[0])
      .segment(f.v[2], f.v[0])
      .label("V")
      .valued(uvw[1])
      .segment(f.v[0], f.v[1])
      .label("W")
      .valued(uvw[2]);
  const bool neg =
      sgn(uvw[0]) < 0 || sgn(uvw[1]) < 0 || sgn(uvw[2])<0, pos = sgn(uvw[0])> 0 || sgn(uvw[1]) > 0 || sgn(uvw[2]) > 0;
  if (neg && pos) {
    e.step(L::sides, K::miss);
    return {};
  }
  const Q det = -f.dn / m, T = -f.na / m;
  e.step(L::det, K::decide).var("det", det);
  if (sgn(det) == 0) {
    e.step(L::det, K::miss);
    return {};
  }
  e.step(L::depth, K::decide).var("T", T);
  if (sgn(T) == 0 || sgn(T) != sgn(det)) {
    e.step(L::sign, K::miss);
    return {};
  }
  const Q t = f.na / f.dn;
  const std::array<Q, 3> b = {f.w[0] / f.dn, f.w[1] / f.dn, f.w[2] / f.dn};
  e.step(L::hit, K::hit).var("t", t).var("b0", b[0]).var("b1", b[1]).var("b2", b[2]).point(at(p, t)).label("hit");
  return {true, t, b};
}

// Seeded small-rational triangles: rays aimed at points of the triangle's plane given by their
// weights (on edges and vertices too), some from behind, some lying in the plane, some
// degenerate (collinear) triangles.
std::vector<Case> small_cases(int count, std::uint64_t seed) {
  SmallRng g(seed);
  static const Q weights[] = {ratio(-1, 2), 0, ratio(1, 4), ratio(1, 3), ratio(1, 2), 1, ratio(3, 2)};
  auto w = [&] { return weights[g.pick(0, 6)]; };
  std::vector<Case> out;
  for (int k = 0; k < count; ++k) {
    std::array<V3, 3> v;
    for (auto& x : v) x = {q(g.num(-2, 2)), q(g.num(-2, 2)), q(g.num(-2, 2))};
    const V3 e1 = sub(v[1], v[0]), e2 = sub(v[2], v[0]);
    if (g.one_in(10)) v[2] = sub(v[0], Q(-w()) * e1);  // collinear
    auto in_plane = [&] {
      const Q s = w(), t = w();
      return V3{v[0].x + s * e1.x + t * e2.x, v[0].y + s * e1.y + t * e2.y, v[0].z + s * e1.z + t * e2.z};
    };
    V3 o = {q(g.num(-3, 3)), q(g.num(-3, 3)), q(g.num(-3, 3))};
    if (g.one_in(10)) o = in_plane();
    V3 d = {q(g.num(-2, 2, false)), q(g.num(-2, 2, false)), q(g.num(-2, 2, false))};
    if (!g.one_in(3)) d = sub(in_plane(), o);
    if (g.one_in(5)) d = sub(V3{}, d);
    if (sgn(d.x) == 0 && sgn(d.y) == 0 && sgn(d.z) == 0) d.z = 1;
    auto js = [](const V3& x) { return Json::array({x.x.get_str(), x.y.get_str(), x.z.get_str()}); };
    out.push_back(
        {"small " + std::to_string(k), {{"ray", {{"o", js(o)}, {"d", js(d)}}}, {"triangle", {js(v[0]), js(v[1]), js(v[2])}}}});
  }
  return out;
}

using ExpectFn = Outcome (*)(const Parsed&, Expected&);

struct Seen {
  std::set<std::string_view> lines, miss_lines;
  int edge_hits = 0, vertex_hits = 0, coplanar = 0, degenerate = 0, back_hits = 0;
};

Seen replay(std::string_view id, ExpectFn expect, std::uint64_t seed) {
  std::vector<Case> cases = example_and_lessons(id);
  for (Case& c : corpus_cases("triangle")) cases.push_back(std::move(c));
  int n = 0;
  for (const Json& j : sw::rays::random_inputs("triangle", 60, seed)) cases.push_back({"random " + std::to_string(n++), j});
  const auto hard = sw::rays::hard_inputs("triangle", 5);
  for (std::size_t i = 0; i < hard.size(); i += hard.size() / 40 + 1) cases.push_back({"hard " + std::to_string(i), hard[i]});
  for (Case& c : small_cases(300, seed + 1)) cases.push_back(std::move(c));
  CHECK(cases.size() >= 400);
  const Listing listing = find_algorithm(id).listing;
  Seen seen;
  for (const Case& c : cases) {
    INFO(id << ", " << c.name << ": " << c.input.dump());
    const Parsed p = parse(c.input, "triangle");
    Recorder<Q> t;
    const Returned got = record_direct(id, c.input, t);
    Expected want;
    const Outcome out = expect(p, want);
    require_matches(t, listing, want, seen.lines);
    if (want.steps.back().kind == K::miss) seen.miss_lines.insert(listing.lines[want.steps.back().line - 1].name);
    // The expected outcome against the oracle, and what the algorithm returned against both.
    const oracle::RayResult o = oracle::ray_triangle(p.o, p.d, p.v);
    REQUIRE(o.hit == out.hit);
    CHECK(got.hit == out.hit);
    const TriForms f = tri_forms(p);
    const V3 zero{};
    seen.degenerate += f.n == zero;
    seen.coplanar += f.n != zero && sgn(f.dn) == 0 && sgn(f.na) == 0;
    if (!out.hit) continue;
    CHECK(o.t == out.t);
    CHECK(o.b == out.b);
    CHECK(got.t == out.t);
    CHECK(got.b == out.b);
    const int zeros = (sgn(out.b[0]) == 0) + (sgn(out.b[1]) == 0) + (sgn(out.b[2]) == 0);
    seen.edge_hits += zeros == 1, seen.vertex_hits += zeros == 2, seen.back_hits += sgn(f.dn) > 0;
  }
  CHECK(seen.edge_hits > 0);
  CHECK(seen.vertex_hits > 0);
  CHECK(seen.coplanar > 0);
  CHECK(seen.degenerate > 0);
  CHECK(seen.back_hits > 0);
  return seen;
}

}  // namespace

TEST_CASE("rays: exact step replay, ray-triangle-barycentric: every value and geometry item matches its closed form",
          "[rays][steps][replay]") {
  const Seen s = replay("ray-triangle-barycentric", barycentric_expected, 401);
  CHECK(s.lines == recorded_lines(ray::RayTriangleBarycentric::listing(), {"edges"}));
  CHECK(s.miss_lines == std::set<std::string_view>{"denom", "t", "inside"});
}

TEST_CASE("rays: exact step replay, ray-triangle-mt: every value and geometry item matches its closed form",
          "[rays][steps][replay]") {
  const Seen s = replay("ray-triangle-mt", mt_expected, 402);
  CHECK(s.lines == recorded_lines(ray::RayTriangleMT::listing(), {"pvec", "inv", "tvec", "qvec"}));
  CHECK(s.miss_lines == std::set<std::string_view>{"det", "u", "v", "t"});
}

TEST_CASE("rays: exact step replay, ray-triangle-watertight: every value and geometry item matches its closed form",
          "[rays][steps][replay]") {
  const Seen s = replay("ray-triangle-watertight", watertight_expected, 403);
  CHECK(s.lines == recorded_lines(ray::RayTriangleWatertight::listing(), {"retry"}));
  CHECK(s.miss_lines == std::set<std::string_view>{"sides", "det", "sign"});
}
