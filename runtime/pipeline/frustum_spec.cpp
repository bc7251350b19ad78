// frustum-cull in the catalog: bounding volumes against the view volume's six planes.
// Semantics: docs/pipeline/semantics.md.
#include <random>
#include "register.hpp"
#include "pipeline/camera_input.hpp"
#include "pipeline/frustum_cull.hpp"
#include "pipeline_oracle.hpp"

namespace sw {
namespace {

using namespace pipespec;

struct FrustumInput {
  CameraInput camera;
  std::vector<pipe::Bounds<Rational>> objects;
};

struct FrustumOutput {
  std::vector<pipe::Cull> states;
  friend bool operator==(const FrustumOutput&, const FrustumOutput&) = default;
};

pipe::Bounds<Rational> parse_bounds(const Json& o, const std::string& what) {
  using K = pipe::Bounds<Rational>::Kind;
  if (!o.is_object() || o.size() != 1)
    throw InputError(what + R"(: expected {"sphere": {"center", "radius"}}, {"aabb": {"min", "max"}} or {"obb": {"center", "axes"}})");
  pipe::Bounds<Rational> b;
  const std::string kind = o.begin().key();
  const Json& v = o.begin().value();
  const std::string w = what + "." + kind;
  if (!v.is_object()) throw InputError(w + ": expected an object");
  if (kind == "sphere") {
    only_keys(v, {"center", "radius"}, w);
    b.kind = K::sphere, b.c = parse_coord3(v["center"], w + ".center"), b.r = parse_coord(v["radius"], w + ".radius");
    if (b.r < 0) throw InputError(w + ".radius: must not be negative");
  } else if (kind == "aabb") {
    only_keys(v, {"min", "max"}, w);
    b.kind = K::aabb, b.lo = parse_coord3(v["min"], w + ".min"), b.hi = parse_coord3(v["max"], w + ".max");
    for (int a = 0; a < 3; ++a)
      if (b.hi[a] < b.lo[a]) throw InputError(w + ": min exceeds max in coordinate " + std::to_string(a));
  } else if (kind == "obb") {
    only_keys(v, {"center", "axes"}, w);
    b.kind = K::obb, b.c = parse_coord3(v["center"], w + ".center");
    const Json& axes = v["axes"];
    if (!axes.is_array() || axes.size() != 3) throw InputError(w + ".axes: expected three half-extent vectors [[x,y,z],[x,y,z],[x,y,z]]");
    for (int a = 0; a < 3; ++a) b.h[a] = parse_coord3(axes[a], w + ".axes[" + std::to_string(a) + "]");
    for (int a = 0; a < 3; ++a)
      for (int c = a + 1; c < 3; ++c)
        if (dot(b.h[a], b.h[c]) != 0) throw InputError(w + ".axes: axes " + std::to_string(a) + " and " + std::to_string(c) + " are not orthogonal");
  } else {
    throw InputError(what + ": unknown volume \"" + one_line(kind, 40) + "\" (expected sphere, aabb or obb)");
  }
  return b;
}

FrustumInput parse_frustum(const Json& j) {
  if (!j.is_object()) throw InputError("input: expected an object with camera, projection, viewport and objects");
  only_keys_optional(j, {"camera", "projection", "viewport", "objects"}, {"depth_range"}, "input");
  FrustumInput in;
  in.camera = parse_camera(j);
  const Json& os = primitive_list(j, "objects", "bounding volumes");
  for (std::size_t i = 0; i < os.size(); ++i) in.objects.push_back(parse_bounds(os[i], "input.objects[" + std::to_string(i) + "]"));
  return in;
}

template <class Num> struct FrustumPrepared {
  pipe::Camera<Num> cam;
  std::vector<pipe::Bounds<Num>> objects;
};

// The eight corners of an axis-aligned or oriented box.
std::array<std::array<Rational, 3>, 8> corners_of(const pipe::Bounds<Rational>& b) {
  std::array<std::array<Rational, 3>, 8> out;
  for (int k = 0; k < 8; ++k) {
    Vec3<Rational> p;
    if (b.kind == pipe::Bounds<Rational>::Kind::aabb) p = {(k & 1 ? b.hi : b.lo).x, (k & 2 ? b.hi : b.lo).y, (k & 4 ? b.hi : b.lo).z};
    else {
      p = b.c;
      for (int a = 0; a < 3; ++a) p = p + Rational(k >> a & 1 ? 1 : -1) * b.h[a];
    }
    out[k] = arr_of(p);
  }
  return out;
}

// Random volumes around a random camera's view volume, and volumes touching its near or far plane
// exactly (those planes' normals are the camera's unit forward), where a rounded test may cull
// what touches the view volume.
std::vector<BenchSet<FrustumInput>> frustum_sets() {
  using K = pipe::Bounds<Rational>::Kind;
  std::vector<BenchSet<FrustumInput>> sets{{"random", {}}, {"touching", {}}};
  CameraGen cams(20261129);
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> size(0.1, 4);
  auto q = [](double v) { return on_grid(v, 16); };
  for (int k = 0; k < 64; ++k)
    for (int set = 0; set < 2; ++set) {
      FrustumInput in{cams.next(Rational(10), Rational(1), Rational(100), 1024, 1024), {}};
      const pipe::Frame<Rational> fr = pipe::look_frame(in.camera.cam.look);
      for (int i = 0; i < 64; ++i) {
        pipe::Bounds<Rational> b;
        const Rational r = q(size(rng));
        Vec3<Rational> c = volume_point(in.camera, rng, 0.5, 110);
        if (set == 1) {  // the centre moved along f to touch the near (i even) or far plane from outside
          const Vec3<Rational> eye = in.camera.cam.look.eye;
          const Rational d = dot(fr.f, c - eye), plane = i % 2 == 0 ? Rational(1) - r : Rational(100) + r;
          c = c + (plane - d) * fr.f;
        }
        switch (i % 3) {
          case 0: b.kind = K::sphere, b.c = c, b.r = r; break;
          case 1: b.kind = K::obb, b.c = c, b.h = {r * fr.s, r * fr.u, r * fr.f}; break;
          default: b.kind = K::aabb, b.lo = c - Vec3<Rational>{r, r, r}, b.hi = c + Vec3<Rational>{r, r, r}; break;
        }
        in.objects.push_back(b);
      }
      sets[set].inputs.push_back(std::move(in));
    }
  return sets;
}

struct FrustumSpec {
  static constexpr std::array hooks{Hook::error, Hook::admit, Hook::estimate_steps, Hook::handles};
  using Algo = pipe::FrustumCull;
  using Input = FrustumInput;
  using Output = FrustumOutput;
  static constexpr std::array views{View::orbit3d, View::table};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact, Numeric::reference};
  // A camera 10 from the origin: a sphere in view, a box beyond the far plane, an oriented box
  // straddling the left plane, and a sphere touching the far plane from outside.
  static inline const std::string example =
      R"({"camera":{"eye":[0,0,10],"target":[0,0,0],"up":[0,1,0]},"projection":{"perspective":[-1,1,-1,1,1,30]},)"
      R"("viewport":[0,0,512,512],"objects":[{"sphere":{"center":[0,0,0],"radius":1}},{"aabb":{"min":[-1,-1,-25],"max":[1,1,-21]}},)"
      R"({"obb":{"center":[-9,0,0],"axes":[[1,1,0],[-1,1,0],[0,0,1]]}},{"sphere":{"center":[0,0,-22],"radius":2}}]})";
  static Input parse(const Json& j) { return parse_frustum(j); }
  static void admit(const Input& in, Numeric n) { admit_camera(in.camera, n); }
  template <class Num> static FrustumPrepared<Num> prepare(const Input& in) {
    FrustumPrepared<Num> p{camera_as<Num>(in.camera.cam), {}};
    for (const auto& b : in.objects) {
      pipe::Bounds<Num> x;
      x.kind = static_cast<typename pipe::Bounds<Num>::Kind>(b.kind);
      x.c = to_num<Num>(b.c), x.lo = to_num<Num>(b.lo), x.hi = to_num<Num>(b.hi), x.r = num::from_rational<Num>(b.r);
      for (int a = 0; a < 3; ++a) x.h[a] = to_num<Num>(b.h[a]);
      p.objects.push_back(x);
    }
    return p;
  }
  template <class Num, class Probe> static Output compute(const FrustumPrepared<Num>& p, Probe& probe) {
    return {pipe::frustum_cull<Num>(p.cam, p.objects, probe)};
  }
  static Json to_json(const Output& o) {
    static constexpr std::array<const char*, 3> names{"outside", "straddles", "inside"};
    Json s = Json::array();
    std::int64_t culled = 0;
    for (pipe::Cull c : o.states) s.push_back(names[static_cast<int>(c)]), culled += c == pipe::Cull::outside;
    return Json{{"objects", std::move(s)}, {"culled", culled}};
  }
  static std::size_t ops(const Output& o) { return o.states.size(); }
  // Culled when exact keeps it (a visible object lost) or kept when exact culls it.
  static constexpr std::string_view error_unit = "wrong culls";
  static double error(const Output& got, const Output& exact) {
    double wrong = 0;
    for (std::size_t i = 0; i < got.states.size() && i < exact.states.size(); ++i)
      wrong += (got.states[i] == pipe::Cull::outside) != (exact.states[i] == pipe::Cull::outside);
    return wrong;
  }
  static std::size_t estimate_steps(const Input& in) { return 1 + 8 * in.objects.size(); }
  static std::vector<Handle> handles() {
    return {{"/camera/eye", Handle::Kind::point3, 8, "eye"}, {"/objects/0/sphere/center", Handle::Kind::point3, 8, "sphere"}};
  }
  static Output oracle(const Input& in) {
    Output o;
    for (const auto& b : in.objects) {
      const auto c = b.kind == pipe::Bounds<Rational>::Kind::sphere ? pipeline_oracle::cull_sphere(in.camera.cam, arr_of(b.c), b.r)
                                                                   : pipeline_oracle::cull_corners(in.camera.cam, corners_of(b));
      o.states.push_back(static_cast<pipe::Cull>(c));
    }
    return o;
  }
  static std::vector<BenchSet<Input>> bench_sets() { return frustum_sets(); }
};

SW_REGISTER(FrustumSpec);

}  // namespace
}  // namespace sw
