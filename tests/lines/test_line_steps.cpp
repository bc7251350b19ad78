// The line family, step by step: every variable and geometry item an exact step of dda-line,
// bresenham-line and dda-grid-walk records, in the order the steps come, against closed forms of
// docs/lines/semantics.md written from the input and the step's index (not by running the
// algorithm), for the catalog examples, the corpus and seeded random segments. A step, variable or
// geometry item without an expectation fails.
//
// Listing lines no step records, by design: dda-line `test` (its outcome is the next step, plot or
// done) and dda-grid-walk `up` and `down` (their moves are recorded by visit_up and visit_down).
// The `done` step with `bound_hit` is never reached in exact mode (the loop bounds hold every
// column and crossing); had it been recorded, its step or variable would have no expectation.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include "catalog.hpp"
#include "input.hpp"
#include "line_cases.hpp"
#include "lines_oracle.hpp"
#include "step_values.hpp"
#include "lines/bresenham_line.hpp"
#include "lines/dda_grid_walk.hpp"
#include "lines/dda_line.hpp"

using namespace sw;
using sw::testing::ceil_q;
using sw::testing::floor_q;
using sw::testing::GeoItem;
using sw::testing::major_axis;
using sw::testing::ratio;
using sw::testing::Segment;
using sw::testing::StepGeometry;
using sw::testing::StepValues;
using Q = Rational;

namespace {

// Rounding written here so that the expectations share no helper with the algorithms.
Q round_q(const Q& v) { return floor_q(v + ratio(1, 2)); }  // a tie goes up
std::int64_t to_int(const Q& v) { return v.get_num().get_si(); }
bool is_half_integer(const Q& v) { return Q(v - ratio(1, 2)).get_den() == 1; }

// One geometry item as the semantics calls for it.
struct ExpectedItem {
  GeoKind kind;
  std::vector<Q> values;
  std::string label, life;  // empty: none, this step only
};
// One step as the semantics calls for it: its line, its kind, its variables and its geometry.
struct ExpectedStep {
  std::uint32_t line;
  StepKind kind;
  std::vector<std::pair<std::string, Q>> vars;
  std::vector<ExpectedItem> geo;
  ExpectedStep& var(const char* name, const Q& v) {
    vars.push_back({name, v});
    return *this;
  }
  ExpectedStep& var(const char* name, std::int64_t v) { return var(name, Q(v)); }
  const Q& value(std::string_view name) const {
    for (const auto& [n, v] : vars)
      if (n == name) return v;
    throw std::logic_error("no expected variable " + std::string(name));
  }
  ExpectedStep& item(GeoKind kind, std::vector<Q> values) {
    geo.push_back({kind, std::move(values), {}, {}});
    return *this;
  }
  // The last item's label, and that it stays on the view from this step on.
  ExpectedStep& label(const char* text) {
    geo.back().label = text;
    return *this;
  }
  ExpectedStep& keep() {
    geo.back().life = "keep";
    return *this;
  }
  ExpectedStep& point(const Vec2<Q>& p) { return item(GeoKind::point2, {p.x, p.y}); }
  ExpectedStep& pixel(const Pixel& p) { return item(GeoKind::pixel, {Q(p.x), Q(p.y)}); }
  ExpectedStep& segment(const Vec2<Q>& p0, const Vec2<Q>& p1) { return item(GeoKind::segment2, {p0.x, p0.y, p1.x, p1.y}); }
};
struct Expected {
  std::vector<ExpectedStep> steps;
  std::vector<Pixel> pixels;  // the plotted or visited pixels, in order
  ExpectedStep& step(std::uint32_t line, StepKind kind) {
    steps.push_back({line, kind, {}, {}});
    return steps.back();
  }
};

Pixel pixel_of(const Q& i, const Q& j) { return {to_int(i), to_int(j)}; }
// The pixel holding point p: (floor(x + 1/2), floor(y + 1/2)).
Pixel holding(const Vec2<Q>& p) { return pixel_of(round_q(p.x), round_q(p.y)); }
// (major, minor) coordinates back to (x, y).
Vec2<Q> from_axes(int a, const Q& major, const Q& minor) { return a == 0 ? Vec2<Q>{major, minor} : Vec2<Q>{minor, major}; }
// The major axis: x if |dx| > |dy|, else y (a tie steps rows).

// dda-line. With from/to the endpoints ordered upward along the major axis a, D = to - from and
// dp = D / D_a, the sample on column c is q(c) = from + (c - from_a) dp; the columns are the integers
// c0 = ceil(from_a), ..., ceil(to_a) - 1, and column c plots the pixel holding q(c).
Expected dda_expected(const Segment& s) {
  using L = lines::DdaLine;
  Expected e;
  const Vec2<Q> d = s.p1 - s.p0;
  e.step(L::delta, StepKind::init).var("dx", d.x).var("dy", d.y).segment(s.p0, s.p1).keep();
  const int a = major_axis(d);
  e.step(L::major, StepKind::decide).var("a", a);
  const bool swapped = d[a] < 0;
  const Vec2<Q> from = swapped ? s.p1 : s.p0, to = swapped ? s.p0 : s.p1, D = to - from;
  e.step(L::swap, StepKind::decide).var("swapped", swapped).var("dx", D.x).var("dy", D.y);
  if (D[a] == 0) {
    e.step(L::empty, StepKind::done);
    return e;
  }
  const Vec2<Q> dp = from_axes(a, 1, D[1 - a] / D[a]);
  e.step(L::slope, StepKind::init).var("dpx", dp.x).var("dpy", dp.y);
  auto q = [&](const Q& c) { return from + (c - from[a]) * dp; };
  const Q c0 = ceil_q(from[a]), off = c0 - from[a];
  e.step(L::offset, StepKind::init)
      .var("dp0x", off * dp.x).var("dp0y", off * dp.y).var("qx", q(c0).x).var("qy", q(c0).y).point(q(c0)).label("q");
  const std::int64_t columns = to_int(ceil_q(to[a]) - c0);
  for (std::int64_t k = 0; k < columns; ++k) {
    const Vec2<Q> qk = q(c0 + k), next = q(c0 + k + 1);
    const Pixel px = holding(qk);
    e.pixels.push_back(px);
    e.step(L::plot, StepKind::plot).var("qx", qk.x).var("qy", qk.y).var("i", px.x).var("j", px.y).pixel(px).point(qk).label("q");
    e.step(L::advance, StepKind::advance).var("qx", next.x).var("qy", next.y).point(next).label("q");
  }
  const Vec2<Q> last = q(c0 + columns);
  e.step(L::done, StepKind::done).var("qx", last.x).var("qy", last.y).point(last).label("q");
  return e;
}

// bresenham-line. Pixel k (k = 0 .. A-1) lies at major p0_a + s_a k and minor round(y_k), where
// y_k = p0_b + s_b k B / A is the segment's exact minor coordinate there; m_k = |round(y_k) - p0_b|
// minor steps have been taken, and e_k = 2(kB - A m_k + B) - A. The minor step after pixel k is
// taken when pixel k + 1 lies on the next row (y_A = p1_b).
Expected bresenham_expected(const Segment& s) {
  using L = lines::BresenhamLine;
  Expected e;
  const Vec2<Q> d = s.p1 - s.p0;
  e.step(L::delta, StepKind::init).var("dx", d.x).var("dy", d.y).segment(s.p0, s.p1).keep();
  const int a = major_axis(d), b = 1 - a;
  e.step(L::major, StepKind::decide).var("a", a);
  const int sa = sgn(d[a]), sb = sgn(d[b]);
  const Q A = abs(d[a]), B = abs(d[b]);
  e.step(L::signs, StepKind::init).var("s_a", sa).var("s_b", sb).var("A", A).var("B", B);
  auto m = [&](std::int64_t k) { return A == 0 ? Q(0) : abs(round_q(s.p0[b] + sb * Q(k) * B / A) - s.p0[b]); };
  auto err = [&](std::int64_t k) { return Q(2 * (Q(k) * B - A * m(k) + B) - A); };
  auto at = [&](std::int64_t k) { return from_axes(a, s.p0[a] + sa * Q(k), s.p0[b] + sb * m(k)); };
  e.step(L::decision, StepKind::init).var("e", err(0));
  const std::int64_t count = to_int(A);
  e.step(L::loop, StepKind::init).var("count", count).point(s.p0);
  for (std::int64_t k = 0; k < count; ++k) {
    const Vec2<Q> p = at(k);
    const Pixel px = pixel_of(p.x, p.y);
    e.pixels.push_back(px);
    e.step(L::plot, StepKind::plot).var("i", px.x).var("j", px.y).var("e", err(k)).pixel(px);
    const bool minor = m(k + 1) != m(k);
    // The documented rule says the same: e > 0, or e = 0 and the minor direction is positive.
    CHECK(minor == (err(k) > 0 || (err(k) == 0 && sb > 0)));
    e.step(L::test, StepKind::decide).var("e", err(k)).var("minor_step", minor);
    if (minor) e.step(L::minor_step, StepKind::advance).var("e", err(k) - 2 * A).point(from_axes(a, at(k)[a], at(k + 1)[b]));
    e.step(L::major_step, StepKind::advance).var("e", err(k + 1)).point(at(k + 1));
  }
  e.step(L::done, StepKind::done);
  return e;
}

// dda-grid-walk. The segment crosses the boundary h = n + 1/2 of axis a at t = (h - p0_a) / d_a;
// the crossings with 0 < t < 1 moving up and 0 <= t < 1 moving down (a start on a lower boundary
// leaves at once) are the walk's events. At an event t the walk first visits the pixel holding
// p(t), if an upward boundary was crossed, then the pixel the segment is in just after t, if a
// downward one was. On an axis, that pixel is floor(p_a(t) + 1/2) moving up, ceil(p_a(t) - 1/2)
// moving down. A cell's exit parameters are tMax_a = (cell_a + s_a/2 - p0_a) / d_a.
Expected walk_expected(const Segment& s) {
  using L = lines::DdaGridWalk;
  Expected e;
  const Vec2<Q> d = s.p1 - s.p0;
  e.step(L::delta, StepKind::init).var("dx", d.x).var("dy", d.y).segment(s.p0, s.p1).keep();
  if (d.x == 0 && d.y == 0) {
    e.step(L::done, StepKind::done);
    return e;
  }
  const Vec2<Q> p0 = s.p0;
  auto p = [&](const Q& t) { return p0 + t * d; };
  Pixel cell = holding(p0);
  e.pixels.push_back(cell);
  e.step(L::start, StepKind::visit).var("i", cell.x).var("j", cell.y).pixel(cell).point(p0);
  const int sx = sgn(d.x), sy = sgn(d.y);
  // An axis the segment does not move along records 0 for tDelta and tMax.
  auto t_delta = [&](int a) { return d[a] == 0 ? Q(0) : Q(1 / abs(d[a])); };
  auto t_max = [&](const Pixel& c, int a) {
    return d[a] == 0 ? Q(0) : Q((Q(a == 0 ? c.x : c.y) + ratio(sgn(d[a]), 2) - p0[a]) / d[a]);
  };
  e.step(L::setup, StepKind::init).var("step_x", sx).var("step_y", sy).var("tDelta_x", t_delta(0)).var("tDelta_y", t_delta(1));
  e.step(L::first_exit, StepKind::init).var("tMax_x", t_max(cell, 0)).var("tMax_y", t_max(cell, 1));
  // Every crossing: t -> which axes cross there.
  std::map<Q, std::array<bool, 2>> events;
  for (int a = 0; a < 2; ++a) {
    if (d[a] == 0) continue;
    const Q lo = d[a] > 0 ? p0[a] : s.p1[a], hi = d[a] > 0 ? s.p1[a] : p0[a];
    for (Q h = floor_q(lo - ratio(1, 2)) + ratio(1, 2); h <= hi; h += 1) {
      const bool crossed = d[a] > 0 ? p0[a] < h && h < s.p1[a] : s.p1[a] < h && h <= p0[a];
      if (crossed) events[(h - p0[a]) / d[a]][a] = true;
    }
  }
  auto pick = [&](const Q& t) {
    e.step(L::pick, StepKind::decide).var("t", t).var("tMax_x", t_max(cell, 0)).var("tMax_y", t_max(cell, 1)).point(p(t));
  };
  for (const auto& event : events) {
    const Q& t = event.first;  // a variable, not a binding: lambdas below capture it (clang 14)
    const auto& axes = event.second;
    CHECK(t >= 0);
    CHECK(t < 1);
    for (int a = 0; a < 2; ++a) CHECK(axes[a] == (d[a] != 0 && is_half_integer(p(t)[a]) && !(t == 0 && d[a] > 0)));
    pick(t);
    if ((axes[0] && sx > 0) || (axes[1] && sy > 0)) {
      cell = holding(p(t));
      e.pixels.push_back(cell);
      e.step(L::visit_up, StepKind::visit)
          .var("i", cell.x).var("j", cell.y).var("tMax_x", t_max(cell, 0)).var("tMax_y", t_max(cell, 1)).pixel(cell);
    }
    if ((axes[0] && sx < 0) || (axes[1] && sy < 0)) {
      auto after = [&](int a) {
        return sgn(d[a]) > 0 ? round_q(p(t)[a]) : sgn(d[a]) < 0 ? ceil_q(p(t)[a] - ratio(1, 2)) : round_q(p0[a]);
      };
      cell = pixel_of(after(0), after(1));
      e.pixels.push_back(cell);
      e.step(L::visit_down, StepKind::visit)
          .var("i", cell.x).var("j", cell.y).var("tMax_x", t_max(cell, 0)).var("tMax_y", t_max(cell, 1)).pixel(cell);
    }
  }
  // The last cell's exit: the first crossing not before p1.
  Q t_end = sx == 0 ? t_max(cell, 1) : sy == 0 ? t_max(cell, 0) : std::min(t_max(cell, 0), t_max(cell, 1));
  CHECK(t_end >= 1);
  pick(t_end);
  e.step(L::test, StepKind::done).var("t", t_end).var("past_p1", 0);  // exact: t reaches 1 before the cell range ends
  return e;
}

// The catalog example, the lessons' inputs for the algorithm, the corpus (both directions, no long
// lines) and seeded random segments.
std::vector<Segment> cases(std::string_view id, bool integer_endpoints, int random_count, std::uint64_t seed) {
  const Json ex = Json::parse(find_algorithm(id).example);
  std::vector<Segment> out{{parse_point2(ex, "p0"), parse_point2(ex, "p1"), "the example"}};
  // A lesson's front matter names its algorithm and input on lines of their own (docs/lessons.md).
  const std::filesystem::path lessons = std::filesystem::path(SW_SOURCE_DIR) / "lessons";
  for (const auto& entry : std::filesystem::directory_iterator(lessons)) {
    if (entry.path().extension() != ".md") continue;
    std::ifstream f(entry.path());
    std::string line, algorithm, input;
    for (int n = 0; n < 20 && std::getline(f, line); ++n) {
      if (line.rfind("algorithm: ", 0) == 0) algorithm = line.substr(11);
      if (line.rfind("input: ", 0) == 0) input = line.substr(7);
    }
    if (algorithm != id) continue;
    const Json in = Json::parse(input);
    out.push_back({parse_point2(in, "p0"), parse_point2(in, "p1"), "lesson " + entry.path().filename().string()});
  }
  CHECK(out.size() > 1);  // each line algorithm has a lesson
  for (Segment& s : sw::testing::hard_segments(integer_endpoints))
    if (!s.long_line) out.push_back(std::move(s));
  for (Segment& s : sw::testing::random_segments(random_count, integer_endpoints, seed)) out.push_back(std::move(s));
  return out;
}

// Replays a recording against the expectation: the same lines, kinds and order; every recorded
// variable and geometry item equal to its closed form, and none without one.
void require_matches(const Recorder<Q>& t, const Listing& listing, const Expected& want, std::set<std::string_view>& seen) {
  for (std::size_t s = 0; s < t.size(); ++s) {
    const std::string_view line = listing.lines[t.at(s).line - 1].name;
    seen.insert(line);
    INFO("step " << s << " (" << line << ")");
    REQUIRE(s < want.steps.size());  // a step the semantics does not call for
    const ExpectedStep& w = want.steps[s];
    INFO("expected line " << listing.lines[w.line - 1].name);
    REQUIRE(t.at(s).line == w.line);
    CHECK(t.at(s).kind == w.kind);
    CHECK(t.at(s).scope == 0);
    StepValues sv = sw::testing::values_of(t, s);
    for (const auto& [name, v] : w.vars) CHECK(sv[name] == v);
    sw::testing::require_all_checked(sv, s);
    StepGeometry g = sw::testing::geometry_of(t, s);
    for (const ExpectedItem& want_item : w.geo) {
      const GeoItem& item = g.take(want_item.kind);
      CHECK(item.values == want_item.values);
      CHECK(item.label == want_item.label);
      CHECK(item.life == want_item.life);
      CHECK(!item.value);  // no line step colours an item by a value
    }
    sw::testing::require_all_geometry_checked(g, s);
  }
  CHECK(t.size() == want.steps.size());  // no step the semantics calls for is missing
}

std::string describe(const Segment& s) {
  return s.name + ": (" + s.p0.x.get_str() + ", " + s.p0.y.get_str() + ") -> (" + s.p1.x.get_str() + ", " + s.p1.y.get_str() + ")";
}

// The lines a listing's steps may record: all but the named ones.
std::set<std::string_view> recorded_lines(const Listing& l, std::set<std::string_view> never) {
  std::set<std::string_view> out;
  for (const ListingLine& line : l.lines)
    if (!never.count(line.name)) out.insert(line.name);
  return out;
}

}  // namespace

TEST_CASE("dda-line: every value and geometry item an exact step records matches its closed form", "[lines][steps][replay]") {
  const auto all = cases("dda-line", false, 300, 1601);
  REQUIRE(all.size() >= 350);
  std::set<std::string_view> seen;
  int swapped = 0, no_column = 0, ties = 0;
  for (const Segment& s : all) {
    INFO(describe(s));
    Recorder<Q> t;
    std::vector<Pixel> out;
    REQUIRE(lines::dda_line<Q>(s.p0, s.p1, out, t));
    const Expected want = dda_expected(s);
    require_matches(t, lines::DdaLine::listing(), want, seen);
    CHECK(out == want.pixels);
    CHECK(want.pixels == oracle::column_pixels(s.p0, s.p1, oracle::Sampling::ascending));  // the closed form against the oracle
    const Vec2<Q> d = s.p1 - s.p0;
    swapped += d[major_axis(d)] < 0;
    no_column += d != Vec2<Q>{} && want.pixels.empty();
    for (const ExpectedStep& w : want.steps)
      if (w.line == lines::DdaLine::plot) ties += is_half_integer(w.value(major_axis(d) == 0 ? "qy" : "qx"));
  }
  // The cases reach every recorded line, both directions, a segment between two columns and minor ties.
  CHECK(seen == recorded_lines(lines::DdaLine::listing(), {"test"}));
  CHECK(swapped > 0);
  CHECK(no_column > 0);
  CHECK(ties > 0);
}

TEST_CASE("bresenham-line: every value and geometry item an exact step records matches its closed form", "[lines][steps][replay]") {
  const auto all = cases("bresenham-line", true, 300, 1602);
  REQUIRE(all.size() >= 320);
  std::set<std::string_view> seen;
  int tie_up = 0, tie_down = 0;
  for (const Segment& s : all) {
    INFO(describe(s));
    Recorder<Q> t;
    std::vector<Pixel> out;
    REQUIRE(lines::bresenham_line<Q>(s.p0, s.p1, out, t));
    const Expected want = bresenham_expected(s);
    require_matches(t, lines::BresenhamLine::listing(), want, seen);
    CHECK(out == want.pixels);
    CHECK(want.pixels == oracle::column_pixels(s.p0, s.p1, oracle::Sampling::directed));
    const Vec2<Q> d = s.p1 - s.p0;
    for (const ExpectedStep& w : want.steps)
      if (w.line == lines::BresenhamLine::test && w.value("e") == 0) ++(sgn(d[1 - major_axis(d)]) > 0 ? tie_up : tie_down);
  }
  CHECK(seen == recorded_lines(lines::BresenhamLine::listing(), {}));
  // e = 0 in both minor directions: the tie rule decides.
  CHECK(tie_up > 0);
  CHECK(tie_down > 0);
}

TEST_CASE("dda-grid-walk: every value and geometry item an exact step records matches its closed form", "[lines][steps][replay]") {
  const auto all = cases("dda-grid-walk", false, 300, 1603);
  REQUIRE(all.size() >= 350);
  std::set<std::string_view> seen;
  int corners_up_down = 0, leave_at_start = 0;
  for (const Segment& s : all) {
    INFO(describe(s));
    Recorder<Q> t;
    std::vector<Pixel> out;
    REQUIRE(lines::dda_grid_walk<Q>(s.p0, s.p1, out, t));
    const Expected want = walk_expected(s);
    require_matches(t, lines::DdaGridWalk::listing(), want, seen);
    CHECK(out == want.pixels);
    CHECK(want.pixels == oracle::walk_cells(s.p0, s.p1));
    using L = lines::DdaGridWalk;
    for (std::size_t k = 1; k < want.steps.size(); ++k) {
      corners_up_down += want.steps[k - 1].line == L::visit_up && want.steps[k].line == L::visit_down;
      leave_at_start += want.steps[k].line == L::pick && want.steps[k].value("t") == 0;
    }
  }
  CHECK(seen == recorded_lines(lines::DdaGridWalk::listing(), {"up", "down"}));
  // The cases reach a corner crossed up on one axis and down on the other, and a start on a lower boundary.
  CHECK(corners_up_down > 0);
  CHECK(leave_at_start > 0);
}
