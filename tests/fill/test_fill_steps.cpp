// The triangle fills (triangle-dda with and without dp0, triangle-edge): every value and geometry
// item of every exact step against a closed form written from the semantics: edge crossings
// X(p0, p1, y), edge functions E(p, q, s), the plane through the attributes and the oracle's
// covered set. scanline-polygon's steps: test_scanline_steps.cpp.
#include <catch2/catch.hpp>
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
  for_each_step<L>(t, [&](std::size_t s, std::string_view line, StepValues& sv, StepGeometry& g) {
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
      check_edge_start(g, e0, e1, label, {X(e0, e1, y), y});
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
  });
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
    for_each_step<L>(t, [&](std::size_t s, std::string_view line, StepValues& sv, StepGeometry& g) {
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
    });
    CHECK(plotted == want);
    CHECK(out == want);
    CHECK(k_edges == (area2 != 0 ? 3 : 0));
  }
}
