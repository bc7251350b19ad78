// transform in the catalog: vertices through model, view, projection, divide and viewport.
// Semantics: docs/pipeline/semantics.md.
#include <random>
#include "register.hpp"
#include "pipeline/camera_input.hpp"
#include "pipeline/transform.hpp"
#include "pipeline_oracle.hpp"

namespace sw {
namespace {

using namespace pipespec;

struct TransformInput {
  CameraInput camera;
  pipe::Mat4<Rational> model;
  std::vector<Vec3<Rational>> points;
};

// Per vertex, as doubles (the exact window position too in exact mode and from the oracle).
struct TransformOutput {
  struct Vertex {
    bool inside = false, projected = false;
    std::array<double, 4> clip{};
    std::array<double, 3> ndc{}, win{};
  };
  std::vector<Vertex> vertices;
  std::vector<std::array<Rational, 3>> exact_win;  // exact mode and the oracle: per projected vertex
  // Modes agree when they make the same decisions: inside the view volume, and in front of the eye.
  friend bool operator==(const TransformOutput& a, const TransformOutput& b) {
    if (a.vertices.size() != b.vertices.size()) return false;
    for (std::size_t i = 0; i < a.vertices.size(); ++i)
      if (a.vertices[i].inside != b.vertices[i].inside || a.vertices[i].projected != b.vertices[i].projected) return false;
    return true;
  }
};

TransformInput parse_transform(const Json& j) {
  if (!j.is_object()) throw InputError("input: expected an object with camera, projection, viewport and points");
  only_keys_optional(j, {"camera", "projection", "viewport", "points"}, {"model", "depth_range"}, "input");
  TransformInput in;
  in.camera = parse_camera(j);
  in.model = pipe::identity<Rational>();
  if (j.contains("model")) {
    const Json& m = j["model"];
    if (!m.is_array() || m.size() != 3) throw InputError("input.model: expected three rows of an affine matrix [[a,b,c,d],[e,f,g,h],[i,j,k,l]]");
    for (int r = 0; r < 3; ++r) {
      const std::string what = "input.model[" + std::to_string(r) + "]";
      if (!m[r].is_array() || m[r].size() != 4) throw InputError(what + ": expected [a, b, c, d]");
      for (int c = 0; c < 4; ++c) in.model[r][c] = parse_coord(m[r][c], what + "[" + std::to_string(c) + "]");
    }
  }
  const Json& pts = primitive_list(j, "points", "points [x, y, z]");
  for (std::size_t i = 0; i < pts.size(); ++i) in.points.push_back(parse_coord3(pts[i], "input.points[" + std::to_string(i) + "]"));
  return in;
}

template <class Num> struct Prepared {
  pipe::Mat4<Num> model;
  pipe::Camera<Num> cam;
  std::vector<Vec3<Num>> points;
};

std::array<double, 3> doubles(const std::array<Rational, 3>& v) { return {v[0].get_d(), v[1].get_d(), v[2].get_d()}; }

// Points in the view volume of a random camera at distance 10 (near 1, far 100; or near 1/100):
// uniform in depth over [lo, hi] of the way from near to far, anywhere across the window.
std::vector<TransformInput> frustum_points(std::uint64_t seed, int cases, const Rational& near, double lo, double hi) {
  CameraGen cams(seed);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> depth(lo, hi), across(-1, 1);
  std::vector<TransformInput> out;
  for (int k = 0; k < cases; ++k) {
    TransformInput in{cams.next(Rational(10), near, Rational(100), 1024, 768), pipe::identity<Rational>(), {}};
    const pipe::Camera<Rational>& c = in.camera.cam;
    const pipe::Frame<Rational> fr = pipe::look_frame(c.look);
    for (int i = 0; i < 16; ++i) {
      const double dd = 1 + depth(rng) * 99;  // the far plane at 100; a point lo..hi of the way there
      auto q = [](double v) { return on_grid(v, 20); };
      const Rational d = q(dd), x = q(across(rng) * dd), y = q(across(rng) * dd);
      in.points.push_back(c.look.eye + d * fr.f + x * fr.s + y * fr.u);
    }
    out.push_back(std::move(in));
  }
  return out;
}

struct TransformSpec {
  static constexpr std::array hooks{Hook::error, Hook::admit, Hook::table_lines, Hook::params, Hook::estimate_steps};
  using Algo = pipe::TransformAlgo;
  using Input = TransformInput;
  using Output = TransformOutput;
  static constexpr std::array views{View::table, View::orbit3d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact, Numeric::reference};
  static constexpr std::array<std::string_view, 1> table_lines{"model"};  // one row per vertex
  // A camera on the z axis 5 from the origin; two vertices near the far plane 1/1000 apart in depth.
  static inline const std::string example =
      R"({"camera":{"eye":[0,0,5],"target":[0,0,0],"up":[0,1,0]},"projection":{"perspective":[-1,1,-0.75,0.75,1,100]},)"
      R"("viewport":[0,0,640,480],"points":[[0,0,0],[1,0.5,-2],[0.25,0.25,-90],[0.25,0.25,-90.001],[3,0,0]]})";
  static Input parse(const Json& j) { return parse_transform(j); }
  static void admit(const Input& in, Numeric n) { admit_camera(in.camera, n); }
  template <class Num> static Prepared<Num> prepare(const Input& in) {
    Prepared<Num> p;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) p.model[i][j] = num::from_rational<Num>(in.model[i][j]);
    p.cam = camera_as<Num>(in.camera.cam);
    for (const auto& q : in.points) p.points.push_back(to_num<Num>(q));
    return p;
  }
  template <class Num, class Probe> static Output compute(const Prepared<Num>& p, Probe& probe) {
    const auto rows = pipe::transform<Num>(p.model, p.cam, p.points, probe);
    Output o;
    for (const auto& t : rows) {
      Output::Vertex v{t.inside, t.projected, {num::to_double(t.clip.x), num::to_double(t.clip.y), num::to_double(t.clip.z), num::to_double(t.clip.w)}, {}, {}};
      if (t.projected) {
        v.ndc = {num::to_double(t.ndc.x), num::to_double(t.ndc.y), num::to_double(t.ndc.z)};
        v.win = {num::to_double(t.win.x), num::to_double(t.win.y), num::to_double(t.win.z)};
        if constexpr (std::is_same_v<Num, Rational>) o.exact_win.push_back({t.win.x, t.win.y, t.win.z});
      }
      o.vertices.push_back(v);
    }
    return o;
  }
  static Json to_json(const Output& o) {
    Json vs = Json::array();
    for (const auto& v : o.vertices) {
      Json x = {{"inside", v.inside}, {"clip", v.clip}};
      if (v.projected) x["ndc"] = v.ndc, x["window"] = v.win;
      vs.push_back(std::move(x));
    }
    return Json{{"vertices", std::move(vs)}};
  }
  static std::size_t ops(const Output& o) { return o.vertices.size(); }
  // Depth is what the lesson is about: the worst window depth, in steps of a 24-bit depth buffer.
  static constexpr std::string_view error_unit = "24-bit depth steps";
  static double error(const Output& got, const Output& exact) {
    double worst = 0;
    // ke, kg: the vertex's place among the projected ones of each run (exact_win holds only those).
    for (std::size_t i = 0, ke = 0, kg = 0; i < exact.vertices.size() && i < got.vertices.size(); ++i) {
      const bool e = exact.vertices[i].projected, g = got.vertices[i].projected;
      if (e && g) {
        const Rational mine = got.exact_win.empty() ? num::to_rational(got.vertices[i].win[2]) : got.exact_win[kg][2];
        worst = std::max(worst, std::ldexp(Rational(abs(Rational(mine - exact.exact_win[ke][2]))).get_d(), 24));
      }
      ke += e, kg += g;
    }
    return worst;
  }
  static std::size_t estimate_steps(const Input& in) { return 2 + 7 * in.points.size(); }
  static std::vector<Param> params() {
    return {{"/projection/perspective/4", "near", 1e-3, 10, true, "The near plane's distance: closer spends depth precision near the eye"},
            {"/projection/perspective/5", "far", 20, 1e5, true, "The far plane's distance"}};
  }
  static Output oracle(const Input& in) {
    Output o;
    for (const auto& p : in.points) {
      const auto v = pipeline_oracle::transform(in.model, in.camera.cam, {p.x, p.y, p.z});
      Output::Vertex x{v.inside, v.win.has_value(), {v.clip[0].get_d(), v.clip[1].get_d(), v.clip[2].get_d(), v.clip[3].get_d()}, {}, {}};
      if (v.win) x.ndc = doubles(*v.ndc), x.win = doubles(*v.win), o.exact_win.push_back(*v.win);
      o.vertices.push_back(x);
    }
    return o;
  }
  // Random cameras and points in their view volume: anywhere, in the last tenth before the far
  // plane, and the same with the near plane 100 times closer (1/100).
  static std::vector<BenchSet<Input>> bench_sets() {
    return {{"inside", frustum_points(20261127, 256, Rational(1), 0, 1)},
            {"far", frustum_points(20261128, 256, Rational(1), 0.9, 1)},
            {"far-near100", frustum_points(20261128, 256, Rational(1, 100), 0.9, 1)}};
  }
};

SW_REGISTER(TransformSpec);

}  // namespace
}  // namespace sw
