// grid-traverse-3d against the exact oracle (oracle/spatial_grid_oracle.*): seeded random
// segments and the hard cases (axis-parallel, through cell edges and corners, on faces,
// zero-length, long). Filtered and exact: 0 wrong; float and double: counted. In every mode the walk
// ends in the cell of the points just before p1 (of the input as that mode rounds it).
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>
#include "catalog.hpp"
#include "spatial/grid_traverse_3d.hpp"
#include "spatial_grid_oracle.hpp"

using namespace sw;

namespace {

using P3 = std::array<double, 3>;
struct Seg3 {
  P3 p0, p1;
  const char* kind;
};

double on_grid(double x, int bits) { return std::ldexp(std::round(std::ldexp(x, bits)), -bits); }

// The corpus: about 10^4 segments of the kinds the header names, seeded.
std::vector<Seg3> corpus() {
  std::mt19937_64 rng(3003);
  std::uniform_real_distribution<double> c(-50, 50), u(-8, 8), unit(-1, 1);
  std::uniform_int_distribution<int> small(-4, 4), axis(0, 2);
  std::vector<Seg3> out;
  auto rand_point = [&](int bits) { return P3{on_grid(c(rng), bits), on_grid(c(rng), bits), on_grid(c(rng), bits)}; };
  for (int n = 0; n < 4000; ++n) {  // short, on the 1/256 grid (ties happen), or any double
    const int bits = n % 4 == 3 ? 40 : 8;
    Seg3 s{rand_point(bits), {}, "random"};
    for (int a = 0; a < 3; ++a) s.p1[a] = on_grid(s.p0[a] + u(rng), bits);
    out.push_back(s);
  }
  for (int n = 0; n < 1500; ++n) {  // one or two axes constant, some of them on a face
    Seg3 s{rand_point(4), {}, "axis-parallel"};
    for (int a = 0; a < 3; ++a) s.p1[a] = on_grid(s.p0[a] + u(rng), 4);
    const int a = axis(rng);
    s.p1[a] = s.p0[a];
    if (n % 2) s.p1[(a + 1) % 3] = s.p0[(a + 1) % 3];
    if (n % 3 == 0) s.p0[a] = s.p1[a] = std::floor(s.p0[a]) + 0.5;
    out.push_back(s);
  }
  for (int n = 0; n < 2500; ++n) {  // through a lattice corner (n even) or an edge (n odd)
    P3 x = rand_point(6), d{};
    for (int a = 0; a < 3; ++a) x[a] = std::floor(x[a]) + 0.5;
    if (n % 2) x[axis(rng)] = on_grid(c(rng), 6);
    for (int a = 0; a < 3; ++a) d[a] = small(rng);
    const double before = on_grid(4 * std::abs(unit(rng)), 3), after = on_grid(4 * std::abs(unit(rng)), 3);
    Seg3 s{{}, {}, n % 2 ? "edge" : "corner"};
    for (int a = 0; a < 3; ++a) s.p0[a] = x[a] - before * d[a], s.p1[a] = x[a] + after * d[a];
    out.push_back(s);
  }
  for (int n = 0; n < 1500; ++n) {  // an end on a face, edge or corner
    Seg3 s{rand_point(8), {}, "end on boundary"};
    for (int a = 0; a < 3; ++a) s.p1[a] = on_grid(s.p0[a] + u(rng), 8);
    P3& end = n % 2 ? s.p1 : s.p0;
    for (int a = 0; a <= n % 3; ++a) end[a] = std::floor(end[a]) + 0.5;
    out.push_back(s);
  }
  for (int n = 0; n < 100; ++n) {  // zero length
    const P3 p = rand_point(n % 2 ? 1 : 30);
    out.push_back({p, p, "zero-length"});
  }
  for (int n = 0; n < 40; ++n) {  // long: up to 3000 cells, far out
    Seg3 s{rand_point(8), {}, "long"};
    for (int a = 0; a < 3; ++a) s.p0[a] += n % 2 ? 1e6 : 0, s.p1[a] = s.p0[a] + on_grid(1000 * unit(rng), 8);
    out.push_back(s);
  }
  return out;
}

Vec3<Rational> exact(const P3& p) { return {num::to_rational(p[0]), num::to_rational(p[1]), num::to_rational(p[2])}; }
Vec3<Rational> as_float(const P3& p) {
  return {num::to_rational(static_cast<float>(p[0])), num::to_rational(static_cast<float>(p[1])), num::to_rational(static_cast<float>(p[2]))};
}

std::vector<oracle::GridCell> to_cells(const Json& result) {
  std::vector<oracle::GridCell> out;
  for (const Json& c : result.at("cells")) out.push_back({c[0].get<std::int64_t>(), c[1].get<std::int64_t>(), c[2].get<std::int64_t>()});
  return out;
}

Json input_of(const Seg3& s) { return {{"p0", {s.p0[0], s.p0[1], s.p0[2]}}, {"p1", {s.p1[0], s.p1[1], s.p1[2]}}}; }

}  // namespace

TEST_CASE("grid-traverse-3d: every mode against the exact oracle, robust modes 0 wrong, every walk ends at p1's cell", "[spatial][spatial-pt][spatial-grid]") {
  const Algorithm& alg = find_algorithm("grid-traverse-3d");
  const std::vector<Seg3> segs = corpus();
  REQUIRE(segs.size() >= 9500);
  std::map<Numeric, std::size_t> wrong, wrong_end;
  std::size_t cells = 0, tie_cases = 0;
  for (const Seg3& s : segs) {
    const auto want = oracle::grid_cells_3d(exact(s.p0), exact(s.p1));
    const bool float_exact = as_float(s.p0) == exact(s.p0) && as_float(s.p1) == exact(s.p1);
    const auto want_float = float_exact ? want : oracle::grid_cells_3d(as_float(s.p0), as_float(s.p1));
    cells += want.size();
    for (Numeric n : {Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact}) {
      const Json r = alg.open(input_of(s), n).run();
      const auto got = to_cells(r);
      if (n == Numeric::filtered && r.at("fallback") == true) ++tie_cases;
      if (got != want) {
        ++wrong[n];
        if (n == Numeric::filtered || n == Numeric::exact) {
          INFO(s.kind << " " << input_of(s).dump() << " in " << numeric_name(n));
          CHECK(got == want);
        }
      }
      // The last cell is the oracle's, for the input as the mode rounds it.
      const auto& end = n == Numeric::f32 ? want_float : want;
      if (got.empty() != end.empty() || (!got.empty() && got.back() != end.back())) {
        ++wrong_end[n];
        INFO(s.kind << " " << input_of(s).dump() << " in " << numeric_name(n));
        CHECK(false);
      }
    }
  }
  WARN("grid-traverse-3d on " << segs.size() << " segments (" << cells << " cells, " << tie_cases << " filtered fallbacks): wrong float " << wrong[Numeric::f32]
                              << ", double " << wrong[Numeric::f64] << ", filtered " << wrong[Numeric::filtered] << ", exact " << wrong[Numeric::exact]);
  CHECK(wrong[Numeric::filtered] == 0);
  CHECK(wrong[Numeric::exact] == 0);
  CHECK(wrong_end.empty());
  // Recorded figures (seed 3003): the rounded modes' failures, shown rather than hidden.
  CHECK(wrong[Numeric::f64] == 1099);
  CHECK(wrong[Numeric::f32] == 1075);
}

TEST_CASE("grid oracle: the column sweep equals the brute force over the bounding box", "[spatial][spatial-pt][spatial-grid]") {
  const std::vector<Seg3> segs = corpus();
  std::size_t n = 0;
  for (std::size_t i = 0; i < segs.size(); i += 37) {
    const Seg3& s = segs[i];
    if (std::string(s.kind) == "long") continue;
    INFO(input_of(s).dump());
    CHECK(oracle::grid_cells_3d(exact(s.p0), exact(s.p1)) == oracle::grid_cells_3d_brute_force(exact(s.p0), exact(s.p1)));
    ++n;
  }
  CHECK(n > 200);
}

TEST_CASE("grid-traverse-3d: the hand-checked tie rules of the 2D walk, extended", "[spatial][spatial-pt][spatial-grid]") {
  const Algorithm& alg = find_algorithm("grid-traverse-3d");
  auto cells = [&](const char* in) { return to_cells(alg.open(Json::parse(in), Numeric::exact).run()); };
  using C = std::vector<oracle::GridCell>;
  // Through the corner (1/2, 1/2, 1/2) moving (+,+,+): straight from (0,0,0) to (1,1,1).
  CHECK(cells(R"({"p0":[0,0,0],"p1":[1.25,1.25,1.25]})") == C{{0, 0, 0}, {1, 1, 1}});
  // Moving (-,-,-) through (-1/2,...): the corner belongs to (0,0,0); then straight to (-1,-1,-1).
  CHECK(cells(R"({"p0":[0,0,0],"p1":[-1.25,-1.25,-1.25]})") == C{{0, 0, 0}, {-1, -1, -1}});
  // Moving (+,-,+) through (1/2, -1/2, 1/2): the corner is in (1, 0, 1); then (1, -1, 1).
  CHECK(cells(R"({"p0":[0,0,0],"p1":[1.25,-1.25,1.25]})") == C{{0, 0, 0}, {1, 0, 1}, {1, -1, 1}});
  // An edge: along z in the line x = y = 1/2 (the edge belongs to (1, 1, k)); z in [1.5, 2) is in k = 2.
  CHECK(cells(R"({"p0":[0.5,0.5,0],"p1":[0.5,0.5,2]})") == C{{1, 1, 0}, {1, 1, 1}, {1, 1, 2}});
  // p1 on a face reached from below: p1's own cell (1,0,0) holds no point of [p0, p1).
  CHECK(cells(R"({"p0":[0,0,0],"p1":[0.5,0,0]})") == C{{0, 0, 0}});
  // ... reached from above: the segment's last points are in p1's cell.
  CHECK(cells(R"({"p0":[1,0,0],"p1":[0.5,0,0]})") == C{{1, 0, 0}});
  CHECK(cells(R"({"p0":[2,3,4],"p1":[2,3,4]})").empty());
}

TEST_CASE("grid-traverse-3d: bad input is one line naming the problem", "[spatial][spatial-pt][spatial-grid]") {
  const Algorithm& alg = find_algorithm("grid-traverse-3d");
  auto err = [&](const char* in) -> std::string {
    try {
      (void)alg.open(Json::parse(in), Numeric::exact);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  CHECK_THAT(err(R"({"p0":[0,0,0]})"), Catch::Contains("p1"));
  CHECK_THAT(err(R"({"p0":[0,0,"nan"],"p1":[1,1,1]})"), Catch::Contains("input.p0"));
  CHECK_THAT(err(R"({"p0":[0,0,0],"p1":[1,1,2e9]})"), Catch::Contains("2^30"));
  CHECK_THAT(err(R"({"p0":[0,0,0],"p1":[3e6,1e6,1e6]})"), Catch::Contains("budget of 2^22"));
  CHECK(err(R"({"p0":[0,0,0],"p1":[2e6,1e6,1e6]})").empty());  // 4 x 10^6 moves: within the budget
  CHECK_THAT(err(R"({"p0":[0,0,0],"p1":[1,1,1],"q":1})"), Catch::Contains("q"));
}
