// depth-sort: the painter's image against the brute-force visible surface (every triangle at every
// sample, exact depth) and against the exact z-buffer, on the example, the corpus and seeded
// scenes that penetrate and overlap in cycles; every paint step against closed forms, so the
// pieces of each split triangle cover its samples exactly once, farthest first.
#include <catch2/catch.hpp>
#include <map>
#include <set>
#include <random>
#include "catalog.hpp"
#include "corpus.hpp"
#include "fill_oracle.hpp"
#include "pipeline/depth_sort.hpp"
#include "pipeline/z_buffer.hpp"
#include "pipeline_oracle.hpp"
#include "pipeline_test_support.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::pipeline;

namespace depth_sort_test {

struct Scene {
  std::int64_t w = 0, h = 0;
  std::vector<po::DepthTriangle> tris;
};

Scene scene_of(const Json& j) { return {j["size"][0].get<std::int64_t>(), j["size"][1].get<std::int64_t>(), window_triangles_of(j)}; }

Json json_of(const Scene& s) {
  Json tris = Json::array();
  for (const auto& t : s.tris) {
    Json v = Json::array();
    for (const auto& p : t.v) v.push_back({p[0].get_str(), p[1].get_str(), p[2].get_str()});
    tris.push_back({{"v", v}, {"id", t.id}});
  }
  return {{"size", {s.w, s.h}}, {"triangles", tris}};
}

// Seeded scenes on a 1/16 grid over a 40 x 32 window: random triangles; pairs crossing in depth;
// pinwheels of three sticks, each over the next (a cycle); stacks of coplanar triangles (ties).
po::DepthTriangle tri(const std::array<V3, 3>& v, std::int64_t id) { return {v, id, 0, 0}; }

std::vector<Json> scenes() {
  std::vector<Json> out{Json::parse(find_algorithm("depth-sort").example)};
  for (Json j : corpus("pipeline")) {
    // The z-buffer's and depth-sort's cases, without the z-buffer's depth settings and offsets.
    if (!j.contains("triangles") || !j.contains("size") || j.contains("background") || j["triangles"].size() > 64) continue;
    bool plain = true;
    for (const Json& t : j["triangles"]) plain = plain && !t.contains("offset") && !t.contains("rgb");
    if (!plain) continue;
    j.erase("depth_bits"), j.erase("depth_func"), j.erase("clear_depth");
    out.push_back(j);
  }
  std::mt19937_64 rng(32);
  auto r = [&](int lo, int hi) { return Rational(std::uniform_int_distribution<int>(lo * 16, hi * 16)(rng), 16); };
  auto z = [&] { return Rational(std::uniform_int_distribution<int>(1, 255)(rng), 256); };
  for (int k = 0; k < 24; ++k) {
    Scene s{40, 32, {}};
    const int kind = k % 4;
    if (kind == 0)
      for (int i = 0; i < 8; ++i) s.tris.push_back(tri({{{r(-4, 44), r(-4, 36), z()}, {r(-4, 44), r(-4, 36), z()}, {r(-4, 44), r(-4, 36), z()}}}, i));
    if (kind == 1)
      for (int i = 0; i < 3; ++i) {
        const Rational y = r(0, 24), near = Rational(1, 8), far = Rational(7, 8);
        s.tris.push_back(tri({{{-2, y, far}, {42, y + r(-4, 4), near}, {20, y + 12, Rational(1, 2)}}}, 2 * i));
        s.tris.push_back(tri({{{-2, y + r(-2, 2), near}, {42, y, far}, {r(10, 30), y + 10, Rational(1, 2)}}}, 2 * i + 1));
      }
    if (kind == 2) {  // three sticks turned by a quarter-ish each, on the grid
      const std::array<std::array<int, 4>, 3> stick{{{2, 10, 38, 12}, {26, 2, 22, 30}, {36, 26, 6, 4}}};
      const Rational jitter = r(-1, 1);
      for (int i = 0; i < 3; ++i) {
        const auto& c = stick[i];
        const Rational x0 = c[0] + jitter, y0 = c[1], x1 = c[2], y1 = c[3] + jitter;
        s.tris.push_back(tri({{{x0, y0 - 2, Rational(1, 5)}, {x0, y0 + 2, Rational(1, 5)}, {x1, y1, Rational(4, 5)}}}, i));
      }
    }
    if (kind == 3)  // one plane, triangles over each other: ties everywhere they overlap
      for (int i = 0; i < 4; ++i) {
        auto at = [&](const Rational& x, const Rational& y) { return std::array<Rational, 3>{x, y, Rational(1, 4) + x / 100 + y / 200}; };
        s.tris.push_back(tri({at(r(-4, 44), r(-4, 36)), at(r(-4, 44), r(-4, 36)), at(r(-4, 44), r(-4, 36))}, i));
      }
    out.push_back(json_of(s));
  }
  // Two of sixteen large triangles, nearly every pair crossing: hundreds of cuts.
  for (int k = 0; k < 2; ++k) {
    Scene s{40, 32, {}};
    for (int i = 0; i < 16; ++i) s.tris.push_back(tri({{{r(-8, 48), r(-8, 40), z()}, {r(-8, 48), r(-8, 40), z()}, {r(-8, 48), r(-8, 40), z()}}}, i));
    out.push_back(json_of(s));
  }
  return out;
}

std::array<Vec2<Rational>, 3> flat(const po::DepthTriangle& t) {
  return {Vec2<Rational>{t.v[0][0], t.v[0][1]}, {t.v[1][0], t.v[1][1]}, {t.v[2][0], t.v[2][1]}};
}

// Depth at (x, y) on a triangle's plane, by barycentric weights (areas over the whole).
Rational depth_at(const po::DepthTriangle& t, const Rational& x, const Rational& y) {
  auto area = [](const Rational& ax, const Rational& ay, const Rational& bx, const Rational& by, const Rational& cx, const Rational& cy) {
    return Rational((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
  };
  const auto& v = t.v;
  const Rational whole = area(v[0][0], v[0][1], v[1][0], v[1][1], v[2][0], v[2][1]);
  const Rational la = area(x, y, v[1][0], v[1][1], v[2][0], v[2][1]) / whole, lb = area(v[0][0], v[0][1], x, y, v[2][0], v[2][1]) / whole;
  return la * v[0][2] + lb * v[1][2] + (1 - la - lb) * v[2][2];
}

// A polygon as a step records it (x0, y0, x1, y1, ...), with its parent's depths.
struct Poly {
  std::vector<V3> v;
};
Poly poly_of(const std::vector<Rational>& xy, const po::DepthTriangle& parent) {
  Poly p;
  for (std::size_t k = 0; k + 1 < xy.size(); k += 2) p.v.push_back({xy[k], xy[k + 1], depth_at(parent, xy[k], xy[k + 1])});
  return p;
}

// Whether some vertex of p lies strictly in front of (side -1) or behind (+1) t's plane: the sign
// of the orientation of (a, b, c, v) times that of (a, b, c) on the screen is that of z - plane.
bool some_side(const Poly& p, const po::DepthTriangle& t, int side) {
  const auto& a = t.v[0];
  const V3 ab{t.v[1][0] - a[0], t.v[1][1] - a[1], t.v[1][2] - a[2]}, ac{t.v[2][0] - a[0], t.v[2][1] - a[1], t.v[2][2] - a[2]};
  const int turn = sgn(ab[0] * ac[1] - ab[1] * ac[0]);
  for (const V3& v : p.v) {
    const V3 av{v[0] - a[0], v[1] - a[1], v[2] - a[2]};
    const Rational det = ab[0] * (ac[1] * av[2] - ac[2] * av[1]) - ab[1] * (ac[0] * av[2] - ac[2] * av[0]) + ab[2] * (ac[0] * av[1] - ac[1] * av[0]);
    if (sgn(det) * turn == side) return true;
  }
  return false;
}

// Whether the vertices of p lie strictly on both sides of the line a -> b.
bool line_crosses(const V3& a, const V3& b, const Poly& p) {
  bool left = false, right = false;
  for (const V3& v : p.v) {
    const int s = sgn((b[0] - a[0]) * (v[1] - a[1]) - (b[1] - a[1]) * (v[0] - a[0]));
    left = left || s > 0, right = right || s < 0;
  }
  return left && right;
}

// Twice the area of the part of p inside q (both convex): p clipped by each edge of q in turn.
Rational common_area(const Poly& p, const Poly& q) {
  auto cross = [](const V3& a, const V3& b, const V3& c) { return Rational((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])); };
  Rational turn = 0;
  for (std::size_t k = 1; k + 1 < q.v.size(); ++k) turn += cross(q.v[0], q.v[k], q.v[k + 1]);
  std::vector<V3> part = p.v;
  for (std::size_t e = 0; e < q.v.size() && !part.empty(); ++e) {
    const V3 &a = q.v[e], &b = q.v[(e + 1) % q.v.size()];
    std::vector<V3> kept;
    for (std::size_t k = 0; k < part.size(); ++k) {
      const V3 &u = part[k], &w = part[(k + 1) % part.size()];
      const Rational su = cross(a, b, u) * sgn(turn), sw = cross(a, b, w) * sgn(turn);
      if (sgn(su) >= 0) kept.push_back(u);
      if ((sgn(su) > 0 && sgn(sw) < 0) || (sgn(su) < 0 && sgn(sw) > 0)) {
        const Rational f = su / (su - sw);
        kept.push_back({u[0] + f * (w[0] - u[0]), u[1] + f * (w[1] - u[1]), 0});
      }
    }
    part = kept;
  }
  Rational area = 0;
  for (std::size_t k = 1; k + 1 < part.size(); ++k) area += cross(part[0], part[k], part[k + 1]);
  return abs(area);
}

// The tests stay in the namespace: the pipeline tests share a unity batch.
TEST_CASE("depth-sort: the painted image is the brute-force visible surface and the exact z-buffer's wherever one surface is nearest",
          "[pipeline][depthsort]") {
  std::int64_t splits = 0, moves = 0, ties = 0, shown = 0;
  for (const Json& j : scenes()) {
    INFO(j.dump());
    const Scene s = scene_of(j);
    const Json got = find_algorithm("depth-sort").open(j, Numeric::exact).run();
    CHECK(got["wrong"] == 0);
    CHECK(got["gave_up"] == false);
    // Brute force: GL_LESS keeps the first of the nearest, GL_LEQUAL the last; they differ where two tie.
    const auto first = po::z_buffer(s.w, s.h, s.tris, 0, false, Rational(2)), last = po::z_buffer(s.w, s.h, s.tris, 0, true, Rational(2));
    // The algorithm under test elsewhere: the exact z-buffer.
    std::vector<pipe::DepthTriangle<Rational>> tris;
    for (const auto& t : s.tris) tris.push_back({{vec(t.v[0]), vec(t.v[1]), vec(t.v[2])}, t.id, 0, 0});
    NoProbe quiet;
    const auto zb = pipe::z_buffer<Rational>(s.w, s.h, tris, 0, pipe::DepthFunc::less, Rational(2), quiet);
    const auto ids = got["ids"].get<std::vector<std::int64_t>>();
    REQUIRE(ids.size() == first.ids.size());
    for (std::size_t p = 0; p < ids.size(); ++p) {
      INFO("pixel (" << p % s.w << ", " << p / s.w << ")");
      const bool tie = first.ids[p] != last.ids[p];
      CHECK(ids[p] == (tie ? pipe::kTie : first.ids[p]));
      if (!tie) CHECK(ids[p] == zb.id[p]);
      ties += tie, shown += ids[p] >= 0;
    }
    splits += got["splits"].get<std::int64_t>(), moves += got["moves"].get<std::int64_t>();
  }
  // The scenes reach every path: splits (penetration and cycles), moves and ties.
  CHECK(splits >= 20);
  CHECK(moves >= 10);
  CHECK(ties >= 100);
  CHECK(shown >= 5000);
}

TEST_CASE("depth-sort: every step exact and a split triangle's pieces cover its samples once and farthest first",
          "[pipeline][depthsort][steps]") {
  std::int64_t painted = 0, split_steps = 0, moves = 0;
  for (const Json& j : scenes()) {
    INFO(j.dump());
    const Scene s = scene_of(j);
    std::vector<std::array<Vec3<Rational>, 3>> tris;
    std::vector<std::int64_t> ids;
    std::map<std::int64_t, const po::DepthTriangle*> by_id;
    for (const auto& t : s.tris) tris.push_back({vec(t.v[0]), vec(t.v[1]), vec(t.v[2])}), ids.push_back(t.id), by_id[t.id] = &t;
    Recorder<Rational> rec;
    const pipe::PaintedImage img = pipe::depth_sort<Rational>(s.w, s.h, tris, ids, std::int64_t(1) << 40, std::int64_t(1) << 40, rec);
    std::map<std::pair<std::int64_t, Pixel>, int> times;  // (triangle, sample): how often painted
    std::map<Pixel, Rational> depth;                      // the depth painted last at each sample
    std::int64_t P_id = -1, Q_id = -1, each_steps = 0;
    Poly P, Q;
    std::vector<Rational> Q_item;
    std::set<std::pair<std::int64_t, std::vector<Rational>>> moved;  // polygons moved to the front once
    for_each_step<pipe::DepthSort>(rec, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
      if (line == "paint") {
        const std::int64_t id = sv["id"].get_num().get_si();
        REQUIRE(by_id.count(id));
        const po::DepthTriangle& t = *by_id[id];
        const GeoItem& px = g.take(GeoKind::pixel);
        const Pixel at{px.values[0].get_num().get_si(), px.values[1].get_num().get_si()};
        CHECK(px.value == Rational(id));
        const Rational z = oracle::linear_at(flat(t), {t.v[0][2], t.v[1][2], t.v[2][2]}, at);
        CHECK(sv["z"] == z);
        const auto under = depth.find(at);
        CHECK(sv["tie"] == Rational(under != depth.end() && under->second == z));
        if (under != depth.end()) CHECK(z <= under->second);  // farthest first
        depth[at] = z;
        ++times[{id, at}], ++painted;
      } else if (line == "split") {
        ++split_steps;
        const std::int64_t cut = sv["cut"].get_num().get_si();
        CHECK(by_id.count(sv["by"].get_num().get_si()));
        REQUIRE(by_id.count(cut));
        // Both pieces lie in the triangle they were cut from.
        const auto tri = flat(*by_id[cut]);
        const int turn = sgn((tri[1].x - tri[0].x) * (tri[2].y - tri[0].y) - (tri[1].y - tri[0].y) * (tri[2].x - tri[0].x));
        for (int piece = 0; piece < 2; ++piece) {
          const GeoItem& poly = g.take(GeoKind::polygon);
          CHECK(poly.values.size() >= 6);
          Rational area = 0;  // twice the piece's signed area: a cut crosses, so neither piece is flat
          for (std::size_t k = 0; k + 1 < poly.values.size(); k += 2) {
            const std::size_t next = (k + 2) % poly.values.size();
            area += poly.values[k] * poly.values[next + 1] - poly.values[next] * poly.values[k + 1];
          }
          CHECK(sgn(area) == turn);
          for (std::size_t k = 0; k + 1 < poly.values.size(); k += 2)
            for (int e = 0; e < 3; ++e) {
              const Vec2<Rational>&a = tri[e], &b = tri[(e + 1) % 3];
              CHECK(sgn((b.x - a.x) * (poly.values[k + 1] - a.y) - (b.y - a.y) * (poly.values[k] - a.x)) * turn >= 0);
            }
        }
      } else if (line == "sort") {
        if (sv.v.count("t")) {  // an edge-on triangle, left out
          const auto tri = flat(*by_id.at(sv["t"].get_num().get_si()));
          CHECK(sv["area2"] == 0);
          CHECK(sgn((tri[1].x - tri[0].x) * (tri[2].y - tri[0].y) - (tri[1].y - tri[0].y) * (tri[2].x - tri[0].x)) == 0);
        } else {
          std::int64_t flat_ones = 0;
          for (const auto& t : s.tris) {
            const auto tri = flat(t);
            flat_ones += sgn((tri[1].x - tri[0].x) * (tri[2].y - tri[0].y) - (tri[1].y - tri[0].y) * (tri[2].x - tri[0].x)) == 0;
          }
          CHECK(sv["polygons"] == Rational(std::int64_t(s.tris.size()) - flat_ones));
        }
      } else if (line == "pick") {
        P_id = sv["P"].get_num().get_si();
        const GeoItem& outline = g.take(GeoKind::polygon);
        CHECK(outline.label == "P");
        CHECK(outline.life == "replace");  // shown while P is painted
        P = poly_of(outline.values, *by_id.at(P_id));
        CHECK(sv["vertices"] == Rational(std::int64_t(P.v.size())));
      } else if (line == "each") {
        ++each_steps;
        Q_id = sv["Q"].get_num().get_si();
        const GeoItem& outline = g.take(GeoKind::polygon);
        CHECK(outline.label == "Q");
        Q_item = outline.values;
        Q = poly_of(Q_item, *by_id.at(Q_id));
        Rational near = P.v[0][2], far = Q.v[0][2];
        for (const V3& v : P.v) near = std::min(near, v[2]);
        for (const V3& v : Q.v) far = std::max(far, v[2]);
        CHECK(sv["P.near"] == near);
        CHECK(sv["Q.far"] == far);
        CHECK(far > near);
      } else if (line == "extent") {
        bool apart = false;
        for (int a = 0; a < 2; ++a) {
          Rational plo = P.v[0][a], phi = plo, qlo = Q.v[0][a], qhi = qlo;
          for (const V3& v : P.v) plo = std::min(plo, v[a]), phi = std::max(phi, v[a]);
          for (const V3& v : Q.v) qlo = std::min(qlo, v[a]), qhi = std::max(qhi, v[a]);
          apart = apart || phi <= qlo || qhi <= plo;
        }
        CHECK(sv["apart"] == Rational(apart));
      } else if (line == "behind") {
        CHECK(sv["P.in_front"] == Rational(some_side(P, *by_id.at(Q_id), -1)));
        CHECK(sv["P.behind"] == Rational(some_side(P, *by_id.at(Q_id), 1)));
      } else if (line == "front") {
        CHECK(sv["Q.in_front"] == Rational(some_side(Q, *by_id.at(P_id), -1)));
        CHECK(sv["Q.behind"] == Rational(some_side(Q, *by_id.at(P_id), 1)));
      } else if (line == "overlap") {
        CHECK(sv["overlap"] == Rational(sgn(common_area(P, Q)) > 0));
      } else if (line == "move") {
        // Q may go first when it lies on or behind P's plane, or P on or in front of Q's.
        const bool q_first = !some_side(Q, *by_id.at(P_id), -1) || !some_side(P, *by_id.at(Q_id), 1);
        CHECK(sv["q_first"] == Rational(q_first));
        const bool before = moved.count({Q_id, Q_item}) > 0;
        CHECK(sv["moved_before"] == Rational(before));
        // A cut: a plane of the two, or an edge line of one, with the other strictly on both sides.
        const po::DepthTriangle &tp = *by_id.at(P_id), &tq = *by_id.at(Q_id);
        bool cut = (some_side(P, tq, -1) && some_side(P, tq, 1)) || (some_side(Q, tp, -1) && some_side(Q, tp, 1));
        for (int pass = 0; pass < 2; ++pass) {
          const Poly &A = pass ? Q : P, &B = pass ? P : Q;
          for (std::size_t e = 0; e < A.v.size(); ++e) cut = cut || line_crosses(A.v[e], A.v[(e + 1) % A.v.size()], B);
        }
        const bool looked = !(q_first && !before);  // the cut is sought only where it may be used
        CHECK(sv["can_cut"] == Rational(looked && cut));
        const bool move = q_first && (!before || !cut);
        CHECK(sv["move"] == Rational(move));
        if (move) moved.insert({Q_id, Q_item}), ++moves;
        if (!q_first) CHECK(cut);  // penetration: Q's plane crosses P
      } else if (line == "done") {
        CHECK(sv["painted"] == Rational(img.painted));
        CHECK(sv["splits"] == Rational(img.splits));
        CHECK(sv["tests"] == Rational(each_steps));  // one test per pair compared
        CHECK(sv["ties"] == Rational(img.ties));
      } else {
        FAIL("unexpected line " << line);
      }
    });
    // Each triangle's samples in the window, each painted exactly once.
    for (const auto& t : s.tris) {
      for (const Pixel& p : po::window_samples(t.v, s.w, s.h)) {
        INFO("triangle " << t.id << " sample (" << p.x << ", " << p.y << ")");
        CHECK(times[{t.id, p}] == 1);
        times.erase({t.id, p});
      }
    }
    CHECK(times.empty());
    CHECK(img.wrong == 0);
    CHECK_FALSE(img.gave_up);
  }
  CHECK(painted >= 5000);
  CHECK(split_steps >= 20);
  CHECK(moves >= 10);
}

TEST_CASE("depth-sort: double's splits miss the cutting plane so crossing triangles split until the bound where exact splits once",
          "[pipeline][depthsort]") {
  // Two triangles crossing like an X in depth: exact cuts one of them by the other's plane once.
  const Json x = {{"size", {32, 32}},
                  {"triangles", {{{"v", {{0, 0, "1/10"}, {31, 0, "9/10"}, {0, 31, "1/10"}}}}, {{"v", {{0, 2, "9/10"}, {31, 2, "1/10"}, {15, 31, "1/2"}}}}}}};
  const Json exact = find_algorithm("depth-sort").open(x, Numeric::exact).run();
  CHECK(exact["splits"] == 1);
  CHECK(exact["gave_up"] == false);
  // In double the cut's new vertices are rounded off the plane: each piece still crosses it.
  const Json dbl = find_algorithm("depth-sort").open(x, Numeric::f64).run();
  CHECK(dbl["gave_up"] == true);
  CHECK(dbl["splits"] == 4 * 2 * 2 + 64);  // the bound on cuts, reached
  CHECK(dbl["tests"].get<std::int64_t>() > 1000);
  CHECK(dbl["wrong"].get<std::int64_t>() > 0);
}

}  // namespace depth_sort_test
