// grid-traverse-3d's steps: every variable and geometry item of every exact step against closed
// forms from the semantics (docs/spatial/grid.md): the cells in the oracle's order, and at each
// pick tMax_a = (cell_a + step_a/2 - p0_a) / d_a for the current cell.
#include <catch2/catch.hpp>
#include <optional>
#include <random>
#include "spatial/grid_traverse_3d.hpp"
#include "spatial_grid_oracle.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;

namespace {

using V3 = Vec3<Rational>;

template <class L, class F> void each_step(const Recorder<Rational>& t, F&& check) {
  for (std::size_t s = 0; s < t.size(); ++s) {
    const std::string_view line = L::lines[t.at(s).line - 1].name;
    INFO("step " << s << " line " << line);
    StepValues sv = values_of(t, s);
    StepGeometry g = geometry_of(t, s);
    check(line, sv, g);
    require_all_checked(sv, s);
    require_all_geometry_checked(g, s);
  }
}

void replay(const V3& p0, const V3& p1) {
  INFO("p0 " << p0.x << " " << p0.y << " " << p0.z << " p1 " << p1.x << " " << p1.y << " " << p1.z);
  Recorder<Rational> rec;
  std::vector<spatial::Cell3> got;
  spatial::grid_traverse_3d<Rational>(p0, p1, got, rec);
  const auto want = oracle::grid_cells_3d(p0, p1);
  const V3 d{Rational(p1.x - p0.x), Rational(p1.y - p0.y), Rational(p1.z - p0.z)};
  auto sgn_of = [&](int a) { return sgn(d[a]); };
  std::size_t next = 0;          // the oracle cell the next visit must be
  oracle::GridCell cur{};        // the cell visited last
  auto t_max = [&](int a) -> Rational { return sgn_of(a) == 0 ? Rational(0) : Rational((Rational(cur[a]) + ratio(sgn_of(a), 2) - p0[a]) / d[a]); };
  auto check_visit = [&](StepValues& sv, StepGeometry& g) {
    REQUIRE(next < want.size());
    cur = want[next++];
    CHECK(sv["i"] == cur[0]);
    CHECK(sv["j"] == cur[1]);
    CHECK(sv["k"] == cur[2]);
    GeoItem& box = g.take(GeoKind::box3);
    CHECK(box.values == std::vector<Rational>{Rational(cur[0]) - Rational(1, 2), Rational(cur[1]) - Rational(1, 2), Rational(cur[2]) - Rational(1, 2),
                                              Rational(cur[0]) + Rational(1, 2), Rational(cur[1]) + Rational(1, 2), Rational(cur[2]) + Rational(1, 2)});
    CHECK(box.life == "keep");
  };
  bool done = false;
  each_step<spatial::GridTraverse3d>(rec, [&](std::string_view line, StepValues& sv, StepGeometry& g) {
    if (line == "delta") {
      CHECK(sv["dx"] == d.x);
      CHECK(sv["dy"] == d.y);
      CHECK(sv["dz"] == d.z);
      GeoItem& seg = g.take(GeoKind::segment3);
      CHECK(seg.values == std::vector<Rational>{p0.x, p0.y, p0.z, p1.x, p1.y, p1.z});
      CHECK(seg.life == "keep");
    } else if (line == "start") {
      REQUIRE(!want.empty());
      check_visit(sv, g);
    } else if (line == "setup") {
      for (int a = 0; a < 3; ++a) {
        const std::string ax(1, "xyz"[a]);
        CHECK(sv["step_" + ax] == sgn_of(a));
        CHECK(sv["tDelta_" + ax] == (sgn_of(a) == 0 ? Rational(0) : Rational(1 / abs(d[a]))));
        CHECK(sv["left_" + ax] == std::abs(want.back()[a] - want.front()[a]));
      }
    } else if (line == "first_exit" || line == "pick") {
      for (int a = 0; a < 3; ++a) CHECK(sv[std::string("tMax_") + "xyz"[a]] == t_max(a));
      if (line == "pick") {
        // t: the least tMax over the axes not yet at the last cell.
        std::optional<Rational> t;
        for (int a = 0; a < 3; ++a)
          if (cur[a] != want.back()[a] && (!t || t_max(a) < *t)) t = t_max(a);
        REQUIRE(t);
        CHECK(sv["t"] == *t);
        CHECK(g.take(GeoKind::point3).values == std::vector<Rational>{p0.x + *t * d.x, p0.y + *t * d.y, p0.z + *t * d.z});
      }
    } else if (line == "visit_up" || line == "visit_down") {
      const oracle::GridCell prev = cur;
      check_visit(sv, g);
      for (int a = 0; a < 3; ++a)
        if (cur[a] != prev[a]) CHECK(cur[a] - prev[a] == (line == "visit_up" ? 1 : -1));
    } else if (line == "done") {
      done = true;
      if (!want.empty()) CHECK(sv["cells"] == Rational(static_cast<long>(want.size())));
    } else {
      FAIL("unexpected line " << line);
    }
  });
  CHECK(done);
  CHECK(next == want.size());
}

}  // namespace

TEST_CASE("grid-traverse-3d steps: every recorded value against its closed form", "[spatial][spatial-pt][spatial-grid]") {
  auto q = [](long a, long b) { return ratio(a, b); };
  std::vector<std::pair<V3, V3>> cases = {
      {{0, 0, 0}, {q(5, 4), q(5, 4), q(5, 4)}},             // through a corner (+,+,+)
      {{0, 0, 0}, {q(5, 4), q(-5, 4), q(5, 4)}},            // through a corner (+,-,+): two visits at one t
      {{q(1, 2), q(1, 2), q(1, 2)}, {q(-5, 2), q(5, 2), q(7, 2)}},  // starting on a corner
      {{q(1, 2), q(1, 2), 0}, {q(1, 2), q(1, 2), 2}},       // along an edge
      {{0, 0, 0}, {q(1, 2), 0, 0}},                         // ending on a face from below
      {{q(1, 4), q(-1, 2), q(3, 4)}, {q(9, 2), q(5, 2), q(-3, 2)}},  // the catalog example
      {{2, 3, 4}, {2, 3, 4}},                               // empty
  };
  std::mt19937_64 rng(77);
  std::uniform_int_distribution<long> c(-24, 24);
  for (int n = 0; n < 60; ++n) cases.push_back({{q(c(rng), 4), q(c(rng), 4), q(c(rng), 4)}, {q(c(rng), 4), q(c(rng), 4), q(c(rng), 4)}});
  for (const auto& [p0, p1] : cases) replay(p0, p1);
}
