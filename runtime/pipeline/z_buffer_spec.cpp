// z-buffer in the catalog: window-space triangles drawn in order through a depth buffer.
// Semantics: docs/pipeline/semantics.md.
#include <random>
#include "register.hpp"
#include "pipeline/camera_input.hpp"
#include "pipeline/z_buffer.hpp"
#include "pipeline_oracle.hpp"

namespace sw {
namespace {

using namespace pipespec;

inline constexpr std::size_t kMaxTriangles = 1024;

struct ZInput {
  std::int64_t width = 0, height = 0;
  std::vector<pipeline_oracle::DepthTriangle> tris;
  int bits = 0;
  pipe::DepthFunc func = pipe::DepthFunc::less;
  Rational clear = 1;
};

struct ZOutput {
  std::int64_t width = 0, height = 0;
  std::vector<std::int64_t> ids;
  std::vector<double> depth;
  std::vector<Rational> exact_depth;  // exact mode and the oracle
  std::int64_t fragments = 0, passed = 0, ties = 0;
  // Modes agree when every pixel shows the same triangle.
  friend bool operator==(const ZOutput& a, const ZOutput& b) { return a.ids == b.ids; }
};

ZInput parse_z(const Json& j) {
  if (!j.is_object()) throw InputError("input: expected an object with size and triangles");
  only_keys_optional(j, {"size", "triangles"}, {"depth_bits", "depth_func", "clear_depth"}, "input");
  ZInput in;
  const WindowTriangles w = parse_window_triangles(j, kMaxTriangles, true, false);
  in.width = w.width, in.height = w.height, in.tris = w.tris;
  if (j.contains("depth_bits")) {
    in.bits = static_cast<int>(parse_integer(j["depth_bits"], "input.depth_bits", 0, 24));
    if (in.bits != 0 && in.bits != 16 && in.bits != 24) throw InputError("input.depth_bits: expected 16 or 24 (or 0: depth in the number type)");
  }
  if (j.contains("depth_func")) {
    if (j["depth_func"] == "less") in.func = pipe::DepthFunc::less;
    else if (j["depth_func"] == "lequal") in.func = pipe::DepthFunc::lequal;
    else throw InputError("input.depth_func: expected \"less\" or \"lequal\" (glDepthFunc)");
  }
  if (j.contains("clear_depth")) {
    in.clear = parse_coord(j["clear_depth"], "input.clear_depth");
    if (in.clear < 0 || in.clear > 1) throw InputError("input.clear_depth: " + in.clear.get_str() + " is outside [0, 1]");
  }
  return in;
}

template <class Num> struct ZPrepared {
  std::int64_t width, height;
  std::vector<pipe::DepthTriangle<Num>> tris;
  int bits;
  pipe::DepthFunc func;
  Num clear;
};

// The samples the triangles' boxes hold inside the window: a bound on the fragments.
double window_samples(const ZInput& in) {
  double total = 0;
  for (const auto& t : in.tris) total += window_box_samples(t.v, in.width, in.height);
  return total;
}

// Seeded scenes: random triangles over a 128 x 128 window; coplanar pairs (the same plane, split
// differently: z-fighting); and near-coplanar pairs 2^-20 apart in depth, which 16 bits cannot
// tell apart.
std::vector<BenchSet<ZInput>> z_sets() {
  std::vector<BenchSet<ZInput>> sets{{"random", {}}, {"coplanar", {}}, {"near-coplanar-16bit", {}}};
  std::mt19937_64 rng(20261130);
  std::uniform_real_distribution<double> xy(-8, 136), zz(0.05, 0.95), tilt(-0.002, 0.002);
  for (int k = 0; k < 16; ++k) {
    ZInput r{128, 128, {}, 24, pipe::DepthFunc::less, 1};
    for (int i = 0; i < 32; ++i) {
      pipeline_oracle::DepthTriangle t;
      for (auto& v : t.v) v = {on_grid(xy(rng), 8), on_grid(xy(rng), 8), on_grid(zz(rng), 24)};
      t.id = i;
      r.tris.push_back(t);
    }
    sets[0].inputs.push_back(r);
    for (int set = 1; set < 3; ++set) {
      // A plane z = z0 + gx x + gy y over the window, drawn as two quads split along different diagonals.
      ZInput p{128, 128, {}, set == 1 ? 0 : 16, pipe::DepthFunc::less, 1};
      const Rational z0 = on_grid(zz(rng), 20), gx = on_grid(tilt(rng), 30), gy = on_grid(tilt(rng), 30);
      const Rational apart = set == 1 ? Rational(0) : Rational(1, 1 << 20);
      auto at = [&](int x, int y, const Rational& dz) { return std::array<Rational, 3>{Rational(x), Rational(y), z0 + gx * x + gy * y + dz}; };
      p.tris.push_back({{at(-4, -4, 0), at(131, -4, 0), at(131, 131, 0)}, 0, 0, 0});
      p.tris.push_back({{at(-4, -4, 0), at(131, 131, 0), at(-4, 131, 0)}, 1, 0, 0});
      p.tris.push_back({{at(-4, -4, -apart), at(131, -4, -apart), at(-4, 131, -apart)}, 2, 0, 0});
      p.tris.push_back({{at(131, -4, -apart), at(131, 131, -apart), at(-4, 131, -apart)}, 3, 0, 0});
      sets[set].inputs.push_back(p);
    }
  }
  return sets;
}

struct ZBufferSpec {
  static constexpr std::array hooks{Hook::error, Hook::estimate_steps};
  using Algo = pipe::ZBuffer;
  using Input = ZInput;
  using Output = ZOutput;
  static constexpr std::array views{View::plane2d, View::table};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  // A quad in one plane drawn twice, split along each diagonal, over a 16 x 12 window: exact depths
  // tie everywhere, so GL_LESS keeps the first pair; float's and double's rounded depths fight.
  static inline const std::string example =
      R"({"size":[16,12],"triangles":[{"v":[[-1,-1,"1/3"],[16,-1,"13/21"],[16,12,"86/105"]]},{"v":[[-1,-1,"1/3"],[16,12,"86/105"],[-1,12,"8/15"]]},)"
      R"({"v":[[-1,-1,"1/3"],[16,-1,"13/21"],[-1,12,"8/15"]]},{"v":[[16,-1,"13/21"],[16,12,"86/105"],[-1,12,"8/15"]]}]})";
  static Input parse(const Json& j) { return parse_z(j); }
  template <class Num> static ZPrepared<Num> prepare(const Input& in) {
    ZPrepared<Num> p{in.width, in.height, {}, in.bits, in.func, num::from_rational<Num>(in.clear)};
    for (const auto& t : in.tris) {
      pipe::DepthTriangle<Num> d;
      for (int k = 0; k < 3; ++k) d.v[k] = to_num<Num>(Vec3<Rational>{t.v[k][0], t.v[k][1], t.v[k][2]});
      d.id = t.id, d.factor = num::from_rational<Num>(t.factor), d.units = num::from_rational<Num>(t.units);
      p.tris.push_back(d);
    }
    return p;
  }
  template <class Num, class Probe> static Output compute(const ZPrepared<Num>& p, Probe& probe) {
    const auto b = pipe::z_buffer<Num>(p.width, p.height, p.tris, p.bits, p.func, p.clear, probe);
    Output o{b.width, b.height, b.id, {}, {}, b.fragments, b.passed, b.ties};
    for (const Num& d : b.depth) o.depth.push_back(num::to_double(d));
    if constexpr (std::is_same_v<Num, Rational>) o.exact_depth = b.depth;
    return o;
  }
  static Json to_json(const Output& o) {
    return Json{{"width", o.width}, {"height", o.height}, {"ids", o.ids}, {"depth", o.depth},
                {"fragments", o.fragments}, {"passed", o.passed}, {"ties", o.ties}};
  }
  static std::size_t ops(const Output& o) { return static_cast<std::size_t>(o.fragments); }
  static constexpr std::string_view error_unit = "pixels";
  static double error(const Output& got, const Output& exact) { return differing_ids(got.ids, exact.ids); }
  // Per triangle a plane, an offset and a cover step; per fragment at most three.
  static std::size_t estimate_steps(const Input& in) { return 2 + 3 * in.tris.size() + static_cast<std::size_t>(3 * window_samples(in)); }
  static Output oracle(const Input& in) {
    const auto b = pipeline_oracle::z_buffer(in.width, in.height, in.tris, in.bits, in.func == pipe::DepthFunc::lequal, in.clear);
    Output o{in.width, in.height, b.ids, {}, b.depth, b.fragments, b.passed, b.ties};
    for (const Rational& d : b.depth) o.depth.push_back(d.get_d());
    return o;
  }
  static std::vector<BenchSet<Input>> bench_sets() { return z_sets(); }
};

SW_REGISTER(ZBufferSpec);

}  // namespace
}  // namespace sw
