// backface-cull in the catalog: the eye-space test against the screen winding, glCullFace.
// Semantics: docs/pipeline/semantics.md.
#include <random>
#include "register.hpp"
#include "pipeline/backface_cull.hpp"
#include "pipeline/camera_input.hpp"
#include "pipeline_oracle.hpp"

namespace sw {
namespace {

using namespace pipespec;

struct BackfaceInput {
  CameraInput camera;
  std::vector<std::array<Vec3<Rational>, 3>> triangles;
  pipe::CullFace mode = pipe::CullFace::back;
  pipe::FrontFace front = pipe::FrontFace::ccw;
};

struct BackfaceOutput {
  std::vector<pipe::Facing> faces;
  friend bool operator==(const BackfaceOutput&, const BackfaceOutput&) = default;
};

BackfaceInput parse_backface(const Json& j) {
  if (!j.is_object()) throw InputError("input: expected an object with camera, projection, viewport and triangles");
  only_keys_optional(j, {"camera", "projection", "viewport", "triangles"}, {"depth_range", "cull", "front_face"}, "input");
  BackfaceInput in;
  in.camera = parse_camera(j);
  const Json& ts = primitive_list(j, "triangles", "triangles [[x,y,z],[x,y,z],[x,y,z]]");
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const std::string what = "input.triangles[" + std::to_string(i) + "]";
    if (!ts[i].is_array() || ts[i].size() != 3) throw InputError(what + ": expected three vertices [[x,y,z],[x,y,z],[x,y,z]]");
    in.triangles.push_back({parse_coord3(ts[i][0], what + "[0]"), parse_coord3(ts[i][1], what + "[1]"), parse_coord3(ts[i][2], what + "[2]")});
  }
  if (j.contains("cull")) {
    const Json& c = j["cull"];
    if (c == "back") in.mode = pipe::CullFace::back;
    else if (c == "front") in.mode = pipe::CullFace::front;
    else if (c == "front_and_back") in.mode = pipe::CullFace::front_and_back;
    else throw InputError("input.cull: expected \"back\", \"front\" or \"front_and_back\" (glCullFace)");
  }
  if (j.contains("front_face")) {
    const Json& f = j["front_face"];
    if (f == "ccw") in.front = pipe::FrontFace::ccw;
    else if (f == "cw") in.front = pipe::FrontFace::cw;
    else throw InputError("input.front_face: expected \"ccw\" or \"cw\" (glFrontFace)");
  }
  return in;
}

template <class Num> struct BackfacePrepared {
  pipe::Camera<Num> cam;
  std::vector<pipe::Triangle<Num>> tris;
  pipe::CullFace mode;
  pipe::FrontFace front;
};

// Random triangles in view, and nearly edge-on ones: c lies almost on the line from a to the eye,
// 2^-20 off it, so the eye is within about that of the triangle's plane.
std::vector<BenchSet<BackfaceInput>> backface_sets() {
  std::vector<BenchSet<BackfaceInput>> sets{{"random", {}}, {"edge-on", {}}};
  CameraGen cams(20261127);
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> u(-1, 1), s(0.05, 0.95);
  for (int k = 0; k < 64; ++k)
    for (int set = 0; set < 2; ++set) {
      BackfaceInput in{cams.next(Rational(10), Rational(1), Rational(100), 1024, 1024), {}, pipe::CullFace::back, pipe::FrontFace::ccw};
      for (int i = 0; i < 64; ++i) {
        const Vec3<Rational> a = volume_point(in.camera, rng, 5, 40), b = volume_point(in.camera, rng, 5, 40);
        Vec3<Rational> c = volume_point(in.camera, rng, 5, 40);
        if (set == 1) {
          const Rational t(static_cast<long>(s(rng) * 1024), 1024);
          const Vec3<Rational> off{Rational(static_cast<long>(u(rng) * 1024), 1L << 30), Rational(static_cast<long>(u(rng) * 1024), 1L << 30),
                                   Rational(static_cast<long>(u(rng) * 1024), 1L << 30)};
          c = a + t * (in.camera.cam.look.eye - a) + off;
        }
        in.triangles.push_back({a, b, c});
      }
      sets[set].inputs.push_back(std::move(in));
    }
  return sets;
}

struct BackfaceSpec {
  static constexpr std::array hooks{Hook::error, Hook::admit, Hook::estimate_steps, Hook::handles};
  using Algo = pipe::BackfaceCull;
  using Input = BackfaceInput;
  using Output = BackfaceOutput;
  static constexpr std::array views{View::orbit3d, View::table};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact, Numeric::reference};
  // A camera 10 from the origin; a triangle facing it, one facing away, and one seen edge-on
  // but for 1/2^20 (its plane passes that close to the eye), where float's two tests part.
  static inline const std::string example =
      R"({"camera":{"eye":[0,0,10],"target":[0,0,0],"up":[0,1,0]},"projection":{"perspective":[-1,1,-1,1,1,100]},)"
      R"("viewport":[0,0,512,512],"triangles":[[[-2,-1,0],[2,-1,0],[0,2,0]],[[-2,-1,-1],[0,2,-1],[2,-1,-1]],)"
      R"([[1,-1,0],[1,1,-3],["1048577/1048576",0,"15/2"]]]})";
  static Input parse(const Json& j) { return parse_backface(j); }
  static void admit(const Input& in, Numeric n) { admit_camera(in.camera, n); }
  template <class Num> static BackfacePrepared<Num> prepare(const Input& in) {
    BackfacePrepared<Num> p{camera_as<Num>(in.camera.cam), {}, in.mode, in.front};
    for (const auto& t : in.triangles) p.tris.push_back({to_num<Num>(t[0]), to_num<Num>(t[1]), to_num<Num>(t[2])});
    return p;
  }
  template <class Num, class Probe> static Output compute(const BackfacePrepared<Num>& p, Probe& probe) {
    return {pipe::backface_cull<Num>(p.cam, p.tris, p.mode, p.front, probe)};
  }
  static Json to_json(const Output& o) {
    Json ts = Json::array();
    std::int64_t culled = 0, disagree = 0;
    for (const auto& f : o.faces) {
      Json t = {{"toward", f.toward}, {"front", f.front}, {"culled", f.culled}};
      if (f.behind) t["behind"] = true;
      else t["winding"] = f.winding, t["agree"] = f.agree;
      culled += f.culled, disagree += !f.agree;
      ts.push_back(std::move(t));
    }
    return Json{{"triangles", std::move(ts)}, {"culled", culled}, {"disagree", disagree}};
  }
  static std::size_t ops(const Output& o) { return o.faces.size(); }
  static constexpr std::string_view error_unit = "wrong culls";
  static double error(const Output& got, const Output& exact) {
    double wrong = 0;
    for (std::size_t i = 0; i < got.faces.size() && i < exact.faces.size(); ++i) wrong += got.faces[i].culled != exact.faces[i].culled;
    return wrong;
  }
  static std::size_t estimate_steps(const Input& in) { return 1 + 8 * in.triangles.size(); }
  static std::vector<Handle> handles() {
    return {{"/triangles/2/2", Handle::Kind::point3, 8, "c"}};  // the example's edge-on vertex
  }
  static Output oracle(const Input& in) {
    Output o;
    for (const auto& t : in.triangles) {
      const auto f = pipeline_oracle::facing(in.camera.cam, {arr_of(t[0]), arr_of(t[1]), arr_of(t[2])});
      pipe::Facing r;
      r.toward = f.toward;
      r.behind = !f.winding;
      const int side = f.winding ? *f.winding : f.toward;  // behind: what clipping leaves, the eye's side
      r.winding = f.winding.value_or(0);
      r.front = in.front == pipe::FrontFace::ccw ? side > 0 : side < 0;
      r.agree = r.behind || r.winding == r.toward;
      r.culled = in.mode == pipe::CullFace::front_and_back || (in.mode == pipe::CullFace::back) != r.front;
      o.faces.push_back(r);
    }
    return o;
  }
  static std::vector<BenchSet<Input>> bench_sets() { return backface_sets(); }
};

SW_REGISTER(BackfaceSpec);

}  // namespace
}  // namespace sw
