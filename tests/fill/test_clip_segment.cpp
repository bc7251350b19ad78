// cohen-sutherland against its exact oracle (the segment meets the closed window, CGAL), every value
// of every exact step against a closed form of docs/fill/clipping.md, the corpus in every mode,
// float's failures, and bad input through the CLI.
#include <catch2/catch.hpp>
#include <optional>
#include "cli_harness.hpp"
#include "scale.hpp"
#include "clip_cases.hpp"
#include "fill/cohen_sutherland.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing::clip;
using sw::testing::ratio;

namespace {

using Ends = std::optional<std::array<Vec2<Q>, 2>>;

template <class Num> fill::ClippedSegment<Num> run(const Vec2<Q>& p0, const Vec2<Q>& p1, const Vec2<Q>& lo, const Vec2<Q>& hi) {
  NoProbe none;
  return fill::cohen_sutherland<Num>(to_num<Num>(p0), to_num<Num>(p1), to_num<Num>(lo), to_num<Num>(hi), none);
}

// The ends as a set, in (x, y) order, as the oracle states them.
Ends as_set(Ends e) {
  if (e && ((*e)[1].x < (*e)[0].x || ((*e)[1].x == (*e)[0].x && (*e)[1].y < (*e)[0].y))) std::swap((*e)[0], (*e)[1]);
  return e;
}

// The outcode, written from the semantics: which boundary lines p lies strictly beyond.
int code(const Vec2<Q>& p, const Vec2<Q>& lo, const Vec2<Q>& hi) {
  int c = 0;
  if (p.x < lo.x) c |= 1;
  if (p.x > hi.x) c |= 2;
  if (p.y < lo.y) c |= 4;
  if (p.y > hi.y) c |= 8;
  return c;
}

struct SegmentCase {
  std::string name;
  Vec2<Q> p0, p1, lo, hi;
};

SegmentCase parse_segment_case(const Case& c) {
  const Json& s = c.input.at("segment");
  const Json& w = c.input.at("window");
  return {c.name, point_of(s[0]), point_of(s[1]), point_of(w.at("min")), point_of(w.at("max"))};
}

// Random cases: half-integer ends and windows on a short range (corners, edges, points and
// zero-width windows come up often), or double-exact values with 20 fraction bits.
SegmentCase random_segment_case(SmallRng& g, bool small) {
  if (small) {
    const Vec2<Q> lo = g.point(0, 3);
    const Vec2<Q> hi{lo.x + Q(g.pick(0, 5)), lo.y + Q(g.pick(0, 4))};
    return {"random", g.point(-3, 9), g.point(-3, 9), lo, hi};
  }
  const Vec2<Q> lo{g.dyadic(-100, 0), g.dyadic(-100, 0)};
  const Vec2<Q> hi{lo.x + g.dyadic(1, 200), lo.y + g.dyadic(1, 200)};
  return {"random", {g.dyadic(-300, 300), g.dyadic(-300, 300)}, {g.dyadic(-300, 300), g.dyadic(-300, 300)}, lo, hi};
}

}  // namespace

TEST_CASE("fill clip: cohen-sutherland in exact and filtered equals the oracle on 10^4 random segments", "[fill][clip]") {
  SmallRng g{std::mt19937_64(41)};
  std::size_t uncertain = 0, accepted = 0, degenerate = 0;
  for (int i = 0; i < sw::testing::cases(10000); ++i) {
    const SegmentCase c = random_segment_case(g, i % 2 == 0);
    INFO("case " << i << ": " << c.p0.x << "," << c.p0.y << " -> " << c.p1.x << "," << c.p1.y << " window " << c.lo.x << "," << c.lo.y << " "
                  << c.hi.x << "," << c.hi.y);
    const Ends want = oracle::clip_segment(c.p0, c.p1, c.lo, c.hi);
    const auto exact = run<Q>(c.p0, c.p1, c.lo, c.hi);
    REQUIRE(!exact.bound_hit);
    REQUIRE(as_set(exact.segment) == want);
    if (exact.segment) {
      ++accepted;
      degenerate += (*exact.segment)[0] == (*exact.segment)[1];
      // The direction is kept: the first end is the one nearer p0 (or the only point).
      const Vec2<Q> d = c.p1 - c.p0, e = (*exact.segment)[1] - (*exact.segment)[0];
      CHECK(d.x * e.x + d.y * e.y >= 0);
    }
    try {
      const auto f = run<Interval>(c.p0, c.p1, c.lo, c.hi);
      REQUIRE(f.segment.has_value() == exact.segment.has_value());
      if (f.segment)
        for (int k = 0; k < 2; ++k) {
          CHECK(within((*f.segment)[k].x, (*exact.segment)[k].x));
          CHECK(within((*f.segment)[k].y, (*exact.segment)[k].y));
        }
    } catch (const Uncertain&) {
      ++uncertain;  // an end on a boundary line after a rounded cut: the chain runs exact
    }
  }
  CHECK(accepted > sw::testing::cases(2000u));
  CHECK(degenerate > sw::testing::cases(50u));      // corner touches and points
  CHECK(uncertain < sw::testing::cases(10000u) / 4);
  WARN("cohen-sutherland random: " << accepted << " accepted, " << degenerate << " single points, filtered uncertain " << uncertain);
}

TEST_CASE("fill clip: cohen-sutherland corpus in every mode against the oracle", "[fill][clip]") {
  const Algorithm& alg = find_algorithm("cohen-sutherland");
  std::size_t rounded_decisions_wrong = 0;
  for (const Case& c : corpus_cases("cohen-sutherland")) {
    INFO(c.name);
    const Json want = alg.canonical(alg.open(c.input).oracle());
    CHECK(alg.canonical(alg.open(c.input, Numeric::exact).run()) == want);
    const Json filtered = alg.open(c.input, Numeric::filtered).run();
    CHECK(filtered["segment"].is_null() == want["segment"].is_null());
    if (filtered["fallback"].get<bool>()) CHECK(alg.canonical(filtered) == want);
    for (Numeric n : {Numeric::f32, Numeric::f64}) {
      const Json got = alg.open(c.input, n).run();
      CHECK(!got.contains("bound_hit"));
      rounded_decisions_wrong += got["segment"].is_null() != want["segment"].is_null();
    }
  }
  CHECK(rounded_decisions_wrong == 1);  // float on "corner miss by 2^-40" (next test)
}

TEST_CASE("fill clip: float accepts a segment that misses a corner by 2^-40", "[fill][clip]") {
  // 3 + 2^-40 and 7 + 2^-40 round to 3 and 7 in float: the line then touches the corner (0, 5).
  const Algorithm& alg = find_algorithm("cohen-sutherland");
  const Json in = Json::parse(R"({"segment":[[-2,"3298534883329/1099511627776"],[2,"7696581394433/1099511627776"]],"window":{"min":[0,0],"max":[8,5]}})");
  CHECK(alg.open(in, Numeric::exact).run()["segment"].is_null());
  CHECK(alg.open(in, Numeric::f64).run()["segment"].is_null());
  CHECK(alg.open(in, Numeric::f32).run()["segment"] == Json::parse("[[0.0,5.0],[0.0,5.0]]"));
  // Near a corner at large scale, float's decisions go wrong in a measurable share of cases.
  SmallRng g{std::mt19937_64(43)};
  std::size_t wrong = 0, bound_hits = 0, cases = 2000;
  for (std::size_t i = 0; i < cases; ++i) {
    const Vec2<Q> lo{0, 0}, hi{1 << 20, 1 << 19}, corner = g.pick(0, 1) ? lo : hi;
    const Vec2<Q> d{g.dyadic(1, 1 << 20), g.dyadic(-(1 << 20), 1 << 20)}, nudge{0, ratio(g.pick(-8, 8), 1 << 12)};
    const SegmentCase c{"near corner", corner - d + nudge, corner + d + nudge, lo, hi};
    const auto f = run<float>(c.p0, c.p1, c.lo, c.hi);
    wrong += f.segment.has_value() != run<Q>(c.p0, c.p1, c.lo, c.hi).segment.has_value();
    bound_hits += f.bound_hit;
  }
  CHECK(wrong > 0);
  WARN("float decides accept/reject wrongly on " << wrong << " of " << cases << " segments within 2^-9 of a corner of a 2^20 window ("
                                                 << bound_hits << " stopped by the cut bound)");
}

TEST_CASE("fill clip: every value a cohen-sutherland step records matches its closed form", "[fill][clip]") {
  using L = fill::CohenSutherland;
  using K = StepKind;
  std::vector<SegmentCase> cases;
  for (const Case& c : corpus_cases("cohen-sutherland")) cases.push_back(parse_segment_case(c));
  SmallRng g{std::mt19937_64(47)};
  for (int i = 0; i < 400; ++i) cases.push_back(random_segment_case(g, true));
  std::size_t cuts_seen = 0;
  for (const SegmentCase& c : cases) {
    INFO(c.name << ": " << c.p0.x << "," << c.p0.y << " -> " << c.p1.x << "," << c.p1.y);
    Recorder<Q> t;
    const auto out = fill::cohen_sutherland<Q>(c.p0, c.p1, c.lo, c.hi, t);
    // The point of the input's line at x = X (or y = Y): where a cut must land, whatever the ends
    // were cut to before.
    auto at_x = [&](const Q& X) { return Vec2<Q>{X, c.p0.y + (c.p1.y - c.p0.y) * (X - c.p0.x) / (c.p1.x - c.p0.x)}; };
    auto at_y = [&](const Q& Y) { return Vec2<Q>{c.p0.x + (c.p1.x - c.p0.x) * (Y - c.p0.y) / (c.p1.y - c.p0.y), Y}; };
    std::array<Vec2<Q>, 2> p{c.p0, c.p1};
    std::array<int, 2> code_of{code(c.p0, c.lo, c.hi), code(c.p1, c.lo, c.hi)};
    std::size_t s = 0;
    auto next = [&](L::Line line, K kind) {
      REQUIRE(s < t.size());
      CHECK(t.at(s).line == line);
      CHECK(t.at(s).kind == kind);
      CHECK(t.at(s).scope == 0);
      return s++;
    };
    auto point_is = [](const testing::GeoItem& item, const Vec2<Q>& v) {
      CHECK(item.values == std::vector<Q>{v.x, v.y});
    };
    auto segment_is = [](const testing::GeoItem& item, const Vec2<Q>& a, const Vec2<Q>& b) {
      CHECK(item.values == std::vector<Q>{a.x, a.y, b.x, b.y});
    };
    {
      const std::size_t k = next(L::codes, K::init);
      testing::StepValues v = testing::values_of(t, k);
      CHECK(v["c0"] == code_of[0]);
      CHECK(v["c1"] == code_of[1]);
      testing::StepGeometry geo = testing::geometry_of(t, k);
      auto& w = geo.take(GeoKind::rect);
      CHECK(w.values == std::vector<Q>{c.lo.x, c.lo.y, c.hi.x, c.hi.y});
      CHECK((w.label == "window" && w.life == "keep"));
      const Vec2<Q> f0{2 * c.lo.x - c.hi.x - 1, 2 * c.lo.y - c.hi.y - 1}, f1{2 * c.hi.x - c.lo.x + 1, 2 * c.hi.y - c.lo.y + 1};
      const std::array<std::pair<const char*, std::array<Vec2<Q>, 2>>, 5> lines{{{"x = xmin", {{{c.lo.x, f0.y}, {c.lo.x, f1.y}}}},
                                                                               {"x = xmax", {{{c.hi.x, f0.y}, {c.hi.x, f1.y}}}},
                                                                               {"y = ymin", {{{f0.x, c.lo.y}, {f1.x, c.lo.y}}}},
                                                                               {"y = ymax", {{{f0.x, c.hi.y}, {f1.x, c.hi.y}}}},
                                                                               {"segment", {{c.p0, c.p1}}}}};
      for (const auto& [label, ends] : lines) {
        auto& item = geo.take(GeoKind::segment2);
        segment_is(item, ends[0], ends[1]);
        CHECK(item.label == label);
        CHECK(item.life == "keep");
      }
      for (int e = 0; e < 2; ++e) {
        auto& item = geo.take(GeoKind::point2);
        point_is(item, p[e]);
        CHECK(item.label == (e ? "p1" : "p0"));
        CHECK(item.life == "replace");
        CHECK(item.value == Q(code_of[e]));
      }
      testing::require_all_checked(v, k);
      testing::require_all_geometry_checked(geo, k);
    }
    std::optional<std::array<Vec2<Q>, 2>> expected;
    for (int cuts = 0; cuts <= 4; ++cuts) {
      INFO("cut " << cuts);
      if ((code_of[0] | code_of[1]) == 0) {
        const std::size_t k = next(L::accept, K::hit);
        testing::StepValues v = testing::values_of(t, k);
        CHECK(v["c0"] == 0);
        CHECK(v["c1"] == 0);
        testing::StepGeometry geo = testing::geometry_of(t, k);
        auto& item = geo.take(GeoKind::segment2);
        segment_is(item, p[0], p[1]);
        CHECK((item.label == "clipped" && item.life == "keep"));
        testing::require_all_checked(v, k);
        testing::require_all_geometry_checked(geo, k);
        expected = p;
        break;
      }
      if ((code_of[0] & code_of[1]) != 0) {
        const std::size_t k = next(L::reject, K::miss);
        testing::StepValues v = testing::values_of(t, k);
        CHECK(v["c0"] == code_of[0]);
        CHECK(v["c1"] == code_of[1]);
        CHECK(t.at(k).geo_begin == t.at(k).geo_end);
        testing::require_all_checked(v, k);
        break;
      }
      REQUIRE(cuts < 4);  // exact: at most four cuts (clipping.md)
      const int e = code_of[0] != 0 ? 0 : 1;
      const int bit = code_of[e] & -code_of[e];
      const bool on_x = bit == 1 || bit == 2;
      p[e] = on_x ? at_x(bit == 1 ? c.lo.x : c.hi.x) : at_y(bit == 4 ? c.lo.y : c.hi.y);
      code_of[e] = code(p[e], c.lo, c.hi);
      ++cuts_seen;
      {
        const std::size_t k = next(on_x ? L::cut_x : L::cut_y, K::advance);
        testing::StepValues v = testing::values_of(t, k);
        CHECK(v["k"] == e);
        CHECK(v["b"] == bit);
        CHECK(v["x"] == p[e].x);
        CHECK(v["y"] == p[e].y);
        testing::StepGeometry geo = testing::geometry_of(t, k);
        auto& item = geo.take(GeoKind::point2);
        point_is(item, p[e]);
        CHECK((item.label == "cut" && item.life.empty()));
        testing::require_all_checked(v, k);
        testing::require_all_geometry_checked(geo, k);
      }
      {
        const std::size_t k = next(L::recode, K::decide);
        testing::StepValues v = testing::values_of(t, k);
        CHECK(v["k"] == e);
        CHECK(v["c0"] == code_of[0]);
        CHECK(v["c1"] == code_of[1]);
        testing::StepGeometry geo = testing::geometry_of(t, k);
        auto& item = geo.take(GeoKind::point2);
        point_is(item, p[e]);
        CHECK(item.label == (e ? "p1" : "p0"));
        CHECK(item.life == "replace");
        CHECK(item.value == Q(code_of[e]));
        testing::require_all_checked(v, k);
        testing::require_all_geometry_checked(geo, k);
      }
    }
    CHECK(s == t.size());  // no step without an expectation
    CHECK(out.segment == expected);
    CHECK(as_set(expected) == oracle::clip_segment(c.p0, c.p1, c.lo, c.hi));
  }
  CHECK(cuts_seen > 300);
}

TEST_CASE("fill clip: cohen-sutherland bad input is one line and exit 2", "[fill][clip][cli]") {
  struct Bad {
    const char *input, *expect;
  };
  for (const Bad& b : std::initializer_list<Bad>{
           {R"({"segment":[[0,0],[1,1]],"window":{"min":[2,0],"max":[1,5]}})", "min[0] > max[0]"},
           {R"({"segment":[[0,0],[1,1]],"window":{"min":[0,6],"max":[8,5]}})", "min[1] > max[1]"},
           {R"({"segment":[[0,"nan"],[1,1]],"window":{"min":[0,0],"max":[8,5]}})", "not a finite number"},
           {R"({"segment":[[0,"-inf"],[1,1]],"window":{"min":[0,0],"max":[8,5]}})", "not a finite number"},
           {R"({"segment":[[0,1073741825],[1,1]],"window":{"min":[0,0],"max":[8,5]}})", "beyond the bound 1073741824"},
           {R"({"segment":[[0,0],[1,1]],"window":{"min":[0,0],"max":["1/36893488147419103232",5]}})", "beyond 64 bits"},
           {R"({"segment":[[0,0]],"window":{"min":[0,0],"max":[8,5]}})", "expected [[x, y], [x, y]]"},
           {R"({"segment":[[0,0],[1]],"window":{"min":[0,0],"max":[8,5]}})", "input.segment[1]: expected [x, y]"},
           {R"({"segment":[[0,0],[1,1]]})", "missing field \"window\""},
           {R"({"segment":[[0,0],[1,1]],"window":{"min":[0,0]}})", "missing field \"max\""},
           {R"({"segment":[[0,0],[1,1]],"window":{"min":[0,0],"max":[8,5]},"clip":1})", "unknown field \"clip\""},
           {R"({"segment":[[0,0],[1,1]],"window":{"min":[0,0],"max":[8,5],"size":2}})", "unknown field \"size\""},
       }) {
    INFO(b.input);
    SW_CHECK_BAD_TRACE("cohen-sutherland", "exact", b.input, b.expect);
  }
}
