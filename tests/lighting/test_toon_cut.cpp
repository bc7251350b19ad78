// Toon over Oren-Nayar: the cut d >= cutoff is an exact sign of square roots of rationals (each of
// the model's three branches multiplied out), so exact ties are decided as ties (above: 1) in every
// mode, a cutoff 2^-40 past the tie is below (0), and away from ties the decision agrees with
// the independent 400-bit oracle's d.
#include <catch2/catch.hpp>
#include <random>
#include "catalog.hpp"
#include "lighting_test_support.hpp"

using namespace sw;
using namespace sw::testing::lighting_models;

namespace {

// sigma = 1/2: A = 1 - (1/2)(1/4)/(1/4 + 33/100) = 91/116, B = (45/100)(1/4)/(1/4 + 9/100) = 45/136.
const Rational kA(91, 116), kB(45, 136);

Json vec(std::initializer_list<Rational> v) {
  Json j = Json::array();
  for (const Rational& x : v) j.push_back(x.get_str());
  return j;
}

double toon(const Json& n, const Json& l, const Json& e, const Rational& cutoff, Numeric mode) {
  const Json in = {{"n", n}, {"l", l}, {"e", e}, {"diffuse", "oren-nayar"}, {"sigma", "1/2"}, {"cutoff", cutoff.get_str()}};
  return find_algorithm("toon").open(in, mode).run()["value"].get<double>();
}

}  // namespace

TEST_CASE("toon over oren-nayar: exact ties in each branch are above, a hair past them below, in every mode", "[lighting][toon]") {
  // Pythagorean unit vectors (then scaled: the decision is on the raw vectors), n.l = 4/5:
  //   g < 0:         e = (0, 3/5, 4/5),    d = (4/5) A
  //   g > 0, a = b:  e = l,                d = (4/5) A + (9/25) B
  //   g > 0, a < b:  e = (5/13, 0, 12/13), d = (4/5) A + B/5   (n.e = 12/13, g = 3/13)
  const Json n = vec({0, 0, 7}), l = vec({Rational(1, 5), 0, Rational(4, 15)});
  const struct {
    Json e;
    Rational d;
  } ties[] = {{vec({0, Rational(3, 5), Rational(4, 5)}), Rational(4, 5) * kA},
              {vec({Rational(3, 2), 0, 2}), Rational(4, 5) * kA + Rational(9, 25) * kB},
              {vec({5, 0, 12}), Rational(4, 5) * kA + kB / 5}};
  // And with irrational lengths: N = (1, 0, 1), L = (0, 1, 1), |N| = |L| = sqrt 2 but n.l = 1/2 exactly:
  //   g < 0:         E = (1, -1, 0),  d = A/2
  //   g > 0, a = b:  E = (1, 1, 0),   d = A/2 + B/4                (l.e = 1/2, g = 1/4)
  //   g > 0, a < b:  E = (1, 0, 3),   d = A/2 + B (3/8 - 1/4)       (a l.e / b = N.L L.E/(N.E L.L))
  // Rounded square roots (300-bit reference) land a hair off these; the exact cut does not.
  const Json n2 = vec({1, 0, 1}), l2 = vec({0, 1, 1});
  const struct {
    Json e;
    Rational d;
  } irrational[] = {{vec({1, -1, 0}), kA / 2}, {vec({1, 1, 0}), kA / 2 + kB / 4}, {vec({1, 0, 3}), kA / 2 + kB / 8}};
  for (const auto& t : irrational)
    for (Numeric mode : {Numeric::f32, Numeric::f64, Numeric::reference}) {
      INFO(t.e.dump() << " d = " << t.d.get_str() << " in " << numeric_name(mode));
      CHECK(toon(n2, l2, t.e, t.d, mode) == 1);
      CHECK(toon(n2, l2, t.e, t.d + Rational(1) / Rational(mpz_class(1) << 40), mode) == 0);
    }
  const Rational hair = Rational(1) / Rational(mpz_class(1) << 40);  // cut-offs have at most 64-bit terms
  for (const auto& t : ties) {
    // The oracle (400 bits) agrees that this is d to within its rounding.
    ModelInput in = lighting_io::parse_model_input("oren-nayar", {{"n", n}, {"l", l}, {"e", t.e}, {"sigma", "1/2"}});
    CHECK(abs(Rational(oracle_of("oren-nayar", in).value - t.d)) < Rational(1) / Rational(mpz_class(1) << 300));
    for (Numeric mode : {Numeric::f32, Numeric::f64, Numeric::reference}) {
      INFO(t.e.dump() << " d = " << t.d.get_str() << " in " << numeric_name(mode));
      CHECK(toon(n, l, t.e, t.d, mode) == 1);
      CHECK(toon(n, l, t.e, t.d + hair, mode) == 0);
      CHECK(toon(n, l, t.e, t.d - hair, mode) == 1);
    }
  }
}

TEST_CASE("toon over oren-nayar: away from ties the exact cut agrees with the 400-bit oracle's d", "[lighting][toon]") {
  std::mt19937_64 rng(2026);
  std::uniform_int_distribution<int> small(-9, 9);
  auto r = [&] { return Rational(small(rng), 1 + (rng() % 7)); };
  int decided = 0, near = 0;
  for (int k = 0; k < 600; ++k) {
    const Json n = vec({r(), r(), Rational(1 + rng() % 5)}), l = vec({r(), r(), r()}), e = vec({r(), r(), r()});
    const Rational sigma(long(rng() % 11), 10);
    ModelInput in;
    try {
      in = lighting_io::parse_model_input("oren-nayar", {{"n", n}, {"l", l}, {"e", e}, {"sigma", sigma.get_str()}});
    } catch (const InputError&) {
      continue;  // a zero vector
    }
    if (!(in.signs.lit && in.signs.seen)) continue;
    const Rational d = oracle_of("oren-nayar", in).value;
    // Cut-offs near d: d rounded to float and to double, and the doubles either side.
    const double dd = d.get_d();
    for (double cd : {double(float(dd)), dd, std::nextafter(dd, 2.0), std::nextafter(dd, -1.0)}) {
      const Rational c(cd);
      if (c < 0 || c > 1) continue;
      if (abs(Rational(d - c)) < Rational(1) / Rational(mpz_class(1) << 350)) continue;  // within the oracle's rounding
      const Json in_toon = {{"n", n}, {"l", l}, {"e", e}, {"diffuse", "oren-nayar"}, {"sigma", sigma.get_str()}, {"cutoff", c.get_str()}};
      const double t = find_algorithm("toon").open(in_toon, Numeric::reference).run()["value"].get<double>();
      INFO(in_toon.dump() << " d = " << d.get_d());
      CHECK(t == (d >= c ? 1 : 0));
      ++decided;
      near += abs(Rational(d - c)) < Rational(1, 1 << 30);
    }
  }
  CHECK(decided > 500);
  CHECK(near > 300);
}
