// sutherland-hodgman against its exact oracle, compared as regions (winding numbers): the oracle's
// region from CGAL's triangle intersections of the two polygons' fans, and the subject's winding
// numbers at probe points. Every value of every exact step against a closed form of
// docs/fill/clipping.md, the corpus in every mode, float's failures, and bad input through the CLI.
#include <catch2/catch.hpp>
#include <algorithm>
#include "cli_harness.hpp"
#include "scale.hpp"
#include "clip_cases.hpp"
#include "fill/sutherland_hodgman.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing::clip;
using sw::testing::ratio;

namespace {

template <class Num> std::vector<Vec2<Num>> run(const Polygon2& subject, const Polygon2& clip) {
  std::vector<Vec2<Num>> s, c;
  for (const auto& v : subject) s.push_back(to_num<Num>(v));
  for (const auto& v : clip) c.push_back(to_num<Num>(v));
  NoProbe none;
  return fill::sutherland_hodgman<Num>(s, c, none);
}

bool on_segment(const Vec2<Q>& a, const Vec2<Q>& b, const Vec2<Q>& p) {
  return sgn(cross(a, b, p)) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}
bool on_boundary(const Polygon2& poly, const Vec2<Q>& p) {
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (on_segment(poly[i], poly[(i + 1) % poly.size()], p)) return true;
  return false;
}

// The convex hull (Andrew's monotone chain, collinear points dropped), counter-clockwise.
Polygon2 hull(Polygon2 pts) {
  std::sort(pts.begin(), pts.end(), [](const Vec2<Q>& a, const Vec2<Q>& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  Polygon2 h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && sgn(cross(h[k - 2], h[k - 1], pts[i])) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && sgn(cross(h[k - 2], h[k - 1], pts[i])) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);
  return h;
}

struct PolygonCase {
  std::string name;
  Polygon2 subject, clip;
};

PolygonCase parse_case(const Case& c) {
  PolygonCase out{c.name, points_of(c.input.at("polygon")), {}};
  if (c.input.contains("window")) {
    const Vec2<Q> lo = point_of(c.input["window"]["min"]), hi = point_of(c.input["window"]["max"]);
    out.clip = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
  } else {
    out.clip = points_of(c.input.at("clip"));
  }
  return out;
}

// Random subjects of 3 to 7 vertices anywhere (self-intersecting often) against the hull of 3 to 6
// random points, either way round, sometimes with a repeated or a collinear extra vertex. Small:
// integers on a short range; else double-exact values.
PolygonCase random_case(SmallRng& g, bool small) {
  auto pt = [&](double lo, double hi) { return small ? Vec2<Q>{Q(g.pick(std::int64_t(lo), std::int64_t(hi))), Q(g.pick(std::int64_t(lo), std::int64_t(hi)))}
                                                     : Vec2<Q>{g.dyadic(lo, hi), g.dyadic(lo, hi)}; };
  PolygonCase c{"random", {}, {}};
  const int n = int(g.pick(3, 7));
  for (int i = 0; i < n; ++i) c.subject.push_back(pt(-2, 10));
  for (int attempt = 0; attempt < 100 && c.clip.size() < 3; ++attempt) {
    Polygon2 pts;
    for (int i = int(g.pick(3, 6)); i > 0; --i) pts.push_back(pt(0, 8));
    c.clip = hull(pts);
  }
  REQUIRE(c.clip.size() >= 3);
  if (g.pick(0, 3) == 0) {
    const std::size_t at = std::size_t(g.pick(0, std::int64_t(c.clip.size()) - 1));
    const Vec2<Q> a = c.clip[at], b = c.clip[(at + 1) % c.clip.size()];
    c.clip.insert(c.clip.begin() + std::ptrdiff_t(at) + 1, g.pick(0, 1) ? a : Vec2<Q>{(a.x + b.x) / 2, (a.y + b.y) / 2});
  }
  if (g.pick(0, 1)) std::reverse(c.clip.begin(), c.clip.end());
  return c;
}

bool inside_convex(const Polygon2& clip, const Vec2<Q>& p) {
  const int o = sgn(oracle::twice_signed_area(clip));
  for (std::size_t k = 0; k < clip.size(); ++k)
    if (o * sgn(cross(clip[k], clip[(k + 1) % clip.size()], p)) < 0) return false;
  return true;
}

// The clipped region's winding numbers, point by point: the subject's inside the clip polygon, 0
// outside. Probes on any boundary are skipped. Returns how many probes were compared.
int probe_regions(SmallRng& g, const PolygonCase& c, const Polygon2& got, int probes) {
  int compared = 0;
  for (int i = 0; i < probes; ++i) {
    const Vec2<Q> p{ratio(g.pick(-2 * 97, 10 * 97), 97), ratio(g.pick(-2 * 97, 10 * 97), 97)};
    if (on_boundary(c.subject, p) || on_boundary(c.clip, p) || on_boundary(got, p)) continue;
    const std::int64_t want = inside_convex(c.clip, p) ? oracle::winding_at(c.subject, p) : 0;
    CHECK(oracle::winding_at(got, p) == want);
    ++compared;
  }
  return compared;
}

}  // namespace

TEST_CASE("fill clip: sutherland-hodgman in exact and filtered equals the oracle as a region on 10^4 random polygons", "[fill][clip]") {
  SmallRng g{std::mt19937_64(53)};
  std::size_t uncertain = 0, empty = 0, probes = 0;
  for (int i = 0; i < sw::testing::cases(10000); ++i) {
    const PolygonCase c = random_case(g, i % 2 == 0);
    INFO("case " << i);
    const Polygon2 exact = run<Q>(c.subject, c.clip);
    const Polygon2 want = oracle::clip_polygon(c.subject, c.clip);
    REQUIRE(oracle::same_region(exact, want));
    empty += exact.empty();
    if (i % 20 == 0) {  // independent of the oracle's construction: areas and winding numbers
      CHECK(oracle::twice_signed_area(exact) == oracle::twice_signed_area(want));
      probes += std::size_t(probe_regions(g, c, exact, 16));
    }
    try {
      const auto f = run<Interval>(c.subject, c.clip);
      REQUIRE(f.size() == exact.size());
      for (std::size_t k = 0; k < f.size(); ++k) {
        CHECK(within(f[k].x, exact[k].x));
        CHECK(within(f[k].y, exact[k].y));
      }
    } catch (const Uncertain&) {
      ++uncertain;  // a vertex on a clip line: the chain runs exact
    }
  }
  CHECK(empty > sw::testing::cases(100u));
  CHECK(probes > sw::testing::cases(5000u));
  CHECK(uncertain < sw::testing::cases(10000u) / 2);
  WARN("sutherland-hodgman random: " << empty << " empty, " << probes << " probe points, filtered uncertain " << uncertain);
}

TEST_CASE("fill clip: the region comparison ignores the vertex list and sees any change of region", "[fill][clip]") {
  const Polygon2 square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  // Another start, a repeated vertex, a collinear vertex, a bridge out and back: the same region.
  CHECK(oracle::same_region(square, {{4, 4}, {0, 4}, {0, 0}, {0, 0}, {2, 0}, {4, 0}}));
  CHECK(oracle::same_region(square, {{0, 0}, {4, 0}, {4, 4}, {9, 9}, {4, 4}, {0, 4}}));
  CHECK(oracle::same_region({}, {{1, 1}, {2, 2}, {3, 3}}));  // zero area
  // The other orientation, a moved vertex, and the square covered twice: different regions.
  CHECK(!oracle::same_region(square, {{0, 0}, {0, 4}, {4, 4}, {4, 0}}));
  CHECK(!oracle::same_region(square, {{0, 0}, {4, 0}, {4, ratio(41, 10)}, {0, 4}}));
  CHECK(!oracle::same_region(square, {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {4, 0}, {4, 4}, {0, 4}}));
  // The catalog's canonical form is that chain: the same for the same region.
  const Algorithm& alg = find_algorithm("sutherland-hodgman");
  CHECK(alg.canonical(Json::parse(R"({"polygon":[[0,0],[4,0],[4,4],[0,4]]})")) ==
        alg.canonical(Json::parse(R"({"polygon":[[4,4],[0,4],[0,0],["2/1",0],[4,0]],"fallback":false})")));
  CHECK(alg.canonical(Json::parse(R"({"polygon":[[0,0],[4,0],[4,4],[0,4]]})")) != alg.canonical(Json::parse(R"({"polygon":[[0,0],[4,0],[4,4]]})")));
}

TEST_CASE("fill clip: sutherland-hodgman corpus in every mode against the oracle", "[fill][clip]") {
  const Algorithm& alg = find_algorithm("sutherland-hodgman");
  std::size_t float_wrong = 0, double_wrong = 0;
  for (const Case& c : corpus_cases("sutherland-hodgman")) {
    INFO(c.name);
    const Json want = alg.canonical(alg.open(c.input).oracle());
    const Json exact = alg.open(c.input, Numeric::exact).run();
    CHECK(alg.canonical(exact) == want);
    const Json filtered = alg.open(c.input, Numeric::filtered).run();
    CHECK(filtered["polygon"].size() == exact["polygon"].size());
    if (filtered["fallback"].get<bool>()) CHECK(alg.canonical(filtered) == want);
    // Rounded modes: a decision differs when the vertex count does.
    float_wrong += alg.open(c.input, Numeric::f32).run()["polygon"].size() != exact["polygon"].size();
    double_wrong += alg.open(c.input, Numeric::f64).run()["polygon"].size() != exact["polygon"].size();
  }
  CHECK(float_wrong == 1);  // "vertex 2^-40 outside" (next test)
  CHECK(double_wrong == 0);
}

TEST_CASE("fill clip: float keeps a vertex 2^-40 outside the window and loses two crossings", "[fill][clip]") {
  // 3 - 2^-40 rounds to 3 in float: the vertex lands on y = ymin, inside the closed half-plane.
  const Algorithm& alg = find_algorithm("sutherland-hodgman");
  const Json in = Json::parse(R"({"polygon":[[2,"3298534883327/1099511627776"],[6,4],[1,4]],"window":{"min":[0,3],"max":[8,5]}})");
  CHECK(alg.open(in, Numeric::exact).run()["polygon"].size() == 4);
  CHECK(alg.open(in, Numeric::f64).run()["polygon"].size() == 4);
  CHECK(alg.open(in, Numeric::f32).run()["polygon"] == Json::parse("[[2.0,3.0],[6.0,4.0],[1.0,4.0]]"));
}

TEST_CASE("fill clip: every value a sutherland-hodgman step records matches its closed form", "[fill][clip]") {
  using L = fill::SutherlandHodgman;
  using K = StepKind;
  std::vector<PolygonCase> cases;
  for (const Case& c : corpus_cases("sutherland-hodgman")) cases.push_back(parse_case(c));
  SmallRng g{std::mt19937_64(59)};
  for (int i = 0; i < 150; ++i) cases.push_back(random_case(g, true));
  std::size_t crossings = 0;
  for (const PolygonCase& c : cases) {
    INFO(c.name);
    Recorder<Q> t;
    const Polygon2 out = fill::sutherland_hodgman<Q>(c.subject, c.clip, t);
    std::size_t s = 0;
    auto next = [&](L::Line line, K kind) {
      REQUIRE(s < t.size());
      CHECK(t.at(s).line == line);
      CHECK(t.at(s).kind == kind);
      return s++;
    };
    auto points_are = [](const testing::GeoItem& item, const Polygon2& pts) {
      std::vector<Q> want;
      for (const auto& p : pts) want.push_back(p.x), want.push_back(p.y);
      CHECK(item.values == want);
    };
    const Q area2 = oracle::twice_signed_area(c.clip);
    const int o = area2 < 0 ? -1 : 1;
    {
      const std::size_t k = next(L::orient, K::init);
      testing::StepValues v = testing::values_of(t, k);
      CHECK(v["area2"] == area2);
      CHECK(v["o"] == o);
      testing::StepGeometry geo = testing::geometry_of(t, k);
      auto& clip = geo.take(GeoKind::polygon);
      points_are(clip, c.clip);
      CHECK((clip.label == "clip" && clip.life == "keep"));
      auto& subject = geo.take(GeoKind::polygon);
      points_are(subject, c.subject);
      CHECK((subject.label == "subject" && subject.life == "keep"));
      testing::require_all_checked(v, k);
      testing::require_all_geometry_checked(geo, k);
    }
    Polygon2 poly = c.subject;
    const std::size_t m = c.clip.size();
    bool emptied = false;
    for (std::size_t e = 0; e < m && !emptied; ++e) {
      const Vec2<Q> a = c.clip[e], b = c.clip[(e + 1) % m];
      auto d = [&](const Vec2<Q>& v) { return Q(o * cross(a, b, v)); };
      // Where s -> p meets the line a b, by Cramer's rule on the two lines' equations.
      auto meet = [&](const Vec2<Q>& s0, const Vec2<Q>& p0) {
        const Q a1 = p0.y - s0.y, b1 = s0.x - p0.x, c1 = a1 * s0.x + b1 * s0.y;
        const Q a2 = b.y - a.y, b2 = a.x - b.x, c2 = a2 * a.x + b2 * a.y;
        const Q det = a1 * b2 - a2 * b1;
        return Vec2<Q>{(c1 * b2 - c2 * b1) / det, (a1 * c2 - a2 * c1) / det};
      };
      {
        const std::size_t k = next(L::edge, K::advance);
        testing::StepValues v = testing::values_of(t, k);
        CHECK(v["k"] == std::int64_t(e));
        testing::StepGeometry geo = testing::geometry_of(t, k);
        auto& item = geo.take(GeoKind::segment2);
        CHECK(item.values == std::vector<Q>{a.x, a.y, b.x, b.y});
        CHECK((item.label == "clip edge" && item.life == "replace"));
        testing::require_all_checked(v, k);
        testing::require_all_geometry_checked(geo, k);
      }
      Polygon2 next_poly;
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2<Q> sv = poly[(i + poly.size() - 1) % poly.size()], p = poly[i];
        const Q ds = d(sv), dp = d(p);
        {
          const std::size_t k = next(L::side, K::decide);
          testing::StepValues v = testing::values_of(t, k);
          CHECK(v["d_s"] == ds);
          CHECK(v["d_p"] == dp);
          testing::StepGeometry geo = testing::geometry_of(t, k);
          auto& item = geo.take(GeoKind::point2);
          CHECK(item.values == std::vector<Q>{p.x, p.y});
          CHECK((item.label == "p" && item.life.empty() && item.value == dp));
          testing::require_all_checked(v, k);
          testing::require_all_geometry_checked(geo, k);
        }
        if (sgn(ds) * sgn(dp) < 0) {
          const Vec2<Q> x = meet(sv, p);
          next_poly.push_back(x);
          ++crossings;
          const std::size_t k = next(L::cross, K::plot);
          testing::StepValues v = testing::values_of(t, k);
          CHECK(v["t"] == ds / (ds - dp));  // d is affine along s -> p and vanishes there
          testing::StepGeometry geo = testing::geometry_of(t, k);
          auto& item = geo.take(GeoKind::point2);
          CHECK(item.values == std::vector<Q>{x.x, x.y});
          CHECK((item.label == "crossing" && item.life.empty()));
          testing::require_all_checked(v, k);
          testing::require_all_geometry_checked(geo, k);
        }
        if (sgn(dp) >= 0) {
          next_poly.push_back(p);
          const std::size_t k = next(L::keep, K::plot);
          testing::StepGeometry geo = testing::geometry_of(t, k);
          auto& item = geo.take(GeoKind::point2);
          CHECK(item.values == std::vector<Q>{p.x, p.y});
          CHECK((item.label == "kept" && item.life.empty()));
          CHECK(t.at(k).var_begin == t.at(k).var_end);
          testing::require_all_geometry_checked(geo, k);
        }
      }
      poly = next_poly;
      if (poly.empty()) {
        const std::size_t k = next(L::empty, K::miss);
        testing::StepValues v = testing::values_of(t, k);
        CHECK(v["k"] == std::int64_t(e));
        CHECK(t.at(k).geo_begin == t.at(k).geo_end);
        testing::require_all_checked(v, k);
        emptied = true;
        break;
      }
      const std::size_t k = next(L::clipped, K::advance);
      testing::StepValues v = testing::values_of(t, k);
      CHECK(v["k"] == std::int64_t(e));
      CHECK(v["n"] == std::int64_t(poly.size()));
      testing::StepGeometry geo = testing::geometry_of(t, k);
      auto& item = geo.take(GeoKind::polygon);
      points_are(item, poly);
      CHECK((item.label == "clipped" && item.life == "replace"));
      testing::require_all_checked(v, k);
      testing::require_all_geometry_checked(geo, k);
    }
    if (!emptied) {
      const std::size_t k = next(L::done, K::done);
      testing::StepValues v = testing::values_of(t, k);
      CHECK(v["n"] == std::int64_t(poly.size()));
      CHECK(t.at(k).geo_begin == t.at(k).geo_end);
      testing::require_all_checked(v, k);
    }
    CHECK(s == t.size());  // no step without an expectation
    CHECK(out == poly);
    CHECK(oracle::same_region(out, oracle::clip_polygon(c.subject, c.clip)));
  }
  CHECK(crossings > 300);
}

TEST_CASE("fill clip: sutherland-hodgman bad input is one line and exit 2", "[fill][clip][cli]") {
  struct Bad {
    const char *input, *expect;
  };
  for (const Bad& b : std::initializer_list<Bad>{
           {R"({"polygon":[[0,0],[4,0]],"window":{"min":[0,0],"max":[8,5]}})", "expected at least 3 vertices, got 2"},
           {R"({"polygon":[[0,0],[4,0],[2,3]],"clip":[[0,0],[4,0]]})", "input.clip: expected at least 3 vertices"},
           {R"({"polygon":[[0,0],[4,"inf"],[2,3]],"window":{"min":[0,0],"max":[8,5]}})", "not a finite number"},
           {R"({"polygon":[[0,0],[4,"NaN"],[2,3]],"window":{"min":[0,0],"max":[8,5]}})", "not a finite number"},
           {R"({"polygon":[[0,0],[4,-1073741825],[2,3]],"window":{"min":[0,0],"max":[8,5]}})", "beyond the bound 1073741824"},
           {R"({"polygon":[[0,0],[4,0],[2,3]],"window":{"min":[9,0],"max":[8,5]}})", "min[0] > max[0]"},
           {R"({"polygon":[[0,0],[4,0],[2,3]],"window":{"min":[0,5],"max":[8,5]}})", "zero area (min[1] = max[1])"},
           {R"({"polygon":[[0,0],[4,0],[2,3]],"clip":[[0,0],[4,0],[1,1],[0,4]]})", "not convex"},
           {R"({"polygon":[[0,0],[4,0],[2,3]],"clip":[[0,0],[4,4],[0,4],[4,0]]})", "zero area"},  // a bow-tie: its halves cancel
           {R"({"polygon":[[0,0],[4,0],[2,3]],"clip":[[4,-1],[7,8],[-1,2],[9,2],[1,8]]})", "not convex"},  // a pentagram
           {R"({"polygon":[[0,0],[4,0],[2,3]],"clip":[[0,0],[2,2],[4,4]]})", "zero area"},
           {R"({"polygon":[[0,0],[4,0],[2,3]],"clip":[[0,0],[4,0],[4,4],[0,4],[0,0],[4,0],[4,4],[0,4]]})", "winds 2 times"},
           {R"({"polygon":[[0,0],[4,0],[2,3]]})", "missing field \"clip\""},
           {R"({"polygon":[[0,0],[4,0],[2,3]],"window":{"min":[0,0],"max":[8,5]},"clip":[[0,0],[4,0],[2,3]]})", "unknown field \"clip\""},
           {R"({"polygon":[[0,0],[4,0],[2,3]],"clip":[[0,0],[4,0],[2,3]],"rule":"nonzero"})", "unknown field \"rule\""},
           {R"({"polygon":[[0,0],[4,0],[2]],"window":{"min":[0,0],"max":[8,5]}})", "input.polygon[2]: expected [x, y]"},
           {R"({"polygon":"square","window":{"min":[0,0],"max":[8,5]}})", "expected an array of [x, y] vertices"},
       }) {
    INFO(b.input);
    SW_CHECK_BAD_TRACE("sutherland-hodgman", "double", b.input, b.expect);
  }
}
