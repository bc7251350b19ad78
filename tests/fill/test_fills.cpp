// The fills against the exact oracle (brute force with CGAL orientation predicates), the oracle
// against hand-worked cases, tiling of meshes and fans, the no-offset variant's overlaps and gaps,
// and bad input.
#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <optional>
#include "catalog.hpp"
#include "scale.hpp"
#include "cli_harness.hpp"
#include "core/interval.hpp"
#include "fill/fill_run.hpp"
#include "fill_oracle.hpp"

using namespace sw;
using namespace sw::testing;

namespace {

Tri random_triangle(std::mt19937_64& rng, long half, long den) {
  const long cx = std::uniform_int_distribution<long>(-50, 50)(rng), cy = std::uniform_int_distribution<long>(-50, 50)(rng);
  Tri t;
  for (auto& v : t) v = {cx + grid_coord(rng, -half, half, den), cy + grid_coord(rng, -half, half, den)};
  return t;
}


}  // namespace

TEST_CASE("fill oracle: hand-worked triangles follow the rule on edges", "[fill][oracle]") {
  // (0,0), (4,0), (0,4): the bottom edge y = 0 and the left edge x = 0 are in, the hypotenuse
  // x + y = 4 is out: the samples with x, y >= 0 and x + y < 4, 4 + 3 + 2 + 1 of them.
  std::vector<Pixel> want;
  for (std::int64_t j = 0; j < 4; ++j)
    for (std::int64_t i = 0; i + j < 4; ++i) want.push_back({i, j});
  CHECK(oracle::triangle_samples({Vec2<Rational>{0, 0}, {4, 0}, {0, 4}}) == want);
  CHECK(oracle::triangle_samples({Vec2<Rational>{0, 4}, {4, 0}, {0, 0}}) == want);  // clockwise: the same set
  // Mirrored, (4,0), (0,4), (4,4): the top edge y = 4 and the right edge x = 4 are out, the
  // hypotenuse x + y = 4 (a left edge going down) is in.
  std::vector<Pixel> mirrored;
  for (std::int64_t j = 0; j < 4; ++j)
    for (std::int64_t i = 4 - j; i < 4; ++i) mirrored.push_back({i, j});
  CHECK(oracle::triangle_samples({Vec2<Rational>{4, 0}, {4, 4}, {0, 4}}) == mirrored);
  CHECK(oracle::triangle_samples({Vec2<Rational>{0, 0}, {2, 2}, {4, 4}}).empty());  // zero area
  CHECK(oracle::triangle_samples({Vec2<Rational>{Rational(1, 3), 0}, {Rational(2, 3), 5}, {Rational(1, 2), 9}}).empty());  // thinner than the gap between samples
  // A star by hand: the pentagram's centre has winding 2, so even-odd leaves it out and nonzero fills it.
  const Rings star{{{0, 10}, {6, -8}, {-9, 3}, {9, 3}, {-6, -8}}};
  CHECK(oracle::winding_number(star, {0, 0}) * oracle::winding_number(star, {0, 0}) == 4);
  CHECK(std::abs(oracle::winding_number(star, {0, 8})) == 1);
  CHECK(oracle::winding_number(star, {20, 0}) == 0);
}

TEST_CASE("fill: triangle-dda, triangle-edge and scanline-polygon in exact, filtered and int equal the oracle on 10^4 random triangles", "[fill][oracle]") {
  std::mt19937_64 rng(2026);
  std::size_t uncertain = 0, covered = 0;
  for (int n = 0; n < sw::testing::cases(10000); ++n) {
    const long den = n % 3 == 0 ? 1 : n % 3 == 1 ? 4 : 256;  // vertices on samples, on quarter points, on llvmpipe's grid
    const Tri t = random_triangle(rng, n % 10 == 0 ? 40 : 8, den);
    const auto want = oracle::triangle_samples(t);
    covered += want.size();
    INFO("triangle " << t[0].x << "," << t[0].y << " " << t[1].x << "," << t[1].y << " " << t[2].x << "," << t[2].y);
    REQUIRE(run_dda<Rational>(t).pixels == want);
    REQUIRE(run_edge<Rational>(t) == want);
    REQUIRE(run_edge_fixed(t) == want);
    REQUIRE(run_scanline<Rational>({{t[0], t[1], t[2]}}, fill::WindingRule::even_odd) == want);
    REQUIRE(run_scanline<Rational>({{t[2], t[1], t[0]}}, fill::WindingRule::nonzero) == want);
    if (auto f = filtered([&] { return run_dda<Interval>(t).pixels; }, uncertain)) REQUIRE(*f == want);
    if (auto f = filtered([&] { return run_edge<Interval>(t); }, uncertain)) REQUIRE(*f == want);
    if (auto f = filtered([&] { return run_scanline<Interval>({{t[0], t[1], t[2]}}, fill::WindingRule::even_odd); }, uncertain)) REQUIRE(*f == want);
  }
  CHECK(covered > sw::testing::cases(100000u));  // the set is not mostly empty triangles
  CHECK(uncertain < 3 * sw::testing::cases(10000u) / 2);  // vertices on samples make exact ties: those fall back to exact
}

TEST_CASE("fill: triangles with rational vertices (thirds) and coordinates near 10^9 equal the oracle", "[fill][oracle]") {
  std::mt19937_64 rng(77);
  for (int n = 0; n < 300; ++n) {
    Tri t = random_triangle(rng, 6, 3);
    if (n % 2) {
      const Rational far(std::int64_t{1000000000} + n);
      for (auto& v : t) v.x += far, v.y -= far;
    }
    const auto want = oracle::triangle_samples(t);
    REQUIRE(run_dda<Rational>(t).pixels == want);
    REQUIRE(run_edge<Rational>(t) == want);
    REQUIRE(run_scanline<Rational>({{t[0], t[1], t[2]}}, fill::WindingRule::nonzero) == want);
  }
}

TEST_CASE("fill: triangle-dda's interpolated values are the plane through the vertices' attributes at each sample", "[fill][oracle]") {
  std::mt19937_64 rng(99);
  for (int n = 0; n < 500; ++n) {
    const Tri t = random_triangle(rng, 10, 4);
    std::vector<std::array<Rational, 3>> attrs(3);
    for (auto& a : attrs)
      for (auto& x : a) x = grid_coord(rng, -5, 5, 8);
    const auto r = run_dda<Rational>(t, attrs);
    REQUIRE(r.pixels == oracle::triangle_samples(t));
    REQUIRE(r.values.size() == 3 * r.pixels.size());
    for (std::size_t p = 0; p < r.pixels.size(); ++p)
      for (int c = 0; c < 3; ++c) REQUIRE(r.values[3 * p + c] == oracle::linear_at(t, attrs[c], r.pixels[p]));
  }
}

TEST_CASE("fill: scanline-polygon equals the oracle on random polygons with holes, self-intersections and repeated vertices, both rules", "[fill][oracle]") {
  std::mt19937_64 rng(4242);
  std::size_t uncertain = 0, differ = 0;
  for (int n = 0; n < 3000; ++n) {
    Rings rings(1 + n % 3);
    for (auto& r : rings) {
      const int count = std::uniform_int_distribution<int>(3, 12)(rng);
      for (int k = 0; k < count; ++k) r.push_back({grid_coord(rng, -12, 12, n % 2 ? 1 : 4), grid_coord(rng, -12, 12, n % 2 ? 1 : 4)});
      if (n % 5 == 0) r.push_back(r.back());  // a repeated vertex
    }
    for (auto rule : {fill::WindingRule::even_odd, fill::WindingRule::nonzero}) {
      const auto want = oracle::polygon_samples(rings, rule == fill::WindingRule::nonzero ? oracle::FillRule::nonzero : oracle::FillRule::even_odd);
      REQUIRE(run_scanline<Rational>(rings, rule) == want);
      if (auto f = filtered([&] { return run_scanline<Interval>(rings, rule); }, uncertain)) REQUIRE(*f == want);
    }
    differ += oracle::polygon_samples(rings, oracle::FillRule::nonzero) != oracle::polygon_samples(rings, oracle::FillRule::even_odd);
  }
  CHECK(differ > 300);  // the rules are told apart often enough to matter
}

TEST_CASE("fill: the triangles of meshes and fans cover each sample of the union once, and no-offset overlaps and misses", "[fill][tiling]") {
  std::mt19937_64 rng(5);
  std::size_t no_offset_wrong = 0;
  for (int n = 0; n < 60; ++n) {
    // A fan of 64 triangles around a centre on a sample point (or on a quarter point), its rim a
    // star-shaped 64-gon with vertices on the quarter grid.
    const Vec2<Rational> c{grid_coord(rng, -3, 3, n % 2 ? 1 : 4), grid_coord(rng, -3, 3, n % 2 ? 1 : 4)};
    std::vector<Vec2<Rational>> rim;
    for (int k = 0; k < 64; ++k) {
      const double a = 6.283185307179586 * k / 64, r = 10 + 6 * std::uniform_real_distribution<double>(0, 1)(rng);
      rim.push_back({Rational(std::lround(4 * r * std::cos(a))) / 4 + c.x, Rational(std::lround(4 * r * std::sin(a))) / 4 + c.y});
    }
    Cover dda, edge, scan, loose;
    for (int k = 0; k < 64; ++k) {
      const Tri t{c, rim[k], rim[(k + 1) % 64]};
      add_cover(dda, run_dda<Rational>(t).pixels);
      add_cover(edge, run_edge<Rational>(t));
      add_cover(scan, run_scanline<Rational>({{t[0], t[1], t[2]}}, fill::WindingRule::nonzero));
      add_cover(loose, run_dda<double, false>(t).pixels);
    }
    const auto want = oracle::polygon_samples({rim}, oracle::FillRule::nonzero);
    Cover once;
    add_cover(once, want);
    CHECK(dda == once);
    CHECK(edge == once);
    CHECK(scan == once);
    no_offset_wrong += loose != once;
  }
  CHECK(no_offset_wrong > 50);  // without dp0 the fan double-covers or misses samples in almost every case
}

TEST_CASE("fill: a square grid cut into triangles both ways tiles exactly", "[fill][tiling]") {
  // A 6 x 6 grid of cells of side 5/2 with jittered interior vertices on the 1/8 grid.
  std::mt19937_64 rng(8);
  std::array<std::array<Vec2<Rational>, 7>, 7> v;
  for (int a = 0; a < 7; ++a)
    for (int b = 0; b < 7; ++b) {
      v[a][b] = {Rational(5 * a, 2), Rational(5 * b, 2)};
      if (a % 6 && b % 6) v[a][b].x += grid_coord(rng, -1, 1, 8) / 2, v[a][b].y += grid_coord(rng, -1, 1, 8) / 2;
    }
  Cover dda, edge;
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) {
      const bool flip = (a + b) % 2;
      const Tri t0{v[a][b], v[a + 1][b], flip ? v[a + 1][b + 1] : v[a][b + 1]};
      const Tri t1{flip ? v[a][b] : v[a + 1][b], v[a + 1][b + 1], v[a][b + 1]};
      for (const Tri& t : {t0, t1}) add_cover(dda, run_dda<Rational>(t).pixels), add_cover(edge, run_edge<Rational>(t));
    }
  Cover square;  // [0, 15) x [0, 15): the boundary's left and bottom edges in, right and top out
  for (std::int64_t j = 0; j < 15; ++j)
    for (std::int64_t i = 0; i < 15; ++i) square[{i, j}] = 1;
  CHECK(dda == square);
  CHECK(edge == square);
}

TEST_CASE("fill: float fails honestly where its spacing is coarser than a pixel, and exact does not", "[fill][accuracy]") {
  // Near 10^9 float's spacing is 64 pixels: its vertices move, and its pixels differ from exact.
  const Rational far(1000000000);
  const Tri t{Vec2<Rational>{far + Rational(1, 4), far}, {far + 20, far + Rational(3, 4)}, {far + 7, far + 13}};
  const auto want = oracle::triangle_samples(t);
  CHECK(run_edge<Rational>(t) == want);
  CHECK(run_edge<double>(t) == want);
  CHECK(run_edge<float>(t) != want);
  CHECK(run_dda<float>(t).pixels != want);
}

TEST_CASE("fill: bad input is one line and exit 2 with no output file", "[fill][cli]") {
  struct Bad {
    const char *alg, *input, *numeric, *expect;
  };
  for (const Bad& b : std::initializer_list<Bad>{
           {"triangle-dda", R"({"triangle":[[0,0],[1,1]]})", "exact", "three vertices"},
           {"triangle-dda", R"({"triangle":[[0,0],[1,1],[2,"nan"]]})", "exact", "input.triangle[2][1]"},
           {"triangle-dda", R"({"triangle":[[0,0],[1,1],[2,1e400]]})", "double", "overflow"},
           {"triangle-dda", R"({"triangle":[[0,0],[1,1],[2,2]],"attrs":[[1],[2,3],[4]]})", "exact", "same count"},
           {"triangle-dda", R"({"triangle":[[0,0],[1,1],[2,2]],"colour":1})", "exact", "unknown field"},
           {"triangle-edge", R"({"triangle":[[0,0],[4096,0],[0,4096]]})", "exact", "budget"},
           {"triangle-edge", R"({"triangle":[[0,0],[2000000000,0],[0,1]]})", "exact", "input.triangle[1][0]"},
           {"triangle-edge", R"({"triangle":[[0.1,0],[4,0],[0,4]]})", "int", "1/256"},
           {"triangle-edge", R"({"triangle":[[3000000,0],[3000004,0],[3000000,4]]})", "int", "input.triangle[0][0]"},
           {"scanline-polygon", R"({"polygon":[[0,0],[1,1]],"rule":"even-odd"})", "exact", "at least 3 vertices"},
           {"scanline-polygon", R"({"polygon":[[0,0],[1,1],[1,0]],"rule":"odd"})", "exact", "input.rule"},
           {"scanline-polygon", R"({"polygon":[[0,0],[1,1],[1,0]]})", "exact", "missing field"},
           {"scanline-polygon", R"({"polygon":[[0,0],[1,1],[1,0]],"rule":"nonzero","rings":[[[0,0]]]})", "exact", "input.rings[0]"},
       }) {
    INFO(b.alg << " " << b.input);
    SW_CHECK_BAD_TRACE(b.alg, b.numeric, b.input, b.expect);
  }
}

namespace {

std::vector<Json> fill_corpus() {
  std::ifstream f(std::string(SW_SOURCE_DIR) + "/tests/cases/fill/fill.jsonl");
  std::vector<Json> out;
  std::string line;
  while (std::getline(f, line))
    if (!line.empty() && line[0] == '{') out.push_back(Json::parse(line));
  return out;
}

std::size_t pixel_count(const Json& result) { return result.at("pixels").size(); }

}  // namespace

TEST_CASE("fill: every corpus case in exact and filtered equals the oracle, and the notes hold", "[fill][corpus]") {
  std::map<std::string, Json> oracle_of;  // "name/algorithm" -> the oracle's result
  for (const Json& c : fill_corpus()) {
    const Algorithm& alg = find_algorithm(c["algorithm"].get<std::string>());
    INFO(c["name"].get<std::string>() << " " << alg.id);
    const Json want = alg.open(c["input"]).oracle();
    // triangle-dda-no-offset's oracle is its own exact run (it has no other specification): only
    // filtered against it says something, and its distance from the covered samples is tested above.
    if (alg.id != "triangle-dda-no-offset") CHECK(alg.open(c["input"], Numeric::exact).run() == want);
    Json filtered = alg.open(c["input"], Numeric::filtered).run();
    filtered.erase("fallback");
    CHECK(filtered == want);
    oracle_of[c["name"].get<std::string>() + "/" + std::string(alg.id)] = want;
  }
  REQUIRE(oracle_of.size() >= 55);
  auto pixels = [&](const char* key) { return pixel_count(oracle_of.at(key)); };
  CHECK(pixels("zero area/triangle-edge") == 0);
  CHECK(pixels("zero area, repeated vertex/triangle-dda") == 0);
  CHECK(pixels("sliver between samples/triangle-edge") == 0);
  CHECK(pixels("tiny off sample/triangle-edge") == 0);
  CHECK(oracle_of.at("tiny/triangle-edge")["pixels"] == Json::parse("[[0,0]]"));
  CHECK(pixels("vertices on samples/triangle-edge") == 36);  // x, y >= 0, x + y < 8: 8 + 7 + ... + 1
  CHECK(pixels("mirrored on samples/triangle-edge") == 36 - 8);  // x, y < 8, x + y >= 8: 1 + 2 + ... + 7 = 28
  CHECK(pixels("square with a hole/scanline-polygon") == 100 - 16);
  CHECK(pixels("hole wound the same way, nonzero/scanline-polygon") == 100);
  CHECK(pixels("hole wound the same way, even-odd/scanline-polygon") == 100 - 16);
  CHECK(pixels("star nonzero/scanline-polygon") > pixels("star even-odd/scanline-polygon"));
  CHECK(pixels("all horizontal/scanline-polygon") == 0);
  CHECK(oracle_of.at("collinear and repeated vertices/scanline-polygon") == find_algorithm("triangle-edge").open(Json::parse(R"({"triangle":[[0,0],[8,0],[4,6]]})")).oracle());
}
