// perspective-interp and affine-interp against their exact oracle (oracle/fill_interp_oracle.cpp:
// covered samples by exact orientation, perspective values from a 3x3 rational system in clip
// space), the guide's worked example, perspective equal to affine when w is the same everywhere,
// the hard cases of tests/cases/fill/interp.jsonl, and bad input.
#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <optional>
#include "catalog.hpp"
#include "scale.hpp"
#include "cli_harness.hpp"
#include "core/interval.hpp"
#include "fill/interp_run.hpp"
#include "fill_oracle.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;

namespace {

template <bool Persp> void check_against_oracle(const ClipTri& t, std::size_t& uncertain) {
  const oracle::InterpSamples want = interp_oracle<Persp>(t);
  const auto exact = run_interp<Persp, Rational>(t);
  CHECK(exact.pixels == want.pixels);
  CHECK(exact.values == want.values);
  try {
    const auto filtered = run_interp<Persp, Interval>(t);
    CHECK(filtered.pixels == want.pixels);
    REQUIRE(filtered.values.size() == want.values.size());
    for (std::size_t k = 0; k < want.values.size(); ++k) {  // each interval holds the exact value
      CHECK(filtered.values[k].lo() <= want.values[k].get_d());
      CHECK(want.values[k].get_d() <= filtered.values[k].hi());
    }
  } catch (const Uncertain&) {
    ++uncertain;  // the chain then runs exact, checked above
  }
}

std::string describe(const ClipTri& t) {
  std::string s;
  for (int k = 0; k < 3; ++k) s += "(" + t.v[k][0].get_str() + "," + t.v[k][1].get_str() + "," + t.v[k][3].get_str() + ") ";
  return s;
}

}  // namespace

TEST_CASE("interp: perspective-interp and affine-interp in exact and filtered equal the oracle on 10^4 random clip-space triangles", "[fill][interp][oracle]") {
  std::mt19937_64 rng(41);
  std::size_t uncertain = 0, clipped = 0, empty = 0;
  for (int i = 0; i < sw::testing::cases(10000); ++i) {  // 10^4 triangles, each through both algorithms
    const ClipTri t = random_clip_tri(rng, 1 + i % 3);
    INFO(describe(t));
    check_against_oracle<true>(t, uncertain);
    check_against_oracle<false>(t, uncertain);
    const auto poly = oracle::clip_w(t.v, t.attrs, Rational(1));
    clipped += poly.corners.size() == 4;
    empty += poly.corners.empty();
  }
  CHECK(clipped > sw::testing::cases(500u));  // the set exercises the clipping: quadrilaterals, and nothing kept
  CHECK(empty > sw::testing::cases(200u));
  CHECK(uncertain < sw::testing::cases(10000u));  // edges exactly through samples on this grid: intervals cannot call those ties
}

TEST_CASE("interp: where w is the same at every vertex, perspective equals affine exactly", "[fill][interp][oracle]") {
  std::mt19937_64 rng(42);
  for (int i = 0; i < 300; ++i) {
    ClipTri t = random_clip_tri(rng, 2);
    const Rational w = grid_coord(rng, 1, 5, 8);
    for (auto& v : t.v) v[3] = w, v[0] *= w, v[1] *= w;
    INFO(describe(t));
    const auto p = run_interp<true, Rational>(t), a = run_interp<false, Rational>(t);
    CHECK(p.pixels == a.pixels);
    CHECK(p.values == a.values);
    CHECK(interp_oracle<true>(t).values == interp_oracle<false>(t).values);
  }
}

TEST_CASE("interp: the guide's worked example, the middle pixel is (r, g, b) = (1, 3/4, 1/4) and w = 3/2", "[fill][interp][oracle]") {
  // The guide's line from (x, y, w) = (-1, 0, 1), colour (1, 1, 0), to (3, 0, 3), colour (1, 0, 1):
  // on screen from x = -1 to x = 1. As the bottom edge of a triangle (apex (0, 4) at w = 1) the row
  // y = 0 is on the triangle, so samples (-1, 0) and (0, 0) carry the line's values. The guide
  // prints (0, 0, 1, 3/4, 0, 1/4) for the middle pixel; hyperbolic interpolation gives 1/w = 2/3,
  // so w = 3/2 and (r, g, b) = (1, 3/4, 1/4): the guide's line lost a value.
  ClipTri t;
  t.v = {oracle::ClipPoint{-1, 0, 0, 1}, {3, 0, 0, 3}, {0, 4, 0, 1}};
  t.attrs = {std::vector<Rational>{1, 1, 0, 1}, {1, 0, 1, 3}, {0, 0, 0, 1}};  // (r, g, b, w): w as an attribute too
  const auto r = run_interp<true, Rational>(t);
  const auto want = interp_oracle<true>(t);
  CHECK(r.pixels == want.pixels);
  CHECK(r.values == want.values);
  REQUIRE(r.pixels.size() >= 2);
  CHECK(r.pixels[0] == Pixel{-1, 0});
  CHECK(r.pixels[1] == Pixel{0, 0});
  CHECK(std::vector<Rational>(r.values.begin(), r.values.begin() + 4) == std::vector<Rational>{1, 1, 0, 1});
  CHECK(std::vector<Rational>(r.values.begin() + 4, r.values.begin() + 8) == std::vector<Rational>{Rational(1), ratio(3, 4), ratio(1, 4), ratio(3, 2)});
  // Affine takes the screen midpoint's average instead: (1, 1/2, 1/2), w = 2.
  const auto a = run_interp<false, Rational>(t);
  CHECK(std::vector<Rational>(a.values.begin() + 4, a.values.begin() + 8) == std::vector<Rational>{Rational(1), ratio(1, 2), ratio(1, 2), Rational(2)});
}

TEST_CASE("interp: clipping before the divide, vertices behind the eye and at w near zero", "[fill][interp][oracle]") {
  auto tri = [](std::array<oracle::ClipPoint, 3> v) {
    ClipTri t;
    t.v = v;
    t.attrs = {std::vector<Rational>{0, 0}, {1, 0}, {0, 1}};
    return t;
  };
  // All behind, or all at w in (0, 1): nothing.
  CHECK(run_interp<true, Rational>(tri({oracle::ClipPoint{0, 0, 0, -1}, {8, 0, 0, -2}, {0, 8, 0, -1}})).pixels.empty());
  CHECK(run_interp<true, Rational>(tri({oracle::ClipPoint{0, 0, 0, ratio(1, 1000)}, {8, 0, 0, ratio(1, 1000)}, {0, 8, 0, ratio(1, 2)}})).pixels.empty());
  // One vertex at w = 1/1000 (it would project 1000x out): the kept quadrilateral, two triangles.
  const ClipTri near = tri({oracle::ClipPoint{-8, -8, 0, 2}, {8, -8, 0, 2}, {0, 8, 0, ratio(1, 1000)}});
  const auto r = run_interp<true, Rational>(near);
  CHECK(oracle::clip_w(near.v, near.attrs, Rational(1)).corners.size() == 4);
  CHECK(r.pixels == interp_oracle<true>(near).pixels);
  CHECK(r.values == interp_oracle<true>(near).values);
  CHECK(!r.pixels.empty());
  for (Pixel p : r.pixels) CHECK(std::abs(p.x) <= 8);  // nothing beyond the clip coordinates' box
}

namespace {

std::vector<Json> interp_corpus() {
  std::ifstream f(std::string(SW_SOURCE_DIR) + "/tests/cases/fill/interp.jsonl");
  std::vector<Json> out;
  std::string line;
  while (std::getline(f, line))
    if (!line.empty() && line[0] == '{') out.push_back(Json::parse(line));
  return out;
}

}  // namespace

TEST_CASE("interp: every corpus case in exact and filtered equals the oracle, and the notes hold", "[fill][interp][corpus]") {
  std::map<std::string, Json> oracle_of;  // "name/algorithm"
  for (const Json& c : interp_corpus()) {
    const Algorithm& alg = find_algorithm(c["algorithm"].get<std::string>());
    INFO(c["name"].get<std::string>() << " " << alg.id);
    const Json want = alg.open(c["input"]).oracle();
    CHECK(alg.open(c["input"], Numeric::exact).run() == want);
    Json filtered = alg.open(c["input"], Numeric::filtered).run();
    filtered.erase("fallback");
    CHECK(filtered["pixels"] == want["pixels"]);
    oracle_of[c["name"].get<std::string>() + "/" + std::string(alg.id)] = want;
  }
  REQUIRE(oracle_of.size() >= 20);
  auto pixels = [&](const std::string& key) { return oracle_of.at(key)["pixels"].size(); };
  CHECK(pixels("all behind/perspective-interp") == 0);
  CHECK(pixels("all nearer than w = 1/perspective-interp") == 0);
  CHECK(pixels("edge-on through the eye/perspective-interp") == 0);
  CHECK(pixels("one behind/perspective-interp") > 0);
  CHECK(pixels("two behind/perspective-interp") > 0);
  CHECK(pixels("w near zero/perspective-interp") > 0);
  CHECK(oracle_of.at("w equal everywhere/perspective-interp") == oracle_of.at("w equal everywhere/affine-interp"));
  CHECK(oracle_of.at("one behind/perspective-interp")["pixels"] == oracle_of.at("one behind/affine-interp")["pixels"]);
  CHECK(oracle_of.at("one behind/perspective-interp")["values"] != oracle_of.at("one behind/affine-interp")["values"]);
  CHECK(oracle_of.at("guide example/perspective-interp")["values"][1] == Json::parse("[1, 0.75, 0.25]"));
}

TEST_CASE("interp: double misses only samples exactly on an edge, and its values are within 1e-9 of exact", "[fill][interp][accuracy]") {
  // Screen corners (-40/3, -10), (40/3, -10), (0, -5/2): the sample (-8, -7) lies exactly on the left
  // edge (a left edge: covered), and double, which cannot hold 40/3, puts it just outside.
  const Algorithm& alg = find_algorithm("perspective-interp");
  const Json in = Json::parse(R"({"triangle":[[-40,-30,0,3],[40,-30,0,3],[0,-30,0,12]],"attrs":[[0,0],[8,0],[4,8]]})");
  const Json want = alg.open(in).oracle(), got = alg.open(in, Numeric::f64).run();
  std::map<std::pair<std::int64_t, std::int64_t>, Json> exact_at;
  for (std::size_t p = 0; p < want["pixels"].size(); ++p) exact_at[{want["pixels"][p][0], want["pixels"][p][1]}] = want["values"][p];
  CHECK(exact_at.count({-8, -7}));
  std::size_t common = 0;
  for (std::size_t p = 0; p < got["pixels"].size(); ++p) {
    const auto it = exact_at.find({got["pixels"][p][0], got["pixels"][p][1]});
    REQUIRE(it != exact_at.end());  // double covers no sample exact does not
    ++common;
    for (std::size_t c = 0; c < 2; ++c) CHECK(std::abs(got["values"][p][c].get<double>() - it->second[c].get<double>()) < 1e-9);
  }
  CHECK(common + 1 == want["pixels"].size());
}

TEST_CASE("interp: bad input is one line and exit 2 with no output file", "[fill][interp][cli]") {
  struct Bad {
    const char *alg, *input, *numeric, *expect;
  };
  for (const Bad& b : std::initializer_list<Bad>{
           {"perspective-interp", R"({"triangle":[[0,0,0,1],[1,1,0,1]],"attrs":[[1],[2],[3]]})", "exact", "three clip-space vertices"},
           {"perspective-interp", R"({"triangle":[[0,0,0,1],[1,1,0,1],[2,2,0]],"attrs":[[1],[2],[3]]})", "exact", "input.triangle[2]: expected [x, y, z, w]"},
           {"perspective-interp", R"({"triangle":[[0,0,0,1],[1,1,0,1],[2,"nan",0,1]],"attrs":[[1],[2],[3]]})", "exact", "input.triangle[2][1]"},
           {"affine-interp", R"({"triangle":[[0,0,0,1],[1,1,0,"inf"],[2,2,0,1]],"attrs":[[1],[2],[3]]})", "double", "input.triangle[1][3]"},
           {"perspective-interp", R"({"triangle":[[0,0,0,1],[1,1,0,1],[2,2,0,1e400]],"attrs":[[1],[2],[3]]})", "double", "overflow"},
           {"perspective-interp", R"({"triangle":[[0,0,0,1],[1,1,0,1],[2,2,0,1]],"attrs":[[1],[2,3],[4]]})", "exact", "same count"},
           {"affine-interp", R"({"triangle":[[0,0,0,1],[1,1,0,1],[2,2,0,1]],"attrs":[[],[],[]]})", "exact", "1 to 8 numbers"},
           {"perspective-interp", R"({"triangle":[[0,0,0,1],[1,1,0,1],[2,2,0,1]],"attrs":[[1,2,3,4,5,6,7,8,9],[1],[1]]})", "exact", "1 to 8 numbers"},
           {"perspective-interp", R"({"triangle":[[0,0,0,1],[1,1,0,1],[2,2,0,1]]})", "exact", "missing field"},
           {"perspective-interp", R"({"triangle":[[0,0,0,1],[1,1,0,1],[2,2,0,1]],"attrs":[[1],[2],[3]],"viewport":{"size":[4,4]}})", "exact", "unknown field"},
           {"perspective-interp", R"({"triangle":[[0,0,0,1],[4096,0,0,1],[0,4096,0,1]],"attrs":[[1],[2],[3]]})", "filtered", "budget"},
           {"affine-interp", R"({"triangle":[[0,0,0,1],[2000000000,0,0,1],[0,1,0,1]],"attrs":[[1],[2],[3]]})", "exact", "input.triangle[1][0]"},
       }) {
    INFO(b.alg << " " << b.input);
    SW_CHECK_BAD_TRACE(b.alg, b.numeric, b.input, b.expect);
  }
  // w <= 0 everywhere is valid input: it covers nothing.
  CHECK(find_algorithm("perspective-interp").open(Json::parse(R"({"triangle":[[0,0,0,-1],[4,0,0,0],[0,4,0,-3]],"attrs":[[1],[2],[3]]})"), Numeric::exact).run()["pixels"].empty());
}
