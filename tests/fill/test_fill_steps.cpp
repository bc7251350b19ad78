// The fills: every value and geometry item of every exact step against a closed form written from
// the semantics: edge crossings X(p0, p1, y), edge functions E(p, q, s), the plane through the
// attributes, winding numbers and the oracle's covered set.
#include <catch2/catch.hpp>
#include <limits>
#include <optional>
#include <set>
#include "fill/fill_run.hpp"
#include "fill_oracle.hpp"
#include "fill/fill_steps.hpp"

using namespace sw;
using namespace sw::testing;

namespace {

using namespace sw::testing::fill_steps;

Tri random_tri(std::mt19937_64& rng, long den) {
  Tri t;
  for (auto& v : t) v = {grid_coord(rng, -6, 6, den), grid_coord(rng, -6, 6, den)};
  return t;
}
// Hand-picked triangles: flat bottom, flat top, a vertex and edges on samples, zero area, a sliver.
std::vector<Tri> corner_cases() {
  return {{V{0, 0}, {6, 0}, {2, 5}}, {V{0, 5}, {6, 5}, {2, 0}}, {V{1, 1}, {5, 3}, {3, 7}}, {V{0, 0}, {2, 2}, {5, 5}},
          {V{Rational(1, 4), 0}, {Rational(3, 4), 9}, {Rational(1, 2), 10}}, {V{Rational(3, 2), Rational(3, 4)}, {Rational(49, 4), Rational(9, 2)}, {5, Rational(21, 2)}}};
}

// triangle-dda and its no-offset variant: the rows and spans stated per row index.
template <bool Offset> void check_dda(const Tri& tri, const std::vector<std::array<Rational, 3>>& attrs) {
  using L = std::conditional_t<Offset, fill::TriangleDda, fill::TriangleDdaNoOffset>;
  Recorder<Rational> t;
  fill::Triangle<Rational> v;
  for (int k = 0; k < 3; ++k) {
    v[k].p = tri[k];
    v[k].n = attrs.size();
    for (std::size_t c = 0; c < attrs.size(); ++c) v[k].a[c] = attrs[c][k];
  }
  fill::FillResult<Rational> res;
  fill::triangle_dda<Offset, Rational>(v, res, t);
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return tri[a].y < tri[b].y; });
  const V b = tri[order[0]], m = tri[order[1]], top = tri[order[2]];
  const std::size_t n = attrs.size();
  // Attribute c of vertex p along the edge p0 -> p1 at row y, and at a point along a span.
  auto vertex_attr = [&](const V& p, std::size_t c) {
    for (int k = 0; k < 3; ++k)
      if (tri[order[k]] == p) return attrs[c][order[k]];
    FAIL("not a vertex");
    return Rational(0);
  };
  auto edge_attr = [&](const V& p0, const V& p1, const Rational& y, std::size_t c) -> Rational {
    return vertex_attr(p0, c) + (y - p0.y) / (p1.y - p0.y) * (vertex_attr(p1, c) - vertex_attr(p0, c));
  };
  auto start_y = [&](const V& p) { return Offset ? ceil_q(p.y) : p.y; };
  const auto want = oracle::triangle_samples(tri);
  const bool area = E(tri[0], tri[1], tri[2]) != 0;
  // The walk's position, followed from the listing's own order: the long edge's row, the short edge's row.
  Rational yc = start_y(b), ys;
  V p0, p1;          // the current short edge
  V l, r;            // the current span's ends (l_x <= r_x)
  std::vector<Rational> la(n), ra(n);
  Rational sx;       // the span's next sample
  bool ok_rows = true;
  std::vector<Pixel> plotted;
  for (std::size_t s = 0; s < t.size(); ++s) {
    const std::string_view line = L::lines[t.at(s).line - 1].name;
    INFO("step " << s << " line " << line);
    StepValues sv = values_of(t, s);
    StepGeometry g = geometry_of(t, s);
    auto check_vary = [&](const char* q, const char* qa, const V& at, const std::vector<Rational>& a) {
      CHECK(sv[std::string(q) + ".x"] == at.x);
      CHECK(sv[std::string(q) + ".y"] == at.y);
      if (qa) {
        CHECK(sv[std::string(qa) + ".size"] == Rational(n));
        for (std::size_t c = 0; c < n; ++c) CHECK(sv[std::string(qa) + "[" + std::to_string(c) + "]"] == a[c]);
      }
    };
    auto edge_start = [&](const V& e0, const V& e1, const char* label) {
      const Rational y = start_y(e0);
      std::vector<Rational> qa(n), da(n);
      for (std::size_t c = 0; c < n; ++c) qa[c] = edge_attr(e0, e1, y, c), da[c] = (vertex_attr(e1, c) - vertex_attr(e0, c)) / (e1.y - e0.y);
      check_vary("q", "q_attrs", {X(e0, e1, y), y}, qa);
      check_vary("dq", "dq_attrs", {(e1.x - e0.x) / (e1.y - e0.y), 1}, da);
      GeoItem& seg = g.take(GeoKind::segment2);
      check_segment(seg, e0, e1);
      CHECK(seg.label == label);
      CHECK(seg.life == "keep");
      GeoItem& q = g.take(GeoKind::point2);
      check_point(q, {X(e0, e1, y), y});
      CHECK(q.label == "q");
    };
    if (line == "sort") {
      check_vary("b", nullptr, b, {});
      check_vary("m", nullptr, m, {});
      check_vary("t", nullptr, top, {});
      check_polygon(g.take(GeoKind::polygon), {b, m, top});
    } else if (line == "long_edge") {
      edge_start(b, top, "c");
    } else if (line == "lower_edge" || line == "upper_edge") {
      p0 = line == "lower_edge" ? b : m;
      p1 = line == "lower_edge" ? m : top;
      if (p0.y == p1.y) {
        CHECK(sv["flat"] == 1);
      } else {
        edge_start(p0, p1, line == "lower_edge" ? "a" : "e");
        ys = start_y(p0);
      }
    } else if (line == "lower_span" || line == "upper_span") {
      const char* qn = line == "lower_span" ? "q_a" : "q_e";
      const V qs{X(p0, p1, ys), ys}, qc{X(b, top, yc), yc};
      check_vary(qn, nullptr, qs, {});
      check_vary("q_c", nullptr, qc, {});
      CHECK(ys < p1.y);
      check_segment(g.take(GeoKind::segment2), qs, qc);
      l = qs, r = qc;
      for (std::size_t c = 0; c < n; ++c) la[c] = edge_attr(p0, p1, ys, c), ra[c] = edge_attr(b, top, yc, c);
      if (r.x < l.x) std::swap(l, r), std::swap(la, ra);
    } else if (line == "lower_step" || line == "upper_step") {
      ys += 1, yc += 1;
      check_vary(line == "lower_step" ? "q_a" : "q_e", nullptr, {X(p0, p1, ys), ys}, {});
      check_vary("q_c", nullptr, {X(b, top, yc), yc}, {});
    } else if (line == "span_start") {
      CHECK(sv["l_x"] == l.x);
      CHECK(sv["r_x"] == r.x);
      CHECK(sv["empty"] == (l.x < r.x ? 0 : 1));
      if (l.x < r.x) {
        sx = Offset ? ceil_q(l.x) : l.x;
        std::vector<Rational> da(n);
        for (std::size_t c = 0; c < n; ++c) da[c] = (ra[c] - la[c]) / (r.x - l.x);
        check_vary("s", nullptr, {sx, l.y + (sx - l.x) * (r.y - l.y) / (r.x - l.x)}, {});
        CHECK(sv["ds_attrs.size"] == Rational(n));
        for (std::size_t c = 0; c < n; ++c) CHECK(sv["ds_attrs[" + std::to_string(c) + "]"] == da[c]);
        GeoItem& span = g.take(GeoKind::segment2);
        check_segment(span, l, r);
        CHECK(span.label == "span");
      }
    } else if (line == "plot") {
      const Rational sy = l.y + (sx - l.x) * (r.y - l.y) / (r.x - l.x);
      const Pixel px{num::floor_int(Rational(sx + Rational(1, 2))), num::floor_int(Rational(sy + Rational(1, 2)))};
      CHECK(sx < r.x);
      CHECK(sv["i"] == px.x);
      CHECK(sv["j"] == px.y);
      CHECK(sv["values.size"] == Rational(n));
      for (std::size_t c = 0; c < n; ++c) {
        const Rational at = la[c] + (sx - l.x) / (r.x - l.x) * (ra[c] - la[c]);
        CHECK(sv["values[" + std::to_string(c) + "]"] == at);
        if (Offset) CHECK(at == oracle::linear_at(tri, attrs[c], px));  // the plane through the attributes, at the sample
        if (n == 3) CHECK(sv[std::string("colour.") + "rgb"[c]] == at);   // three attributes are the pixel's colour
      }
      CHECK(g.take(GeoKind::pixel).values == std::vector<Rational>{px.x, px.y});
      check_point(g.take(GeoKind::point2), {sx, sy});
      plotted.push_back(px);
      if (Offset) ok_rows = ok_rows && sx == px.x && sy == px.y;  // with dp0 every sample is a pixel centre
    } else if (line == "span_step") {
      sx += 1;
      const V at{sx, l.y + (sx - l.x) * (r.y - l.y) / (r.x - l.x)};
      check_vary("s", nullptr, at, {});
      check_point(g.take(GeoKind::point2), at);
    } else if (line == "done") {
      CHECK(s + 1 == t.size());
      CHECK(sv["pixels"] == Rational(static_cast<long>(plotted.size())));
      if (!(b.y < top.y)) CHECK(plotted.empty());
    } else {
      FAIL("a step on an unexpected line");
    }
    require_all_checked(sv, s);
    require_all_geometry_checked(g, s);
  }
  CHECK(ok_rows);
  CHECK(plotted == res.pixels);
  if (Offset) CHECK(plotted == want);
  if (!area) CHECK(want.empty());
}

}  // namespace

TEST_CASE("fill steps: every value a triangle-dda step records matches its closed form, with and without dp0", "[fill][replay]") {
  std::mt19937_64 rng(31);
  std::vector<Tri> tris = corner_cases();
  for (int k = 0; k < 60; ++k) tris.push_back(random_tri(rng, k % 2 ? 4 : 1));
  for (const Tri& tri : tris) {
    INFO("triangle " << tri[0].x << "," << tri[0].y << " " << tri[1].x << "," << tri[1].y << " " << tri[2].x << "," << tri[2].y);
    std::vector<std::array<Rational, 3>> attrs(2), rgb(3);
    for (auto& a : attrs)
      for (auto& x : a) x = grid_coord(rng, -4, 4, 8);
    for (auto& a : rgb)
      for (auto& x : a) x = grid_coord(rng, 0, 1, 16);
    check_dda<true>(tri, attrs);
    check_dda<true>(tri, rgb);
    check_dda<true>(tri, {});
    check_dda<false>(tri, attrs);
  }
}

TEST_CASE("fill steps: every value a triangle-edge step records matches its closed form", "[fill][replay]") {
  using L = fill::TriangleEdge;
  std::mt19937_64 rng(32);
  std::vector<Tri> tris = corner_cases();
  for (int k = 0; k < 60; ++k) tris.push_back(random_tri(rng, k % 2 ? 4 : 1));
  for (const Tri& tri : tris) {
    INFO("triangle " << tri[0].x << "," << tri[0].y << " " << tri[1].x << "," << tri[1].y << " " << tri[2].x << "," << tri[2].y);
    Recorder<Rational> t;
    std::vector<Pixel> out;
    fill::triangle_edge<Rational>({tri, Rational(1)}, out, t);
    const Rational area2 = E(tri[0], tri[1], tri[2]);
    Tri ccw = tri;
    if (area2 < 0) std::swap(ccw[1], ccw[2]);
    const auto want = oracle::triangle_samples(tri);
    std::int64_t i0 = 0, j0 = 0, i1 = -1, j1 = -1, i = 0, j = 0;
    int k_edges = 0, k_ties = 0;
    std::vector<Pixel> plotted;
    for (std::size_t s = 0; s < t.size(); ++s) {
      const std::string_view line = L::lines[t.at(s).line - 1].name;
      INFO("step " << s << " line " << line);
      StepValues sv = values_of(t, s);
      StepGeometry g = geometry_of(t, s);
      auto check_E = [&](const V& at) {
        for (int k = 0; k < 3; ++k) CHECK(sv["E" + std::to_string(k)] == E(ccw[k], ccw[(k + 1) % 3], at));
      };
      if (line == "orient") {
        CHECK(sv["area2"] == area2);
        CHECK(sv["swapped"] == (area2 < 0));
        check_polygon(g.take(GeoKind::polygon), {ccw[0], ccw[1], ccw[2]});
      } else if (line == "edges") {
        const int k = k_edges++;
        const V &p = ccw[k], &q = ccw[(k + 1) % 3];
        CHECK(sv["k"] == k);
        CHECK(sv["dE_di"] == -(q.y - p.y));
        CHECK(sv["dE_dj"] == q.x - p.x);
        GeoItem& e = g.take(GeoKind::segment2);
        check_segment(e, p, q);
        CHECK(e.label == "E" + std::to_string(k));
      } else if (line == "ties") {
        const int k = k_ties++;
        const V &p = ccw[k], &q = ccw[(k + 1) % 3];
        CHECK(sv["k"] == k);
        CHECK(sv["on_edge_inside"] == (q.y < p.y || (q.y == p.y && q.x > p.x)));
      } else if (line == "box") {
        i0 = num::ceil_int(std::min({tri[0].x, tri[1].x, tri[2].x})), i1 = num::floor_int(std::max({tri[0].x, tri[1].x, tri[2].x}));
        j0 = num::ceil_int(std::min({tri[0].y, tri[1].y, tri[2].y})), j1 = num::floor_int(std::max({tri[0].y, tri[1].y, tri[2].y}));
        CHECK(sv["i0"] == i0);
        CHECK(sv["i1"] == i1);
        CHECK(sv["j0"] == j0);
        CHECK(sv["j1"] == j1);
        j = j0 - 1;
      } else if (line == "row_start") {
        ++j, i = i0;
        CHECK(j <= j1);
        CHECK(sv["j"] == j);
        check_E({Rational(i0), Rational(j)});
      } else if (line == "test") {
        CHECK(i <= i1);
        CHECK(sv["i"] == i);
        CHECK(sv["j"] == j);
        check_E({Rational(i), Rational(j)});
        const bool in = covered(want, {i, j});
        CHECK(sv["inside"] == in);
        CHECK((t.at(s).kind == StepKind::plot) == in);
        if (in) {
          CHECK(g.take(GeoKind::pixel).values == std::vector<Rational>{i, j});
          plotted.push_back({i, j});
        }
      } else if (line == "step") {
        ++i;
        check_E({Rational(i), Rational(j)});
      } else if (line == "done") {
        CHECK(s + 1 == t.size());
        CHECK(sv["pixels"] == Rational(static_cast<long>(want.size())));
        if (area2 != 0) CHECK(j == j1);
      } else {
        FAIL("a step on an unexpected line");
      }
      require_all_checked(sv, s);
      require_all_geometry_checked(g, s);
    }
    CHECK(plotted == want);
    CHECK(out == want);
    CHECK(k_edges == (area2 != 0 ? 3 : 0));
  }
}

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
  for (const auto& [rings, rule] : cases) {
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
    for (std::size_t s = 0; s < t.size(); ++s) {
      const std::string_view line = L::lines[t.at(s).line - 1].name;
      INFO("step " << s << " line " << line);
      StepValues sv = values_of(t, s);
      StepGeometry g = geometry_of(t, s);
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
      require_all_checked(sv, s);
      require_all_geometry_checked(g, s);
    }
    CHECK(plotted == want);
    CHECK(out == want);
    CHECK(next_edge == edges.size());
  }
}
