// perspective-interp and affine-interp: every value and geometry item of every exact step against a
// closed form written from the semantics (docs/fill/interpolation.md): the clipped corners from the
// oracle's own clipping, edge crossings X(p0, p1, y), the linear functions h on screen, the plane
// through the projected corners' h at each sample, and the oracle's values per pixel.
#include <catch2/catch.hpp>
#include <cmath>
#include "fill/interp_run.hpp"
#include "fill_oracle.hpp"
#include "fill/fill_steps.hpp"

using namespace sw;
using namespace sw::testing;

namespace {

using namespace sw::testing::fill_steps;
using H = std::vector<Rational>;
// The linear function with values h0 at y0 and h1 at y1, at y (componentwise).
H lerp_y(const H& h0, const H& h1, const Rational& y0, const Rational& y1, const Rational& y) {
  H r;
  for (std::size_t c = 0; c < h0.size(); ++c) r.push_back(h0[c] + (y - y0) / (y1 - y0) * (h1[c] - h0[c]));
  return r;
}
H slope(const H& h0, const H& h1, const Rational& d) {
  H r;
  for (std::size_t c = 0; c < h0.size(); ++c) r.push_back((h1[c] - h0[c]) / d);
  return r;
}
void check_list(StepValues& sv, const std::string& name, const H& want) {
  CHECK(sv[name + ".size"] == Rational(static_cast<long>(want.size())));
  for (std::size_t c = 0; c < want.size(); ++c) CHECK(sv[name + "[" + std::to_string(c) + "]"] == want[c]);
}
void check_vec(StepValues& sv, const std::string& name, const V& p) {
  CHECK(sv[name + ".x"] == p.x);
  CHECK(sv[name + ".y"] == p.y);
}

template <bool Persp> void check_steps(const ClipTri& tri) {
  using L = std::conditional_t<Persp, fill::PerspectiveInterp, fill::AffineInterp>;
  Recorder<Rational> t;
  const auto res = run_interp<Persp, Rational>(tri, t);
  const std::size_t n = tri.attrs[0].size();
  const Rational wn(fill::kWNear);
  const oracle::ClippedPolygon poly = oracle::clip_w(tri.v, tri.attrs, wn);
  const std::vector<V> screen = oracle::project(poly.corners);  // every kept corner has w >= 1
  const oracle::InterpSamples want = interp_oracle<Persp>(tri);
  // h at each kept corner: a/w and 1/w, or a.
  auto h_of = [&](std::size_t k) {
    H h;
    for (std::size_t c = 0; c < n; ++c) h.push_back(Persp ? poly.attrs[k][c] / poly.corners[k][3] : poly.attrs[k][c]);
    if (Persp) h.push_back(1 / poly.corners[k][3]);
    return h;
  };
  std::size_t edge = 0, kept = 0, tri_index = 0;
  std::array<V, 3> sp;  // the current fan triangle's corners, sorted by y
  std::array<H, 3> sh;
  std::array<V, 3> fan;
  std::array<H, 3> fan_h;
  Rational yc, ys;
  V p0, p1;
  H h0, h1;
  V l, r;
  H hl, hr;
  Rational sx;
  std::vector<Pixel> plotted;
  for_each_step<L>(t, [&](std::size_t s, std::string_view line, StepValues& sv, StepGeometry& g) {
    auto corner = [&](std::size_t k) {
      CHECK(sv["k"] == Rational(static_cast<long>(k)));
      check_list(sv, "c", H(poly.corners[k].begin(), poly.corners[k].end()));
      check_list(sv, "c_attrs", poly.attrs[k]);
      GeoItem& p = g.take(GeoKind::point2);
      CHECK(p.values == std::vector<Rational>{poly.corners[k][0] / poly.corners[k][3], poly.corners[k][1] / poly.corners[k][3]});
      CHECK(p.label == "c");
      CHECK(p.life == "keep");
    };
    auto edge_start = [&](const V& e0, const V& e1, const H& g0, const H& g1, const char* label) {
      const Rational y = ceil_q(e0.y);
      check_vec(sv, "q", {X(e0, e1, y), y});
      check_list(sv, "q_h", lerp_y(g0, g1, e0.y, e1.y, y));
      check_vec(sv, "dq", {(e1.x - e0.x) / (e1.y - e0.y), 1});
      check_list(sv, "dq_h", slope(g0, g1, e1.y - e0.y));
      GeoItem& seg = g.take(GeoKind::segment2);
      CHECK(seg.values == std::vector<Rational>{e0.x, e0.y, e1.x, e1.y});
      CHECK(seg.label == label);
      GeoItem& q = g.take(GeoKind::point2);
      CHECK(q.values == std::vector<Rational>{X(e0, e1, y), y});
      CHECK(q.label == "q");
    };
    if (line == "clip_edge") {
      const auto &P = tri.v[edge], &Q = tri.v[(edge + 1) % 3];
      const Rational dp = P[3] - wn, dq = Q[3] - wn;
      CHECK(sv["P"] == Rational(static_cast<long>(edge)));
      CHECK(sv["d_P"] == dp);
      CHECK(sv["d_Q"] == dq);
      CHECK(sv["keep"] == (dp >= 0));
      CHECK(sv["cut"] == (dp * dq < 0));
      ++edge;
    } else if (line == "clip_keep") {
      REQUIRE(kept < poly.corners.size());
      CHECK(poly.corners[kept] == tri.v[edge - 1]);
      corner(kept++);
    } else if (line == "clip_cut") {
      const auto &P = tri.v[edge - 1], &Q = tri.v[edge % 3];
      CHECK(sv["t"] == (P[3] - wn) / (P[3] - Q[3]));
      REQUIRE(kept < poly.corners.size());
      CHECK(poly.corners[kept][3] == wn);
      corner(kept++);
    } else if (line == "fan") {
      CHECK(kept == poly.corners.size());
      CHECK(sv["corners"] == Rational(static_cast<long>(poly.corners.size())));
      std::vector<Rational> ring;
      for (const V& p : screen) ring.push_back(p.x), ring.push_back(p.y);
      GeoItem& pg = g.take(GeoKind::polygon);
      CHECK(pg.values == ring);
      CHECK(pg.life == "keep");
    } else if (line == "project") {
      CHECK(sv["triangle"] == Rational(static_cast<long>(tri_index)));
      const std::array<std::size_t, 3> idx{0, tri_index + 1, tri_index + 2};
      for (int k = 0; k < 3; ++k) {
        fan[k] = screen[idx[k]], fan_h[k] = h_of(idx[k]);
        check_vec(sv, "s" + std::to_string(k), fan[k]);
        check_list(sv, "h" + std::to_string(k), fan_h[k]);
      }
      ++tri_index;
    } else if (line == "sort") {
      std::array<int, 3> order{0, 1, 2};
      std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return fan[a].y < fan[b].y; });
      for (int k = 0; k < 3; ++k) sp[k] = fan[order[k]], sh[k] = fan_h[order[k]];
      check_vec(sv, "b", sp[0]);
      check_vec(sv, "m", sp[1]);
      check_vec(sv, "t", sp[2]);
      CHECK(g.take(GeoKind::polygon).values == std::vector<Rational>{sp[0].x, sp[0].y, sp[1].x, sp[1].y, sp[2].x, sp[2].y});
      yc = ceil_q(sp[0].y);
    } else if (line == "long_edge") {
      edge_start(sp[0], sp[2], sh[0], sh[2], "c");
    } else if (line == "lower_edge" || line == "upper_edge") {
      const int a = line == "lower_edge" ? 0 : 1;
      p0 = sp[a], p1 = sp[a + 1], h0 = sh[a], h1 = sh[a + 1];
      if (p0.y == p1.y) {
        CHECK(sv["flat"] == 1);
      } else {
        edge_start(p0, p1, h0, h1, a == 0 ? "a" : "e");
        ys = ceil_q(p0.y);
      }
    } else if (line == "lower_span" || line == "upper_span") {
      const V qs{X(p0, p1, ys), ys}, qc{X(sp[0], sp[2], yc), yc};
      check_vec(sv, line == "lower_span" ? "q_a" : "q_e", qs);
      check_vec(sv, "q_c", qc);
      CHECK(ys < p1.y);
      GeoItem& row = g.take(GeoKind::segment2);
      CHECK(row.values == std::vector<Rational>{qs.x, qs.y, qc.x, qc.y});
      CHECK(row.label == "row");
      l = qs, r = qc, hl = lerp_y(h0, h1, p0.y, p1.y, ys), hr = lerp_y(sh[0], sh[2], sp[0].y, sp[2].y, yc);
      if (r.x < l.x) std::swap(l, r), std::swap(hl, hr);
    } else if (line == "lower_step" || line == "upper_step") {
      ys += 1, yc += 1;
      check_vec(sv, line == "lower_step" ? "q_a" : "q_e", {X(p0, p1, ys), ys});
      check_vec(sv, "q_c", {X(sp[0], sp[2], yc), yc});
    } else if (line == "span_start") {
      CHECK(sv["l_x"] == l.x);
      CHECK(sv["r_x"] == r.x);
      CHECK(sv["empty"] == (l.x < r.x ? 0 : 1));
      if (l.x < r.x) {
        sx = ceil_q(l.x);
        check_vec(sv, "s", {sx, l.y});
        check_list(sv, "ds_h", slope(hl, hr, r.x - l.x));
        GeoItem& span = g.take(GeoKind::segment2);
        CHECK(span.values == std::vector<Rational>{l.x, l.y, r.x, r.y});
        CHECK(span.label == "span");
      }
    } else if (line == "plot") {
      const Pixel px{num::floor_int(sx), num::floor_int(l.y)};
      CHECK(sx < r.x);
      CHECK(sv["i"] == px.x);
      CHECK(sv["j"] == px.y);
      // h at the sample: the plane through the fan triangle's corners' h.
      H h;
      const std::array<V, 3> ft{fan[0], fan[1], fan[2]};
      for (std::size_t c = 0; c < fan_h[0].size(); ++c) h.push_back(oracle::linear_at(ft, {fan_h[0][c], fan_h[1][c], fan_h[2][c]}, px));
      check_list(sv, "h", h);
      H a;
      for (std::size_t c = 0; c < n; ++c) a.push_back(Persp ? h[c] / h[n] : h[c]);
      check_list(sv, "values", a);
      // The attributes the oracle states for this sample.
      const auto at = std::lower_bound(want.pixels.begin(), want.pixels.end(), px, [](Pixel p, Pixel q) { return std::pair(p.y, p.x) < std::pair(q.y, q.x); });
      REQUIRE(at != want.pixels.end());
      REQUIRE(*at == px);
      const std::size_t k = static_cast<std::size_t>(at - want.pixels.begin());
      CHECK(a == H(want.values.begin() + k * n, want.values.begin() + (k + 1) * n));
      const double sum = std::floor(a[0].get_d()) + (n > 1 ? std::floor(a[1].get_d()) : 0.0);
      const bool light = std::fmod(std::fabs(sum), 2.0) == 0;
      CHECK(sv["texel.r"] == (light ? ratio(7, 8) : ratio(1, 4)));
      CHECK(sv["texel.g"] == (light ? ratio(7, 8) : ratio(3, 8)));
      CHECK(sv["texel.b"] == (light ? ratio(3, 4) : ratio(5, 8)));
      CHECK(g.take(GeoKind::pixel).values == std::vector<Rational>{px.x, px.y});
      CHECK(g.take(GeoKind::point2).values == std::vector<Rational>{sx, l.y});
      plotted.push_back(px);
    } else if (line == "span_step") {
      sx += 1;
      check_vec(sv, "s", {sx, l.y});
      CHECK(g.take(GeoKind::point2).values == std::vector<Rational>{sx, l.y});
    } else if (line == "done") {
      CHECK(s + 1 == t.size());
      CHECK(sv["pixels"] == Rational(static_cast<long>(plotted.size())));
    } else {
      FAIL("a step on an unexpected line");
    }
  });
  CHECK(edge == 3);
  CHECK(tri_index == (poly.corners.size() >= 3 ? poly.corners.size() - 2 : 0));
  std::sort(plotted.begin(), plotted.end(), [](Pixel p, Pixel q) { return std::pair(p.y, p.x) < std::pair(q.y, q.x); });
  CHECK(plotted == want.pixels);
  CHECK(res.pixels == want.pixels);
}

}  // namespace

TEST_CASE("interp steps: every value a perspective-interp or affine-interp step records matches its closed form", "[fill][interp][replay]") {
  std::mt19937_64 rng(43);
  std::vector<ClipTri> tris;
  auto hand = [&](std::array<oracle::ClipPoint, 3> v) {
    ClipTri t;
    t.v = v;
    t.attrs = {H{0, 1}, {1, 0}, {ratio(1, 2), 2}};
    tris.push_back(t);
  };
  hand({oracle::ClipPoint{-24, -16, 0, 2}, {24, -16, 0, 2}, {0, -4, -1, ratio(-1, 2)}});  // one behind
  hand({oracle::ClipPoint{-12, -8, 0, 4}, {24, -16, 0, -1}, {0, 16, 0, -2}});             // two behind
  hand({oracle::ClipPoint{0, 0, 0, -1}, {8, 0, 0, -2}, {0, 8, 0, -1}});                   // all behind
  hand({oracle::ClipPoint{0, 0, 0, 1}, {8, 0, 0, 1}, {0, 16, 0, 2}});                     // an edge on the plane
  hand({oracle::ClipPoint{0, 0, 0, 1}, {8, 0, 0, -1}, {0, 8, 0, -1}});                    // a vertex on the plane
  hand({oracle::ClipPoint{-8, -8, 0, 2}, {8, -8, 0, 2}, {0, 8, 0, 0}});                   // w = 0 at a vertex
  for (int k = 0; k < 80; ++k) tris.push_back(random_clip_tri(rng, 1 + k % 3));
  for (const ClipTri& tri : tris) {
    INFO("triangle " << tri.v[0][0] << "," << tri.v[0][1] << "," << tri.v[0][3] << " " << tri.v[1][0] << "," << tri.v[1][1] << "," << tri.v[1][3] << " "
                     << tri.v[2][0] << "," << tri.v[2][1] << "," << tri.v[2][3]);
    check_steps<true>(tri);
    check_steps<false>(tri);
  }
}
