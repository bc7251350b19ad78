// bezier-forward-diff against its exact oracle (Bernstein points joined by the DDA specification),
// every recorded value of its own steps against a closed form, and the nested dda-line listing.
#include <catch2/catch.hpp>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include "catalog.hpp"
#include "scale.hpp"
#include "curves/bezier_de_casteljau.hpp"
#include "curves/bezier_forward_diff.hpp"
#include "curves_bezier_oracle.hpp"
#include "lines_oracle.hpp"
#include "step_values.hpp"
#include "trace_io.hpp"

using namespace sw;

namespace {

template <class Num> std::vector<Pixel> run(const std::array<Vec2<Rational>, 4>& p, std::int64_t n) {
  curves::Bezier<Num> b;
  for (int i = 0; i < 4; ++i) b.p[i] = {num::from_rational<Num>(p[i].x), num::from_rational<Num>(p[i].y)};
  b.n = n;
  std::vector<Pixel> out;
  NoProbe none;
  curves::bezier_forward_diff<Num>(b, out, none);
  return out;
}

using testing::ratio;

}  // namespace

TEST_CASE("curves bezier: exact and filtered equal the oracle on 10^4 random curves", "[curves][bezier]") {
  std::mt19937_64 rng(17);
  auto u = [&](long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); };
  std::size_t uncertain = 0;
  for (int i = 0; i < sw::testing::cases(10000); ++i) {
    std::array<Vec2<Rational>, 4> p;
    for (auto& c : p) c = {ratio(u(-400, 400), 8), ratio(u(-400, 400), 8)};
    const std::int64_t n = u(1, 12);
    const auto want = oracle::bezier_pixels(p, n);
    if (i % 4 == 0) REQUIRE(run<Rational>(p, n) == want);
    std::optional<std::vector<Pixel>> f;
    try {
      f = run<Interval>(p, n);
    } catch (const Uncertain&) {
      ++uncertain;  // a sample within rounding of a pixel boundary: the chain runs exact
    }
    if (f) REQUIRE(*f == want);
  }
  CHECK(uncertain < sw::testing::cases(10000u) / 4);  // t = k/n rounds for most n: samples near a boundary stay undecided
}

TEST_CASE("curves bezier: every value of its own steps matches its closed form and dda-line runs nested", "[curves][bezier]") {
  const std::array<Vec2<Rational>, 4> p = {Vec2<Rational>{ratio(1, 2), 0}, {3, ratio(29, 4)}, {ratio(19, 2), ratio(-5, 3)}, {12, 6}};
  auto B = [&](std::int64_t k, std::int64_t n) { return oracle::bezier_point(p, ratio(k, n)); };
  for (std::int64_t n : {1, 3, 7}) {
    for (int depth : {8, 0}) {
      INFO("n = " << n << ", max depth " << depth);
      curves::Bezier<Rational> b{p, n};
      Recorder<Rational> t;
      t.set_max_depth(depth);
      std::vector<Pixel> out;
      curves::bezier_forward_diff<Rational>(b, out, t);
      REQUIRE(out == oracle::bezier_pixels(p, n));
      const Listing L = curves::BezierForwardDiff::listing();
      std::int64_t k = 0;
      std::vector<Pixel> nested;  // pixels plotted by the nested dda-line of segment k
      std::size_t nested_steps = 0;
      for (std::size_t s = 0; s < t.size(); ++s) {
        const StepRecord& st = t.at(s);
        if (st.scope) {
          CHECK(t.scope_id(st.scope) == "dda-line");
          CHECK(t.scope_listing(st.scope).title == lines::DdaLine::listing().title);
          ++nested_steps;
          for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g)
            if (t.geo_at(g).kind == GeoKind::pixel) nested.push_back({t.int_value(t.geo_at(g).slot), t.int_value(t.geo_at(g).slot + 1)});
          continue;
        }
        const std::string_view line = L.lines[st.line - 1].name;
        INFO("step " << s << " line " << line);
        testing::StepValues v = testing::values_of(t, s);
        if (line == "samples") {
          for (int j = 0; j < 4; ++j) {
            CHECK(v["q" + std::to_string(j) + ".x"] == B(j, n).x);
            CHECK(v["q" + std::to_string(j) + ".y"] == B(j, n).y);
          }
          REQUIRE(st.geo_end - st.geo_begin == 1);
          const GeoRecord& g = t.geo_at(st.geo_begin);
          REQUIRE(g.kind == GeoKind::polyline);
          const std::int64_t m = g.count / 2 - 1;
          CHECK(m == std::min<std::int64_t>(8 * n, 512));
          for (std::int64_t j = 0; j <= m; ++j) {
            CHECK(t.num_value(g.slot + 2 * j) == B(j, m).x);
            CHECK(t.num_value(g.slot + 2 * j + 1) == B(j, m).y);
          }
        } else if (line == "table") {
          const auto d1 = B(1, n) - B(0, n), d2 = (B(2, n) - B(1, n)) - d1, d3 = (B(3, n) - B(2, n)) - (B(2, n) - B(1, n)) - d2;
          CHECK(v["d1.x"] == d1.x);
          CHECK(v["d1.y"] == d1.y);
          CHECK(v["d2.x"] == d2.x);
          CHECK(v["d2.y"] == d2.y);
          CHECK(v["d3.x"] == d3.x);
          CHECK(v["d3.y"] == d3.y);
        } else if (line == "segment") {
          CHECK(v["k"] == k);
          REQUIRE(st.geo_end - st.geo_begin == 1);
          const GeoRecord& g = t.geo_at(st.geo_begin);
          REQUIRE(g.kind == GeoKind::segment2);
          CHECK(t.num_value(g.slot) == B(k, n).x);
          CHECK(t.num_value(g.slot + 1) == B(k, n).y);
          CHECK(t.num_value(g.slot + 2) == B(k + 1, n).x);
          CHECK(t.num_value(g.slot + 3) == B(k + 1, n).y);
          nested.clear();
          nested_steps = 0;
        } else if (line == "step") {
          // The nested call drew exactly the DDA specification of segment k (or nothing when summarised).
          CHECK(nested == (depth > 0 ? oracle::column_pixels(B(k, n), B(k + 1, n), oracle::Sampling::ascending) : std::vector<Pixel>{}));
          if (depth == 0) CHECK(nested_steps == 0);
          else CHECK(nested_steps > 0);
          ++k;
          CHECK(v["k"] == k);
          CHECK(v["q.x"] == B(k, n).x);
          CHECK(v["q.y"] == B(k, n).y);
          CHECK(v["d1.x"] == B(k + 1, n).x - B(k, n).x);
          CHECK(v["d1.y"] == B(k + 1, n).y - B(k, n).y);
          REQUIRE(st.geo_end - st.geo_begin == 1);
          CHECK(t.geo_at(st.geo_begin).kind == GeoKind::point2);
          CHECK(t.num_value(t.geo_at(st.geo_begin).slot) == B(k, n).x);
          CHECK(t.num_value(t.geo_at(st.geo_begin).slot + 1) == B(k, n).y);
        } else if (line == "done") {
          CHECK(v["k"] == n);
        } else {
          FAIL("no expectation for line " << line);
        }
        testing::require_all_checked(v, s);
      }
      CHECK(k == n);
    }
  }
}

TEST_CASE("curves bezier: check follows the nested listing and names a step from the wrong one", "[curves][bezier][check]") {
  const Algorithm& alg = find_algorithm("bezier-forward-diff");
  const Json in = Json::parse(alg.example);
  std::stringstream good;
  write_trace(alg.open(in, Numeric::exact), good);
  CHECK(check_trace(good).status == 0);
  // Move the first nested step out of dda-line's listing: the replay names the listing.
  std::string text = good.str();
  const auto at = text.find(",\"in\":\"dda-line\"");
  REQUIRE(at != std::string::npos);
  text.erase(at, std::string(",\"in\":\"dda-line\"").size());
  std::stringstream bad(text);
  const CheckReport rep = check_trace(bad);
  CHECK(rep.status == 1);
  CHECK_THAT(rep.message, Catch::Contains("listing: expected a step of dda-line"));
}

namespace {

// The cubic's blossom f(t1, t2, t3): symmetric, affine in each argument, f(t, t, t) = B(t). The
// piece of the curve over [a, b] has control points f(a,a,a), f(a,a,b), f(a,b,b), f(b,b,b).
Vec2<Rational> blossom(const std::array<Vec2<Rational>, 4>& p, const Rational& t1, const Rational& t2, const Rational& t3) {
  const Rational s1 = 1 - t1, s2 = 1 - t2, s3 = 1 - t3;
  const Rational w[4] = {s1 * s2 * s3, t1 * s2 * s3 + s1 * t2 * s3 + s1 * s2 * t3, t1 * t2 * s3 + t1 * s2 * t3 + s1 * t2 * t3, t1 * t2 * t3};
  Vec2<Rational> q{0, 0};
  for (int i = 0; i < 4; ++i) q = q + Rational(w[i]) * p[i];
  return q;
}

template <class Num> std::vector<Pixel> run_de_casteljau(const std::array<Vec2<Rational>, 4>& p, int depth) {
  curves::BezierDepth<Num> b;
  for (int i = 0; i < 4; ++i) b.p[i] = {num::from_rational<Num>(p[i].x), num::from_rational<Num>(p[i].y)};
  b.depth = depth;
  std::vector<Pixel> out;
  NoProbe none;
  curves::bezier_de_casteljau<Num>(b, out, none);
  return out;
}

}  // namespace

TEST_CASE("curves bezier: de Casteljau in exact and filtered equals the oracle at n = 2^depth on 10^4 random curves", "[curves][bezier]") {
  std::mt19937_64 rng(29);
  auto u = [&](long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); };
  std::size_t uncertain = 0;
  for (int i = 0; i < sw::testing::cases(10000); ++i) {
    std::array<Vec2<Rational>, 4> p;
    for (auto& c : p) c = {ratio(u(-400, 400), 8), ratio(u(-400, 400), 8)};
    const int depth = int(u(0, 4));
    const auto want = oracle::bezier_pixels(p, std::int64_t{1} << depth);
    if (i % 4 == 0) REQUIRE(run_de_casteljau<Rational>(p, depth) == want);
    std::optional<std::vector<Pixel>> f;
    try {
      f = run_de_casteljau<Interval>(p, depth);
    } catch (const Uncertain&) {
      ++uncertain;
    }
    if (f) REQUIRE(*f == want);
  }
  // Halving is exact in binary: intervals stay points unless a pixel boundary needs the exact run.
  CHECK(uncertain < sw::testing::cases(10000u) / 20);
}

TEST_CASE("curves bezier: every value a de Casteljau step records is the blossom of its piece", "[curves][bezier]") {
  const std::array<Vec2<Rational>, 4> p = {Vec2<Rational>{ratio(1, 2), 0}, {3, ratio(29, 4)}, {ratio(19, 2), ratio(-5, 3)}, {12, 6}};
  for (int depth : {0, 1, 3}) {
    INFO("depth " << depth);
    curves::BezierDepth<Rational> b{p, depth};
    Recorder<Rational> t;
    std::vector<Pixel> out;
    curves::bezier_de_casteljau<Rational>(b, out, t);
    REQUIRE(out == oracle::bezier_pixels(p, std::int64_t{1} << depth));
    const Listing L = curves::BezierDeCasteljau::listing();
    // The walk's call stack, followed from the steps: piece (level, k) covers [k, k + 1] / 2^(depth - level).
    struct Node {
      std::int64_t level, k;
      bool right_started;
    };
    std::vector<Node> stack;
    std::int64_t next_leaf = 0;
    std::pair<std::int64_t, std::int64_t> announced{depth, 0};  // the piece the next call must be
    std::set<std::pair<std::int64_t, std::int64_t>> called;
    auto ends = [&] {
      const Node& n = stack.back();
      const std::int64_t pieces = std::int64_t{1} << (depth - n.level);
      return std::pair{ratio(n.k, pieces), ratio(n.k + 1, pieces)};
    };
    for (std::size_t s = 0; s < t.size(); ++s) {
      const StepRecord& st = t.at(s);
      if (st.scope) {  // the chord's dda-line: its own tests check its steps
        CHECK(t.scope_id(st.scope) == "dda-line");
        continue;
      }
      const std::string_view line = L.lines[st.line - 1].name;
      INFO("step " << s << " line " << line);
      testing::StepValues v = testing::values_of(t, s);
      const std::uint32_t items = st.geo_end - st.geo_begin;
      const GeoRecord* g = items ? &t.geo_at(st.geo_begin) : nullptr;
      auto vec_is = [&](const std::string& name, const Vec2<Rational>& want) {
        CHECK(v[name + ".x"] == want.x);
        CHECK(v[name + ".y"] == want.y);
      };
      if (line == "call") {
        CHECK(v["level"] == announced.first);
        CHECK(v["k"] == announced.second);
        stack.push_back({announced.first, announced.second, false});
        CHECK(called.insert(announced).second);  // each piece once
        const auto [a, bb] = ends();
        REQUIRE(items == 1);
        REQUIRE(g->kind == GeoKind::polyline);
        REQUIRE(g->count == 8);
        const Vec2<Rational> q[4] = {blossom(p, a, a, a), blossom(p, a, a, bb), blossom(p, a, bb, bb), blossom(p, bb, bb, bb)};
        for (int i = 0; i < 4; ++i) {
          CHECK(t.num_value(g->slot + 2 * i) == q[i].x);
          CHECK(t.num_value(g->slot + 2 * i + 1) == q[i].y);
        }
      } else if (line == "leaf") {
        CHECK(v["level"] == 0);
        CHECK(v["k"] == next_leaf);  // the leaves come in order along the curve
        ++next_leaf;
        REQUIRE(!stack.empty());
        CHECK(stack.back().level == 0);
        const auto [a, bb] = ends();
        REQUIRE(items == 1);
        REQUIRE(g->kind == GeoKind::segment2);
        CHECK(t.num_value(g->slot) == blossom(p, a, a, a).x);
        CHECK(t.num_value(g->slot + 1) == blossom(p, a, a, a).y);
        CHECK(t.num_value(g->slot + 2) == blossom(p, bb, bb, bb).x);
        CHECK(t.num_value(g->slot + 3) == blossom(p, bb, bb, bb).y);
        stack.pop_back();  // returns: and so does every ancestor whose second half this was
        while (!stack.empty() && stack.back().right_started) stack.pop_back();
      } else if (line == "halve") {
        REQUIRE(!stack.empty());
        const auto [a, bb] = ends();
        const Rational m = (a + bb) / 2;
        vec_is("P01", blossom(p, a, a, m));
        vec_is("P12", blossom(p, a, m, bb));
        vec_is("P23", blossom(p, m, bb, bb));
        CHECK(items == 0);
      } else if (line == "halve2") {
        const auto [a, bb] = ends();
        const Rational m = (a + bb) / 2;
        vec_is("P012", blossom(p, a, m, m));
        vec_is("P123", blossom(p, m, m, bb));
        vec_is("M", oracle::bezier_point(p, m));
        REQUIRE(items == 1);
        CHECK(g->kind == GeoKind::point2);
        CHECK(t.num_value(g->slot) == oracle::bezier_point(p, m).x);
        CHECK(t.num_value(g->slot + 1) == oracle::bezier_point(p, m).y);
        CHECK(g->label == std::string("M"));
      } else if (line == "left" || line == "right") {
        REQUIRE(!stack.empty());
        Node& n = stack.back();
        if (line == "right") n.right_started = true;
        announced = {n.level - 1, 2 * n.k + (line == "right")};
        CHECK(v["level"] == announced.first);
        CHECK(v["k"] == announced.second);
        CHECK(items == 0);
      } else if (line == "done") {
        CHECK(v["pieces"] == (std::int64_t{1} << depth));
        CHECK(items == 0);
      } else {
        FAIL("no expectation for line " << line);
      }
      testing::require_all_checked(v, s);
    }
    CHECK(next_leaf == (std::int64_t{1} << depth));
    CHECK(stack.empty());
    CHECK(called.size() == (std::size_t{2} << depth) - 1);  // every node of the binary tree
  }
}
