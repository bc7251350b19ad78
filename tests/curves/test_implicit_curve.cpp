// implicit-curve against its exact oracle (oracle::implicit_walk_pixels, a direct per-move
// statement), against circle-midpoint's set on circles, the corpus's hard cases against their
// documented outcome (docs/curves/implicit.md), and bad input through the CLI.
#include <catch2/catch.hpp>
#include <optional>
#include <set>
#include "cli_harness.hpp"
#include "scale.hpp"
#include "implicit_support.hpp"

using namespace sw;
using namespace sw::testing::implicit;
using sw::testing::ratio;

TEST_CASE("implicit-curve: exact and filtered equal the oracle on 10^4 random cubics and conics", "[curves][oracle]") {
  std::mt19937_64 rng(17);
  std::size_t uncertain = 0;
  std::map<std::string, int> reasons;
  for (int i = 0; i < sw::testing::cases(10000); ++i) {
    const Case k = random_case(rng, i);
    INFO("case " << i << " start (" << k.start.x << ", " << k.start.y << ") max_steps " << k.max_steps);
    const Walk want = oracle_walk(k);
    ++reasons[want.stopped];
    REQUIRE(walk<Rational>(k) == want);
    std::optional<Walk> filtered;
    try {
      filtered = walk<Interval>(k);
    } catch (const Uncertain&) {
      ++uncertain;        // undecided (a zero gradient, a tie or P(M) = 0 with inexact coefficients)
      CHECK(i % 4 == 2);  // integer and dyadic coefficients stay exact: their intervals are points
    }
    if (filtered) REQUIRE(*filtered == want);
  }
  CHECK(uncertain < sw::testing::cases(10000u) / 4);  // at most the thirds' cases (one in 4)
  for (const char* r : {"closed", "max_steps", "singular", "revisit"}) CHECK(reasons[r] > sw::testing::cases(20));  // every stop is exercised
}

TEST_CASE("implicit-curve: x^2 + y^2 = r^2 from its leftmost pixel plots circle-midpoint's set and closes for r = 1..300",
          "[curves][oracle]") {
  for (std::int64_t r = 1; r <= 300; ++r) {
    INFO("r = " << r);
    Case k{{}, {-r, 0}, std::int64_t{1} << 20};
    k.c[2][0] = k.c[0][2] = 1;
    k.c[0][0] = -r * r;
    const Walk w = walk<Rational>(k);
    CHECK(w.stopped == "closed");
    CHECK(w.steps == static_cast<std::int64_t>(w.pixels.size()));  // the last move returns to the start
    std::vector<Pixel> set = w.pixels;
    std::sort(set.begin(), set.end());
    REQUIRE(std::adjacent_find(set.begin(), set.end()) == set.end());  // each pixel once
    REQUIRE(set == oracle::circle_midpoint_pixels(0, 0, r));
    // Every mode is exact here (integers and quarters far inside the significands).
    CHECK(walk<double>(k) == w);
    CHECK(walk<Interval>(k) == w);
    if (r <= 40 || r % 50 == 0) CHECK(oracle_walk(k) == w);
    if (r <= 100) CHECK(walk<float>(k) == w);
  }
}

TEST_CASE("implicit-curve: the corpus's hard cases stop as documented in every mode", "[curves][corpus]") {
  const auto cases = corpus();
  const auto get = [&](const std::string& name) {
    INFO(name);
    REQUIRE(cases.count(name));
    return case_of(cases.at(name));
  };
  const Algorithm& alg = find_algorithm("implicit-curve");
  // Through the catalog, every mode but float equals the oracle on every corpus case.
  for (const auto& [name, in] : cases) {
    INFO(name);
    const Json want = alg.open(in).oracle();
    for (Numeric n : {Numeric::exact, Numeric::filtered, Numeric::f64}) {
      Json got = alg.open(in, n).run();
      got.erase("fallback");
      CHECK(got == want);
    }
    CHECK(oracle_walk(case_of(in)) == walk<Rational>(case_of(in)));
  }
  {  // The circle and the rational ellipse close.
    for (const char* n : {"implicit: circle r=10", "implicit: rotated ellipse, rational coefficients", "implicit: circle r=1"}) {
      INFO(n);
      CHECK(walk<Rational>(get(n)).stopped == "closed");
    }
    const Walk w = walk<Rational>(get("implicit: circle r=1"));
    CHECK(w.pixels == std::vector<Pixel>{{-1, 0}, {0, -1}, {1, 0}, {0, 1}});
  }
  {  // The line plots the row nearest the line in each column, left to right, until max_steps.
    const Walk w = walk<Rational>(get("implicit: line 3x - 7y + 2 = 0"));
    CHECK(w.stopped == "max_steps");
    for (std::size_t i = 0; i < w.pixels.size(); ++i) {
      const auto [x, y] = w.pixels[i];
      CHECK(x == static_cast<std::int64_t>(i));
      CHECK(abs(ratio(3 * x + 2, 7) - y) < ratio(1, 2));
    }
  }
  {  // The hyperbola runs up along its asymptote x = 0 and never closes.
    const Case k = get("implicit: hyperbola xy = 30 along its asymptote");
    const Walk w = walk<Rational>(k);
    CHECK(w.stopped == "max_steps");
    CHECK(w.steps == k.max_steps);
    CHECK(w.pixels.size() == static_cast<std::size_t>(k.max_steps + 1));
    for (std::size_t i = 0; i < w.pixels.size(); ++i) CHECK(w.pixels[i].x == (i < 31 ? 1 : 0));  // 30 / y < 1/2 from y = 61 on
    CHECK(w.pixels.back().y == w.pixels.front().y + k.max_steps);
  }
  {  // y^2 = x^2 (x + 8): the walk comes into the node along one branch and leaves along the other.
    const Walk w = walk<Rational>(get("implicit: nodal cubic y^2 = x^2 (x + 8), turns at the node"));
    CHECK(w.stopped == "max_steps");
    CHECK(std::find(w.pixels.begin(), w.pixels.end(), Pixel{0, 0}) == w.pixels.end());
    const auto at = std::find(w.pixels.begin(), w.pixels.end(), Pixel{0, -1});
    REQUIRE(at + 2 < w.pixels.end());
    CHECK(at[-1] == Pixel{-1, -2});  // from the lower left (the loop's lower half) ...
    CHECK(at[1] == Pixel{1, -1});    // ... out to the lower right (the other branch)
    CHECK(at[2] == Pixel{1, -2});
  }
  {  // y^2 = x^2 (x + 4): the walk lands on the node, where the gradient is 0.
    const Walk w = walk<Rational>(get("implicit: nodal cubic y^2 = x^2 (x + 4), reaches the node"));
    CHECK(w.stopped == "singular");
    CHECK(w.pixels.back() == Pixel{0, 0});
    CHECK(w.steps + 1 == static_cast<std::int64_t>(w.pixels.size()));
  }
  {  // The cusp: toward it on the upper branch, it stops there; on the lower branch it walks away.
    const Walk up = walk<Rational>(get("implicit: cusp y^2 = x^3, toward the cusp"));
    CHECK(up.stopped == "singular");
    CHECK(up.pixels.back() == Pixel{0, 0});
    const Walk down = walk<Rational>(get("implicit: cusp y^2 = x^3, away from the cusp"));
    CHECK(down.stopped == "max_steps");
    for (std::size_t i = 1; i < down.pixels.size(); ++i) CHECK(down.pixels[i].y < down.pixels[i - 1].y);
  }
  {  // Far from the circle, the walk slides down to it, goes round and stops where it joined.
    const Walk w = walk<Rational>(get("implicit: far start, circle r=10 from (40, 3)"));
    CHECK(w.stopped == "revisit");
    const auto circle = oracle::circle_midpoint_pixels(0, 0, 10);
    const auto on = [&](Pixel q) { return std::binary_search(circle.begin(), circle.end(), q); };
    const auto first = std::find_if(w.pixels.begin(), w.pixels.end(), on);
    REQUIRE(first != w.pixels.end());
    CHECK(std::all_of(first, w.pixels.end(), on));
    CHECK(static_cast<std::size_t>(w.pixels.end() - first) == circle.size());  // all of the circle, once
    // On the way in (a spiral), P never increases from one pixel to the next.
    const Case k = get("implicit: far start, circle r=10 from (40, 3)");
    for (auto q = w.pixels.begin(); q + 1 < first; ++q) CHECK(P(k.c, q[1].x, q[1].y) <= P(k.c, q[0].x, q[0].y));
    CHECK(first - w.pixels.begin() == 63);
  }
  {  // Started at the circle's centre, where grad P = 0: no move.
    const Walk w = walk<Rational>(get("implicit: start at the circle's centre"));
    CHECK(w.stopped == "singular");
    CHECK(w.steps == 0);
    CHECK(w.pixels == std::vector<Pixel>{{0, 0}});
  }
}

TEST_CASE("implicit-curve: bad input is one line and exit 2 with no trace", "[curves][cli]") {
  struct Bad {
    const char *input, *numeric, *expect;
  };
  for (const Bad& b : std::initializer_list<Bad>{
           {R"({"P":[[1,2,2],[1,0,0]],"start":[0,0],"max_steps":10})", "exact", "beyond 3"},
           {R"({"P":[[1,-1,0]],"start":[0,0],"max_steps":10})", "exact", "outside [0, 3]"},
           {R"({"P":[[1,0,"1/2"]],"start":[0,0],"max_steps":10})", "exact", "not an integer"},
           {R"({"P":[[1,1.5,0]],"start":[0,0],"max_steps":10})", "double", "not an integer"},
           {R"({"P":[],"start":[0,0],"max_steps":10})", "exact", "non-empty"},
           {R"({"P":{},"start":[0,0],"max_steps":10})", "exact", "non-empty"},
           {R"({"P":[[5,0,0]],"start":[0,0],"max_steps":10})", "exact", "P is constant"},
           {R"({"P":[[0,1,0],[5,0,0]],"start":[0,0],"max_steps":10})", "exact", "P is constant"},
           {R"({"P":[[1,1,0],[2,1,0]],"start":[0,0],"max_steps":10})", "exact", "duplicate term x^1 y^0"},
           {R"({"P":[[1,2]],"start":[0,0],"max_steps":10})", "exact", "expected a term"},
           {R"({"P":[["36893488147419103232",1,0]],"start":[0,0],"max_steps":10})", "exact", "beyond 64 bits"},
           {R"({"P":[["1/36893488147419103232",1,0]],"start":[0,0],"max_steps":10})", "filtered", "beyond 64 bits"},
           {R"({"P":[["nan",1,0]],"start":[0,0],"max_steps":10})", "exact", "not a finite number"},
           {R"({"P":[[1,1,0]],"start":[1048577,0],"max_steps":10})", "exact", "outside"},
           {R"({"P":[[1,1,0]],"start":[0,-1048577],"max_steps":10})", "exact", "outside"},
           {R"({"P":[[1,1,0]],"start":[0],"max_steps":10})", "exact", "expected the start pixel"},
           {R"({"P":[[1,1,0]],"start":[0,0],"max_steps":0})", "exact", "outside [1, 1048576]"},
           {R"({"P":[[1,1,0]],"start":[0,0],"max_steps":1048577})", "exact", "outside [1, 1048576]"},
           {R"({"P":[[10000000000000,3,0]],"start":[0,0],"max_steps":1048576})", "float", "beyond the bound 2^100"},
           {R"({"P":[[1,1,0]],"start":[0,0]})", "exact", "missing field"},
           {R"({"P":[[1,1,0]],"start":[0,0],"max_steps":10,"r":1})", "exact", "unknown field"},
           {R"({"P":[[1,1,0]],"start":[0,0],"max_steps":10})", "int", "does not run on 'int'"},
       }) {
    INFO(b.input << " " << b.numeric);
    SW_CHECK_BAD_TRACE("implicit-curve", b.numeric, b.input, b.expect);
  }
}
