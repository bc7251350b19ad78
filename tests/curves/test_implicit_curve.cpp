// implicit-curve against its exact oracle (oracle::implicit_walk_pixels, a direct per-move
// statement), against circle-midpoint's set on circles, every recorded value of every exact step
// against a closed form, the corpus's hard cases against their documented outcome
// (docs/curves/implicit.md), and bad input through the CLI.
#include <catch2/catch.hpp>
#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <random>
#include <set>
#include "catalog.hpp"
#include "cli_harness.hpp"
#include "step_values.hpp"
#include "curves/implicit_curve.hpp"
#include "curves_oracle.hpp"
#include "input.hpp"

using namespace sw;

namespace {

using testing::StepValues;
using testing::require_all_checked;
using testing::values_of;

using Coeffs = std::array<std::array<Rational, 4>, 4>;

struct Case {
  Coeffs c;
  Pixel start;
  std::int64_t max_steps = 1;
};

struct Walk {
  std::vector<Pixel> pixels;
  std::string stopped;
  std::int64_t steps = 0;
  friend bool operator==(const Walk&, const Walk&) = default;
};

int degree_of(const Coeffs& c) {
  int d = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; i + j < 4; ++j)
      if (c[i][j] != 0) d = std::max(d, i + j);
  return d;
}

template <class Num> curves::ImplicitPoly<Num> poly(const Case& k) {
  curves::ImplicitPoly<Num> p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; i + j < 4; ++j) p.c[i][j] = num::from_rational<Num>(k.c[i][j]);
  p.start = k.start, p.max_steps = k.max_steps, p.degree = degree_of(k.c);
  return p;
}

template <class Num> Walk walk(const Case& k) {
  Walk w;
  NoProbe none;
  const curves::WalkEnd end = curves::implicit_curve<Num>(poly<Num>(k), w.pixels, none);
  w.stopped = curves::kWalkStopNames[static_cast<std::size_t>(end.stopped)];
  w.steps = end.steps;
  return w;
}

Walk oracle_walk(const Case& k) {
  oracle::ImplicitWalkEnd end;
  Walk w{oracle::implicit_walk_pixels(k.c, k.start, k.max_steps, &end), "", 0};
  w.stopped = end.stopped, w.steps = end.steps;
  return w;
}

// An input object of the corpus's form, read without the runtime's validation (the tests feed
// only valid inputs here).
Case case_of(const Json& in) {
  Case k;
  for (const Json& t : in.at("P")) k.c[t[1].get<int>()][t[2].get<int>()] = parse_rational(t[0], "term");
  k.start = {in.at("start")[0].get<std::int64_t>(), in.at("start")[1].get<std::int64_t>()};
  k.max_steps = in.at("max_steps").get<std::int64_t>();
  return k;
}

// The implicit-curve cases of the curves corpus, by name.
std::map<std::string, Json> corpus() {
  std::map<std::string, Json> out;
  std::ifstream f(std::string(SW_SOURCE_DIR) + "/tests/cases/curves/corpus.jsonl");
  std::string line;
  while (std::getline(f, line))
    if (!line.empty() && line[0] == '{') {
      const Json j = Json::parse(line);
      if (j.at("input").contains("P")) out[j.at("name").get<std::string>()] = j.at("input");
    }
  return out;
}

// --- The closed forms: P, its partials and its forward differences, directly in Rational. ---

// a / b in lowest terms (mpq_class(a, b) is not canonicalized).
Rational frac(std::int64_t a, std::int64_t b) { return Rational(a) / Rational(b); }
Rational power(const Rational& b, int e) {
  Rational r = 1;
  for (int k = 0; k < e; ++k) r *= b;
  return r;
}
// (d/dx)^dx (d/dy)^dy P at (x, y), dx + dy <= 1.
Rational P(const Coeffs& c, const Rational& x, const Rational& y, int dx = 0, int dy = 0) {
  Rational s = 0;
  for (int i = dx; i < 4; ++i)
    for (int j = dy; i + j < 4; ++j) s += c[i][j] * (dx ? i : 1) * (dy ? j : 1) * power(x, i - dx) * power(y, j - dy);
  return s;
}
long binom(int n, int k) { return k == 0 || k == n ? 1 : binom(n - 1, k - 1) + binom(n - 1, k); }
// Du^m Dv^n Q at (u, v), Q(u, v) = P(u/2, v/2): the binomial sum over the corners.
Rational diff(const Coeffs& c, std::int64_t u, std::int64_t v, int m, int n) {
  Rational s = 0;
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j)
      s += ((m - i + n - j) % 2 ? -1 : 1) * binom(m, i) * binom(n, j) * P(c, frac(u + i, 2), frac(v + j, 2));
  return s;
}



Case random_case(std::mt19937_64& rng, int i) {
  const auto u = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  // Integer, dyadic (exact in every mode) or thirds (the filter's intervals are not points).
  const int den = std::array{1, 4, 3, 2}[i % 4];
  const int deg = 2 + i % 2;
  Case k;
  for (int a = 0; a <= deg; ++a)
    for (int b = 0; a + b <= deg; ++b)
      if (a + b > 0) k.c[a][b] = frac(u(0, 2) ? u(-4, 4) : 0, den);
  if (degree_of(k.c) == 0) k.c[0][1] = 1;
  k.start = {u(-6, 6), u(-6, 6)};
  // The constant term puts the curve through the start, or within a little of it; one case in 8
  // starts far from it (P(start) up to 40).
  k.c[0][0] = -P(k.c, k.start.x, k.start.y) + (i % 8 == 5 ? frac(u(-40, 40), 1) : frac(u(-3, 3), u(1, 4)));
  k.max_steps = i % 8 < 2 ? u(1, 200) : u(1, 30);
  return k;
}

}  // namespace

TEST_CASE("implicit-curve: exact and filtered equal the oracle on 10^4 random cubics and conics", "[curves][oracle]") {
  std::mt19937_64 rng(17);
  std::size_t uncertain = 0;
  std::map<std::string, int> reasons;
  for (int i = 0; i < 10000; ++i) {
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
  CHECK(uncertain < 10000 / 4);  // at most the thirds' cases (one in 4)
  for (const char* r : {"closed", "max_steps", "singular", "revisit"}) CHECK(reasons[r] > 20);  // every stop is exercised
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

TEST_CASE("implicit-curve: every value an exact step records matches its closed form", "[curves][replay]") {
  std::vector<std::pair<std::string, Case>> cases;
  for (const auto& [name, in] : corpus()) cases.push_back({name, case_of(in)});
  cases.push_back({"the example", case_of(Json::parse(find_algorithm("implicit-curve").example))});
  std::mt19937_64 rng(19);
  for (int i = 0; i < 40; ++i) cases.push_back({"random " + std::to_string(i), random_case(rng, i)});
  REQUIRE(cases.size() >= 48);
  const Listing L = curves::ImplicitCurve::listing();
  std::set<std::string_view> lines_seen;
  for (const auto& [name, k] : cases) {
    Recorder<Rational> t;
    std::vector<Pixel> out;
    const curves::WalkEnd end = curves::implicit_curve<Rational>(poly<Rational>(k), out, t);
    // The walk's state, followed from the steps' own records and the closed forms.
    Pixel p = k.start;
    std::int64_t moves = 0;
    int major = 0, sa = 0, sb = 0, gb = 0;
    Rational PM;
    Pixel next = p;
    std::optional<std::string> stop;
    bool table_done = false;
    std::set<Pixel> plotted;
    std::vector<Pixel> plot_order;
    for (std::size_t s = 0; s < t.size(); ++s) {
      const std::string_view line = L.lines[t.at(s).line - 1].name;
      lines_seen.insert(line);
      INFO(name << " step " << s << " line " << line);
      StepValues sv = values_of(t, s);
      std::vector<std::pair<GeoKind, std::vector<Rational>>> geo;
      for (std::uint32_t g = t.at(s).geo_begin; g < t.at(s).geo_end; ++g) {
        const GeoRecord& r = t.geo_at(g);
        std::vector<Rational> vals;
        for (std::uint32_t q = 0; q < r.count; ++q)
          vals.push_back(geo_desc(r.kind).integer ? Rational(t.int_value(r.slot + q)) : t.num_value(r.slot + q));
        geo.push_back({r.kind, vals});
      }
      // 2M = 2p + 2 s_a e_a + s_b e_b.
      const std::int64_t mu = 2 * p.x + (major == 0 ? 2 * sa : sb), mv = 2 * p.y + (major == 1 ? 2 * sa : sb);
      if (line == "start") {
        CHECK(s == 0);
        CHECK(sv["degree"] == degree_of(k.c));
        CHECK(sv["x"] == k.start.x);
        CHECK(sv["y"] == k.start.y);
        CHECK(geo.empty());
      } else if (line == "plot") {
        REQUIRE(geo.size() == 1);
        CHECK(geo[0].first == GeoKind::pixel);
        const Pixel at{geo[0].second[0].get_num().get_si(), geo[0].second[1].get_num().get_si()};
        CHECK(at == (moves == 0 ? k.start : next));
        CHECK(plotted.insert(at).second);  // each pixel once
        plot_order.push_back(at);
        p = at;
      } else if (line == "grad") {
        CHECK(sv["x"] == p.x);
        CHECK(sv["y"] == p.y);
        const Rational gx = P(k.c, p.x, p.y, 1, 0), gy = P(k.c, p.x, p.y, 0, 1);
        CHECK(sv["gx"] == gx);
        CHECK(sv["gy"] == gy);
        CHECK(moves < k.max_steps);
        if (gx == 0 && gy == 0) stop = "singular";
        // The axes as the documentation states them, for the steps that follow.
        const Rational tx = -gy, ty = gx;
        major = abs(tx) > abs(ty) || (abs(tx) == abs(ty) && sgn(tx) * sgn(ty) < 0) ? 0 : 1;
        sa = sgn(major == 0 ? tx : ty);
        gb = sgn(major == 0 ? gy : gx);
        sb = sgn(major == 0 ? ty : tx) != 0 ? sgn(major == 0 ? ty : tx) : -gb;
        CHECK(geo.empty());
      } else if (line == "axes") {
        CHECK(!stop);
        CHECK(sv["major"] == major);
        CHECK(sv["sa"] == sa);
        CHECK(sv["sb"] == sb);
        CHECK(sa != 0);
        CHECK(sb != 0);
        CHECK(geo.empty());
      } else if (line == "table" || line == "probe") {
        CHECK(table_done == (line == "probe"));  // the table is made once, at the first midpoint
        table_done = true;
        CHECK(sv["u"] == mu);
        CHECK(sv["v"] == mv);
        PM = P(k.c, frac(mu, 2), frac(mv, 2));
        if (line == "table") {
          for (int m = 0; m < 4; ++m)
            for (int n = 0; m + n < 4; ++n) CHECK(sv["Q" + std::to_string(m) + std::to_string(n)] == diff(k.c, mu, mv, m, n));
          CHECK(diff(k.c, mu, mv, 0, 0) == PM);
        } else {
          CHECK(sv["PM"] == PM);
        }
        REQUIRE(geo.size() == 1);
        CHECK(geo[0].first == GeoKind::point2);
        CHECK(geo[0].second == std::vector<Rational>{frac(mu, 2), frac(mv, 2)});
      } else if (line == "decide") {
        CHECK(sv["PM"] == PM);
        const bool diagonal = sgn(PM) * sb * gb < 0;
        CHECK(sv["diagonal"] == diagonal);
        next = p;
        (major == 0 ? next.x : next.y) += sa;
        if (diagonal) (major == 0 ? next.y : next.x) += sb;
        CHECK(geo.empty());
      } else if (line == "move") {
        ++moves;
        CHECK(sv["x"] == next.x);
        CHECK(sv["y"] == next.y);
        CHECK(sv["k"] == moves);
        if (next == k.start) stop = "closed";
        else if (plotted.count(next)) stop = "revisit";
        CHECK(geo.empty());
      } else if (line == "done") {
        CHECK(s + 1 == t.size());
        if (!stop) {
          CHECK(moves == k.max_steps);
          stop = "max_steps";
        }
        CHECK(curves::kWalkStopNames[sv["stopped"].get_num().get_si()] == *stop);
        CHECK(sv["steps"] == moves);
        CHECK(geo.empty());
      } else {
        FAIL("no expectation for line " << line);
      }
      require_all_checked(sv, s);
    }
    CHECK(plot_order == out);
    CHECK(end.steps == moves);
    CHECK((stop && curves::kWalkStopNames[static_cast<std::size_t>(end.stopped)] == *stop));
  }
  CHECK(lines_seen.size() == L.lines.size());
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
    const Json want = alg.oracle(in);
    for (Numeric n : {Numeric::exact, Numeric::filtered, Numeric::f64}) {
      Json got = alg.run(in, n);
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
      CHECK(abs(frac(3 * x + 2, 7) - y) < frac(1, 2));
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
    const auto dir = testing::scratch("implicit-bad");
    const auto out = dir / "t.jsonl";
    const auto ran = testing::run_stepwise(std::string("trace implicit-curve --numeric ") + b.numeric + " --input " +
                                           testing::sh_quote(b.input) + " --out " + testing::sh_quote(out.string()));
    CHECK(ran.status == 2);
    CHECK_THAT(ran.err, Catch::Contains(b.expect));
    CHECK(std::count(ran.err.begin(), ran.err.end(), '\n') == 1);
    CHECK(!std::filesystem::exists(out));
  }
}
