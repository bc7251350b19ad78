// raster-clip: every value and geometry item of every exact step against a closed form written from
// the semantics: the edges' crossings X(p0, p1, y) at the rows on screen, first(v, lo, hi) =
// min(max(ceil v, lo), hi) for the first row and column on screen, the plane through the
// attributes, and the oracle's covered set on the screen. The rows visited are exactly the
// triangle's rows on the screen.
#include <catch2/catch.hpp>
#include <set>
#include "fill/raster_clip_run.hpp"
#include "fill_oracle.hpp"
#include "fill_raster_oracle.hpp"
#include "fill/fill_steps.hpp"

using namespace sw;
using namespace sw::testing;

namespace {

using namespace sw::testing::fill_steps;
// The crossing of the line through p0, p1 (p0.y != p1.y) with the row y.
std::int64_t first(const Rational& v, std::int64_t lo, std::int64_t hi) { return std::min(std::max(num::ceil_int(v), lo), hi); }

void check_clip(const Tri& tri, const fill::Screen& sc, const std::vector<std::array<Rational, 3>>& attrs) {
  using L = fill::RasterClip;
  Recorder<Rational> t;
  fill::Triangle<Rational> v;
  for (int k = 0; k < 3; ++k) {
    v[k].p = tri[k];
    v[k].n = attrs.size();
    for (std::size_t c = 0; c < attrs.size(); ++c) v[k].a[c] = attrs[c][k];
  }
  fill::FillResult<Rational> res;
  fill::raster_clip<Rational>(v, sc, res, t);
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return tri[a].y < tri[b].y; });
  const V b = tri[order[0]], m = tri[order[1]], top = tri[order[2]];
  const std::size_t n = attrs.size();
  auto vertex_attr = [&](const V& p, std::size_t c) -> Rational {
    for (int k = 0; k < 3; ++k)
      if (tri[order[k]] == p) return attrs[c][order[k]];
    FAIL("not a vertex");
    return Rational(0);
  };
  // Attribute c along the edge p0 -> p1 at row y.
  auto edge_attr = [&](const V& p0, const V& p1, const Rational& y, std::size_t c) -> Rational {
    return vertex_attr(p0, c) + (y - p0.y) / (p1.y - p0.y) * (vertex_attr(p1, c) - vertex_attr(p0, c));
  };
  const auto want = oracle::triangle_samples_in_window(tri, {sc.i0, sc.j0, sc.i1, sc.j1});
  V p0, p1;                   // the current short edge
  V l, r;                     // the current span's ends (l_x <= r_x), on row j
  std::vector<Rational> la(n), ra(n);
  std::int64_t j = 0, i = 0;  // the walk's row and column, followed from the listing's order
  std::set<std::int64_t> rows;
  std::vector<Pixel> plotted;
  for_each_step<L>(t, [&](std::size_t s, std::string_view line, StepValues& sv, StepGeometry& g) {
    auto check_vec = [&](const std::string& q, const V& at) {
      CHECK(sv[q + ".x"] == at.x);
      CHECK(sv[q + ".y"] == at.y);
    };
    auto check_list = [&](const std::string& q, const std::vector<Rational>& want_list) {
      CHECK(sv[q + ".size"] == Rational(static_cast<long>(want_list.size())));
      for (std::size_t c = 0; c < want_list.size(); ++c) CHECK(sv[q + "[" + std::to_string(c) + "]"] == want_list[c]);
    };
    auto edge_start = [&](const V& e0, const V& e1, const char* label) {
      j = first(e0.y, sc.j0, sc.j1);  // dp0 to the first row on screen
      CHECK(sv["j"] == j);
      std::vector<Rational> qa(n), da(n);
      for (std::size_t c = 0; c < n; ++c) qa[c] = edge_attr(e0, e1, Rational(j), c), da[c] = (vertex_attr(e1, c) - vertex_attr(e0, c)) / (e1.y - e0.y);
      check_vec("q", {X(e0, e1, j), j});
      check_list("q_attrs", qa);
      check_vec("dq", {(e1.x - e0.x) / (e1.y - e0.y), 1});
      check_list("dq_attrs", da);
      check_edge_start(g, e0, e1, label, {X(e0, e1, j), j});
    };
    if (line == "sort") {
      check_vec("b", b);
      check_vec("m", m);
      check_vec("t", top);
      GeoItem& poly = g.take(GeoKind::polygon);
      CHECK(poly.values == std::vector<Rational>{b.x, b.y, m.x, m.y, top.x, top.y});
      CHECK(poly.life == "keep");
    } else if (line == "screen") {
      CHECK(sv["i0"] == sc.i0);
      CHECK(sv["j0"] == sc.j0);
      CHECK(sv["i1"] == sc.i1);
      CHECK(sv["j1"] == sc.j1);
      GeoItem& rect = g.take(GeoKind::rect);
      const Rational h(1, 2);
      CHECK(rect.values == std::vector<Rational>{sc.i0 - h, sc.j0 - h, sc.i1 - h, sc.j1 - h});
      CHECK(rect.label == "screen");
      CHECK(rect.life == "keep");
    } else if (line == "long_edge") {
      CHECK(b.y < top.y);
      edge_start(b, top, "c");
    } else if (line == "lower_edge" || line == "upper_edge") {
      p0 = line == "lower_edge" ? b : m;
      p1 = line == "lower_edge" ? m : top;
      if (p0.y == p1.y) {
        CHECK(sv["flat"] == 1);
      } else {
        // The upper half starts on the row the lower half stopped at: first(m_y, j0, j1).
        const std::int64_t walked = j;
        edge_start(p0, p1, line == "lower_edge" ? "a" : "e");
        CHECK(j == walked);
      }
    } else if (line == "lower_span" || line == "upper_span") {
      const char* qn = line == "lower_span" ? "q_a" : "q_e";
      CHECK(sv["j"] == j);
      const V qs{X(p0, p1, j), j}, qc{X(b, top, j), j};
      check_vec(qn, qs);
      check_vec("q_c", qc);
      CHECK((sc.j0 <= j && j < sc.j1 && p0.y <= j && j < p1.y));  // a row of the half, on screen
      CHECK(rows.insert(j).second);
      GeoItem& row = g.take(GeoKind::segment2);
      check_segment(row, qs, qc);
      CHECK(row.label == "row");
      l = qs, r = qc;
      for (std::size_t c = 0; c < n; ++c) la[c] = edge_attr(p0, p1, Rational(j), c), ra[c] = edge_attr(b, top, Rational(j), c);
      if (r.x < l.x) std::swap(l, r), std::swap(la, ra);
    } else if (line == "lower_step" || line == "upper_step") {
      ++j;
      CHECK(sv["j"] == j);
      check_vec(line == "lower_step" ? "q_a" : "q_e", {X(p0, p1, j), j});
      check_vec("q_c", {X(b, top, j), j});
    } else if (line == "span_start") {
      CHECK(sv["l_x"] == l.x);
      CHECK(sv["r_x"] == r.x);
      CHECK(sv["empty"] == (l.x < r.x ? 0 : 1));
      if (l.x < r.x) {
        i = first(l.x, sc.i0, sc.i1);  // dp0 to the first column on screen
        CHECK(sv["i"] == i);
        check_vec("s", {i, j});
        std::vector<Rational> da(n);
        for (std::size_t c = 0; c < n; ++c) da[c] = (ra[c] - la[c]) / (r.x - l.x);
        check_list("ds_attrs", da);
        GeoItem& span = g.take(GeoKind::segment2);
        check_segment(span, l, r);
        CHECK(span.label == "span");
      }
    } else if (line == "plot") {
      CHECK(sv["i"] == i);
      CHECK(sv["j"] == j);
      CHECK((sc.i0 <= i && i < sc.i1 && l.x <= i && i < r.x));  // a sample of the span, on screen
      std::vector<Rational> at(n);
      for (std::size_t c = 0; c < n; ++c) {
        at[c] = la[c] + (i - l.x) / (r.x - l.x) * (ra[c] - la[c]);
        CHECK(at[c] == oracle::linear_at(tri, attrs[c], {i, j}));  // the plane through the attributes, at the sample
      }
      check_list("values", at);
      if (n == 3) {  // three attributes are also the pixel's colour
        CHECK(sv["colour.r"] == at[0]);
        CHECK(sv["colour.g"] == at[1]);
        CHECK(sv["colour.b"] == at[2]);
      }
      CHECK(g.take(GeoKind::pixel).values == std::vector<Rational>{i, j});
      GeoItem& sp = g.take(GeoKind::point2);
      check_point(sp, {i, j});
      CHECK(sp.label == "s");
      plotted.push_back({i, j});
    } else if (line == "span_step") {
      ++i;
      CHECK(sv["i"] == i);
      check_vec("s", {i, j});
      GeoItem& sp = g.take(GeoKind::point2);
      check_point(sp, {i, j});
      CHECK(sp.label == "s");
    } else if (line == "done") {
      CHECK(s + 1 == t.size());
      CHECK(sv["pixels"] == Rational(static_cast<long>(plotted.size())));
    } else {
      FAIL("a step on an unexpected line");
    }
  });
  // The rows walked are exactly the triangle's rows on the screen: [max(ceil b_y, j0), min(ceil t_y, j1)).
  std::set<std::int64_t> want_rows;
  if (b.y < top.y)
    for (std::int64_t y = std::max(num::ceil_int(b.y), sc.j0); y < std::min(num::ceil_int(top.y), sc.j1); ++y) want_rows.insert(y);
  CHECK(rows == want_rows);
  CHECK(plotted == res.pixels);
  CHECK(plotted == want);
}

// Hand-picked triangles, each against screens cutting it in different ways.
std::vector<Tri> corner_cases() {
  return {{V{0, 0}, {6, 0}, {2, 5}}, {V{0, 5}, {6, 5}, {2, 0}}, {V{1, 1}, {5, 3}, {3, 7}}, {V{0, 0}, {2, 2}, {5, 5}},
          {V{Rational(1, 4), 0}, {Rational(3, 4), 9}, {Rational(1, 2), 10}}, {V{Rational(3, 2), Rational(3, 4)}, {Rational(49, 4), Rational(9, 2)}, {5, Rational(21, 2)}},
          {V{-1000000, -1000000}, {1000001, -1000000}, {-1000000, 1000001}}, {V{-999999, Rational(1, 3)}, {1000000, Rational(5, 2)}, {3, 4000000}}};
}

}  // namespace

TEST_CASE("raster-clip steps: every value each exact step records matches its closed form, rows and columns start on the screen and stop at its edge", "[fill][raster-clip][replay]") {
  std::mt19937_64 rng(41);
  const std::vector<fill::Screen> screens{{0, 0, 4, 4}, {2, 1, 5, 3}, {-3, -2, 8, 9}, {1, 1, 2, 2}, {-20, -20, -10, -10}, {3, 0, 7, 12}};
  std::vector<std::pair<Tri, fill::Screen>> cases;
  for (const Tri& t : corner_cases())
    for (const fill::Screen& s : screens) cases.push_back({t, s});
  for (int k = 0; k < 60; ++k) {
    const fill::Screen s{std::uniform_int_distribution<long>(-6, 2)(rng), std::uniform_int_distribution<long>(-6, 2)(rng), std::uniform_int_distribution<long>(3, 8)(rng), std::uniform_int_distribution<long>(3, 8)(rng)};
    Tri t;
    if (k % 3 == 2) t = huge_crossing(rng, s, k % 2 ? 1000000 : 1000, 4);
    else for (auto& v : t) v = {grid_coord(rng, -9, 9, k % 2 ? 4 : 1), grid_coord(rng, -9, 9, k % 2 ? 4 : 1)};
    cases.push_back({t, s});
  }
  for (const auto& [tri, s] : cases) {
    INFO("triangle " << tri[0].x << "," << tri[0].y << " " << tri[1].x << "," << tri[1].y << " " << tri[2].x << "," << tri[2].y << " screen " << s.i0 << "," << s.j0 << " " << s.i1 << "," << s.j1);
    std::vector<std::array<Rational, 3>> attrs(2), rgb(3);
    for (auto* list : {&attrs, &rgb})
      for (auto& a : *list)
        for (auto& x : a) x = grid_coord(rng, -4, 4, 8);
    check_clip(tri, s, attrs);
    check_clip(tri, s, rgb);
    check_clip(tri, s, {});
  }
}
