// The line family's catalog entries: dda-line, dda-grid-walk, bresenham-line.
#include <random>
#include "register.hpp"
#include "pixels.hpp"
#include "lines_oracle.hpp"
#include "lines/bresenham_line.hpp"
#include "lines/dda_grid_walk.hpp"
#include "lines/dda_line.hpp"

namespace sw {
namespace {

// Coordinates are bounded so that every mode's loop bound fits and traces stay finite.
constexpr double kCoordBound = 16777216.0;  // 2^24

struct SegmentInput {
  Vec2<Rational> p0, p1;
};

// Throws unless both endpoints are integers; `why` says who needs them.
void require_integer_endpoints(const SegmentInput& in, const char* why) {
  for (const auto* p : {&in.p0, &in.p1})
    for (int a = 0; a < 2; ++a)
      if ((*p)[a].get_den() != 1)
        throw InputError(std::string("input.") + (p == &in.p0 ? "p0" : "p1") + "[" + std::to_string(a) + "]: " + (*p)[a].get_str() +
                         " is not an integer (" + why + ")");
}

SegmentInput parse_segment(const Json& j, bool integer_endpoints) {
  only_keys(j, {"p0", "p1"}, "input");
  SegmentInput in{parse_point2(j, "p0"), parse_point2(j, "p1")};
  for (const auto* p : {&in.p0, &in.p1})
    for (int a = 0; a < 2; ++a) check_bound((*p)[a], kCoordBound, std::string("input.") + (p == &in.p0 ? "p0" : "p1") + "[" + std::to_string(a) + "]");
  if (integer_endpoints) require_integer_endpoints(in, "this algorithm takes integer endpoints");
  return in;
}


// Seeded bench sets: short random segments with fractional (or integer) endpoints, and long lines.
// Quick: the long lines 64 times shorter (65 thousand pixels each instead of 4 million).
std::vector<BenchSet<SegmentInput>> segment_bench_sets(bool integer_endpoints, BenchSize size) {
  const double s = size == BenchSize::full ? 1 : 1.0 / 64;
  std::mt19937_64 rng(20261122);
  auto coord = [&](double lo, double hi) {
    std::uniform_real_distribution<double> u(lo, hi);
    const double v = u(rng);
    return integer_endpoints ? Rational(static_cast<long>(std::floor(v))) : num::to_rational(std::ldexp(std::floor(std::ldexp(v, 20)), -20));
  };
  BenchSet<SegmentInput> random{"random", {}}, long_lines{"long", {}};
  for (int i = 0; i < 4000; ++i) {
    Vec2<Rational> p0{coord(-512, 512), coord(-512, 512)};
    Vec2<Rational> p1{p0.x + coord(-64, 64), p0.y + coord(-64, 64)};
    random.inputs.push_back({p0, p1});
  }
  for (int i = 0; i < 4; ++i) {
    Vec2<Rational> p0{coord(-2.1e6 * s, -2e6 * s), coord(-2e6 * s, 2e6 * s)};
    Vec2<Rational> p1{coord(2e6 * s, 2.1e6 * s), coord(-2e6 * s, 2e6 * s)};
    if (i % 2) std::swap(p0.x, p0.y), std::swap(p1.x, p1.y);
    long_lines.inputs.push_back({p0, p1});
  }
  return {random, long_lines};
}

template <class AlgoT, bool IntegerEndpoints> struct SegmentSpec {
  static constexpr std::array hooks{Hook::estimate_steps, Hook::handles, Hook::write_members, Hook::admit, Hook::contract_inputs};  // write_members: each Spec below
  using Algo = AlgoT;
  using Input = SegmentInput;
  using Output = PixelsOutput;
  static constexpr std::array views{View::plane2d};
  static Input parse(const Json& j) { return parse_segment(j, IntegerEndpoints); }
  static void admit(const Input& in, Numeric n) {
    if (n == Numeric::integer) require_integer_endpoints(in, "int mode takes integer endpoints");
  }
  template <class Num> static std::array<Vec2<Num>, 2> prepare(const Input& in) { return {to_num<Num>(in.p0), to_num<Num>(in.p1)}; }
  static std::size_t ops(const Output& o) { return o.pixels.size(); }
  // Each algorithm takes at most three steps per pixel it passes, plus its set-up.
  static std::size_t estimate_steps(const Input& in) {
    const Rational span = abs(in.p1.x - in.p0.x) + abs(in.p1.y - in.p0.y);
    return 3 * static_cast<std::size_t>(num::ceil_int(span)) + 16;
  }
  static std::vector<BenchSet<Input>> bench_sets(BenchSize size) { return segment_bench_sets(IntegerEndpoints, size); }
  // The seeded sets hold no zero-length segment, which stops each walk on its own line.
  static constexpr std::array contract_inputs{std::string_view(R"({"p0":[3,3],"p1":[3,3]})")};
  static std::vector<Handle> handles() {
    const int snap = IntegerEndpoints ? 1 : 8;
    return {{"/p0", Handle::Kind::point2, snap, "p0"}, {"/p1", Handle::Kind::point2, snap, "p1"}};
  }
};

struct DdaLineSpec : SegmentSpec<lines::DdaLine, false> {
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"p0":[1.25,2.5],"p1":[12.75,7.25]})";
  template <class Num, class Probe> static Output compute(const std::array<Vec2<Num>, 2>& p, Probe& probe) {
    Output o;
    o.finished = lines::dda_line<Num>(p[0], p[1], o.pixels, probe);
    return o;
  }
  static Json to_json(const Output& o) { return pixels_json("pixels", o); }
  static void write_members(const Output& o, std::ostream& os) { pixels_members("pixels", o, os); }
  static Output oracle(const Input& in) { return {oracle::column_pixels(in.p0, in.p1, oracle::Sampling::ascending)}; }
};

struct GridWalkSpec : SegmentSpec<lines::DdaGridWalk, false> {
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"p0":[1.25,2.5],"p1":[9.5,6.5]})";
  template <class Num, class Probe> static Output compute(const std::array<Vec2<Num>, 2>& p, Probe& probe) {
    Output o;
    o.finished = lines::dda_grid_walk<Num>(p[0], p[1], o.pixels, probe);
    return o;
  }
  static Json to_json(const Output& o) { return pixels_json("cells", o); }
  static void write_members(const Output& o, std::ostream& os) { pixels_members("cells", o, os); }
  static Output oracle(const Input& in) { return {oracle::walk_cells(in.p0, in.p1)}; }
};

struct BresenhamSpec : SegmentSpec<lines::BresenhamLine, true> {
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::integer, Numeric::exact};
  static inline const std::string example = R"({"p0":[1,2],"p1":[13,7]})";
  template <class Num, class Probe> static Output compute(const std::array<Vec2<Num>, 2>& p, Probe& probe) {
    Output o;
    o.finished = lines::bresenham_line<Num>(p[0], p[1], o.pixels, probe);
    return o;
  }
  static Json to_json(const Output& o) { return pixels_json("pixels", o); }
  static void write_members(const Output& o, std::ostream& os) { pixels_members("pixels", o, os); }
  static Output oracle(const Input& in) { return {oracle::column_pixels(in.p0, in.p1, oracle::Sampling::directed)}; }
};

SW_REGISTER(DdaLineSpec);
SW_REGISTER(GridWalkSpec);
SW_REGISTER(BresenhamSpec);

}  // namespace

}  // namespace sw
