// The ray family's camera and inverse-mapping entries: camera-ray and sphere-uv, in float, double
// and reference (their values are transcendental). The Rational instantiation evaluates sqrt and
// trig in 300-bit MPFR: reference mode, the bench's baseline and check's replay (`oracle`). Their
// decisions (fisheye's rho > 1) are exact there: rho is an exact root when rho^2 is a rational
// square, and otherwise differs from 1 by far more than 2^-300.
#include <cmath>
#include <memory>
#include <random>
#include "register.hpp"
#include "rays/camera_ray.hpp"
#include "rays/ray_input.hpp"
#include "rays/sphere_uv.hpp"

namespace sw {
namespace {

using rays::point3;
using rays::kCoordBound;

struct CameraInput {
  Vec3<Rational> eye, vpn, vup;
  Rational dist, fov_deg;
  bool has_window = false;
  std::array<Rational, 4> window;  // umin, umax, vmin, vmax (perspective only)
  std::int64_t w = 1, h = 1, i = 0, j = 0;
  ray::Projection projection = ray::Projection::perspective;
};


CameraInput parse_camera(const Json& j) {
  only_keys(j, {"camera", "pixel", "size", "projection"}, "input");
  CameraInput in;
  const Json& c = j["camera"];
  only_keys_optional(c, {"eye", "vpn", "vup", "d"}, {"fov", "window"}, "input.camera");
  if (c.contains("fov") == c.contains("window")) throw InputError("input.camera: give exactly one of \"fov\" and \"window\" [umin, umax, vmin, vmax]");
  in.eye = point3(c["eye"], "input.camera.eye");
  in.vpn = point3(c["vpn"], "input.camera.vpn");
  in.vup = point3(c["vup"], "input.camera.vup");
  in.dist = parse_rational(c["d"], "input.camera.d");
  if (c.contains("window")) {
    const Json& w = c["window"];
    if (!w.is_array() || w.size() != 4) throw InputError("input.camera.window: expected [umin, umax, vmin, vmax]");
    in.has_window = true;
    for (std::size_t k = 0; k < 4; ++k) {
      in.window[k] = parse_rational(w[k], "input.camera.window[" + std::to_string(k) + "]");
      if (abs(in.window[k]) > Rational(kCoordBound)) throw InputError("input.camera.window[" + std::to_string(k) + "]: must be within 1e15");
    }
    if (in.window[0] >= in.window[1]) throw InputError("input.camera.window: umin must be < umax");
    if (in.window[2] >= in.window[3]) throw InputError("input.camera.window: vmin must be < vmax");
    in.fov_deg = 60;  // unused
  } else {
    in.fov_deg = parse_rational(c["fov"], "input.camera.fov");
  }
  const Vec3<Rational> side = cross(in.vup, in.vpn);
  if (sgn(in.vpn.x) == 0 && sgn(in.vpn.y) == 0 && sgn(in.vpn.z) == 0) throw InputError("input.camera.vpn: the view-plane normal is zero");
  if (sgn(side.x) == 0 && sgn(side.y) == 0 && sgn(side.z) == 0) throw InputError("input.camera.vup: parallel to vpn (or zero)");
  if (sgn(in.dist) <= 0 || in.dist > Rational(kCoordBound)) throw InputError("input.camera.d: must be in (0, 1e15]");
  const Json& proj = j["projection"];
  if (!proj.is_string()) throw InputError("input.projection: expected \"perspective\", \"fisheye\" or \"cylindrical\"");
  const std::string ps = proj.get<std::string>();
  if (ps == "perspective") in.projection = ray::Projection::perspective;
  else if (ps == "fisheye") in.projection = ray::Projection::fisheye;
  else if (ps == "cylindrical") in.projection = ray::Projection::cylindrical;
  else throw InputError("input.projection: unknown projection '" + ps + "' (perspective, fisheye, cylindrical)");
  const Rational max_fov = in.projection == ray::Projection::fisheye ? 360 : 179;
  if (in.has_window && in.projection != ray::Projection::perspective) throw InputError("input.camera.window: a window needs the perspective projection");
  if (sgn(in.fov_deg) <= 0 || in.fov_deg > max_fov) throw InputError("input.camera.fov: degrees in (0, " + max_fov.get_str() + "] for " + ps);
  const Json& size = j["size"];
  const Json& px = j["pixel"];
  if (!size.is_array() || size.size() != 2) throw InputError("input.size: expected [W, H]");
  if (!px.is_array() || px.size() != 2) throw InputError("input.pixel: expected [i, j]");
  in.w = parse_integer(size[0], "input.size[0]", 1, 1 << 20);
  in.h = parse_integer(size[1], "input.size[1]", 1, 1 << 20);
  in.i = parse_integer(px[0], "input.pixel[0]", 0, in.w - 1);
  in.j = parse_integer(px[1], "input.pixel[1]", 0, in.h - 1);
  return in;
}

// Values as doubles (the mode's values widened), plus the 300-bit reference's rationals.
struct ValuesOutput {
  bool valid = true;
  int bits = 53;
  std::vector<double> x;
  std::shared_ptr<const std::vector<Rational>> ref;
  friend bool operator==(const ValuesOutput& a, const ValuesOutput& b) { return a.valid == b.valid; }
};
template <class Num> ValuesOutput values_output(bool valid, std::initializer_list<Num> xs) {
  ValuesOutput o;
  o.valid = valid;
  if constexpr (std::is_same_v<Num, float>) o.bits = 24;
  if constexpr (std::is_same_v<Num, Rational>) {
    auto r = std::make_shared<std::vector<Rational>>();
    for (const Num& v : xs) r->push_back(num::round_bits(v, 200)), o.x.push_back(v.get_d());
    o.ref = std::move(r);
  } else {
    for (const Num& v : xs) o.x.push_back(num::to_double(v));
  }
  return o;
}
// The largest error over the values, in ulps of the mode at the largest reference value.
double values_error(const ValuesOutput& got, const ValuesOutput& ref) {
  if (!got.valid || !ref.valid || !ref.ref) return 0;
  double scale = 0, worst = 0;
  for (const Rational& r : *ref.ref) scale = std::max(scale, std::fabs(r.get_d()));
  if (scale == 0) return 0;
  for (std::size_t k = 0; k < got.x.size(); ++k)
    worst = std::max(worst, std::fabs(Rational(num::to_rational(got.x[k]) - (*ref.ref)[k]).get_d()));
  return std::ldexp(worst, got.bits - 1 - std::ilogb(scale));
}

struct CameraSpec {
  static constexpr std::array hooks{Hook::error};
  using Algo = ray::CameraRayAlgo;
  using Input = CameraInput;
  using Output = ValuesOutput;
  static constexpr std::array views{View::orbit3d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::reference};
  static inline const std::string example =
      R"({"camera":{"eye":[0,1,5],"vpn":[0,0,1],"vup":[0,1,0],"d":1,"fov":60},"pixel":[3,2],"size":[8,6],"projection":"perspective"})";
  static Input parse(const Json& j) { return parse_camera(j); }
  template <class Num> struct Prepared {
    ray::Camera<Num> cam;
    std::int64_t i, j;
  };
  template <class Num> static Prepared<Num> prepare(const Input& in) {
    ray::Camera<Num> c{to_num<Num>(in.eye), to_num<Num>(in.vpn), to_num<Num>(in.vup), num::from_rational<Num>(in.dist), Num(0), in.w, in.h, in.projection};
    if constexpr (std::is_same_v<Num, Rational>) c.fov = in.fov_deg * num::pi<Rational>() / 180;
    else c.fov = Num(num::from_rational<Num>(in.fov_deg) * Num(3.14159265358979323846 / 180));
    c.has_window = in.has_window;
    for (std::size_t k = 0; k < 4; ++k) c.window[k] = num::from_rational<Num>(in.window[k]);
    return {c, in.i, in.j};
  }
  template <class Num, class Probe> static Output compute(const Prepared<Num>& p, Probe& probe) {
    const auto r = ray::camera_ray<Num>(p.cam, p.i, p.j, probe);
    const auto& o = r.ray.o;
    const auto& d = r.ray.d;
    return values_output<Num>(r.valid, {o.x, o.y, o.z, d.x, d.y, d.z});
  }
  static Json to_json(const Output& o) {
    if (!o.valid) return Json{{"valid", false}};
    return Json{{"valid", true}, {"o", {o.x[0], o.x[1], o.x[2]}}, {"d", {o.x[3], o.x[4], o.x[5]}}};
  }
  static std::size_t ops(const Output&) { return 1; }
  static Output oracle(const Input& in) {
    NoProbe none;
    return compute<Rational>(prepare<Rational>(in), none);
  }
  static constexpr std::string_view error_unit = "ulps";
  static double error(const Output& got, const Output& ref) { return values_error(got, ref); }
  static std::vector<BenchSet<Input>> bench_sets();
};

struct SphereUVInput {
  Vec3<Rational> c, p;
  Rational r;
};
struct SphereUVSpec {
  static constexpr std::array hooks{Hook::error};
  using Algo = ray::SphereUVAlgo;
  using Input = SphereUVInput;
  using Output = ValuesOutput;
  static constexpr std::array views{View::orbit3d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::reference};
  static inline const std::string example = R"({"sphere":{"c":[0,0,0],"r":1},"point":[-0.6,0,0.8]})";
  static Input parse(const Json& j) {
    only_keys(j, {"sphere", "point"}, "input");
    only_keys(j["sphere"], {"c", "r"}, "input.sphere");
    Input in{point3(j["sphere"]["c"], "input.sphere.c"), point3(j["point"], "input.point"), parse_rational(j["sphere"]["r"], "input.sphere.r")};
    if (sgn(in.r) <= 0) throw InputError("input.sphere.r: the radius must be > 0, got " + in.r.get_str());
    if (in.p == in.c) throw InputError("input.point: equals the centre (no direction to map)");
    return in;
  }
  template <class Num> static std::array<Vec3<Num>, 2> prepare(const Input& in) { return {to_num<Num>(in.c), to_num<Num>(in.p)}; }
  template <class Num, class Probe> static Output compute(const std::array<Vec3<Num>, 2>& x, Probe& probe) {
    const auto m = ray::sphere_uv<Num>(x[0], x[1], probe);
    return values_output<Num>(true, {m.normal.x, m.normal.y, m.normal.z, m.lat, m.lon, m.u, m.v});
  }
  static Json to_json(const Output& o) {
    return Json{{"normal", {o.x[0], o.x[1], o.x[2]}}, {"lat", o.x[3]}, {"lon", o.x[4]}, {"u", o.x[5]}, {"v", o.x[6]}};
  }
  static std::size_t ops(const Output&) { return 1; }
  static Output oracle(const Input& in) {
    NoProbe none;
    return compute<Rational>(prepare<Rational>(in), none);
  }
  static constexpr std::string_view error_unit = "ulps";
  static double error(const Output& got, const Output& ref) { return values_error(got, ref); }
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(77);
    auto u = [&](double lo, double hi) { return num::to_rational(double(float(std::uniform_real_distribution<double>(lo, hi)(rng)))); };
    BenchSet<Input> random{"random", {}}, hard{"hard", {}};
    for (int k = 0; k < 5000; ++k) random.inputs.push_back({{u(-5, 5), u(-5, 5), u(-5, 5)}, {u(-9, 9), u(-9, 9), u(-9, 9)}, 1});
    // The seam (y = 0, x < 0), the poles, and points very close to them.
    for (int k = 0; k < 1000; ++k) {
      const Rational x = u(-2, -0.1), z = u(-1, 1), tiny = k % 3 == 0 ? Rational(0) : u(-1e-6, 1e-6);
      hard.inputs.push_back({{0, 0, 0}, {x, tiny, z}, 1});
      hard.inputs.push_back({{0, 0, 0}, {tiny, Rational(tiny * 3), z + (sgn(z) >= 0 ? 1 : -1)}, 1});
    }
    return {random, hard};
  }
};

std::vector<BenchSet<CameraInput>> CameraSpec::bench_sets() {
  // Random cameras and pixels for each projection; the hard set: the image corners and edges,
  // wide angles (fisheye up to 360 degrees, at the circle's rim), and far eyes.
  std::mt19937_64 rng(91);
  auto u = [&](double lo, double hi) { return num::to_rational(double(float(std::uniform_real_distribution<double>(lo, hi)(rng)))); };
  auto camera = [&](ray::Projection p, bool hard) {
    CameraInput c;
    const double far = hard ? 1e7 : 10;
    c.eye = {u(-far, far), u(-far, far), u(-far, far)};
    c.vpn = {u(-1, 1), u(-1, 1), u(-1, 1)};
    c.vup = {u(-1, 1), u(-1, 1), u(-1, 1)};
    c.dist = u(0.5, 3);
    c.projection = p;
    c.fov_deg = p == ray::Projection::fisheye ? (hard ? Rational(360) : u(60, 200)) : (hard ? Rational(170) : u(20, 120));
    c.w = 640, c.h = 480;
    const bool edge = hard && rng() % 2;
    c.i = edge ? std::int64_t(rng() % 2) * 639 : std::int64_t(rng() % 640);
    c.j = edge ? std::int64_t(rng() % 2) * 479 : std::int64_t(rng() % 480);
    if (hard && p == ray::Projection::fisheye) c.j = 239 + std::int64_t(rng() % 2), c.i = std::int64_t(rng() % 2) ? 80 : 559;  // near the rim
    return c;
  };
  BenchSet<CameraInput> random{"random", {}}, hard{"hard", {}};
  for (auto p : {ray::Projection::perspective, ray::Projection::fisheye, ray::Projection::cylindrical})
    for (int k = 0; k < 1500; ++k) random.inputs.push_back(camera(p, false)), hard.inputs.push_back(camera(p, true));
  return {random, hard};
}
SW_REGISTER(CameraSpec);
SW_REGISTER(SphereUVSpec);

}  // namespace

}  // namespace sw
