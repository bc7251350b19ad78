// The ray family's intersection Specs, shared by the units that register them: ray_plane_box.cpp,
// ray_spheres.cpp and ray_triangles.cpp each instantiate only their own intersection tests, so a
// change to one test rebuilds one unit. Semantics: docs/rays/semantics.md.
#pragma once
#include <cmath>
#include <memory>
#include <vector>
#include "register.hpp"
#include "rays/ray_common.hpp"
#include "rays/ray_input.hpp"
#include "rays_oracle.hpp"

namespace sw::rays {

enum class Prim { triangle, sphere, box, plane };

struct RayInput {
  Vec3<Rational> o, d;
  std::array<bool, 3> d_neg_zero{};  // a JSON -0.0 direction component (kept for float modes)
  std::array<Vec3<Rational>, 3> v;   // triangle vertices; sphere: v[0] = c; box: v[0], v[1] = min, max; plane: p, n
  Rational r;                        // sphere radius
  std::array<std::vector<Rational>, 3> attr;  // triangle: optional per-vertex attributes (same length)
};

RayInput parse_input(const Json& j, Prim prim);

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

RayOutput from_oracle(const Exact& e);

Json number_json(double d, const Rational* q);

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

std::vector<BenchSet<RayInput>> bench_sets_for(Prim p);

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
double round_to(Numeric n, double x);
template <class Num> Num from_double(double x) {
  if constexpr (std::is_same_v<Num, Rational>) return num::to_rational(x);
  else return Num(x);
}

SweepFrame sweep_frame(const RayInput& in, Prim prim, Numeric inputs);
// Sample (i, j)'s origin: an offset from the input's own, so that the sample at the marker is the
// input ray.
std::array<double, 3> sample_origin(const SweepFrame& f, const SweepGrid& g, int i, int j);

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
  static constexpr std::string_view error_unit = "ulps of t";
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

}  // namespace sw::rays
