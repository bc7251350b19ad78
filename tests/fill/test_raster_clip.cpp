// raster-clip against its exact oracle (the covered samples on the screen, by brute force over the
// screen only), against triangle-dda restricted to the screen, the tiling of adjacent screens, work
// bounded by the screen for huge triangles, the corpus and bad input.
#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include "catalog.hpp"
#include "cli_harness.hpp"
#include "core/interval.hpp"
#include "fill/raster_clip_run.hpp"
#include "fill_oracle.hpp"
#include "fill_raster_oracle.hpp"
#include "trace_io.hpp"

using namespace sw;
using namespace sw::testing;

namespace {

oracle::SampleWindow window(const fill::Screen& s) { return {s.i0, s.j0, s.i1, s.j1}; }
std::vector<Pixel> want_of(const Tri& t, const fill::Screen& s) { return oracle::triangle_samples_in_window(t, window(s)); }

fill::Screen random_screen(std::mt19937_64& rng, long lo, long hi) {
  auto u = [&](long a, long b) { return std::uniform_int_distribution<long>(a, b)(rng); };
  const long i0 = u(-20, 20), j0 = u(-20, 20);
  return {i0, j0, i0 + u(lo, hi), j0 + u(lo, hi)};
}

enum Kind { partly, inside, outside, huge, on_edges, kinds };

// One random case of the given kind; den: vertices on the 1/den grid.
std::pair<Tri, fill::Screen> random_case(std::mt19937_64& rng, Kind kind, long den) {
  auto u = [&](long a, long b) { return std::uniform_int_distribution<long>(a, b)(rng); };
  fill::Screen s = random_screen(rng, 1, 12);
  Tri t;
  switch (kind) {
    case partly:  // about the screen's size, around it
      for (auto& v : t) v = {grid_coord(rng, s.i0 - 8, s.i1 + 8, den), grid_coord(rng, s.j0 - 8, s.j1 + 8, den)};
      break;
    case inside:  // every vertex within the screen's samples: the whole triangle's samples are on screen
      s = random_screen(rng, 3, 14);
      for (auto& v : t) v = {grid_coord(rng, s.i0, s.i1 - 1, den), grid_coord(rng, s.j0, s.j1 - 1, den)};
      break;
    case outside: {  // every vertex left of i0, right of i1 (or on), below j0 or above j1 (or on)
      const int side = static_cast<int>(u(0, 3));
      for (auto& v : t) {
        v = {grid_coord(rng, s.i0 - 10, s.i1 + 10, den), grid_coord(rng, s.j0 - 10, s.j1 + 10, den)};
        if (side == 0) v.x = Rational(s.i0) - grid_coord(rng, 0, 10, den);
        if (side == 1) v.x = Rational(s.i1) + grid_coord(rng, 0, 10, den);
        if (side == 2) v.y = Rational(s.j0) - grid_coord(rng, 0, 10, den);
        if (side == 3) v.y = Rational(s.j1) + grid_coord(rng, 0, 10, den);
      }
      break;
    }
    case huge: {  // 10^3 to 10^6 (and now and then 10^10) times the screen's width
      const long K = std::array<long, 5>{1000, 10000, 100000, 1000000, 10000000000}[u(0, 4)];
      t = huge_crossing(rng, s, K, den);
      break;
    }
    case on_edges: {  // coordinates on the screen's edges i0, i1, j0, j1 and on samples
      const std::array<long, 6> xs{s.i0, s.i1, s.i0 - 1, s.i1 + 1, (s.i0 + s.i1) / 2, s.i1 - 1};
      const std::array<long, 6> ys{s.j0, s.j1, s.j0 - 1, s.j1 + 1, (s.j0 + s.j1) / 2, s.j1 - 1};
      for (auto& v : t) v = {Rational(xs[u(0, 5)]), Rational(ys[u(0, 5)])};
      if (u(0, 3) == 0) t[0].x += Rational(u(-3, 3), 2);  // a vertex off the grid now and then
      break;
    }
    default: break;
  }
  return {t, s};
}

bool small(const Tri& t) {
  for (int a = 0; a < 2; ++a) {
    const Rational lo = std::min({t[0][a], t[1][a], t[2][a]}), hi = std::max({t[0][a], t[1][a], t[2][a]});
    if (hi - lo > 64) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("raster-clip oracle: the screen's samples of hand-worked triangles, and the whole-box oracle restricted", "[fill][raster-clip][oracle]") {
  // (0,0), (8,0), (0,8) covers x, y >= 0, x + y < 8. On the screen [2, 5) x [1, 3): rows 1 and 2,
  // columns 2..4 with x + y < 8: all six.
  const Tri t{Vec2<Rational>{0, 0}, {8, 0}, {0, 8}};
  CHECK(oracle::triangle_samples_in_window(t, {2, 1, 5, 3}) == std::vector<Pixel>{{2, 1}, {3, 1}, {4, 1}, {2, 2}, {3, 2}, {4, 2}});
  // The screen [6, 9) x [0, 3): x + y < 8 keeps (6,0), (7,0), (6,1).
  CHECK(oracle::triangle_samples_in_window(t, {6, 0, 9, 3}) == std::vector<Pixel>{{6, 0}, {7, 0}, {6, 1}});
  CHECK(oracle::triangle_samples_in_window(t, {-3, -3, 0, 0}).empty());  // below and left: (0,0) is not on [-3, 0)
  CHECK(oracle::triangle_samples_in_window(t, {0, 0, 1, 1}) == std::vector<Pixel>{{0, 0}});
  CHECK(oracle::triangle_samples_in_window({Vec2<Rational>{0, 0}, {2, 2}, {4, 4}}, {0, 0, 8, 8}).empty());  // zero area
  // A triangle 10^9 wide whose hypotenuse x + y = 1 crosses the screen [-2, 3) x [-2, 3).
  const Rational G(1000000000);
  const Tri big{Vec2<Rational>{-G, -G}, {G + 1, -G}, {-G, G + 1}};
  std::vector<Pixel> want;
  for (std::int64_t j = -2; j < 3; ++j)
    for (std::int64_t i = -2; i < 3; ++i)
      if (i + j < 1) want.push_back({i, j});
  CHECK(oracle::triangle_samples_in_window(big, {-2, -2, 3, 3}) == want);
  // Against the independent whole-box oracle, restricted.
  std::mt19937_64 rng(1);
  for (int n = 0; n < 500; ++n) {
    const auto [tri, s] = random_case(rng, n % 2 ? partly : on_edges, n % 3 ? 4 : 1);
    REQUIRE(oracle::triangle_samples_in_window(tri, window(s)) == restrict_to(oracle::triangle_samples(tri), s));
  }
}

TEST_CASE("raster-clip: exact and filtered equal the oracle on 10^4 random triangles and screens, and triangle-dda restricted to the screen", "[fill][raster-clip][oracle]") {
  std::mt19937_64 rng(2027);
  std::size_t uncertain = 0, covered = 0, dda_compared = 0, huge_partial = 0, with_values = 0;
  std::array<std::size_t, kinds> nonempty{};
  for (int n = 0; n < 10000; ++n) {
    const Kind kind = Kind(n % kinds);
    const long den = (n / kinds) % 3 == 0 ? 1 : (n / kinds) % 3 == 1 ? 4 : 256;
    const auto c = random_case(rng, kind, den);
    const Tri& t = c.first;  // variables, not bindings: the lambda below captures them (clang 14)
    const fill::Screen& s = c.second;
    INFO("kind " << kind << " triangle " << t[0].x << "," << t[0].y << " " << t[1].x << "," << t[1].y << " " << t[2].x << "," << t[2].y
                 << " screen " << s.i0 << "," << s.j0 << " " << s.i1 << "," << s.j1);
    const auto want = want_of(t, s);
    covered += want.size();
    nonempty[kind] += !want.empty();
    if (kind == huge) huge_partial += !want.empty() && want.size() < std::size_t((s.i1 - s.i0) * (s.j1 - s.j0));
    if (n % 10 == 0) {  // with attributes: the plane through them at each sample
      std::vector<std::array<Rational, 3>> attrs(2);
      for (auto& a : attrs)
        for (auto& x : a) x = grid_coord(rng, -5, 5, 8);
      const auto r = run_clip<Rational>(t, s, attrs);
      REQUIRE(r.pixels == want);
      for (std::size_t p = 0; p < r.pixels.size(); ++p)
        for (int c = 0; c < 2; ++c) REQUIRE(r.values[2 * p + c] == oracle::linear_at(t, attrs[c], r.pixels[p]));
      ++with_values;
    } else {
      REQUIRE(run_clip<Rational>(t, s).pixels == want);
    }
    if (auto f = filtered([&] { return run_clip<Interval>(t, s).pixels; }, uncertain)) REQUIRE(*f == want);
    if (kind == inside) REQUIRE(want == oracle::triangle_samples(t));  // nothing of it is off the screen
    if (kind == outside) REQUIRE(want.empty());
    if (small(t) && n % 2 == 0) {
      REQUIRE(restrict_to(run_dda<Rational>(t).pixels, s) == want);
      ++dda_compared;
    }
  }
  INFO("covered " << covered << ", uncertain " << uncertain << ", compared with triangle-dda " << dda_compared << ", huge and partly on screen " << huge_partial);
  CHECK(covered > 60000);  // about 8 samples per case: the set is not mostly empty screens
  for (int k = 0; k < kinds; ++k) CHECK((k == outside ? nonempty[k] == 0 : nonempty[k] > 600));
  CHECK(huge_partial > 300);    // huge triangles whose edge crosses the screen, not only covering it all
  CHECK(dda_compared > 3000);
  CHECK(with_values == 1000);
  CHECK(uncertain < 2000);
}

TEST_CASE("raster-clip: rational vertices (thirds) and vertices near the bound 2^40 equal the oracle", "[fill][raster-clip][oracle]") {
  std::mt19937_64 rng(3);
  for (int n = 0; n < 200; ++n) {
    const fill::Screen s = random_screen(rng, 1, 10);
    Tri t;
    if (n % 2) {
      for (auto& v : t) v = {grid_coord(rng, s.i0 - 6, s.i1 + 6, 3), grid_coord(rng, s.j0 - 6, s.j1 + 6, 3)};
    } else {
      t = huge_crossing(rng, s, 30000000000, n % 4 ? 3 : 256);  // |x|, |y| up to about 2^39
    }
    for (const auto& v : t) REQUIRE((abs(v.x) <= Rational(std::int64_t{1} << 40) && abs(v.y) <= Rational(std::int64_t{1} << 40)));
    const auto want = want_of(t, s);
    REQUIRE(run_clip<Rational>(t, s).pixels == want);
    std::size_t unc = 0;
    if (auto f = filtered([&] { return run_clip<Interval>(t, s).pixels; }, unc)) REQUIRE(*f == want);
  }
}

TEST_CASE("raster-clip: adjacent screens tile: split at a column and a row, each sample is drawn once", "[fill][raster-clip][tiling]") {
  std::mt19937_64 rng(4);
  for (int n = 0; n < 400; ++n) {
    const Kind kind = n % 2 ? huge : n % 4 ? partly : on_edges;
    const auto [t, s] = random_case(rng, kind, n % 3 ? 4 : 1);
    const std::int64_t im = std::uniform_int_distribution<std::int64_t>(s.i0, s.i1)(rng), jm = std::uniform_int_distribution<std::int64_t>(s.j0, s.j1)(rng);
    const auto whole = run_clip<Rational>(t, s).pixels;
    Cover got, once;
    add_cover(once, whole);
    for (const fill::Screen& q : {fill::Screen{s.i0, s.j0, im, jm}, {im, s.j0, s.i1, jm}, {s.i0, jm, im, s.j1}, {im, jm, s.i1, s.j1}})
      if (q.i0 < q.i1 && q.j0 < q.j1) add_cover(got, run_clip<Rational>(t, q).pixels);
    REQUIRE(got == once);
  }
  // A fan of 32 triangles around a centre on a sample, its rim far larger than the screens, drawn
  // on a 3 x 3 grid of screens: every sample of the rim's inside on the big screen exactly once.
  for (int n = 0; n < 6; ++n) {
    const Vec2<Rational> c{grid_coord(rng, -3, 3, 1), grid_coord(rng, -3, 3, 1)};
    std::vector<Vec2<Rational>> rim;
    for (int k = 0; k < 32; ++k) {
      const double a = 6.283185307179586 * k / 32, r = 1000 * (1 + std::uniform_real_distribution<double>(0, 1)(rng));
      rim.push_back({Rational(std::lround(4 * r * std::cos(a))) / 4, Rational(std::lround(4 * r * std::sin(a))) / 4});
    }
    Cover got;
    for (int k = 0; k < 32; ++k)
      for (std::int64_t a = 0; a < 3; ++a)
        for (std::int64_t b = 0; b < 3; ++b) add_cover(got, run_clip<Rational>({c, rim[k], rim[(k + 1) % 32]}, {-9 + 6 * a, -9 + 6 * b, -3 + 6 * a, -3 + 6 * b}).pixels);
    Cover screen;  // the rim encloses the whole 18 x 18 screen
    for (std::int64_t j = -9; j < 9; ++j)
      for (std::int64_t i = -9; i < 9; ++i) screen[{i, j}] = 1;
    CHECK(got == screen);
  }
}

TEST_CASE("raster-clip: the work is bounded by the screen: a triangle 10^6 and 10^10 times its size records at most 2 steps per pixel and 3 per row", "[fill][raster-clip][time]") {
  std::mt19937_64 rng(5);
  const Algorithm& alg = find_algorithm("raster-clip");
  for (int n = 0; n < 40; ++n) {
    const fill::Screen s = random_screen(rng, 4, 16);
    const Tri t = huge_crossing(rng, s, n % 2 ? 1000000 : 10000000000, 4);
    Json in{{"viewport", {{"min", {s.i0, s.j0}}, {"max", {s.i1, s.j1}}}}};
    for (const auto& v : t) in["triangle"].push_back({v.x.get_str(), v.y.get_str()});
    const Recorded rec = alg.open(in, Numeric::exact).record();
    // Per covered pixel on screen a plot and a step, per row on screen a row, a span and an
    // advance, and six more: the sort, the screen, three edges and done.
    const std::size_t w = s.i1 - s.i0, h = s.j1 - s.j0, pixels = rec.result["pixels"].size();
    CHECK(pixels <= w * h);
    CHECK(rec.trace->size() <= 2 * pixels + 3 * h + 6);
  }
  // The same triangle on a 1024 x 1024 screen, double, untraced: about 10^6 pixels.
  const Rational G(std::int64_t{1} << 39);
  const auto r = run_clip<double>({Vec2<Rational>{-G, -G}, {G, Rational(1, 3)}, {Rational(-7, 2), G}}, {-512, -512, 512, 512});
  CHECK(r.pixels.size() > 500000);
}

TEST_CASE("raster-clip: float cannot hold vertices far off the screen, exact and filtered can", "[fill][raster-clip][accuracy]") {
  // At 2^35 float's spacing is 2^12: G + 1 is G, and the hypotenuse x + y = 1 through the screen
  // moves to x + y = 0.
  const Rational G(std::int64_t{1} << 35);
  const Tri t{Vec2<Rational>{-G, -G}, {G + 1, -G}, {-G, G + 1}};
  const fill::Screen s{-8, -8, 8, 8};
  const auto want = want_of(t, s);
  CHECK(!want.empty());
  CHECK(run_clip<Rational>(t, s).pixels == want);
  CHECK(run_clip<Interval>(t, s).pixels == want);
  CHECK(run_clip<double>(t, s).pixels == want);
  CHECK(run_clip<float>(t, s).pixels != want);
}

TEST_CASE("raster-clip: bad input is one line and exit 2 with no output file", "[fill][raster-clip][cli]") {
  struct Bad {
    const char *input, *numeric, *expect;
  };
  for (const Bad& b : std::initializer_list<Bad>{
           {R"({"triangle":[[0,0],[4,0],[0,4]],"viewport":{"min":[5,0],"max":[2,4]}})", "exact", "min[0] > max[0]"},
           {R"({"triangle":[[0,0],[4,0],[0,4]],"viewport":{"min":[0,5],"max":[4,2]}})", "double", "min[1] > max[1]"},
           {R"({"triangle":[[0,0],[4,0],[0,4]],"viewport":{"min":[0,0],"max":[0,4]}})", "exact", "empty"},
           {R"({"triangle":[[0,0],[4,0],[0,4]],"viewport":{"min":[0,3],"max":[4,3]}})", "filtered", "empty"},
           {R"({"triangle":[[0,0],[4,0],[0,4]],"viewport":{"min":[0,0],"max":[2048,1024]}})", "exact", "budget"},
           {R"({"triangle":[[0,0],[4,0],[0,"nan"]],"viewport":{"min":[0,0],"max":[4,4]}})", "exact", "input.triangle[2][1]"},
           {R"({"triangle":[[0,0],[4,0],[0,4]],"viewport":{"min":[0,"nan"],"max":[4,4]}})", "exact", "input.viewport.min[1]"},
           {R"({"triangle":[[0,0],[4,0],[0,4]],"viewport":{"min":[0,0.5],"max":[4,4]}})", "exact", "not an integer"},
           {R"({"triangle":[[0,0],[4,0],[0,4]],"viewport":{"min":[0,0],"max":[4,2000000000]}})", "exact", "input.viewport.max[1]"},
           {R"({"triangle":[[0,0],[2000000000000,0],[0,4]],"viewport":{"min":[0,0],"max":[4,4]}})", "exact", "input.triangle[1][0]"},
           {R"({"triangle":[[0,0],[4,0],[0,4]]})", "exact", "missing field"},
           {R"({"viewport":{"min":[0,0],"max":[4,4]}})", "exact", "missing field"},
           {R"({"triangle":[[0,0],[4,0],[0,4]],"viewport":{"min":[0,0]}})", "exact", "missing field"},
           {R"({"triangle":[[0,0],[4,0]],"viewport":{"min":[0,0],"max":[4,4]}})", "exact", "three vertices"},
           {R"({"triangle":[[0,0],[4,0],[0,4]],"viewport":[0,0,4,4]})", "exact", "input.viewport"},
           {R"({"triangle":[[0,0],[4,0],[0,4]],"viewport":{"min":[0,0],"max":[4,4]},"attrs":[[1],[2,3],[4]]})", "exact", "same count"},
           {R"({"triangle":[[0,0],[4,0],[0,4]],"viewport":{"min":[0,0],"max":[4,4]},"window":1})", "exact", "unknown field"},
       }) {
    INFO(b.input);
    SW_CHECK_BAD_TRACE("raster-clip", b.numeric, b.input, b.expect);
  }
}

namespace {
struct CorpusCase {
  std::string name;
  Json input;
};
std::vector<CorpusCase> raster_corpus() {
  std::ifstream f(std::string(SW_SOURCE_DIR) + "/tests/cases/fill/raster_clip.jsonl");
  std::vector<CorpusCase> out;
  std::string line;
  while (std::getline(f, line))
    if (!line.empty() && line[0] == '{') {
      const Json j = Json::parse(line);
      out.push_back({j.at("name").get<std::string>(), j.at("input")});
    }
  return out;
}
}  // namespace

TEST_CASE("raster-clip: every corpus case in exact, filtered and traced equals the oracle, and the notes hold", "[fill][raster-clip][corpus]") {
  const Algorithm& alg = find_algorithm("raster-clip");
  std::map<std::string, Json> got;
  for (const CorpusCase& c : raster_corpus()) {
    INFO(c.name);
    const Json want = alg.open(c.input).oracle();
    CHECK(alg.open(c.input, Numeric::exact).run() == want);
    CHECK(alg.open(c.input, Numeric::filtered).run()["pixels"] == want["pixels"]);  // its values are the filter's approximations
    std::stringstream trace;
    write_trace(alg.open(c.input, Numeric::exact), trace);
    CHECK(check_trace(trace).status == 0);
    got[c.name] = want;
  }
  REQUIRE(got.size() >= 16);
  auto count = [&](const char* name) { return got.at(name)["pixels"].size(); };
  CHECK(count("wholly outside, right") == 0);
  CHECK(count("below, apex on the screen's bottom row") == 0);
  CHECK(count("above, bottom vertex on row j1") == 0);
  CHECK(count("left of the screen, right edge on column i0") == 0);
  CHECK(count("zero area, huge") == 0);
  CHECK(count("wholly inside") == 36);
  CHECK(count("covers the screen, 10^6 times its size") == 16 * 16);
  CHECK(count("screen of one sample on a vertex") == 1);
  CHECK(count("screen of one sample on a right edge") == 0);
  CHECK(count("hypotenuse through the screen, 2^39") == 15);
  CHECK(count("vertices on the screen's corners") == 36);
  CHECK(got.at("left half")["pixels"].size() + got.at("right half")["pixels"].size() == count("both halves"));
}
