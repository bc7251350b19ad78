// The curves family against its exact oracle (oracle/curves_oracle.*), every recorded value of
// every exact step against a closed-form statement of the semantics, and bad input.
#include <catch2/catch.hpp>
#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <random>
#include <set>
#include "catalog.hpp"
#include "scale.hpp"
#include "cli_harness.hpp"
#include "step_values.hpp"
#include "curves/circle_interior.hpp"
#include "curves/circle_midpoint.hpp"
#include "curves/poly_horner.hpp"
#include "curves_oracle.hpp"

using namespace sw;

namespace {

using testing::StepValues;
using testing::require_all_checked;
using testing::values_of;

std::vector<Pixel> sorted(std::vector<Pixel> v) {
  std::sort(v.begin(), v.end());
  return v;
}

template <class Num> std::vector<Pixel> circle(bool midpoint, const curves::CircleInput& c) {
  std::vector<Pixel> out;
  NoProbe none;
  if (midpoint) curves::circle_midpoint<Num>(c, out, none);
  else curves::circle_interior<Num>(c, out, none);
  return out;
}

std::vector<Pixel> circle_oracle(bool midpoint, const curves::CircleInput& c) {
  return midpoint ? oracle::circle_midpoint_pixels(c.cx, c.cy, c.r) : oracle::circle_interior_pixels(c.cx, c.cy, c.r);
}

template <class Num> std::vector<Pixel> cubic(bool forward, const std::array<Rational, 4>& c, std::int64_t xs, std::int64_t xe) {
  curves::Cubic<Num> p;
  for (int k = 0; k < 4; ++k) p.c[k] = num::from_rational<Num>(c[k]);
  p.xs = xs, p.xe = xe;
  std::vector<Pixel> out;
  NoProbe none;
  if (forward) curves::poly_forward_diff<Num>(p, out, none);
  else curves::poly_horner<Num>(p, out, none);
  return out;
}

Rational P(const std::array<Rational, 4>& c, const Rational& x) { return c[0] * x * x * x + c[1] * x * x + c[2] * x + c[3]; }


std::vector<Pixel> pixels_of(const Recorder<Rational>& t, std::size_t s) {
  std::vector<Pixel> px;
  for (std::uint32_t g = t.at(s).geo_begin; g < t.at(s).geo_end; ++g)
    if (t.geo_at(g).kind == GeoKind::pixel) px.push_back({t.int_value(t.geo_at(g).slot), t.int_value(t.geo_at(g).slot + 1)});
  return px;
}


}  // namespace

TEST_CASE("curves: circles in exact, filtered and int equal the oracle on 10^4 random circles", "[curves][oracle]") {
  std::mt19937_64 rng(7);
  for (bool midpoint : {true, false}) {
    INFO((midpoint ? "circle-midpoint" : "circle-interior"));
    for (int i = 0; i < sw::testing::cases(10000); ++i) {
      const auto u = [&](std::int64_t lo, std::int64_t hi) { return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng); };
      const curves::CircleInput c{u(-100000, 100000), u(-100000, 100000), i < 200 ? i : u(0, i % 10 == 0 ? 3000 : 120)};
      INFO("c = (" << c.cx << ", " << c.cy << "), r = " << c.r);
      const auto want = circle_oracle(midpoint, c);
      REQUIRE(sorted(circle<std::int64_t>(midpoint, c)) == want);
      if (i % 10 == 0) {
        REQUIRE(sorted(circle<Rational>(midpoint, c)) == want);
        REQUIRE(sorted(circle<Interval>(midpoint, c)) == want);
      }
      const auto got = circle<double>(midpoint, c);
      REQUIRE(std::set<Pixel>(got.begin(), got.end()).size() == got.size());  // no pixel twice
    }
  }
}

TEST_CASE("curves: cubics in exact and filtered equal the oracle on 10^4 random cubics", "[curves][oracle]") {
  std::mt19937_64 rng(11);
  std::size_t uncertain = 0;
  for (bool forward : {true, false}) {
    INFO((forward ? "poly-forward-diff" : "poly-horner"));
    for (int i = 0; i < sw::testing::cases(10000); ++i) {
      const auto u = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
      // Small dyadic and odd-denominator coefficients: both give y exactly on half-integers.
      const int den = i % 2 ? 64 : 3 * (1 + i % 5);
      using testing::ratio;
      const std::array<Rational, 4> c{ratio(u(-4, 4), den * den), ratio(u(-40, 40), den), ratio(u(-300, 300), den), ratio(u(-999, 999), 2)};
      const std::int64_t xs = u(-60, 40), xe = xs + u(0, 24);
      INFO("case " << i);
      const auto want = oracle::poly_pixels(c, xs, xe);
      REQUIRE(cubic<Rational>(forward, c, xs, xe) == want);
      std::optional<std::vector<Pixel>> filtered;
      try {
        filtered = cubic<Interval>(forward, c, xs, xe);
      } catch (const Uncertain&) {
        ++uncertain;  // the filter gave up (a value within rounding of a tie); the chain runs exact
      }
      if (filtered) REQUIRE(*filtered == want);
    }
  }
  CHECK(uncertain < sw::testing::cases(10000u));  // of 2 runs a case: the filter decides most by itself
}

TEST_CASE("curves: the catalog's filtered and exact modes match the oracle through the adapter", "[curves][oracle]") {
  std::mt19937_64 rng(13);
  for (const Algorithm& alg : catalog()) {
    const bool cubic_alg = alg.id.rfind("poly", 0) == 0;
    if (alg.family != "curves" || !(cubic_alg || alg.id.rfind("circle", 0) == 0)) continue;  // the others: their own files
    INFO(alg.id);
    const bool circle_alg = alg.id.rfind("circle", 0) == 0;
    for (int i = 0; i < 60; ++i) {
      const auto u = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
      const Json in = circle_alg ? Json{{"c", {u(-50, 50), u(-50, 50)}}, {"r", u(0, 60)}}
                                 : Json{{"coeffs", {std::to_string(u(-3, 3)) + "/16", std::to_string(u(-9, 9)) + "/4", u(-9, 9), "1/2"}}, {"xs", u(-20, 0)}, {"xe", u(0, 20)}};
      INFO(in.dump());
      const Json want = alg.canonical(alg.open(in).oracle());
      for (Numeric n : {Numeric::exact, Numeric::filtered}) {
        Json got = alg.open(in, n).run();
        got.erase("fallback");
        CHECK(alg.canonical(got) == want);
      }
    }
  }
}

TEST_CASE("curves: every value a circle step records matches its closed form", "[curves][replay]") {
  for (bool midpoint : {true, false}) {
    for (std::int64_t r : {0, 1, 2, 3, 7, 10, 23, 50}) {
      const curves::CircleInput c{-3, 5, r};
      Recorder<Rational> t;
      std::vector<Pixel> out;
      if (midpoint) curves::circle_midpoint<Rational>(c, out, t);
      else curves::circle_interior<Rational>(c, out, t);
      const Listing L = midpoint ? curves::CircleMidpoint::listing() : curves::CircleInterior::listing();
      const std::string V = midpoint ? "Q" : "P";
      // The tracked value at (x, y): midpoint 4 P(x + 1/2, y), interior P(x, y); and its steps.
      auto value = [&](const Rational& x, const Rational& y) {
        return midpoint ? Rational((2 * x + 1) * (2 * x + 1) + 4 * y * y - 4 * r * r) : Rational(x * x + y * y - r * r);
      };
      Rational x = -r, y = 0;  // the walk's position, followed from the steps' own records
      std::vector<Pixel> plotted;
      for (std::size_t s = 0; s < t.size(); ++s) {
        INFO((midpoint ? "midpoint" : "interior") << " r = " << r << " step " << s << " line " << L.lines[t.at(s).line - 1].name);
        StepValues sv = values_of(t, s);
        const std::string_view line = L.lines[t.at(s).line - 1].name;
        if (line == "start") {
          CHECK(sv["x"] == -r);
          CHECK(sv["y"] == 0);
        } else if (line == "init") {
          CHECK(sv[V] == value(-r, 0));
          CHECK(sv[V + "x"] == value(-r + 1, 0) - value(-r, 0));
          CHECK(sv[V + "y"] == value(-r, 1) - value(-r, 0));
        } else if (line == "plot") {
          CHECK(sv["x"] == x);
          CHECK(sv["y"] == y);
          CHECK(sv[V] == value(x, y));
          CHECK(y <= -x);  // inside the octant
          std::set<Pixel> want;
          const std::int64_t xi = x.get_num().get_si(), yi = y.get_num().get_si();
          for (auto [a, b] : {std::pair{xi, yi}, {-xi, yi}, {xi, -yi}, {-xi, -yi}, {yi, xi}, {-yi, xi}, {yi, -xi}, {-yi, -xi}}) want.insert({c.cx + a, c.cy + b});
          const auto got = pixels_of(t, s);
          CHECK(std::set<Pixel>(got.begin(), got.end()) == want);
          CHECK(got.size() == want.size());
          plotted.insert(plotted.end(), got.begin(), got.end());
        } else if (line == "step_y") {
          y += 1;
          CHECK(sv["y"] == y);
          CHECK(sv[V] == value(x, y));
          CHECK(sv[V + "y"] == value(x, y + 1) - value(x, y));
        } else if (line == "decide") {
          CHECK(sv[V] == value(x, y));
          CHECK(sv["inward"] == (value(x, y) > 0 ? 1 : 0));
        } else if (line == "step_x") {
          x += 1;
          CHECK(sv["x"] == x);
          CHECK(sv[V] == value(x, y));
          CHECK(sv[V + "x"] == value(x + 1, y) - value(x, y));
        } else if (line == "done") {
          CHECK(sv["x"] == x);
          CHECK(sv["y"] == y);
          CHECK(y > -x);
        } else {
          FAIL("no expectation for line " << line);
        }
        require_all_checked(sv, s);
        // Geometry: plot steps hold pixels only; the start step the exact circle, kept; the decide
        // step the two candidate pixels on the row, labelled with the tracked value and valued by it.
        for (std::uint32_t g = t.at(s).geo_begin; g < t.at(s).geo_end; ++g) {
          const GeoRecord& geo = t.geo_at(g);
          if (line == "start") {
            REQUIRE(geo.kind == GeoKind::circle);
            CHECK(t.num_value(geo.slot) == c.cx);
            CHECK(t.num_value(geo.slot + 1) == c.cy);
            CHECK(t.num_value(geo.slot + 2) == r);
            CHECK(geo.life == Life::keep);
          } else if (line == "decide") {
            REQUIRE(geo.kind == GeoKind::segment2);
            CHECK(t.num_value(geo.slot) == c.cx + x);
            CHECK(t.num_value(geo.slot + 1) == c.cy + y);
            CHECK(t.num_value(geo.slot + 2) == c.cx + x + 1);
            CHECK(t.num_value(geo.slot + 3) == c.cy + y);
            REQUIRE(geo.label);
            CHECK(geo.label == V);
            REQUIRE(geo.value != GeoRecord::kNoValue);
            CHECK(t.num_value(geo.value) == value(x, y));
            CHECK(geo.life == Life::step);
          } else {
            CHECK(line == "plot");
            CHECK(geo.kind == GeoKind::pixel);
            CHECK(geo.life == Life::step);
          }
        }
      }
      CHECK(plotted == out);
    }
  }
}

TEST_CASE("curves: every value a cubic step records matches its closed form", "[curves][replay]") {
  const std::array<Rational, 4> c{Rational(1, 7), Rational(-3, 4), Rational(5, 2), Rational(-1, 3)};
  for (bool forward : {true, false}) {
    for (auto [xs, xe] : {std::pair<std::int64_t, std::int64_t>{-9, 9}, {4, 4}, {0, 1}}) {
      curves::Cubic<Rational> p{c, xs, xe};
      Recorder<Rational> t;
      std::vector<Pixel> out;
      if (forward) curves::poly_forward_diff<Rational>(p, out, t);
      else curves::poly_horner<Rational>(p, out, t);
      const Listing L = forward ? curves::PolyForwardDiff::listing() : curves::PolyHorner::listing();
      auto d1 = [&](const Rational& x) { return Rational(P(c, x + 1) - P(c, x)); };
      auto d2 = [&](const Rational& x) { return Rational(P(c, x + 2) - 2 * P(c, x + 1) + P(c, x)); };
      std::vector<Pixel> plotted;
      std::int64_t x = xs;
      for (std::size_t s = 0; s < t.size(); ++s) {
        const std::string_view line = L.lines[t.at(s).line - 1].name;
        INFO((forward ? "forward" : "horner") << " step " << s << " line " << line);
        StepValues sv = values_of(t, s);
        if (line == "samples") {
          for (int k = 0; k < 4; ++k) CHECK(sv["y" + std::to_string(k)] == P(c, Rational(xs + k)));
        } else if (line == "table") {
          CHECK(sv["d1"] == d1(xs));
          CHECK(sv["d2"] == d2(xs));
          CHECK(sv["d3"] == 6 * c[0]);
        } else if (line == "start") {
          CHECK(sv["x"] == xs);
          CHECK(sv["y"] == P(c, Rational(xs)));
        } else if (line == "eval") {
          CHECK(sv["x"] == x);
          CHECK(sv["y"] == P(c, Rational(x)));
        } else if (line == "plot") {
          const Rational yx = P(c, Rational(x));
          const std::int64_t j = num::floor_int(Rational(yx + Rational(1, 2)));
          CHECK(sv["x"] == x);
          CHECK(sv["j"] == j);
          if (forward) CHECK(sv["y"] == yx);
          const auto px = pixels_of(t, s);
          REQUIRE(px.size() == 1);
          CHECK(px[0] == Pixel{x, j});
          plotted.push_back(px[0]);
          // The point geometry is the exact curve point (x, P(x)).
          bool point = false;
          for (std::uint32_t g = t.at(s).geo_begin; g < t.at(s).geo_end; ++g)
            if (t.geo_at(g).kind == GeoKind::point2) {
              point = true;
              CHECK(t.num_value(t.geo_at(g).slot) == x);
              CHECK(t.num_value(t.geo_at(g).slot + 1) == yx);
            }
          CHECK(point);
          if (!forward) ++x;
        } else if (line == "step") {
          ++x;
          CHECK(sv["x"] == x);
          CHECK(sv["y"] == P(c, Rational(x)));
          CHECK(sv["d1"] == d1(x));
          CHECK(sv["d2"] == d2(x));
        } else if (line == "done") {
          if (forward) CHECK(sv["x"] == xe);
        } else {
          FAIL("no expectation for line " << line);
        }
        require_all_checked(sv, s);
        // Geometry: the exact curve once (on the first step that has it), pixels and points on plot.
        for (std::uint32_t g = t.at(s).geo_begin; g < t.at(s).geo_end; ++g) {
          const GeoRecord& geo = t.geo_at(g);
          if (line == "plot") {
            CHECK((geo.kind == GeoKind::pixel || geo.kind == GeoKind::point2));
            continue;
          }
          REQUIRE(geo.kind == GeoKind::polyline);
          CHECK((line == "samples" || (line == "eval" && x == xs)));
          REQUIRE(geo.count >= 4);
          CHECK(t.num_value(geo.slot) == xs);
          CHECK(t.num_value(geo.slot + geo.count - 2) == xe);
          for (std::uint32_t k = 0; k < geo.count; k += 2) CHECK(t.num_value(geo.slot + k + 1) == P(c, t.num_value(geo.slot + k)));
        }
      }
      CHECK(plotted == out);
      CHECK(out.size() == static_cast<std::size_t>(xe - xs));
    }
  }
}

TEST_CASE("curves: forward differencing in float drifts over 10^6 columns and Horner does not", "[curves][accuracy]") {
  // y = x^3 / 2^40 - x^2 / 2^21 + x/8 + 3 on [0, 10^6): every value is a dyadic rational.
  const std::array<Rational, 4> c{Rational(1, mpz_class(1) << 40), Rational(-1, 1 << 21), Rational(1, 8), 3};
  const auto exact = oracle::poly_pixels(c, 0, 1000000);
  auto wrong = [&](const std::vector<Pixel>& got) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < got.size(); ++i) n += got[i] != exact[i];
    return n;
  };
  const auto fd = cubic<float>(true, c, 0, 1000000), horner = cubic<float>(false, c, 0, 1000000);
  const auto fd_double = cubic<double>(true, c, 0, 1000000);
  REQUIRE(fd.size() == exact.size());
  CHECK(wrong(fd) > 1000);             // the carried table's error grows with x^3
  CHECK(wrong(horner) < wrong(fd) / 10);
  CHECK(wrong(fd_double) < wrong(fd));
}

TEST_CASE("curves: bad input is one line and exit 2", "[curves][cli]") {
  struct Bad {
    const char *alg, *input, *numeric, *expect;
  };
  for (const Bad& b : std::initializer_list<Bad>{
           {"circle-midpoint", R"({"c":[0,0],"r":2.5})", "exact", "not an integer"},
           {"circle-midpoint", R"({"c":[0,0],"r":4194305})", "int", "outside"},
           {"circle-interior", R"({"c":[0,0],"r":-1})", "int", "outside"},
           {"circle-interior", R"({"c":[0,"1/2"],"r":3})", "int", "not an integer"},
           {"circle-midpoint", R"({"c":[0,0]})", "int", "missing field"},
           {"circle-midpoint", R"({"c":[0,0],"r":3,"x":1})", "int", "unknown field"},
           {"poly-forward-diff", R"({"coeffs":[1,0,0,0],"xs":5,"xe":4})", "double", "below xs"},
           {"poly-forward-diff", R"({"coeffs":[1,0,0,0],"xs":0,"xe":5000000})", "double", "outside"},
           {"poly-forward-diff", R"({"coeffs":[1,0,0,0],"xs":-2000000,"xe":2000000})", "double", "beyond the bound 2^21"},
           {"poly-horner", R"({"coeffs":[1,0,0,0],"xs":0,"xe":2000000})", "double", "2^60"},
           {"poly-horner", R"({"coeffs":["1/2",0,0,0],"xs":0,"xe":3})", "int", "not an integer"},
           {"poly-horner", R"({"coeffs":[1,0,0],"xs":0,"xe":3})", "double", "expected [a, b, c, d]"},
           {"poly-horner", R"({"coeffs":[1,0,0,"1/0"],"xs":0,"xe":3})", "double", "zero denominator"},
       }) {
    INFO(b.alg << " " << b.input);
    SW_CHECK_BAD_TRACE(b.alg, b.numeric, b.input, b.expect);
  }
}
