// num::exact_sign, the filter chain behind every exact decision of the lighting and tracer families
// (the shading frame's horizon and mirror side, refraction's TIR): its sign against the polynomial
// evaluated in GMP rationals, on inputs built to sit on or next to the decision's boundary. The
// first stage runs on MagChecked, which throws when an expression's error index exceeds the budget
// the Mag bound is proved for, or a product nears underflow.
#include <catch2/catch.hpp>
#include <random>
#include "core/exact_sign.hpp"
#include "lighting/lighting_common.hpp"
#include "tracer/refraction.hpp"

using namespace sw;

namespace {

Rational q(double x) { return num::to_rational(x); }
Vec3<Rational> q(const Vec3<double>& v) { return {q(v.x), q(v.y), q(v.z)}; }

// The exact sign, straight from the polynomial in rationals.
template <class F, class... V> int exact(F&& f, const V&... v) { return sgn(Rational(f(q(v)...))); }

struct Inputs {
  std::mt19937_64 rng{20261203};
  // A coordinate of random sign and a magnitude from 2^-110 to 2^110 (beyond Mag's input range
  // [2^-100, 2^100] at both ends), sometimes 0 or a small integer.
  double coordinate() {
    const int kind = int(rng() % 8);
    if (kind == 0) return 0;
    if (kind == 1) return double(int(rng() % 11) - 5);
    std::uniform_real_distribution<double> m(1, 2);
    std::uniform_int_distribution<int> e(kind == 2 ? -110 : -30, kind == 2 ? 110 : 30);
    return (rng() % 2 ? -1 : 1) * std::ldexp(m(rng), e(rng));
  }
  Vec3<double> vec() { return {coordinate(), coordinate(), coordinate()}; }
  // A unit-ish vector of one scale.
  Vec3<double> direction() {
    std::normal_distribution<double> g;
    return {g(rng), g(rng), g(rng)};
  }
};

// b nearly perpendicular to a: a x c rounded, so a.b is 0 up to the rounding of the cross product.
Vec3<double> near_perpendicular(const Vec3<double>& a, const Vec3<double>& c) { return cross(a, c); }

// The mirror of l about n, unnormalised and rounded: 2 (n.l) n - (n.n) l. Exactly on the mirror
// side's boundary before rounding.
Vec3<double> near_mirror(const Vec3<double>& n, const Vec3<double>& l) { return 2 * dot(n, l) * n - dot(n, n) * l; }

// Counts which stage decided, so that each test shows it reaches both.
struct Stages {
  int mag = 0, later = 0;
};

template <class F, class... V> void expect_exact(Stages& st, F&& f, const V&... v) {
  const int want = exact(f, v...);
  const int got = num::exact_sign_on<MagChecked>(f, v...);
  REQUIRE(got == want);
  REQUIRE(num::exact_sign(f, v...) == want);
  MagChecked::clear_uncertain();
  const MagChecked value = f(num::detail::stage_of<MagChecked>(v)...);
  REQUIRE(value.index() <= 11);  // what exact_sign.hpp states for its callers
  const int first = MagChecked::sign_of(value);
  if (MagChecked::uncertain()) ++st.later;
  else {
    ++st.mag;
    REQUIRE(first == want);  // what the first stage certifies is exact
  }
  MagChecked::clear_uncertain();
}

}  // namespace

TEST_CASE("exact sign: dot products, near-perpendicular pairs and wide scales, as GMP says", "[exact_sign]") {
  Inputs in;
  Stages st;
  for (int i = 0; i < 4000; ++i) {
    const Vec3<double> a = in.vec(), c = in.vec();
    expect_exact(st, lighting::dot_polynomial, a, c);
    expect_exact(st, lighting::dot_polynomial, a, near_perpendicular(a, c));
    const Vec3<double> d = in.direction(), e = in.direction();
    expect_exact(st, lighting::dot_polynomial, d, near_perpendicular(d, e));
  }
  // Exactly perpendicular: a sign of 0 no filter can certify from a magnitude.
  expect_exact(st, lighting::dot_polynomial, Vec3<double>{3, 4, 0}, Vec3<double>{-4, 3, 7});
  expect_exact(st, lighting::dot_polynomial, Vec3<double>{0, 0, 0}, Vec3<double>{1, 2, 3});
  CHECK(st.mag > 3000);
  CHECK(st.later > 3000);
}

TEST_CASE("exact sign: the mirror side on and next to the mirror direction, as GMP says", "[exact_sign]") {
  Inputs in;
  Stages st;
  for (int i = 0; i < 4000; ++i) {
    const Vec3<double> n = in.vec(), l = in.vec(), e = in.vec();
    expect_exact(st, lighting::mirror_polynomial, n, l, e);
    const Vec3<double> dn = in.direction(), dl = in.direction();
    expect_exact(st, lighting::mirror_polynomial, dn, dl, near_mirror(dn, dl));
  }
  // Exactly the mirror: n = z, l = (1, 2, 3), e = (-1, -2, 3).
  expect_exact(st, lighting::mirror_polynomial, Vec3<double>{0, 0, 1}, Vec3<double>{1, 2, 3}, Vec3<double>{-1, -2, 3});
  CHECK(st.mag > 2000);
  CHECK(st.later > 200);
}

TEST_CASE("exact sign: total internal reflection at and around the critical angle, as GMP says", "[exact_sign]") {
  Inputs in;
  Stages st;
  // n1 = 5/4 into air: d = (4, 0, -3) against the normal z is exactly critical (sin^2 = 16/25 = 1/n1^2).
  expect_exact(st, tracer::tir_polynomial, Vec3<double>{4, 0, -3}, Vec3<double>{0, 0, 1}, 1.25, 1.0);
  REQUIRE(num::exact_sign(tracer::tir_polynomial, Vec3<double>{4, 0, -3}, Vec3<double>{0, 0, 1}, 1.25, 1.0) == 0);
  std::uniform_real_distribution<double> ior(1, 2.5);
  for (int i = 0; i < 4000; ++i) {
    const double n1 = ior(in.rng), n2 = ior(in.rng);
    expect_exact(st, tracer::tir_polynomial, in.vec(), in.vec(), n1, n2);
    // Scaled copies of the exact critical case, and a direction a rounding step off it.
    const double s = std::ldexp(1.0, int(in.rng() % 120) - 60);
    expect_exact(st, tracer::tir_polynomial, Vec3<double>{4 * s, 0, -3 * s}, Vec3<double>{0, 0, s}, 1.25, 1.0);
    expect_exact(st, tracer::tir_polynomial, Vec3<double>{std::nextafter(4.0, 5.0), 0, -3}, Vec3<double>{0, 0, 1}, 1.25, 1.0);
    const Vec3<double> d = in.direction(), m = in.direction();
    // n1 for which d is nearly critical: n1^2 = |d|^2 |m|^2 / (|d|^2 |m|^2 - (d.m)^2), rounded.
    const double dd = dot(d, d), mm = dot(m, m), dm = dot(d, m);
    expect_exact(st, tracer::tir_polynomial, d, m, std::sqrt(dd * mm / (dd * mm - dm * dm)), 1.0);
  }
  CHECK(st.mag > 3000);
  CHECK(st.later > 4000);
}
