// bsp-build and bsp-painter against the independent oracle (oracle/spatial_bsp_oracle.hpp): in
// exact and filtered modes the fragments cover the segments exactly and the painter's order is
// valid, on random crossing and non-crossing sets and on degenerate ones; float and double
// failures are counted. Steps: test_bsp_steps.cpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include "spatial/bsp_run.hpp"

using namespace sw;
using namespace sw::testing::bsp;

namespace {

const std::array<Numeric, 4> kBspModes{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};

bool robust(Numeric n) { return n == Numeric::filtered || n == Numeric::exact; }

struct SceneCase {
  std::string name;
  std::vector<Seg> segs;
  std::array<double, 2> eye;
};

// A rounded mode's failures: cases whose fragments are off their segments (a rounded cut), whose
// order has a pair painted wrongly, or that passed the fragment budget.
struct Failures {
  int cover = 0, order = 0, crossing = 0, budget = 0;  // crossing: order failures all from crossing fragments
  friend bool operator==(const Failures&, const Failures&) = default;
  friend std::ostream& operator<<(std::ostream& os, const Failures& f) {
    return os << "{cover " << f.cover << ", order " << f.order << " (crossings only " << f.crossing << "), budget " << f.budget << "}";
  }
};

// Runs the painter on every mode: robust modes must pass the oracle and agree with each other
// exactly; rounded modes' failures are counted per mode.
void run_case(const SceneCase& c, std::map<Numeric, Failures>& failures) {
  INFO("case " << c.name << ": " << input_json(c.segs, c.eye).dump());
  Json exact;
  for (Numeric n : kBspModes) {
    INFO(numeric_name(n));
    Json r;
    const Verdict v = judge("bsp-painter", c.segs, c.eye, n, &r);
    if (robust(n)) {
      INFO(v.cover << " / " << v.order.first);
      CHECK(v.ok());
      r.erase("fallback");
      if (n == Numeric::exact) CHECK(r == exact);
      if (n == Numeric::filtered) exact = find_algorithm("bsp-painter").open(input_json(c.segs, c.eye), Numeric::exact).run();
      if (n == Numeric::filtered) CHECK(r == exact);
    } else {
      failures[n].cover += !v.cover.empty();
      failures[n].order += v.order.violations > 0;
      failures[n].crossing += v.order.violations > 0 && v.order.violations == v.order.crossings;
      failures[n].budget += v.budget;
    }
  }
}

}  // namespace

TEST_CASE("bsp: random crossing and non-crossing sets: robust modes cover exactly and paint in a valid order, rounded failures counted", "[spatial][spatial-bsp]") {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> e(-80, 80);
  std::map<Numeric, Failures> failures;
  int cases = 0;
  auto eye = [&] { return std::array<double, 2>{std::floor(e(rng) * 8) / 8, std::floor(e(rng) * 8) / 8}; };
  for (int k = 0; k < 12; ++k, ++cases) run_case({"crossing on 1/64", random_segments(rng, 20, true, 64), eye()}, failures);
  for (int k = 0; k < 6; ++k, ++cases) run_case({"disjoint on 1/64", random_segments(rng, 36, false, 64), eye()}, failures);
  for (int k = 0; k < 8; ++k, ++cases) run_case({"crossing, full doubles", random_segments(rng, 16, true, 0), eye()}, failures);
  for (int k = 0; k < 6; ++k, ++cases) run_case({"disjoint, full doubles", random_segments(rng, 25, false, 0), eye()}, failures);
  WARN("random sets: " << cases << " cases; failures: float " << failures[Numeric::f32] << ", double " << failures[Numeric::f64]);
  // The counts as measured, pinned, not hidden: a rounded cut leaves its segment's line (cover),
  // and the pieces then cross the splitter by a hair, so no order of the two is valid (crossing).
  CHECK(failures[Numeric::f32] == Failures{32, 20, 20, 0});
  CHECK(failures[Numeric::f64] == Failures{30, 20, 20, 0});
  // The build alone: the same fragments as the painter's, exact in both robust modes.
  for (int k = 0; k < 4; ++k) {
    const auto segs = random_segments(rng, 24, true, 16);
    for (Numeric n : {Numeric::filtered, Numeric::exact}) {
      const Verdict v = judge("bsp-build", segs, std::nullopt, n);
      INFO(v.cover);
      CHECK(v.ok());
    }
  }
}

TEST_CASE("bsp: degenerate sets: collinear, overlapping, shared endpoints, T-junctions, the eye on lines, huge and tiny coordinates", "[spatial][spatial-bsp]") {
  std::vector<SceneCase> cases;
  const std::vector<Seg> example{{0, 0, 8, 8}, {8, 0, 0, 8}, {-2, 3, 10, 3}, {2, 10, 6, 10}, {10, 10, 12, 12}, {1, -3, 7, -3}};
  cases.push_back({"example", example, {3, -6}});
  cases.push_back({"eye on the root splitter's line (y = 10)", example, {20, 10}});
  cases.push_back({"eye on a splitter's line inside the set (y = x)", example, {-2, -2}});
  cases.push_back({"eye on a segment's line (y = 3) and inside the segment", example, {4, 3}});
  cases.push_back({"eye on a segment's end", example, {8, 8}});
  cases.push_back({"eye at a crossing", example, {4, 4}});
  const std::vector<Seg> collinear{{0, 0, 1, 1}, {2, 2, 3, 3}, {1, 1, 2, 2}, {3, 3, 0, 0}, {0.5, 0.5, 2.5, 2.5}, {0, 1, 3, 4}};
  for (std::array<double, 2> eye : {std::array<double, 2>{5, 0}, {4, 4}, {0.5, 0.5}, {-1, 0}, {1.5, 2.5}})
    cases.push_back({"collinear and overlapping", collinear, eye});
  std::vector<Seg> fan;
  for (int k = 0; k < 8; ++k) fan.push_back({0, 0, std::cos(k * 0.785398) * 4, std::sin(k * 0.785398) * 4});
  fan.push_back({-3, 2, 3, 2});
  for (std::array<double, 2> eye : {std::array<double, 2>{0, 0}, {1, 1}, {0, 2}, {-5, 0.25}}) cases.push_back({"a fan sharing one endpoint", fan, eye});
  const std::vector<Seg> square{{0, 0, 4, 0}, {4, 0, 4, 4}, {4, 4, 0, 4}, {0, 4, 0, 0}, {0, 0, 4, 4}, {4, 0, 0, 4}, {2, 0, 2, 4}, {2, 2, 6, 2}};
  for (std::array<double, 2> eye : {std::array<double, 2>{1, 3}, {2, 2}, {8, 2}, {2, -1}, {-1, -1}}) cases.push_back({"a square, its diagonals, T-junctions", square, eye});
  const double H = 1e15;
  const std::vector<Seg> huge{{-H, -H, H, H}, {H, -H, -H, H}, {-H, 3, H, 5}, {1, H, 3, -H}, {-H, H, H, H - 1}};
  for (std::array<double, 2> eye : {std::array<double, 2>{H, -H}, {0, 0}, {-H, 4}, {3, 0.5}}) cases.push_back({"huge coordinates", huge, eye});
  std::mt19937_64 rng(7);
  for (double scale : {std::ldexp(1.0, -1000), std::ldexp(1.0, -60), std::ldexp(1.0, 40)}) {
    auto segs = random_segments(rng, 14, true, 64);
    for (Seg& s : segs)
      for (double& x : s) x *= scale;
    cases.push_back({"scaled by 2^" + std::to_string(std::ilogb(scale)), segs, {3 * scale, -70 * scale}});
  }
  // Near-degenerate: segments through one point, perturbed by 2^-45 and 2^-40.
  for (int p : {45, 40}) {
    std::vector<Seg> near;
    for (int k = 0; k < 10; ++k) {
      const double d = std::ldexp(1.0, -p) * (k % 3 - 1);
      near.push_back({-4.0 + k, -4.0 + d, 4.0 - k, 4.0 + k * 0.5 - d});
    }
    cases.push_back({"near-degenerate 2^-" + std::to_string(p), near, {0.5, -9}});
  }
  std::map<Numeric, Failures> failures;
  for (const SceneCase& c : cases) run_case(c, failures);
  WARN("degenerate sets: " << cases.size() << " cases; failures: float " << failures[Numeric::f32] << ", double " << failures[Numeric::f64]);
  CHECK(failures[Numeric::f32] == Failures{13, 10, 8, 0});
  CHECK(failures[Numeric::f64] == Failures{8, 11, 9, 0});
}

TEST_CASE("bsp-painter: the order flips exactly as the eye crosses the splitter's line", "[spatial][spatial-bsp]") {
  // Segment 0 (the root: both cost 1, ties go to the lowest id) on y = 0, pointing -x, so its front
  // is y < 0; segment 1 above it. From above, 1 hides 0 and is painted last; from below, the reverse.
  const std::vector<Seg> segs{{1, 0, -1, 0}, {-1, 2, 1, 2}};
  const double tiny = std::ldexp(1.0, -40);
  for (Numeric n : {Numeric::filtered, Numeric::exact}) {
    INFO(numeric_name(n));
    auto order = [&](double y) {
      Json r;
      const Verdict v = judge("bsp-painter", segs, std::array<double, 2>{0.25, y}, n, &r);
      CHECK(v.ok());
      return r.at("order").get<std::vector<std::int32_t>>();
    };
    // Segment 0's line points -x, so the eye above it (y > 0) is behind it: its far side is the
    // front (below, empty), then segment 0, then the near side (segment 1).
    CHECK(order(5) == std::vector<std::int32_t>{0, 1});
    CHECK(order(tiny) == std::vector<std::int32_t>{0, 1});
    CHECK(order(-tiny) == std::vector<std::int32_t>{1, 0});
    CHECK(order(-5) == std::vector<std::int32_t>{1, 0});
    CHECK(order(0) == std::vector<std::int32_t>{1, 0});  // on the line: as in front (either order is valid)
  }
}

TEST_CASE("bsp: bad input is one line naming the problem", "[spatial][spatial-bsp]") {
  const Algorithm& build = find_algorithm("bsp-build");
  const Algorithm& painter = find_algorithm("bsp-painter");
  auto message = [](const Algorithm& a, const std::string& text) {
    try {
      (void)a.open(Json::parse(text), Numeric::exact);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK_THAT(message(build, R"({"segments":[[[0,0],[1,1]],[[2,2],[2,2]]]})"), Catch::Contains("input.segments[1]: zero length"));
  CHECK_THAT(message(build, R"({"segments":[[[0,"nan"],[1,1]]]})"), Catch::Contains("input.segments[0][0]"));
  CHECK_THAT(message(build, R"({"segments":[[[0,0],[1,1]]],"eye":[0,0]})"), Catch::Contains("eye"));
  CHECK_THAT(message(painter, R"({"segments":[[[0,0],[1,1]]]})"), Catch::Contains("eye"));
  CHECK_THAT(message(build, R"({"segments":[]})"), Catch::Contains("input.segments"));
  CHECK_THAT(message(build, R"({"segments":[[[0,0],[2e15,1]]]})"), Catch::Contains("input.segments[0][1]"));
  Json many = Json::array();
  for (int k = 0; k < 4097; ++k) many.push_back({{k, 0}, {k, 1}});
  CHECK_THAT(message(build, Json{{"segments", many}}.dump()), Catch::Contains("more than the bound 4096"));
  std::mt19937_64 rng(3);
  CHECK_THAT(message(build, input_json(random_segments(rng, 1200, true, 64)).dump()), Catch::Contains("budget"));
  CHECK(message(build, input_json(random_segments(rng, 1024, false, 64)).dump()) == "accepted");
}
