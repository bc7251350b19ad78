// The line family against the exact oracle: results in every exact-capable mode, every step's
// variables in exact mode, and the oracle's two statements against each other.
#include <catch2/catch.hpp>
#include "line_cases.hpp"
#include "scale.hpp"
#include "lines_oracle.hpp"
#include "lines/bresenham_line.hpp"
#include "lines/dda_grid_walk.hpp"
#include "lines/dda_line.hpp"

using namespace sw;
using sw::testing::ceil_q;
using sw::testing::major_axis;
using sw::testing::Segment;
using Q = Rational;

namespace {

template <class Num> Vec2<Num> as(const Vec2<Q>& p) { return {num::from_rational<Num>(p.x), num::from_rational<Num>(p.y)}; }

enum class Alg { dda, walk, bresenham };

template <class Num, class Probe> std::vector<Pixel> run(Alg alg, const Segment& s, Probe& probe, bool* finished = nullptr) {
  std::vector<Pixel> px;
  bool ok = false;
  switch (alg) {
    case Alg::dda: ok = lines::dda_line<Num>(as<Num>(s.p0), as<Num>(s.p1), px, probe); break;
    case Alg::walk: ok = lines::dda_grid_walk<Num>(as<Num>(s.p0), as<Num>(s.p1), px, probe); break;
    case Alg::bresenham: ok = lines::bresenham_line<Num>(as<Num>(s.p0), as<Num>(s.p1), px, probe); break;
  }
  if (finished) *finished = ok;
  return px;
}
template <class Num> std::vector<Pixel> run(Alg alg, const Segment& s, bool* finished = nullptr) {
  NoProbe none;
  return run<Num>(alg, s, none, finished);
}

std::vector<Pixel> expected(Alg alg, const Segment& s) {
  switch (alg) {
    case Alg::dda: return oracle::column_pixels(s.p0, s.p1, oracle::Sampling::ascending);
    case Alg::walk: return oracle::walk_cells(s.p0, s.p1);
    case Alg::bresenham: return oracle::column_pixels(s.p0, s.p1, oracle::Sampling::directed);
  }
  return {};
}

// Random segments plus the hard corpus; the step replays leave out the long lines.
std::vector<Segment> cases_for(Alg alg, int random_count, bool with_long = true) {
  const bool ints = alg == Alg::bresenham;
  auto all = sw::testing::random_segments(random_count, ints);
  for (auto& s : sw::testing::hard_segments(ints))
    if (with_long || !s.long_line) all.push_back(s);
  return all;
}

const char* name(Alg a) { return a == Alg::dda ? "dda-line" : a == Alg::walk ? "dda-grid-walk" : "bresenham-line"; }

// Reads recorded variables by name.
struct StepReader {
  const Recorder<Q>& rec;
  std::size_t i;
  const StepRecord& s() const { return rec.at(i); }
  const VarRecord* find(const char* n) const {
    for (auto v = s().var_begin; v < s().var_end; ++v)
      if (std::string(rec.var_at(v).name) == n) return &rec.var_at(v);
    return nullptr;
  }
  Q q(const char* n) const {
    const VarRecord* v = find(n);
    if (!v || v->is_int) throw std::runtime_error(std::string("step has no number variable ") + n);
    return rec.num_value(v->slot);
  }
  std::int64_t k(const char* n) const {
    const VarRecord* v = find(n);
    if (!v || !v->is_int) throw std::runtime_error(std::string("step has no integer variable ") + n);
    return rec.int_value(v->slot);
  }
  std::optional<Pixel> pixel() const {
    for (auto g = s().geo_begin; g < s().geo_end; ++g)
      if (rec.geo_at(g).kind == GeoKind::pixel) return Pixel{rec.int_value(rec.geo_at(g).slot), rec.int_value(rec.geo_at(g).slot + 1)};
    return std::nullopt;
  }
};

// Collects the first failed expectation of a replay, so a million-step trace costs one assertion.
struct Replay {
  std::string failure;
  void expect(bool ok, std::size_t step, const char* what) {
    if (!ok && failure.empty()) failure = "step " + std::to_string(step) + ": " + what;
  }
};
#define EXPECT(cond) replay.expect(static_cast<bool>(cond), i, #cond)

}  // namespace

TEST_CASE("oracle: the direct and brute-force statements agree", "[oracle][lines]") {
  for (const Segment& s : sw::testing::random_segments(1500, false, 99)) {
    INFO(s.name << " " << s.p0.x << "," << s.p0.y << " -> " << s.p1.x << "," << s.p1.y);
    REQUIRE(oracle::column_pixels(s.p0, s.p1, oracle::Sampling::ascending) == oracle::column_pixels_brute_force(s.p0, s.p1, oracle::Sampling::ascending));
    REQUIRE(oracle::column_pixels(s.p0, s.p1, oracle::Sampling::directed) == oracle::column_pixels_brute_force(s.p0, s.p1, oracle::Sampling::directed));
    REQUIRE(oracle::walk_cells(s.p0, s.p1) == oracle::walk_cells_brute_force(s.p0, s.p1));
  }
}

TEST_CASE("oracle: hand-checked cases", "[oracle][lines]") {
  using P = std::vector<Pixel>;
  const Vec2<Q> o{0, 0};
  // Ties round up: the minor value 1/2 at x = 1 and 3/2 at x = 3 go to the upper pixel.
  CHECK(oracle::column_pixels(o, {4, 2}, oracle::Sampling::ascending) == P{{0, 0}, {1, 1}, {2, 1}, {3, 2}});
  // Falling: -1/2 rounds up to 0, -3/2 to -1.
  CHECK(oracle::column_pixels(o, {4, -2}, oracle::Sampling::ascending) == P{{0, 0}, {1, 0}, {2, -1}, {3, -1}});
  // Bresenham walks from p0 and excludes p1; the DDA always excludes the larger end.
  CHECK(oracle::column_pixels({3, 0}, o, oracle::Sampling::directed) == P{{3, 0}, {2, 0}, {1, 0}});
  CHECK(oracle::column_pixels({3, 0}, o, oracle::Sampling::ascending) == P{{0, 0}, {1, 0}, {2, 0}});
  // Through the corner (1/2, 1/2) going up-right: the corner belongs to (1, 1), so (1, 0) and (0, 1) are skipped.
  CHECK(oracle::walk_cells(o, {Q(3, 2), Q(3, 2)}) == P{{0, 0}, {1, 1}});
  // Going up-left through (-1/2, 1/2): the corner point itself lies in (0, 1), then (-1, 1).
  CHECK(oracle::walk_cells(o, {Q(-3, 2), Q(3, 2)}) == P{{0, 0}, {0, 1}, {-1, 1}});
  // Zero length is empty; a segment ending exactly on a boundary excludes the next cell.
  CHECK(oracle::walk_cells(o, o).empty());
  CHECK(oracle::walk_cells(o, {Q(1, 2), 0}) == P{{0, 0}});
}

TEST_CASE("exact and filtered results equal the oracle", "[lines]") {
  for (Alg alg : {Alg::dda, Alg::walk, Alg::bresenham}) {
    // The two 10^6-pixel lines take most of this test's time, 400 s under the sanitizers: there
    // they are left out (the short hard cases reach the same code).
    for (const Segment& s : cases_for(alg, sw::testing::cases(10000), !sw::testing::kSanitized)) {
      INFO(name(alg) << ": " << s.name << " " << s.p0.x << "," << s.p0.y << " -> " << s.p1.x << "," << s.p1.y);
      const auto want = expected(alg, s);
      bool finished = false;
      REQUIRE(run<Q>(alg, s, &finished) == want);
      REQUIRE(finished);
      if (alg == Alg::bresenham) {
        REQUIRE(run<std::int64_t>(alg, s) == want);
      } else {
        std::vector<Pixel> filtered;
        try {
          filtered = run<Interval>(alg, s);
        } catch (const Uncertain&) {
          filtered = run<Q>(alg, s);  // what filtered mode does
        }
        REQUIRE(filtered == want);
      }
    }
  }
}

TEST_CASE("float loops stay bounded where float cannot advance", "[lines]") {
  // |dy| = 2^25: tDelta = 2^-25 is half an ulp of t near 1 in float, so tMax can stop growing.
  // The walk must still end, within its bound, and say whether the bound stopped it.
  const Q B(16777216);
  const Segment s{{Q(-3, 7), -B}, {Q(5, 3), B}, "full height"};
  bool finished = true;
  const auto f = run<float>(Alg::walk, s, &finished);
  // The documented loop bound: 4 + (|dx| + 2) + (|dy| + 2) passes, at most two cells each.
  CHECK(f.size() <= 2u * (4u + 3u + 33554434u));
  CHECK(f.size() >= 33554432u / 2);
  INFO("float walk finished by its own test: " << finished << ", cells " << f.size());
  // It stops at p1: no cell beyond the range between p0's cell (0, -2^24) and p1's (2, 2^24),
  // which the range guard on the test line enforces where tMax stalls (it used to run on past p1).
  CHECK(finished);
  bool inside = true;
  for (const Pixel& c : f) inside = inside && c.x >= 0 && c.x <= 2 && c.y >= -16777216 && c.y <= 16777216;
  CHECK(inside);
  CHECK(f.back().y <= 16777216);
}

TEST_CASE("dda-line: every exact step matches its definition", "[lines][steps]") {
  for (const Segment& s : cases_for(Alg::dda, sw::testing::cases(10000), false)) {
    INFO(s.name << " " << s.p0.x << "," << s.p0.y << " -> " << s.p1.x << "," << s.p1.y);
    Recorder<Q> rec;
    const auto pixels = run<Q>(Alg::dda, s, rec);
    const Vec2<Q> d = s.p1 - s.p0;
    const int a = major_axis(d);
    const bool swap = d[a] < 0;
    const Vec2<Q> from = swap ? s.p1 : s.p0, to = swap ? s.p0 : s.p1, dd = to - from;
    const auto want = oracle::column_pixels(s.p0, s.p1, oracle::Sampling::ascending);
    std::size_t plots = 0;
    Q last_qa;
    Replay replay;
    for (std::size_t i = 0; i < rec.size(); ++i) {
      StepReader r{rec, i};
      const auto line = r.s().line;
      using L = lines::DdaLine;
      if (line == L::delta) EXPECT((r.q("dx") == d.x && r.q("dy") == d.y));
      if (line == L::major) EXPECT(r.k("a") == a);
      if (line == L::swap) EXPECT((r.k("swapped") == swap && r.q("dx") == dd.x && r.q("dy") == dd.y));
      if (line == L::slope) EXPECT((r.q(a == 0 ? "dpx" : "dpy") == 1 && r.q(a == 0 ? "dpy" : "dpx") == dd[1 - a] / dd[a]));
      if (line == L::offset || line == L::plot || line == L::advance || line == L::done) {
        // q lies exactly on the line, on an integer column.
        const Vec2<Q> q{r.q("qx"), r.q("qy")};
        EXPECT((q.x - from.x) * dd.y == (q.y - from.y) * dd.x);
        EXPECT(q[a].get_den() == 1);
        if (line == L::offset) {
          EXPECT(q[a] == ceil_q(from[a]));
          EXPECT(r.q(a == 0 ? "dp0x" : "dp0y") == ceil_q(from[a]) - from[a]);
        }
        if (line == L::advance) EXPECT(q[a] == last_qa + 1);
        if (line == L::plot) {
          if (plots >= want.size()) { replay.expect(false, i, "more plots than the oracle"); break; }
          EXPECT(r.pixel() == want[plots]);
          EXPECT((Pixel{r.k("i"), r.k("j")} == want[plots]));
          ++plots;
        }
        if (line == L::done) EXPECT(q[a] >= to[a]);
        last_qa = q[a];
      }
    }
    CHECK(replay.failure == "");
    CHECK(plots == want.size());
    CHECK(pixels == want);
    CHECK(rec.at(rec.size() - 1).kind == StepKind::done);
  }
}

TEST_CASE("dda-grid-walk: every exact step matches its definition", "[lines][steps]") {
  for (const Segment& s : cases_for(Alg::walk, sw::testing::cases(10000), false)) {
    INFO(s.name << " " << s.p0.x << "," << s.p0.y << " -> " << s.p1.x << "," << s.p1.y);
    Recorder<Q> rec;
    run<Q>(Alg::walk, s, rec);
    const Vec2<Q> d = s.p1 - s.p0;
    const auto want = oracle::walk_cells(s.p0, s.p1);
    std::size_t visits = 0;
    Pixel cell{};
    Replay replay;
    for (std::size_t i = 0; i < rec.size(); ++i) {
      StepReader r{rec, i};
      using L = lines::DdaGridWalk;
      const auto line = r.s().line;
      if (line == L::delta) EXPECT((r.q("dx") == d.x && r.q("dy") == d.y));
      if (r.s().kind == StepKind::visit) {
        if (visits >= want.size()) { replay.expect(false, i, "more visits than the oracle"); break; }
        cell = *r.pixel();
        EXPECT(cell == want[visits]);
        ++visits;
      }
      if (line == L::pick) {
        // tMax is where the segment crosses the current cell's exit boundary, computed afresh.
        for (int a = 0; a < 2; ++a) {
          if (d[a] == 0) continue;
          const Q boundary = Q(a == 0 ? cell.x : cell.y) + Q(d[a] > 0 ? 1 : -1, 2);
          EXPECT(r.q(a == 0 ? "tMax_x" : "tMax_y") == (boundary - s.p0[a]) / d[a]);
        }
        // t is where the walk leaves the cell: the next cell's entry, or >= 1 at the end.
        const Q t = r.q("t");
        if (visits < want.size()) {
          const oracle::Entry e = oracle::cell_entry(s.p0, s.p1, want[visits]);
          EXPECT(t == e.t);
        } else {
          EXPECT(t >= 1);
        }
      }
    }
    CHECK(replay.failure == "");
    CHECK(visits == want.size());
  }
}

TEST_CASE("bresenham-line: every exact step matches its definition", "[lines][steps]") {
  for (const Segment& s : cases_for(Alg::bresenham, sw::testing::cases(10000), false)) {
    INFO(s.name << " " << s.p0.x << "," << s.p0.y << " -> " << s.p1.x << "," << s.p1.y);
    Recorder<Q> rec;
    run<Q>(Alg::bresenham, s, rec);
    const Vec2<Q> d = s.p1 - s.p0;
    const int a = major_axis(d);
    const Q A = abs(d[a]), B = abs(d[1 - a]);
    const auto want = oracle::column_pixels(s.p0, s.p1, oracle::Sampling::directed);
    std::size_t plots = 0;
    Replay replay;
    for (std::size_t i = 0; i < rec.size(); ++i) {
      StepReader r{rec, i};
      if (r.s().line != lines::BresenhamLine::plot) continue;
      if (plots >= want.size()) { replay.expect(false, i, "more plots than the oracle"); break; }
      EXPECT(r.pixel() == want[plots]);
      // e = 2A (offset of the next sample from the current minor row) + 2B - A: minor offset of
      // sample k is k B / A; m_k is how many minor steps were taken.
      const Q k(static_cast<long>(plots));
      const Q m = abs(Q(a == 0 ? want[plots].y - want[0].y : want[plots].x - want[0].x));
      EXPECT(r.q("e") == 2 * (k * B - A * m + B) - A);
      ++plots;
    }
    CHECK(replay.failure == "");
    CHECK(plots == want.size());
  }
}
