// scanline-polygon: every value and geometry item of every exact step against a closed form: edge
// crossings X(lo, hi, j), the rows each edge crosses, winding numbers and the oracle's covered set.
#include <catch2/catch.hpp>
#include <limits>
#include <optional>
#include <set>
#include "fill/fill_run.hpp"
#include "fill/fill_steps.hpp"
#include "fill_oracle.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::fill_steps;

TEST_CASE("fill steps: every value a scanline-polygon step records matches its closed form", "[fill][replay]") {
  using L = fill::ScanlinePolygon;
  std::mt19937_64 rng(33);
  std::vector<std::pair<Rings, fill::WindingRule>> cases = {
      {{{{0, 10}, {6, -8}, {-9, 3}, {9, 3}, {-6, -8}}}, fill::WindingRule::even_odd},  // a star
      {{{{0, 10}, {6, -8}, {-9, 3}, {9, 3}, {-6, -8}}}, fill::WindingRule::nonzero},
      {{{{0, 0}, {8, 0}, {8, 8}, {0, 8}}, {{2, 2}, {2, 6}, {6, 6}, {6, 2}}}, fill::WindingRule::nonzero},  // a square with a hole
      {{{{0, 0}, {4, 0}, {4, 0}, {8, 0}, {4, 4}}}, fill::WindingRule::even_odd},  // collinear and repeated vertices
      {{{{0, 0}, {4, 0}, {2, 0}}}, fill::WindingRule::even_odd},  // zero area, all horizontal
      {{{{0, 0}, {3, 0}, {3, 2}}, {{0, 9}, {3, 9}, {3, 12}}}, fill::WindingRule::even_odd},  // rings apart: j jumps
  };
  for (int k = 0; k < 40; ++k) {
    Rings rings(1 + k % 2);
    for (auto& r : rings)
      for (int v = 0; v < 3 + k % 6; ++v) r.push_back({grid_coord(rng, -8, 8, k % 3 ? 2 : 1), grid_coord(rng, -8, 8, k % 3 ? 2 : 1)});
    cases.push_back({rings, k % 2 ? fill::WindingRule::nonzero : fill::WindingRule::even_odd});
  }
  for (const auto& c : cases) {
    const auto& rings = c.first;  // variables, not bindings: lambdas below capture them (clang 14)
    const auto rule = c.second;
    Recorder<Rational> t;
    std::vector<Pixel> out;
    fill::scanline_polygon<Rational>({rings, rule}, out, t);
    const auto want = oracle::polygon_samples(rings, rule == fill::WindingRule::nonzero ? oracle::FillRule::nonzero : oracle::FillRule::even_odd);
    // The non-horizontal edges, low end first, with their direction.
    struct Edge {
      V lo, hi;
      int dir;
    };
    std::vector<Edge> edges;
    for (const auto& r : rings)
      for (std::size_t k = 0; k < r.size(); ++k) {
        const V &p = r[k], &q = r[(k + 1) % r.size()];
        if (p.y != q.y) edges.push_back(p.y < q.y ? Edge{p, q, 1} : Edge{q, p, -1});
      }
    auto crossing = [](const Edge& e, std::int64_t j) { return e.lo.y <= j && j < e.hi.y; };
    std::size_t ring = 0, vertex = 0, next_edge = 0;
    std::int64_t j = 0;
    std::optional<std::int64_t> j_prev;
    std::vector<Rational> xs;  // the row's crossings in the recorded order
    std::vector<std::int64_t> dirs;
    std::int64_t w = 0, last_k = 0;
    bool first_span = true;
    std::vector<Pixel> plotted;
    for_each_step<L>(t, [&](std::size_t s, std::string_view line, StepValues& sv, StepGeometry& g) {
      auto list = [&](const std::string& name) {
        std::vector<Rational> v(sv[name + ".size"].get_num().get_si());
        for (std::size_t k = 0; k < v.size(); ++k) v[k] = sv[name + "[" + std::to_string(k) + "]"];
        return v;
      };
      auto row_crossings = [&](std::int64_t row, std::int64_t at) {
        std::vector<Rational> v;
        for (const Edge& e : edges)
          if (crossing(e, row)) v.push_back(X(e.lo, e.hi, Rational(at)));
        std::sort(v.begin(), v.end());
        return v;
      };
      if (line == "edge") {
        REQUIRE(ring < rings.size());
        const auto& r = rings[ring];
        const V &p = r[vertex], &q = r[(vertex + 1) % r.size()];
        CHECK(sv["p.x"] == p.x);
        CHECK(sv["p.y"] == p.y);
        CHECK(sv["q.x"] == q.x);
        CHECK(sv["q.y"] == q.y);
        CHECK(sv["horizontal"] == (p.y == q.y));
        check_segment(g.take(GeoKind::segment2), p, q);
        if (vertex == 0) check_polygon(g.take(GeoKind::polygon), r);
        if (++vertex == r.size()) ++ring, vertex = 0;
      } else if (line == "bucket") {
        REQUIRE(next_edge < edges.size());
        const Edge& e = edges[next_edge++];
        const Rational row = ceil_q(e.lo.y);
        CHECK(sv["row"] == row);
        CHECK(sv["x"] == X(e.lo, e.hi, row));
        CHECK(sv["dx"] == (e.hi.x - e.lo.x) / (e.hi.y - e.lo.y));
        CHECK(sv["y_high"] == e.hi.y);
        CHECK(sv["dir"] == e.dir);
        GeoItem& seg = g.take(GeoKind::segment2);
        check_segment(seg, e.lo, e.hi);
        CHECK(seg.label == (e.dir > 0 ? "up" : "down"));
        CHECK(seg.life == "keep");
      } else if (line == "first") {
        std::int64_t lowest = std::numeric_limits<std::int64_t>::max();
        for (const Edge& e : edges) lowest = std::min(lowest, num::ceil_int(e.lo.y));
        j = lowest;
        CHECK(sv["j"] == j);
      } else if (line == "add") {
        CHECK(sv["j"] == j);
        std::int64_t active = 0;  // added by now and not dropped at an earlier row
        for (const Edge& e : edges) active += num::ceil_int(e.lo.y) <= j && (!j_prev || *j_prev < e.hi.y);
        CHECK(sv["active"] == active);
      } else if (line == "drop") {
        std::int64_t active = 0;
        for (const Edge& e : edges) active += crossing(e, j);
        CHECK(sv["active"] == active);
      } else if (line == "sort") {
        CHECK(sv["j"] == j);
        xs = list("x");
        const auto d = list("dir");
        CHECK(xs == row_crossings(j, j));
        // Each (x, dir) pair is an edge's: the multisets agree.
        std::multiset<std::pair<Rational, std::int64_t>> got, exp;
        dirs.clear();
        for (std::size_t k = 0; k < xs.size(); ++k) got.insert({xs[k], d[k].get_num().get_si()}), dirs.push_back(d[k].get_num().get_si());
        for (const Edge& e : edges)
          if (crossing(e, j)) exp.insert({X(e.lo, e.hi, Rational(j)), e.dir});
        CHECK(got == exp);
        w = 0;
        first_span = true;
      } else if (line == "spans") {
        const std::int64_t k = sv["k"].get_num().get_si();
        CHECK(k == (last_k = first_span ? 0 : last_k + 1));
        first_span = false;
        REQUIRE(k + 1 < static_cast<std::int64_t>(xs.size()));
        w += dirs[k];
        CHECK(sv["w"] == w);
        const std::int64_t first = num::ceil_int(xs[k]);
        if (first < xs[k + 1]) CHECK(w == oracle::winding_number(rings, {first, j}));  // the winding number of the span's samples
        const bool inside = rule == fill::WindingRule::nonzero ? w != 0 : w % 2 != 0;
        CHECK(sv["inside"] == inside);
      } else if (line == "fill") {
        // The span of the last spans step: between crossings k and k + 1.
        const Rational xl = sv["x_l"], xr = sv["x_r"];
        CHECK(xl == xs[last_k]);
        CHECK(xr == xs[last_k + 1]);
        const std::int64_t i0 = num::ceil_int(xl), i1 = num::ceil_int(xr) - 1;
        CHECK(i0 <= i1);
        CHECK(g.take(GeoKind::span).values == std::vector<Rational>{j, i0, i1});
        for (std::int64_t i = i0; i <= i1; ++i) {
          CHECK(covered(want, {i, j}));
          plotted.push_back({i, j});
        }
      } else if (line == "advance") {
        std::vector<Rational> moved = row_crossings(j, j + 1);  // each active edge one row on
        j_prev = j;
        // With nothing active after the drop, j jumps to the lowest edge-table row above j.
        std::int64_t crossing_now = 0, jump = std::numeric_limits<std::int64_t>::max();
        for (const Edge& e : edges) {
          crossing_now += crossing(e, j);
          if (num::ceil_int(e.lo.y) > j) jump = std::min(jump, num::ceil_int(e.lo.y));
        }
        const std::int64_t next_row = crossing_now == 0 && jump != std::numeric_limits<std::int64_t>::max() ? jump : j + 1;
        j = next_row;
        CHECK(sv["j"] == j);
        auto got = list("x");
        std::sort(got.begin(), got.end());
        CHECK(got == moved);
      } else if (line == "done") {
        CHECK(s + 1 == t.size());
        CHECK(sv["pixels"] == Rational(static_cast<long>(want.size())));
      } else {
        FAIL("a step on an unexpected line");
      }
    });
    CHECK(plotted == want);
    CHECK(out == want);
    CHECK(next_edge == edges.size());
  }
}
