// raster-clip in the catalog (registered by specs.cpp): the double-DDA triangle fill clipped to a
// screen at rasterization time. Semantics, bounds and figures: docs/fill/raster-clip.md.
#include <random>
#include "adapter.hpp"
#include "fill/raster_clip.hpp"
#include "fill_oracle.hpp"
#include "fill_raster_oracle.hpp"
#include "pixels.hpp"

namespace sw {
namespace {

// Vertices may lie far off the screen: |x|, |y| <= 2^40 (the other fills: 2^30). Exact and
// filtered are exact at any size; double's crossings on screen are off by about 2^-13 pixel at
// 2^40, and float cannot even hold such vertices (its spacing there is 2^16): docs/fill/raster-clip.md.
constexpr double kVertexBound = 1099511627776.0;  // 2^40
constexpr double kAttrBound = 1073741824.0;       // 2^30, as the other fills' attributes
constexpr std::int64_t kScreenBound = 1073741824;  // 2^30: |i0|, |j0|, |i1|, |j1|
constexpr double kMaxScreenSamples = 1048576.0;    // 2^20 samples on the screen: the pixel budget

struct RasterClipInput {
  std::array<Vec2<Rational>, 3> v;
  std::vector<std::vector<Rational>> attrs;  // empty, or 3 lists of n values
  fill::Screen screen;
};

// Pixels in scanline order and, with attributes, n values per pixel (widened to double; exact
// mode's and the oracle's also as rationals). Modes are compared by their pixels.
struct ClipFillOutput {
  std::vector<Pixel> pixels;
  std::size_t n = 0;
  std::vector<double> values;
  std::vector<Rational> exact_values;
  friend bool operator==(const ClipFillOutput& a, const ClipFillOutput& b) { return a.pixels == b.pixels; }
};

Vec2<Rational> parse_vertex(const Json& v, const std::string& what) {
  if (!v.is_array() || v.size() != 2) throw InputError(what + ": expected [x, y]");
  Vec2<Rational> p;
  for (int a = 0; a < 2; ++a) {
    const std::string w = what + "[" + std::to_string(a) + "]";
    p[a] = parse_rational(v[a], w);
    check_bound(p[a], kVertexBound, w);
    check_digits(p[a], w);
  }
  return p;
}

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
  if (samples > kMaxScreenSamples)
    throw InputError("input.viewport: holds " + std::to_string(static_cast<long long>(samples)) + " samples, more than the budget of 2^20");
  return s;
}

RasterClipInput parse_input(const Json& j) {
  only_keys_optional(j, {"triangle", "viewport"}, {"attrs"}, "input");
  const Json& t = j["triangle"];
  if (!t.is_array() || t.size() != 3) throw InputError("input.triangle: expected three vertices [[x,y],[x,y],[x,y]]");
  RasterClipInput in;
  for (int k = 0; k < 3; ++k) in.v[k] = parse_vertex(t[k], "input.triangle[" + std::to_string(k) + "]");
  in.screen = parse_viewport(j["viewport"]);
  if (j.contains("attrs")) {
    const Json& a = j["attrs"];
    if (!a.is_array() || a.size() != 3) throw InputError("input.attrs: expected one list of numbers per vertex (three lists)");
    for (int k = 0; k < 3; ++k) {
      const std::string what = "input.attrs[" + std::to_string(k) + "]";
      if (!a[k].is_array() || a[k].empty() || a[k].size() > fill::kMaxAttrs) throw InputError(what + ": expected a list of 1 to 8 numbers");
      if (k > 0 && a[k].size() != a[0].size())
        throw InputError(what + ": has " + std::to_string(a[k].size()) + " values, input.attrs[0] has " + std::to_string(a[0].size()) + " (every vertex needs the same count)");
      in.attrs.emplace_back();
      for (std::size_t c = 0; c < a[k].size(); ++c) {
        const std::string w = what + "[" + std::to_string(c) + "]";
        in.attrs.back().push_back(parse_rational(a[k][c], w));
        check_bound(in.attrs.back().back(), kAttrBound, w);
        check_digits(in.attrs.back().back(), w);
      }
    }
  }
  return in;
}

template <class Num> struct ClipTriangle {
  fill::Triangle<Num> t;
  fill::Screen screen;
};

// Wrong pixels against exact: the symmetric difference (both in scanline order).
double wrong_pixels(const ClipFillOutput& got, const ClipFillOutput& exact) {
  std::vector<Pixel> a = got.pixels, b = exact.pixels, diff;
  auto row_major = [](Pixel p, Pixel q) { return std::pair(p.y, p.x) < std::pair(q.y, q.x); };
  std::sort(a.begin(), a.end(), row_major);
  std::sort(b.begin(), b.end(), row_major);
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(diff), row_major);
  return static_cast<double>(diff.size());
}

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
  static constexpr std::array hooks{Hook::handles, Hook::error, Hook::estimate_steps};
  using Algo = fill::RasterClip;
  using Input = RasterClipInput;
  using Output = ClipFillOutput;
  static constexpr std::string_view family = "fill";
  static constexpr std::array views{View::plane2d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example =
      R"({"triangle":[[-6.5,-3.25],[30.75,6.5],[3,40.5]],"viewport":{"min":[0,0],"max":[16,12]},"attrs":[[1,0,0],[0,1,0],[0,0,1]]})";
  static Input parse(const Json& j, Numeric) { return parse_input(j); }
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
    Output o{std::move(r.pixels), c.t[0].n, {}, {}};
    for (const Num& v : r.values) o.values.push_back(num::to_double(v));
    if constexpr (std::is_same_v<Num, Rational>) o.exact_values = std::move(r.values);
    return o;
  }
  static Json to_json(const Output& o) {
    Json r = pixels_json("pixels", {o.pixels});
    if (o.n == 0) return r;
    Json vs = Json::array();
    for (std::size_t p = 0; p < o.pixels.size(); ++p) vs.push_back(std::vector<double>(o.values.begin() + p * o.n, o.values.begin() + (p + 1) * o.n));
    r["values"] = std::move(vs);
    return r;
  }
  static std::size_t ops(const Output& o) { return o.pixels.size(); }
  static double error(const Output& got, const Output& exact) { return wrong_pixels(got, exact); }
  // The screen's samples (a plot and a step each at most) and, per screen row, a row and a span.
  static std::size_t estimate_steps(const Input& in) {
    const auto& s = in.screen;
    return static_cast<std::size_t>(2 * (s.i1 - s.i0) * (s.j1 - s.j0) + 4 * (s.j1 - s.j0) + 64);
  }
  // The covered samples on the screen, by brute force over the screen's samples only, and at each
  // the plane through the vertices' attributes.
  static Output oracle(const Input& in) {
    const auto& s = in.screen;
    Output o{oracle::triangle_samples_in_window(in.v, {s.i0, s.j0, s.i1, s.j1}), in.attrs.empty() ? 0 : in.attrs[0].size(), {}, {}};
    for (const Pixel& p : o.pixels)
      for (std::size_t c = 0; c < o.n; ++c) o.exact_values.push_back(oracle::linear_at(in.v, {in.attrs[0][c], in.attrs[1][c], in.attrs[2][c]}, p));
    for (const Rational& v : o.exact_values) o.values.push_back(v.get_d());
    return o;
  }
  // A 256 x 256 screen and triangles about its size, then 10^3 and 10^6 times its width: the time
  // per pixel on screen stays the same (docs/fill/raster-clip.md).
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(20261125);
    return {{"screen-sized", random_inputs(rng, 40, 1)}, {"1000x", random_inputs(rng, 40, 1000)}, {"huge", random_inputs(rng, 40, 1000000)}};
  }
};

}  // namespace

void register_raster_clip(std::vector<Algorithm>& out) { out.push_back(make_algorithm<RasterClipSpec>()); }

}  // namespace sw
