// depth-sort in the catalog: the painter's algorithm over window-space triangles, checked against
// the brute-force visible surface. Semantics: docs/pipeline/semantics.md.
#include <cmath>
#include <numbers>
#include <random>
#include "register.hpp"
#include "pipeline/camera_input.hpp"
#include "pipeline/depth_sort.hpp"
#include "pipeline_oracle.hpp"

namespace sw {
namespace {

using namespace pipespec;

inline constexpr std::size_t kMaxTriangles = 256;

using DSInput = WindowTriangles;

struct DSOutput {
  std::int64_t width = 0, height = 0;
  std::vector<std::int64_t> ids;  // -1: background; -2: a tie
  std::int64_t painted = 0, moves = 0, splits = 0, tests = 0, ties = 0, wrong = 0;
  bool gave_up = false;
  // Modes agree when every pixel shows the same triangle.
  friend bool operator==(const DSOutput& a, const DSOutput& b) { return a.ids == b.ids; }
};

// The bounds on the pairs compared and on the cuts. Thirty-two large triangles crossing each other
// at random (the bench's random set) take up to 105,094 tests and 841 cuts in exact; the bounds
// leave 2.5 and 4.9 times that. Float's slivers, cut again and again, stop at them.
std::int64_t max_tests(std::size_t n) { return 256 * static_cast<std::int64_t>(n * n) + 4096; }
std::int64_t max_splits(std::size_t n) { return 4 * static_cast<std::int64_t>(n * n) + 64; }

template <class Num> struct DSPrepared {
  std::int64_t width, height;
  std::vector<std::array<Vec3<Num>, 3>> tris;
  std::vector<std::int64_t> ids;
};

// Seeded scenes: random triangles (many penetrate); pairs crossing in depth like an X seen from
// above; and three sticks in a pinwheel, each over the next: a cycle no order paints.
std::vector<BenchSet<DSInput>> ds_sets() {
  std::vector<BenchSet<DSInput>> sets{{"random", {}}, {"penetrating", {}}, {"cyclic", {}}};
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> xy(-8, 136), zz(0.05, 0.95), turn(0, 2 * std::numbers::pi), u(-1, 1);
  // A 128 x 128 window: x and y on a 1/256 grid, depth on a 2^-24 grid.
  auto vertex = [](double x, double y, double z) { return std::array<Rational, 3>{on_grid(x, 8), on_grid(y, 8), on_grid(z, 24)}; };
  auto add = [](DSInput& in, const std::array<std::array<Rational, 3>, 3>& v, std::int64_t id) { in.tris.push_back({v, id, 0, 0}); };
  for (int k = 0; k < 16; ++k) {
    DSInput r{128, 128, {}};
    for (int i = 0; i < 32; ++i) add(r, {vertex(xy(rng), xy(rng), zz(rng)), vertex(xy(rng), xy(rng), zz(rng)), vertex(xy(rng), xy(rng), zz(rng))}, i);
    sets[0].inputs.push_back(r);
    DSInput x{128, 128, {}};
    for (int i = 0; i < 8; ++i) {  // depth falls left to right on even ids, rises on odd ones
      const double y0 = 8 + 14 * i + 4 * u(rng), lean = 0.3 * u(rng);
      const double near = 0.1 + 0.1 * (1 + u(rng)), far = 0.7 + 0.1 * (1 + u(rng));
      for (int s = 0; s < 2; ++s) {
        const double zl = s ? near : far, zr = s ? far : near;
        add(x, {vertex(-4, y0, zl), vertex(132, y0 + 40 * lean, zr), vertex(64, y0 + 30, 0.5 * (zl + zr))}, 2 * i + s);
      }
    }
    sets[1].inputs.push_back(x);
    DSInput c{128, 128, {}};
    const double a0 = turn(rng), offset = 14 + 4 * u(rng);
    for (int s = 0; s < 3; ++s) {  // stick s: from depth 0.2 to 0.8 along its length, 120 degrees apart
      const double a = a0 + 2 * std::numbers::pi * s / 3, dx = std::cos(a), dy = std::sin(a);
      const double cx = 64 - offset * dy, cy = 64 + offset * dx;  // the stick's line passes offset from the centre
      add(c, {vertex(cx - 56 * dx - 4 * dy, cy - 56 * dy + 4 * dx, 0.2), vertex(cx - 56 * dx + 4 * dy, cy - 56 * dy - 4 * dx, 0.2),
              vertex(cx + 56 * dx, cy + 56 * dy, 0.8)}, s);
    }
    sets[2].inputs.push_back(c);
  }
  return sets;
}

struct DepthSortSpec {
  static constexpr std::array hooks{Hook::error, Hook::estimate_steps, Hook::canonical};
  using Algo = pipe::DepthSort;
  using Input = DSInput;
  using Output = DSOutput;
  static constexpr std::array views{View::plane2d, View::table};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  // Three sticks over a 24 x 24 window, each lying over the next where they cross: no order of
  // the three paints them right, and exact cuts three times.
  static inline const std::string example =
      R"({"size":[24,24],"triangles":[{"v":[[1,6,"1/5"],[1,9,"1/5"],[23,7,"4/5"]]},)"
      R"({"v":[[17,1,"1/5"],[14,1,"1/5"],[16,23,"4/5"]]},{"v":[[23,17,"1/5"],[20,21,"1/5"],[3,3,"4/5"]]}]})";
  static Input parse(const Json& j) {
    if (!j.is_object()) throw InputError("input: expected an object with size and triangles");
    only_keys(j, {"size", "triangles"}, "input");
    return parse_window_triangles(j, kMaxTriangles, false, true);
  }
  template <class Num> static DSPrepared<Num> prepare(const Input& in) {
    DSPrepared<Num> p{in.width, in.height, {}, {}};
    for (const auto& t : in.tris) {
      std::array<Vec3<Num>, 3> v;
      for (int k = 0; k < 3; ++k) v[k] = to_num<Num>(Vec3<Rational>{t.v[k][0], t.v[k][1], t.v[k][2]});
      p.tris.push_back(v), p.ids.push_back(t.id);
    }
    return p;
  }
  template <class Num, class Probe> static Output compute(const DSPrepared<Num>& p, Probe& probe) {
    const auto img = pipe::depth_sort<Num>(p.width, p.height, p.tris, p.ids, max_tests(p.tris.size()), max_splits(p.tris.size()), probe);
    return {img.width, img.height, img.id, img.painted, img.moves, img.splits, img.tests, img.ties, img.wrong, img.gave_up};
  }
  static Json to_json(const Output& o) {
    return Json{{"width", o.width}, {"height", o.height}, {"ids", o.ids}, {"ties", o.ties}, {"wrong", o.wrong}, {"gave_up", o.gave_up},
                {"painted", o.painted}, {"moves", o.moves}, {"splits", o.splits}, {"tests", o.tests}};
  }
  // The oracle knows the picture, not the work done to paint it.
  static Json canonical(const Json& r) {
    Json c = r;
    c.erase("painted"), c.erase("moves"), c.erase("splits"), c.erase("tests");
    return c;
  }
  static std::size_t ops(const Output& o) { return static_cast<std::size_t>(std::max<std::int64_t>(1, o.painted)); }
  static constexpr std::string_view error_unit = "pixels";
  static double error(const Output& got, const Output& exact) { return differing_ids(got.ids, exact.ids); }
  // With T the bound on tests: at most n + 2T rounds (a paint, or a move or cut after a test),
  // each a pick and at most a move step and a cut step; five steps per test; the painted samples,
  // which the pieces of a triangle split among them (twice the triangles' boxes: float's pieces may
  // overlap by rounding); the sort's steps and done.
  static std::size_t estimate_steps(const Input& in) {
    const double n = double(in.tris.size()), T = double(max_tests(in.tris.size()));
    double samples = 0;
    for (const auto& t : in.tris) samples += window_box_samples(t.v, in.width, in.height);
    return static_cast<std::size_t>(std::min(1e18, 2 + n + 3 * (n + 2 * T) + 5 * T + 2 * samples));
  }
  // The visible surface by brute force: the exact z-buffer with GL_LESS keeps the first of the
  // nearest, GL_LEQUAL the last; where they differ, two triangles tie (ids are distinct).
  static Output oracle(const Input& in) {
    const auto first = pipeline_oracle::z_buffer(in.width, in.height, in.tris, 0, false, Rational(2));
    const auto last = pipeline_oracle::z_buffer(in.width, in.height, in.tris, 0, true, Rational(2));
    Output o{in.width, in.height, first.ids};
    for (std::size_t i = 0; i < o.ids.size(); ++i)
      if (first.ids[i] != last.ids[i]) o.ids[i] = pipe::kTie, ++o.ties;
    return o;
  }
  static std::vector<BenchSet<Input>> bench_sets() { return ds_sets(); }
};

SW_REGISTER(DepthSortSpec);

}  // namespace
}  // namespace sw
