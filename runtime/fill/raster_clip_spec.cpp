// raster-clip in the catalog (registered here): the double-DDA triangle fill clipped to a
// screen at rasterization time. Semantics, bounds and figures: docs/fill/raster-clip.md.
#include <random>
#include "register.hpp"
#include "fill/raster_clip.hpp"
#include "fill_oracle.hpp"
#include "fill_raster_oracle.hpp"
#include "fill/fill_common.hpp"

namespace sw {
namespace {

using namespace fillspec;  // FillOutput, fill_json, parse_vertex, parse_attrs, wrong_pixels, plane_values

// Vertices may lie far off the screen: |x|, |y| <= 2^40 (the other fills: 2^30). Exact and
// filtered are exact at any size; double's crossings on screen are off by about 2^-13 pixel at
// 2^40, and float cannot even hold such vertices (its spacing there is 2^16): docs/fill/raster-clip.md.
constexpr double kVertexBound = 1099511627776.0;  // 2^40
constexpr std::int64_t kScreenBound = 1073741824;  // 2^30: |i0|, |j0|, |i1|, |j1|

struct RasterClipInput {
  std::array<Vec2<Rational>, 3> v;
  std::vector<std::vector<Rational>> attrs;  // empty, or 3 lists of n values
  fill::Screen screen;
};

using ClipFillOutput = FillOutput;

// {"min":[i0,j0],"max":[i1,j1]}: integers with i0 < i1, j0 < j1, at most 2^20 samples.
fill::Screen parse_viewport(const Json& j) {
  if (!j.is_object()) throw InputError("input.viewport: expected {\"min\":[i0,j0],\"max\":[i1,j1]}");
  only_keys(j, {"min", "max"}, "input.viewport");
  std::int64_t c[2][2];
  const char* names[2] = {"min", "max"};
  for (int k = 0; k < 2; ++k) {
    const Json& p = j[names[k]];
    const std::string what = std::string("input.viewport.") + names[k];
    if (!p.is_array() || p.size() != 2) throw InputError(what + ": expected [i, j] (integers)");
    for (int a = 0; a < 2; ++a) c[k][a] = parse_integer(p[a], what + "[" + std::to_string(a) + "]", -kScreenBound, kScreenBound);
  }
  for (int a = 0; a < 2; ++a) {
    const std::string k = "[" + std::to_string(a) + "]";
    if (c[0][a] > c[1][a]) throw InputError("input.viewport: min" + k + " > max" + k + " (min is the lower-left sample, max is past the upper-right one)");
    if (c[0][a] == c[1][a]) throw InputError("input.viewport: empty (min" + k + " = max" + k + "; the window [min, max) is half-open)");
  }
  const fill::Screen s{c[0][0], c[0][1], c[1][0], c[1][1]};
  const double samples = double(s.i1 - s.i0) * double(s.j1 - s.j0);
  if (samples > kMaxSamples)
    throw InputError("input.viewport: holds " + std::to_string(static_cast<long long>(samples)) + " samples, more than the budget of 2^20");
  return s;
}

RasterClipInput parse_input(const Json& j) {
  only_keys_optional(j, {"triangle", "viewport"}, {"attrs"}, "input");
  const Json& t = j["triangle"];
  if (!t.is_array() || t.size() != 3) throw InputError("input.triangle: expected three vertices [[x,y],[x,y],[x,y]]");
  RasterClipInput in;
  for (int k = 0; k < 3; ++k) in.v[k] = parse_vertex(t[k], "input.triangle[" + std::to_string(k) + "]", kVertexBound);
  in.screen = parse_viewport(j["viewport"]);
  if (j.contains("attrs")) in.attrs = parse_attrs(j["attrs"], 3);
  return in;
}

template <class Num> struct ClipTriangle {
  fill::Triangle<Num> t;
  fill::Screen screen;
};

// Random triangles K times as wide as a 256 x 256 screen at the origin, on the 1/256 grid: one edge
// runs through two random points of the screen (so the screen holds a clipped piece, not all or
// nothing), the third vertex is K screen widths off in a random direction.
std::vector<RasterClipInput> random_inputs(std::mt19937_64& rng, int count, long K) {
  std::uniform_int_distribution<long> on(0, 256 * 256), dir(-256 * 256, 256 * 256);
  auto grid = [](long n) -> Rational { return Rational(n) / 256; };
  std::vector<RasterClipInput> out;
  while (static_cast<int>(out.size()) < count) {
    const Vec2<Rational> p{grid(on(rng)), grid(on(rng))}, q{grid(on(rng)), grid(on(rng))};
    if (p == q) continue;
    RasterClipInput in;
    in.v = {Vec2<Rational>{p.x + K * (p.x - q.x), p.y + K * (p.y - q.y)}, {q.x + K * (q.x - p.x), q.y + K * (q.y - p.y)}, {grid(dir(rng) * K), grid(dir(rng) * K)}};
    in.screen = {0, 0, 256, 256};
    out.push_back(std::move(in));
  }
  return out;
}

struct RasterClipSpec {
  static constexpr std::array hooks{Hook::handles, Hook::error, Hook::estimate_steps, Hook::step_cost};
  using Algo = fill::RasterClip;
  using Input = RasterClipInput;
  using Output = ClipFillOutput;
  static constexpr std::array views{View::plane2d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example =
      R"({"triangle":[[-6.5,-3.25],[30.75,6.5],[3,40.5]],"viewport":{"min":[0,0],"max":[16,12]},"attrs":[[1,0,0],[0,1,0],[0,0,1]]})";
  static Input parse(const Json& j) { return parse_input(j); }
  static std::vector<Handle> handles() {
    std::vector<Handle> h;
    for (int k = 0; k < 3; ++k) h.push_back({"/triangle/" + std::to_string(k), Handle::Kind::point2, 8, "p" + std::to_string(k)});
    h.push_back({"/viewport/min", Handle::Kind::point2, 1, "min"});
    h.push_back({"/viewport/max", Handle::Kind::point2, 1, "max"});
    return h;
  }
  template <class Num> static ClipTriangle<Num> prepare(const Input& in) {
    ClipTriangle<Num> c{{}, in.screen};
    for (int k = 0; k < 3; ++k) {
      c.t[k].p = to_num<Num>(in.v[k]);
      c.t[k].n = in.attrs.empty() ? 0 : in.attrs[k].size();
      for (std::size_t a = 0; a < c.t[k].n; ++a) c.t[k].a[a] = num::from_rational<Num>(in.attrs[k][a]);
    }
    return c;
  }
  template <class Num, class Probe> static Output compute(const ClipTriangle<Num>& c, Probe& probe) {
    fill::FillResult<Num> r;
    fill::raster_clip<Num>(c.t, c.screen, r, probe);
    return fill_output<Num>(std::move(r.pixels), c.t[0].n, r.values);
  }
  static Json to_json(const Output& o) { return fill_json(o); }
  static std::size_t ops(const Output& o) { return o.pixels.size(); }
  static constexpr std::string_view error_unit = "pixels";
  static double error(const Output& got, const Output& exact) { return wrong_pixels(got, exact); }
  // The screen's samples (a plot and a step each at most) and, per screen row, a row and a span.
  static std::size_t estimate_steps(const Input& in) {
    const auto& s = in.screen;
    return static_cast<std::size_t>(2 * (s.i1 - s.i0) * (s.j1 - s.j0) + 4 * (s.j1 - s.j0) + 64);
  }
  // Budget units a step costs (measured, docs/cli.md: the largest accepted input within 10 s).
  static std::size_t step_cost(Numeric n) { return n == Numeric::exact ? 3 : 1; }
  // The covered samples on the screen, by brute force over the screen's samples only, and at each
  // the plane through the vertices' attributes.
  static Output oracle(const Input& in) {
    const auto& s = in.screen;
    return plane_values(oracle::triangle_samples_in_window(in.v, {s.i0, s.j0, s.i1, s.j1}), in.v, in.attrs);
  }
  // A 256 x 256 screen and triangles about its size, then 10^3 and 10^6 times its width: the time
  // per pixel on screen stays the same (docs/fill/raster-clip.md).
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(20261125);
    return {{"screen-sized", random_inputs(rng, 40, 1)}, {"1000x", random_inputs(rng, 40, 1000)}, {"huge", random_inputs(rng, 40, 1000000)}};
  }
};

SW_REGISTER(RasterClipSpec);

}  // namespace

}  // namespace sw
