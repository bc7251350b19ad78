// blend in the catalog: transparent triangles in the given and in painter's order.
// Semantics: docs/pipeline/semantics.md.
#include <numeric>
#include <random>
#include "register.hpp"
#include "pipeline/blend.hpp"
#include "pipeline/camera_input.hpp"
#include "pipeline_oracle.hpp"

namespace sw {
namespace {

using namespace pipespec;

inline constexpr std::int64_t kMaxBlendSide = 256;
inline constexpr std::size_t kMaxBlendTriangles = 64;  // the painter's order is one recorded list

struct BlendInput {
  std::int64_t width = 0, height = 0;
  std::vector<pipeline_oracle::BlendTriangle> tris;
  std::array<Rational, 3> background{0, 0, 0};
  bool depth_write = true;
};

struct BlendOutput {
  std::int64_t width = 0, height = 0;
  std::vector<std::array<double, 3>> given, sorted;
  std::vector<std::array<Rational, 3>> exact_given, exact_sorted;  // exact mode and the oracle
  std::vector<std::int64_t> painter;
  std::int64_t differ = 0;
  // Modes agree on the decisions: the painter's order (the depth tests show in the colours).
  friend bool operator==(const BlendOutput& a, const BlendOutput& b) { return a.painter == b.painter; }
};

Rational unit_value(const Json& v, const std::string& what) {
  Rational x = parse_coord(v, what);
  if (x < 0 || x > 1) throw InputError(what + ": " + x.get_str() + " is outside [0, 1]");
  return x;
}
std::array<Rational, 3> parse_rgb(const Json& v, const std::string& what) {
  if (!v.is_array() || v.size() != 3) throw InputError(what + ": expected [r, g, b] in [0, 1]");
  return {unit_value(v[0], what + "[0]"), unit_value(v[1], what + "[1]"), unit_value(v[2], what + "[2]")};
}

BlendInput parse_blend(const Json& j) {
  if (!j.is_object()) throw InputError("input: expected an object with size and triangles");
  only_keys_optional(j, {"size", "triangles"}, {"background", "depth_write"}, "input");
  BlendInput in;
  const Json& size = j["size"];
  if (!size.is_array() || size.size() != 2) throw InputError("input.size: expected [width, height]");
  in.width = parse_integer(size[0], "input.size[0]", 1, kMaxBlendSide);
  in.height = parse_integer(size[1], "input.size[1]", 1, kMaxBlendSide);
  if (j.contains("background")) in.background = parse_rgb(j["background"], "input.background");
  if (j.contains("depth_write")) {
    if (!j["depth_write"].is_boolean()) throw InputError("input.depth_write: expected true or false (glDepthMask)");
    in.depth_write = j["depth_write"].get<bool>();
  }
  const Json& ts = require(j, "triangles", "input");
  if (!ts.is_array() || ts.empty() || ts.size() > kMaxBlendTriangles)
    throw InputError("input.triangles: expected a list of 1 to " + std::to_string(kMaxBlendTriangles) + " triangles");
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const std::string what = "input.triangles[" + std::to_string(i) + "]";
    const Json& t = ts[i];
    if (!t.is_object()) throw InputError(what + R"(: expected {"v": [[x,y,z],[x,y,z],[x,y,z]], "rgb": [r,g,b], "alpha": a})");
    only_keys(t, {"v", "rgb", "alpha"}, what);
    pipeline_oracle::BlendTriangle b;
    if (!t["v"].is_array() || t["v"].size() != 3) throw InputError(what + ".v: expected three vertices [x, y, z]");
    for (int k = 0; k < 3; ++k) {
      const std::string w = what + ".v[" + std::to_string(k) + "]";
      b.v[k] = arr_of(parse_coord3(t["v"][k], w));
      for (int a = 0; a < 2; ++a) check_bound(b.v[k][a], 1e5, w + "[" + std::to_string(a) + "]");
      if (b.v[k][2] < 0 || b.v[k][2] > 1) throw InputError(w + "[2]: depth " + b.v[k][2].get_str() + " is outside [0, 1] (clip first)");
    }
    b.rgb = parse_rgb(t["rgb"], what + ".rgb");
    b.alpha = unit_value(t["alpha"], what + ".alpha");
    in.tris.push_back(b);
  }
  return in;
}

template <class Num> struct BlendPrepared {
  std::int64_t width, height;
  std::vector<pipe::BlendTriangle<Num>> tris;
  Vec3<Num> background;
  bool depth_write;
};

template <class Num> Vec3<Num> vec_of(const std::array<Rational, 3>& a) { return to_num<Num>(Vec3<Rational>{a[0], a[1], a[2]}); }

// Seeded scenes of 16 transparent triangles over 64 x 64, with depth writes on and off.
std::vector<BenchSet<BlendInput>> blend_sets() {
  std::vector<BenchSet<BlendInput>> sets{{"depth-write", {}}, {"no-depth-write", {}}};
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> xy(-4, 68), u(0, 1);
  for (int k = 0; k < 16; ++k)
    for (int set = 0; set < 2; ++set) {
      BlendInput in{64, 64, {}, {0, 0, 0}, set == 0};
      for (int i = 0; i < 16; ++i) {
        pipeline_oracle::BlendTriangle t;
        for (auto& v : t.v) v = {on_grid(xy(rng), 8), on_grid(xy(rng), 8), on_grid(u(rng), 16)};
        t.rgb = {on_grid(u(rng), 8), on_grid(u(rng), 8), on_grid(u(rng), 8)};
        t.alpha = on_grid(0.2 + 0.6 * u(rng), 8);
        in.tris.push_back(t);
      }
      sets[set].inputs.push_back(in);
    }
  return sets;
}

struct BlendSpec {
  static constexpr std::array hooks{Hook::error, Hook::estimate_steps};
  using Algo = pipe::Blend;
  using Input = BlendInput;
  using Output = BlendOutput;
  static constexpr std::array views{View::plane2d, View::table};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  // A red and a blue half-transparent triangle over a white background, the nearer (blue) listed first.
  static inline const std::string example =
      R"({"size":[12,10],"background":[1,1,1],"triangles":[{"v":[[1,1,0.25],[11,2,0.25],[4,9,0.25]],"rgb":[0,0,1],"alpha":0.5},)"
      R"({"v":[[0,4,0.75],[10,0,0.75],[9,9,0.75]],"rgb":[1,0,0],"alpha":0.5}]})";
  static Input parse(const Json& j) { return parse_blend(j); }
  template <class Num> static BlendPrepared<Num> prepare(const Input& in) {
    BlendPrepared<Num> p{in.width, in.height, {}, vec_of<Num>(in.background), in.depth_write};
    for (const auto& t : in.tris) {
      pipe::BlendTriangle<Num> b;
      for (int k = 0; k < 3; ++k) b.v[k] = vec_of<Num>(t.v[k]);
      b.rgb = vec_of<Num>(t.rgb), b.alpha = num::from_rational<Num>(t.alpha);
      p.tris.push_back(b);
    }
    return p;
  }
  template <class Num, class Probe> static Output compute(const BlendPrepared<Num>& p, Probe& probe) {
    const auto r = pipe::blend<Num>(p.width, p.height, p.tris, p.background, p.depth_write, probe);
    Output o{p.width, p.height, {}, {}, {}, {}, std::vector<std::int64_t>(r.painter.begin(), r.painter.end()), r.differ};
    auto doubles = [](const Vec3<Num>& c) { return std::array<double, 3>{num::to_double(c.x), num::to_double(c.y), num::to_double(c.z)}; };
    for (std::size_t k = 0; k < r.given.colour.size(); ++k) {
      o.given.push_back(doubles(r.given.colour[k])), o.sorted.push_back(doubles(r.sorted.colour[k]));
      if constexpr (std::is_same_v<Num, Rational>) {
        const auto &g = r.given.colour[k], &s = r.sorted.colour[k];
        o.exact_given.push_back({g.x, g.y, g.z}), o.exact_sorted.push_back({s.x, s.y, s.z});
      }
    }
    return o;
  }
  static Json to_json(const Output& o) {
    return Json{{"width", o.width}, {"height", o.height}, {"given", o.given}, {"sorted", o.sorted}, {"painter", o.painter}, {"differ", o.differ}};
  }
  static std::size_t ops(const Output& o) { return o.given.size(); }
  // The worst colour channel against exact, over both pictures, in steps of 8-bit colour.
  static constexpr std::string_view error_unit = "1/255 steps";
  static double error(const Output& got, const Output& exact) {
    double worst = 0;
    const bool has_exact = !got.exact_given.empty();
    for (std::size_t k = 0; k < got.given.size() && k < exact.exact_given.size(); ++k)
      for (int a = 0; a < 3; ++a) {
        const Rational g = has_exact ? got.exact_given[k][a] : num::to_rational(got.given[k][a]);
        const Rational s = has_exact ? got.exact_sorted[k][a] : num::to_rational(got.sorted[k][a]);
        worst = std::max(worst, std::abs(Rational(g - exact.exact_given[k][a]).get_d()) * 255);
        worst = std::max(worst, std::abs(Rational(s - exact.exact_sorted[k][a]).get_d()) * 255);
      }
    return worst;
  }
  static std::size_t estimate_steps(const Input& in) {
    double samples = 0;
    for (const auto& t : in.tris) samples += window_box_samples(t.v, in.width, in.height);
    return 4 + 2 * in.tris.size() + static_cast<std::size_t>(6 * samples);
  }
  static Output oracle(const Input& in) {
    std::vector<std::size_t> given(in.tris.size());
    std::iota(given.begin(), given.end(), std::size_t(0));
    std::vector<std::size_t> painter = given;
    auto centroid = [&](std::size_t t) { return Rational(in.tris[t].v[0][2] + in.tris[t].v[1][2] + in.tris[t].v[2][2]); };
    std::stable_sort(painter.begin(), painter.end(), [&](std::size_t a, std::size_t b) { return centroid(b) < centroid(a); });
    Output o{in.width, in.height, {}, {}, pipeline_oracle::blend(in.width, in.height, in.tris, given, in.background, in.depth_write),
             pipeline_oracle::blend(in.width, in.height, in.tris, painter, in.background, in.depth_write),
             std::vector<std::int64_t>(painter.begin(), painter.end()), 0};
    for (std::size_t k = 0; k < o.exact_given.size(); ++k) {
      const auto &g = o.exact_given[k], &s = o.exact_sorted[k];
      o.given.push_back({g[0].get_d(), g[1].get_d(), g[2].get_d()}), o.sorted.push_back({s[0].get_d(), s[1].get_d(), s[2].get_d()});
      o.differ += g != s;
    }
    return o;
  }
  static std::vector<BenchSet<Input>> bench_sets() { return blend_sets(); }
};

SW_REGISTER(BlendSpec);

}  // namespace
}  // namespace sw
