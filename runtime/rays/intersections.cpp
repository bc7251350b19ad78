// The ray family's intersection tests in the catalog: ray-plane, ray-sphere-{geometric,quadratic,
// stable}, ray-box, ray-triangle-{barycentric,mt,watertight}. Semantics: docs/rays/semantics.md.
#include <cmath>
#include <memory>
#include <random>
#include "register.hpp"
#include "rays/cases.hpp"
#include "rays/ray_box.hpp"
#include "rays/ray_plane.hpp"
#include "rays/ray_sphere_geometric.hpp"
#include "rays/ray_sphere_quadratic.hpp"
#include "rays/ray_sphere_stable.hpp"
#include "rays/ray_triangle_barycentric.hpp"
#include "rays/ray_triangle_mt.hpp"
#include "rays/ray_triangle_watertight.hpp"
#include "rays/ray_input.hpp"
#include "rays_oracle.hpp"

namespace sw {
namespace {

using rays::kCoordBound;
using rays::point3;


enum class Prim { triangle, sphere, box, plane };

struct RayInput {
  Vec3<Rational> o, d;
  std::array<bool, 3> d_neg_zero{};  // a JSON -0.0 direction component (kept for float modes)
  std::array<Vec3<Rational>, 3> v;   // triangle vertices; sphere: v[0] = c; box: v[0], v[1] = min, max; plane: p, n
  Rational r;                        // sphere radius
  std::array<std::vector<Rational>, 3> attr;  // triangle: optional per-vertex attributes (same length)
};

RayInput parse_input(const Json& j, Prim prim) {
  static const char* names[] = {"triangle", "sphere", "box", "plane"};
  const char* key = names[static_cast<int>(prim)];
  if (prim == Prim::triangle && j.is_object() && j.contains("attr")) {
    Json rest = j;
    rest.erase("attr");
    only_keys(rest, {"ray", key}, "input");
  } else {
    only_keys(j, {"ray", key}, "input");
  }
  RayInput in;
  const Json& ray = j["ray"];
  only_keys(ray, {"o", "d"}, "input.ray");
  in.o = point3(ray["o"], "input.ray.o");
  in.d = point3(ray["d"], "input.ray.d", &in.d_neg_zero);
  if (sgn(in.d.x) == 0 && sgn(in.d.y) == 0 && sgn(in.d.z) == 0) throw InputError("input.ray.d: the direction is zero");
  const Json& g = j[key];
  switch (prim) {
    case Prim::triangle: {
      if (!g.is_array() || g.size() != 3) throw InputError("input.triangle: expected [[x,y,z],[x,y,z],[x,y,z]]");
      for (int i = 0; i < 3; ++i) in.v[i] = point3(g[i], "input.triangle[" + std::to_string(i) + "]");
      // A degenerate (zero-area) triangle is valid input and a defined miss (docs/rays/semantics.md).
      if (j.contains("attr")) {
        // Per-vertex attributes (uv, normals, colours...): three arrays of one length, 1..16.
        const Json& a = j["attr"];
        if (!a.is_array() || a.size() != 3) throw InputError("input.attr: expected three arrays, one per vertex");
        for (int i = 0; i < 3; ++i) {
          const std::string what = "input.attr[" + std::to_string(i) + "]";
          if (!a[i].is_array() || a[i].empty() || a[i].size() > 16 || a[i].size() != a[0].size())
            throw InputError(what + ": expected 1 to 16 numbers, as many as for every vertex");
          for (std::size_t k = 0; k < a[i].size(); ++k) {
            in.attr[i].push_back(parse_rational(a[i][k], what + "[" + std::to_string(k) + "]"));
            check_bound(in.attr[i].back(), kCoordBound, what);
          }
        }
      }
      break;
    }
    case Prim::sphere:
      only_keys(g, {"c", "r"}, "input.sphere");
      in.v[0] = point3(g["c"], "input.sphere.c");
      in.r = parse_rational(g["r"], "input.sphere.r");
      check_bound(in.r, kCoordBound, "input.sphere.r");
      if (sgn(in.r) <= 0) throw InputError("input.sphere.r: the radius must be > 0, got " + in.r.get_str());
      break;
    case Prim::box:
      only_keys(g, {"min", "max"}, "input.box");
      in.v[0] = point3(g["min"], "input.box.min");
      in.v[1] = point3(g["max"], "input.box.max");
      for (int k = 0; k < 3; ++k)
        if (in.v[0][k] > in.v[1][k]) throw InputError("input.box: min[" + std::to_string(k) + "] > max[" + std::to_string(k) + "]");
      break;
    case Prim::plane:
      only_keys(g, {"p", "n"}, "input.plane");
      in.v[0] = point3(g["p"], "input.plane.p");
      in.v[1] = point3(g["n"], "input.plane.n");
      if (sgn(in.v[1].x) == 0 && sgn(in.v[1].y) == 0 && sgn(in.v[1].z) == 0) throw InputError("input.plane.n: the normal is zero");
      break;
  }
  return in;
}

template <class Num> struct Prepared {
  ray::Ray3<Num> ray;
  std::array<Vec3<Num>, 3> v;
  Num r;
  std::shared_ptr<const std::array<std::vector<Num>, 3>> attr;  // null unless given (keeps Prepared small)
};

// Every number is exact data here, except the sphere's irrational t (rounded to 128 bits).
using Exact = oracle::RayResult;

// One output for every mode: doubles for float, double and filtered; the exact values otherwise.
struct RayOutput {
  bool hit = false;
  int bits = 53;  // significand bits of the mode that produced the doubles (24 for float)
  double t = 0, t_near = 0, t_far = 0;
  std::array<double, 3> b{};
  std::vector<double> attr;
  std::shared_ptr<const Exact> exact;  // exact mode (and filtered fallbacks, and the oracle)
  // A rounded mode said hit but its t is not a finite number > 0 (NaN from a direction of 1e-300,
  // or 0 from a tiny positive t): by the semantics no hit. Reported, and never equal to exact.
  bool failed = false;

  // Hit or miss, and when both sides are exact, every reported value.
  friend bool operator==(const RayOutput& x, const RayOutput& y) {
    if (x.hit != y.hit || x.failed != y.failed) return false;
    if (!x.hit || !x.exact || !y.exact) return true;
    return x.exact->t == y.exact->t && x.exact->b == y.exact->b && x.exact->t_near == y.exact->t_near && x.exact->t_far == y.exact->t_far &&
           x.exact->attr == y.exact->attr;
  }
};

template <class Num>
RayOutput make_output(bool hit, const Num& t, bool t_exact, const std::array<Num, 3>* b, const Num* tn, const Num* tf, const std::vector<Num>* attr = nullptr) {
  RayOutput o;
  o.hit = hit;
  if constexpr (std::is_same_v<Num, Rational>) {
    auto e = std::make_shared<Exact>();
    e->hit = hit;
    if (hit) {
      e->t_exact = t_exact;
      e->t = t_exact ? t : num::round_bits(t, oracle::kSphereTBits);
      if (b) e->b = *b;
      if (tn) e->t_near = *tn, e->t_far = *tf;
      if (attr) e->attr = *attr;
    }
    o.exact = std::move(e);
  } else {
    if constexpr (std::is_same_v<Num, float>) o.bits = 24;
    if (hit) {
      o.t = num::to_double(t);
      o.failed = !(std::isfinite(o.t) && o.t > 0);
      if (b) o.b = {num::to_double((*b)[0]), num::to_double((*b)[1]), num::to_double((*b)[2])};
      if (tn) o.t_near = num::to_double(*tn), o.t_far = num::to_double(*tf);
      if (attr)
        for (const Num& a : *attr) o.attr.push_back(num::to_double(a));
    }
  }
  return o;
}

RayOutput from_oracle(const Exact& e) {
  RayOutput o;
  o.hit = e.hit;
  o.exact = std::make_shared<Exact>(e);
  return o;
}

Json number_json(double d, const Rational* q) { return q ? Json(q->get_str()) : Json(d); }

template <Prim P> Json output_json(const RayOutput& o) {
  Json j{{"hit", o.hit}};
  if (!o.hit) return j;
  const Exact* e = o.exact.get();
  j["t"] = number_json(o.t, e ? &e->t : nullptr);
  if (o.failed) j["failure"] = "t-not-finite-positive";  // docs/trace-format.md
  if constexpr (P == Prim::triangle) {
    Json b = Json::array();
    for (int i = 0; i < 3; ++i) b.push_back(number_json(o.b[i], e ? &e->b[i] : nullptr));
    j["b"] = b;
    const std::size_t na = e ? e->attr.size() : o.attr.size();
    if (na > 0) {
      Json a = Json::array();
      for (std::size_t k = 0; k < na; ++k) a.push_back(number_json(e ? 0.0 : o.attr[k], e ? &e->attr[k] : nullptr));
      j["attr"] = a;
    }
  }
  if constexpr (P == Prim::box) {
    j["t_near"] = number_json(o.t_near, e ? &e->t_near : nullptr);
    j["t_far"] = number_json(o.t_far, e ? &e->t_far : nullptr);
  }
  return j;
}

std::vector<BenchSet<RayInput>> bench_sets_for(Prim p) {
  static const char* names[] = {"triangle", "sphere", "box", "plane"};
  const char* name = names[static_cast<int>(p)];
  BenchSet<RayInput> random{"random", {}}, hard{"hard", {}};
  for (const Json& j : rays::random_inputs(name, 10000, 20261122)) random.inputs.push_back(parse_input(j, p));
  for (const Json& j : rays::hard_inputs(name, 20261123)) hard.inputs.push_back(parse_input(j, p));
  return {random, hard};
}

// The image view's sweep: rays parallel to the input's d, their origins on a grid over the plane
// through o across d's major axis m, framing the primitive's shadow on it ([-1, 1]^2 in the grid).
// Coordinates are rounded to the grid's input mode, so every mode sweeps the very same rays.
struct SweepFrame {
  int m = 2, a = 0, b = 1;
  double flip = 1;               // -1 mirrors axis a, so the image is seen looking along d
  double ca = 0, cb = 0, s = 1;  // the frame's centre and half size on the plane
  double mx = 0, my = 0;         // the input's origin in the frame (the marker)
  std::array<double, 3> o{}, d{};
};
double round_to(Numeric n, double x) { return n == Numeric::f32 ? double(float(x)) : x; }
template <class Num> Num from_double(double x) {
  if constexpr (std::is_same_v<Num, Rational>) return num::to_rational(x);
  else return Num(x);
}

SweepFrame sweep_frame(const RayInput& in, Prim prim, Numeric inputs) {
  SweepFrame f;
  std::array<double, 3> o, d;
  for (int k = 0; k < 3; ++k) o[k] = in.o[k].get_d(), d[k] = in.d[k].get_d();
  for (int k = 0; k < 3; ++k)
    if (std::fabs(d[k]) > std::fabs(d[f.m])) f.m = k;
  f.a = (f.m + 1) % 3, f.b = (f.m + 2) % 3, f.flip = d[f.m] < 0 ? 1 : -1;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  auto add = [&](const Vec3<Rational>& q, double pad) {  // q's shadow along d, grown by pad
    const double t = (q[f.m].get_d() - o[f.m]) / d[f.m];
    const double p[2] = {q[f.a].get_d() - t * d[f.a], q[f.b].get_d() - t * d[f.b]};
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k] - pad), hi[k] = std::max(hi[k], p[k] + pad);
  };
  const double stretch = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / std::fabs(d[f.m]);
  switch (prim) {
    case Prim::triangle: for (const auto& v : in.v) add(v, 0); break;
    case Prim::sphere: add(in.v[0], in.r.get_d() * stretch); break;
    case Prim::box:
      for (int c = 0; c < 8; ++c) add({in.v[c & 1].x, in.v[(c >> 1) & 1].y, in.v[c >> 2].z}, 0);
      break;
    case Prim::plane: add(in.o, std::max(1.0, std::sqrt(dot(in.o - in.v[0], in.o - in.v[0]).get_d()))); break;
  }
  f.ca = (lo[0] + hi[0]) / 2, f.cb = (lo[1] + hi[1]) / 2;
  f.s = std::max(hi[0] - lo[0], hi[1] - lo[1]) / 2 * 1.15;
  if (!(f.s > 0) || !std::isfinite(f.s)) f.s = 1;
  for (int k = 0; k < 3; ++k) f.o[k] = round_to(inputs, o[k]), f.d[k] = in.d_neg_zero[k] ? -0.0 : round_to(inputs, d[k]);
  f.mx = (o[f.a] - f.ca) / f.s * f.flip, f.my = (o[f.b] - f.cb) / f.s;
  return f;
}
// Sample (i, j)'s origin: an offset from the input's own, so that the sample at the marker is the
// input ray.
std::array<double, 3> sample_origin(const SweepFrame& f, const SweepGrid& g, int i, int j) {
  std::array<double, 3> o = f.o;
  o[f.a] = round_to(g.inputs, f.o[f.a] + f.flip * (g.x(i) - f.mx) * f.s);
  o[f.b] = round_to(g.inputs, f.o[f.b] + (g.y(j) - f.my) * f.s);
  return o;
}

template <class AlgoT, Prim P> struct RaySpec {
  static constexpr std::array hooks{Hook::filters, Hook::handles, Hook::sweeper, Hook::sweep_caption, Hook::sweep_input, Hook::sweep_marker, Hook::error,
                                    Hook::result_keys};
  using Algo = AlgoT;
  using Input = RayInput;
  static constexpr std::array result_keys{std::string_view("hit")};  // output_json: always
  using Output = RayOutput;
  // The magnitude filter, then intervals for what it leaves uncertain (docs/rays/accuracy.md).
  using Filters = std::tuple<Mag, Interval>;
  static constexpr std::array views{View::orbit3d, View::image};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static Input parse(const Json& j) { return parse_input(j, P); }
  static std::vector<Handle> handles() { return {{"/ray/o", Handle::Kind::point3, 8, "o"}, {"/ray/d", Handle::Kind::direction3, 0, "o + d"}}; }
  template <class Num> static Prepared<Num> prepare(const Input& in) {
    Prepared<Num> p;
    p.ray.o = to_num<Num>(in.o);
    p.ray.d = to_num<Num>(in.d);
    if constexpr (std::is_floating_point_v<Num> || is_filtered<Num>)
      for (int k = 0; k < 3; ++k)
        if (in.d_neg_zero[k]) p.ray.d[k] = Num(-0.0);
    for (int i = 0; i < 3; ++i) p.v[i] = to_num<Num>(in.v[i]);
    if (!in.attr[0].empty()) {
      auto a = std::make_shared<std::array<std::vector<Num>, 3>>();
      for (int i = 0; i < 3; ++i)
        for (const Rational& x : in.attr[i]) (*a)[i].push_back(num::from_rational<Num>(x));
      p.attr = std::move(a);
    }
    p.r = num::from_rational<Num>(in.r);
    return p;
  }
  static Json to_json(const Output& o) { return output_json<P>(o); }
  static std::size_t ops(const Output&) { return 1; }
  static std::vector<BenchSet<Input>> bench_sets() { return bench_sets_for(P); }
  static constexpr std::string_view sweep_caption = "rays parallel to d";
  template <class Num> static auto sweeper(const Input& in, const SweepGrid& g) {
    return [f = sweep_frame(in, P, g.inputs), g](int i, int j, Prepared<Num>& p) {
      const std::array<double, 3> o = sample_origin(f, g, i, j);
      for (int k = 0; k < 3; ++k) p.ray.o[k] = from_double<Num>(o[k]), p.ray.d[k] = from_double<Num>(f.d[k]);
    };
  }
  static Json sweep_input(Json j, const Input& in, const SweepGrid& g, int i, int k) {
    const SweepFrame f = sweep_frame(in, P, g.inputs);
    const std::array<double, 3> o = sample_origin(f, g, i, k);
    j["ray"] = Json{{"o", {o[0], o[1], o[2]}}, {"d", {f.d[0], f.d[1], f.d[2]}}};  // Json{…}: see lighting/model_specs.cpp's sweep_input
    return j;
  }
  static float sweep_value(const Output& o) {
    if (!o.hit) return NAN;
    return static_cast<float>(o.exact ? o.exact->t.get_d() : o.t);
  }
  // The input ray's origin in the frame.
  static std::optional<std::array<double, 2>> sweep_marker(const Input& in) {
    const SweepFrame f = sweep_frame(in, P, Numeric::f64);
    return std::array<double, 2>{f.mx, f.my};
  }
  static Output oracle(const Input& in) {
    switch (P) {
      case Prim::triangle: {
        oracle::RayResult res = oracle::ray_triangle(in.o, in.d, in.v);
        if (res.hit)  // the attributes' definition: sum of b_i a_i
          for (std::size_t k = 0; k < in.attr[0].size(); ++k)
            res.attr.push_back(res.b[0] * in.attr[0][k] + res.b[1] * in.attr[1][k] + res.b[2] * in.attr[2][k]);
        return from_oracle(res);
      }
      case Prim::sphere: return from_oracle(oracle::ray_sphere(in.o, in.d, in.v[0], in.r));
      case Prim::box: return from_oracle(oracle::ray_box(in.o, in.d, in.v[0], in.v[1]));
      case Prim::plane: return from_oracle(oracle::ray_plane(in.o, in.d, in.v[0], in.v[1]));
    }
    return {};
  }
  // The t error in units in the last place of the producing mode, at the exact t.
  static double error(const Output& got, const Output& exact) {
    if (!got.hit || !exact.hit || !exact.exact) return 0;
    const Rational& te = exact.exact->t;
    const Rational diff = abs(Rational((got.exact ? got.exact->t : num::to_rational(got.t)) - te));
    if (sgn(diff) == 0) return 0;
    return std::ldexp(diff.get_d(), got.bits - 1 - std::ilogb(te.get_d()));  // diff / ulp(te)
  }
};

template <class AlgoT> struct TriangleSpec : RaySpec<AlgoT, Prim::triangle> {
  static inline const std::string example =
      R"({"ray":{"o":[0,0,10],"d":[0.30458447,0.30458447,-0.9024725]},"triangle":[[-5,-5,0],[5,-5,0],[5,5,0]]})";
  template <class Num, class Probe> [[gnu::always_inline]] static RayOutput compute(const Prepared<Num>& p, Probe& probe) {
    const auto h = AlgoT{}(p.ray, p.v, probe);
    if (!h.hit || !p.attr) return make_output<Num>(h.hit, h.t, true, &h.b, nullptr, nullptr);
    // Inverse mapping: the vertex attributes interpolated with the barycentric weights.
    const auto& a = *p.attr;
    std::vector<Num> attr;
    for (std::size_t k = 0; k < a[0].size(); ++k) attr.push_back(Num(h.b[0] * a[0][k] + h.b[1] * a[1][k] + h.b[2] * a[2][k]));
    return make_output<Num>(h.hit, h.t, true, &h.b, nullptr, nullptr, &attr);
  }
};
template <class AlgoT> struct SphereSpec : RaySpec<AlgoT, Prim::sphere> {
  static inline const std::string example = R"({"ray":{"o":[0,0,0],"d":[1,0.0001,0]},"sphere":{"c":[100000000,0,0],"r":1}})";
  template <class Num, class Probe> [[gnu::always_inline]] static RayOutput compute(const Prepared<Num>& p, Probe& probe) {
    const auto h = AlgoT{}(p.ray, p.v[0], p.r, probe);
    return make_output<Num>(h.hit, h.t, h.t_exact, nullptr, nullptr, nullptr);
  }
};

struct BoxSpec : RaySpec<ray::RayBox, Prim::box> {
  static inline const std::string example = R"({"ray":{"o":[0,1,0.5],"d":[1,-0.0,0]},"box":{"min":[1,0,0],"max":[2,1,1]}})";
  template <class Num, class Probe> [[gnu::always_inline]] static RayOutput compute(const Prepared<Num>& p, Probe& probe) {
    const auto h = ray::RayBox{}(p.ray, p.v[0], p.v[1], probe);
    return make_output<Num>(h.hit, h.t, true, nullptr, &h.t_near, &h.t_far);
  }
};
struct PlaneSpec : RaySpec<ray::RayPlane, Prim::plane> {
  static inline const std::string example = R"({"ray":{"o":[0,0,1],"d":[1,0,-0.001]},"plane":{"p":[0,0,0],"n":[0,0,1]}})";
  template <class Num, class Probe> [[gnu::always_inline]] static RayOutput compute(const Prepared<Num>& p, Probe& probe) {
    const auto h = ray::RayPlane{}(p.ray, p.v[0], p.v[1], probe);
    return make_output<Num>(h.hit, h.t, true, nullptr, nullptr, nullptr);
  }
};


SW_REGISTER(PlaneSpec);
SW_REGISTER(SphereSpec<ray::RaySphereGeometric>);
SW_REGISTER(SphereSpec<ray::RaySphereQuadratic>);
SW_REGISTER(SphereSpec<ray::RaySphereStable>);
SW_REGISTER(BoxSpec);
SW_REGISTER(TriangleSpec<ray::RayTriangleBarycentric>);
SW_REGISTER(TriangleSpec<ray::RayTriangleMT>);
SW_REGISTER(TriangleSpec<ray::RayTriangleWatertight>);

}  // namespace

}  // namespace sw
