// fog in the catalog: GL's fog factor per fragment. Semantics: docs/pipeline/semantics.md.
#include <random>
#include "register.hpp"
#include "pipeline/camera_input.hpp"
#include "pipeline/fog.hpp"
#include "pipeline_oracle.hpp"

namespace sw {
namespace {

using namespace pipespec;

inline constexpr std::size_t kMaxFragments = 4096;

struct FogInput {
  pipe::FogParams<Rational> params;
  std::vector<pipe::Fragment<Rational>> frags;
};

struct FogOutput {
  std::vector<double> f;
  std::vector<std::array<double, 3>> rgb;
  std::vector<Rational> exact_f;  // reference mode and the oracle
  std::vector<int> clamped;       // -1: f = 0 (all fog), 1: f = 1 (no fog), 0: between
  friend bool operator==(const FogOutput& a, const FogOutput& b) { return a.clamped == b.clamped; }
};

Rational unit_of(const Json& v, const std::string& what) {
  Rational x = parse_coord(v, what);
  if (x < 0 || x > 1) throw InputError(what + ": " + x.get_str() + " is outside [0, 1]");
  return x;
}
Vec3<Rational> rgb_of(const Json& v, const std::string& what) {
  if (!v.is_array() || v.size() != 3) throw InputError(what + ": expected [r, g, b] in [0, 1]");
  return {unit_of(v[0], what + "[0]"), unit_of(v[1], what + "[1]"), unit_of(v[2], what + "[2]")};
}

FogInput parse_fog(const Json& j) {
  if (!j.is_object()) throw InputError("input: expected an object with fog and fragments");
  only_keys(j, {"fog", "fragments"}, "input");
  FogInput in;
  const Json& f = j["fog"];
  if (!f.is_object()) throw InputError(R"(input.fog: expected {"mode": "linear"|"exp"|"exp2", "start", "end", "density", "rgb"})");
  only_keys_optional(f, {"mode", "rgb"}, {"start", "end", "density"}, "input.fog");
  pipe::FogParams<Rational>& p = in.params;
  if (f["mode"] == "linear") p.mode = pipe::FogMode::linear;
  else if (f["mode"] == "exp") p.mode = pipe::FogMode::exp;
  else if (f["mode"] == "exp2") p.mode = pipe::FogMode::exp2;
  else throw InputError("input.fog.mode: expected \"linear\", \"exp\" or \"exp2\" (GL_FOG_MODE)");
  p.rgb = rgb_of(f["rgb"], "input.fog.rgb");
  if (f.contains("start")) p.start = parse_coord(f["start"], "input.fog.start");
  if (f.contains("end")) p.end = parse_coord(f["end"], "input.fog.end");
  if (f.contains("density")) p.density = parse_coord(f["density"], "input.fog.density");
  if (p.mode == pipe::FogMode::linear && p.start == p.end) throw InputError("input.fog: start equals end, so linear fog divides by zero");
  if (p.density < 0) throw InputError("input.fog.density: must not be negative (GL refuses it)");
  const Json& fs = require(j, "fragments", "input");
  if (!fs.is_array() || fs.empty() || fs.size() > kMaxFragments)
    throw InputError("input.fragments: expected a list of 1 to " + std::to_string(kMaxFragments) + " fragments {\"c\": distance, \"rgb\": [r,g,b]}");
  for (std::size_t i = 0; i < fs.size(); ++i) {
    const std::string what = "input.fragments[" + std::to_string(i) + "]";
    if (!fs[i].is_object()) throw InputError(what + R"(: expected {"c": distance, "rgb": [r,g,b]})");
    only_keys(fs[i], {"c", "rgb"}, what);
    const Rational c = parse_coord(fs[i]["c"], what + ".c");
    if (c < 0) throw InputError(what + ".c: a distance must not be negative");
    in.frags.push_back({c, rgb_of(fs[i]["rgb"], what + ".rgb")});
  }
  return in;
}

template <class Num> struct FogPrepared {
  pipe::FogParams<Num> params;
  std::vector<pipe::Fragment<Num>> frags;
};

// Fragments at seeded distances over [0, 100] (and beyond the linear fog's range), each mode.
std::vector<BenchSet<FogInput>> fog_sets() {
  std::vector<BenchSet<FogInput>> sets{{"linear", {}}, {"exp", {}}, {"exp2", {}}};
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> dist(0, 120), u(0, 1);
  auto q = [](double v) { return on_grid(v, 16); };
  for (int k = 0; k < 32; ++k)
    for (int m = 0; m < 3; ++m) {
      FogInput in{{static_cast<pipe::FogMode>(m), Rational(10), Rational(100), Rational(1, 32), Vec3<Rational>{q(0.5), q(0.5), q(0.5)}}, {}};
      for (int i = 0; i < 64; ++i) in.frags.push_back({q(dist(rng)), Vec3<Rational>{q(u(rng)), q(u(rng)), q(u(rng))}});
      sets[m].inputs.push_back(in);
    }
  return sets;
}

struct FogSpec {
  static constexpr std::array hooks{Hook::error, Hook::table_lines, Hook::estimate_steps};
  using Algo = pipe::FogAlgo;
  using Input = FogInput;
  using Output = FogOutput;
  static constexpr std::array views{View::table, View::plot};
  // Reference: rationals with e^x to 300 bits, so linear fog is exact in it (as the lighting models).
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::reference};
  static constexpr std::array<std::string_view, 1> table_lines{"fragment"};  // one row per fragment
  // Grey exponential-squared fog over five red fragments from 0 to 40 units away.
  static inline const std::string example =
      R"({"fog":{"mode":"exp2","density":0.05,"rgb":[0.5,0.5,0.5]},"fragments":[{"c":0,"rgb":[1,0,0]},{"c":10,"rgb":[1,0,0]},)"
      R"({"c":20,"rgb":[1,0,0]},{"c":30,"rgb":[1,0,0]},{"c":40,"rgb":[1,0,0]}]})";
  static Input parse(const Json& j) { return parse_fog(j); }
  static std::size_t estimate_steps(const Input& in) { return 4 * in.frags.size(); }
  template <class Num> static FogPrepared<Num> prepare(const Input& in) {
    FogPrepared<Num> p;
    const auto& q = in.params;
    p.params = {q.mode, num::from_rational<Num>(q.start), num::from_rational<Num>(q.end), num::from_rational<Num>(q.density), to_num<Num>(q.rgb)};
    for (const auto& f : in.frags) p.frags.push_back({num::from_rational<Num>(f.c), to_num<Num>(f.rgb)});
    return p;
  }
  template <class Num, class Probe> static Output compute(const FogPrepared<Num>& p, Probe& probe) {
    const auto r = pipe::fog<Num>(p.params, p.frags, probe);
    Output o;
    for (std::size_t i = 0; i < r.size(); ++i) {
      o.f.push_back(num::to_double(r[i].f));
      o.rgb.push_back({num::to_double(r[i].rgb.x), num::to_double(r[i].rgb.y), num::to_double(r[i].rgb.z)});
      if constexpr (std::is_same_v<Num, Rational>) o.exact_f.push_back(r[i].f);
      o.clamped.push_back(r[i].f == Num(0) ? -1 : r[i].f == Num(1) ? 1 : 0);
    }
    return o;
  }
  static Json to_json(const Output& o) { return Json{{"f", o.f}, {"rgb", o.rgb}}; }
  static std::size_t ops(const Output& o) { return o.f.size(); }
  static constexpr std::string_view error_unit = "1/255 steps of f";
  static double error(const Output& got, const Output& exact) {
    double worst = 0;
    for (std::size_t i = 0; i < got.f.size() && i < exact.exact_f.size(); ++i) {
      const Rational mine = got.exact_f.empty() ? num::to_rational(got.f[i]) : got.exact_f[i];
      worst = std::max(worst, std::abs(Rational(mine - exact.exact_f[i]).get_d()) * 255);
    }
    return worst;
  }
  static Output oracle(const Input& in) {
    Output o;
    const auto& p = in.params;
    for (const auto& q : in.frags) {
      const Rational f = pipeline_oracle::fog_factor(static_cast<int>(p.mode), p.start, p.end, p.density, q.c);
      o.exact_f.push_back(f), o.f.push_back(f.get_d());
      std::array<double, 3> c;
      for (int a = 0; a < 3; ++a) c[a] = Rational(f * q.rgb[a] + (1 - f) * p.rgb[a]).get_d();
      o.rgb.push_back(c);
      o.clamped.push_back(f == 0 ? -1 : f == 1 ? 1 : 0);
    }
    return o;
  }
  static std::vector<BenchSet<Input>> bench_sets() { return fog_sets(); }
};

SW_REGISTER(FogSpec);

}  // namespace
}  // namespace sw
