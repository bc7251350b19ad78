// The reflection models one light at a time: lambert, minnaert, oren-nayar, toon, phong,
// blinn-phong, gaussian, beckmann, cook-torrance, in float, double and reference (Rational with
// sqrt, pow, exp, acos in 300-bit MPFR). The decisions (lit, seen, the mirror side, the toon cut)
// are made once on the exact input, so every mode takes the reference's branches and differs only
// in its values. The oracle is oracle/lighting_oracle.cpp (400-bit MPFR from the papers' angle
// formulas). A float result that is NaN or infinite, negative, or above 1 for a model whose exact
// term never is, is a failure: shown in the result and counted as a bench mismatch.
// Semantics: docs/lighting/semantics.md; accuracy: docs/lighting/accuracy.md.
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <mpfr.h>
#include "register.hpp"
#include "lighting/lighting_input.hpp"
#include "lighting/model_table.hpp"
#include "lighting/models.hpp"
#include "lighting_oracle.hpp"

namespace sw {

// The table of reflection models (model_table.hpp): one row per parameter and per entry. A new
// model adds its row below, its example and its SW_REGISTER line at the end of this file.
namespace lighting_io {
namespace {
using lighting::DiffuseModel;
using lighting::ModelChoice;
using lighting::SpecularModel;
using P = lighting::ModelParams<Rational>;

const ModelParam kK{"k", 0, 1, false, 0, 1, false, "Minnaert's darkening exponent: 1 is Lambert, lower darkens the limb less",
                    0, 1, {0, 1, 0.001, 0.999}, [](P& p, const Rational& x) { p.minnaert_k = x; },
                    [](const P& p) { return p.minnaert_k; }};
const ModelParam kSigma{"sigma", 0, 1, false, 0, 1, false, "Oren-Nayar's slope spread in radians: 0 is Lambert",
                        0, 1, {0, 1, 0.999}, [](P& p, const Rational& x) { p.sigma = x; },
                    [](const P& p) { return p.sigma; }};
const ModelParam kCutoff{"cutoff", 0, 1, false, 0, 1, false, "toon: the diffuse value at which the band switches",
                         0, 1, {}, [](P& p, const Rational& x) { p.toon = x; },
                         [](const P& p) { return p.toon.value_or(Rational(0)); }};
const ModelParam kShininess{"shininess", 0, 1e6, false, 0, 10000, true, "the highlight exponent n",
                            1, 200, {10000, 1000, 0, 1}, [](P& p, const Rational& x) { p.shininess = x; },
                    [](const P& p) { return p.shininess; }};
const ModelParam kM{"m", 0, 100, true, 0.001, 1, true, "the RMS slope of the microfacets: lower is glossier",
                    0.05, 1, {0.001, 0.01, 1, 5}, [](P& p, const Rational& x) { p.m = x; },
                    [](const P& p) { return p.m; }};
const ModelParam kIor{"ior", 1, 100, false, 1, 3, false, "the index of refraction in the Fresnel term",
                      1, 3, {1, 1.0001, 50}, [](P& p, const Rational& x) { p.ior = x; },
                    [](const P& p) { return p.ior; }};

constexpr ModelChoice diffuse(DiffuseModel m) { return {.specular = false, .diffuse = m}; }
constexpr ModelChoice specular(SpecularModel m) { return {.specular = true, .spec = m}; }

}  // namespace

const std::vector<ModelRow>& model_table() {
  static const std::vector<ModelRow> rows = {
      {"lambert", diffuse(DiffuseModel::lambert), {}, false, false, true, R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2]})"},
      {"minnaert", diffuse(DiffuseModel::minnaert), {&kK}, false, false, false, R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"k":0.5})"},
      {"oren-nayar", diffuse(DiffuseModel::oren_nayar), {&kSigma}, false, false, false, R"({"n":[0,0,1],"l":[1,0,1],"e":[1,1,2],"sigma":0.5})"},
      {"toon", diffuse(DiffuseModel::lambert), {&kCutoff}, true, false, false,
       R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"diffuse":"lambert","cutoff":0.5})"},
      {"phong", specular(SpecularModel::phong), {&kShininess}, false, false, true, R"({"n":[0,0,1],"l":[1,0,1],"e":[-1,0.25,2],"shininess":20})"},
      {"blinn-phong", specular(SpecularModel::blinn_phong), {&kShininess}, false, false, true,
       R"({"n":[0,0,1],"l":[1,0,1],"e":[-1,0.25,2],"shininess":20})"},
      {"gaussian", specular(SpecularModel::gaussian), {&kM}, false, false, true, R"({"n":[0,0,1],"l":[1,0,1],"e":[-1,0.25,2],"m":0.3})"},
      {"beckmann", specular(SpecularModel::beckmann), {&kM}, false, false, false, R"({"n":[0,0,1],"l":[1,0,1],"e":[-1,0.25,2],"m":0.3})"},
      {"cook-torrance", specular(SpecularModel::cook_torrance), {&kM, &kIor}, false, true, false,
       R"({"n":[0,0,1],"l":[1,0,1],"e":[-1,0.25,2],"m":0.3,"ior":1.5,"fresnel":"exact"})"},
      {"ward", specular(SpecularModel::ward), {&kM}, false, false, false, R"({"n":[0,0,1],"l":[1,0,1],"e":[-1,0.25,2],"m":0.3})"},
  };
  return rows;
}

}  // namespace lighting_io

namespace {

using lighting_io::ModelInput;
using namespace sw::lighting;

enum class Failure : std::uint8_t { none, not_finite, negative, above_one };
constexpr std::string_view kFailureNames[] = {"none", "nan-or-inf", "negative", "above-1"};

struct ModelOutput {
  bool outside = false;  // a sweep sample off the sphere: no value
  bool lit = false, seen = false;
  Failure failure = Failure::none;
  int bits = 53;
  double value = 0;
  Vec3<double> n, l, e;  // the unit frame as the mode computed it
  std::shared_ptr<const Rational> ref;  // the value itself, in reference mode and from the oracle
  friend bool operator==(const ModelOutput& a, const ModelOutput& b) {
    return a.lit == b.lit && a.seen == b.seen && a.failure == b.failure;
  }
};

template <class Num> ModelParams<Num> params_as(const ModelParams<Rational>& q) {
  auto f = [](const Rational& x) { return num::from_rational<Num>(x); };
  ModelParams<Num> p;
  p.minnaert_k = f(q.minnaert_k), p.sigma = f(q.sigma), p.shininess = f(q.shininess), p.m = f(q.m), p.ior = f(q.ior);
  if (q.toon) p.toon = f(*q.toon);
  p.toon_above = q.toon_above, p.fresnel = q.fresnel, p.shadowing = q.shadowing;
  return p;
}

template <class Num> struct Prepared {
  ModelChoice choice;
  Vec3<Num> n, l, e;
  ModelParams<Num> p;
  FrameSigns signs;
  bool bounded;
  bool outside = false;  // a sweep sample off the sphere
};

// A swept vector, computed in double and rounded to the grid's inputs, so that every mode shades
// the same vector.
Vec3<Rational> sweep_vector(const SweepGrid& g, const Vec3<double>& v) {
  auto in = [&](double x) { return num::to_rational(g.inputs == Numeric::f32 ? double(float(x)) : x); };
  return {in(v.x), in(v.y), in(v.z)};
}

// The image view's sweep: sample (i, j) of the grid is the point (x, y) of a unit sphere seen from
// +z, whose normal is (x, y, sqrt(1 - x^2 - y^2)); off the sphere: none.
std::optional<Vec3<Rational>> sphere_normal(const SweepGrid& g, int i, int j) {
  const double x = g.x(i), y = g.y(j), zz = 1 - x * x - y * y;
  if (!(zz > 0)) return std::nullopt;
  return sweep_vector(g, {x, y, std::sqrt(zz)});
}

// A direction in double, scaled by its largest component first (exactly), so that a denormal or a
// huge input vector still has a unit direction.
Vec3<double> direction_of(const Vec3<Rational>& v) {
  const Rational m = std::max({abs(v.x), abs(v.y), abs(v.z)});
  return lighting::unit(Vec3<double>{Rational(v.x / m).get_d(), Rational(v.y / m).get_d(), Rational(v.z / m).get_d()});
}

// The lobe view's plane of incidence, in double: the unit normal u, and the unit tangent t in the
// plane of n and l pointing away from the light (towards the mirror direction). A light along the
// normal leaves the plane free: then the eye's side, else any tangent.
struct IncidencePlane {
  Vec3<double> u, t;
  static IncidencePlane of(const ModelInput& in) {
    const Vec3<double> u = direction_of(in.n);
    auto tangent = [&](const Vec3<double>& v, double sign) -> std::optional<Vec3<double>> {
      const Vec3<double> w = v - dot(v, u) * u;
      if (!(dot(w, w) > 1e-20)) return std::nullopt;
      return lighting::unit(sign * w);
    };
    const auto t = tangent(direction_of(in.l), -1);
    if (t) return {u, *t};
    if (const auto te = tangent(direction_of(in.e), 1)) return {u, *te};
    return {u, *tangent(std::fabs(u.x) < 0.9 ? Vec3<double>{1, 0, 0} : Vec3<double>{0, 1, 0}, 1)};
  }
  // The direction at `deg` degrees from the normal, positive towards the mirror side.
  Vec3<double> at(double deg) const {
    const double a = deg * (3.141592653589793 / 180);
    return std::cos(a) * u + std::sin(a) * t;
  }
  // A unit direction's angle in the plane, or NaN if it leaves the plane by more than 1e-9.
  double angle(const Vec3<double>& w) const {
    const Vec3<double> b = cross(u, t);
    if (std::fabs(dot(w, b)) > 1e-9) return NAN;
    return std::atan2(dot(w, t), dot(w, u)) * (180 / 3.141592653589793);
  }
};

// |got - ref| in units in the last place of the mode at ref (ref's exponent, at least the mode's
// smallest normal one); 0 where both are 0; in ulps of 1 where only ref is 0 (a term that should
// be exactly 0, e.g. Fresnel at ior 1, but is a rounding residue).
double ulps(const Rational& got, const Rational& ref, int bits) {
  const Rational err = abs(Rational(got - ref));
  if (sgn(err) == 0) return 0;
  long exp = sgn(ref) == 0 ? 1 : bits == 24 ? -125 : -1021;
  if (sgn(ref) != 0) {
    mpfr_t m;
    mpfr_init2(m, 64);
    mpfr_set_q(m, ref.get_mpq_t(), MPFR_RNDN);
    exp = std::max<long>(exp, mpfr_get_exp(m));  // ref in [2^(exp-1), 2^exp)
    mpfr_clear(m);
  }
  mpfr_t u;
  mpfr_init2(u, 64);
  mpfr_set_q(u, err.get_mpq_t(), MPFR_RNDN);
  mpfr_mul_2si(u, u, bits - exp, MPFR_RNDN);  // err / 2^(exp - bits)
  const double r = mpfr_get_d(u, MPFR_RNDN);
  mpfr_clear(u);
  return r;
}

Vec3<double> vec_of(const lighting_oracle::OracleTerm& o, const char* k) {
  auto at = [&](const char* c) { return o.named.at(std::string(k) + c).get_d(); };
  return {at(".x"), at(".y"), at(".z")};
}

template <class A> struct ModelSpec {
  using Algo = A;
  static constexpr std::array hooks{Hook::error,      Hook::handles, Hook::sweeper, Hook::sweep_caption, Hook::sweep_input, Hook::sweep_shaded,
                                    Hook::lobe,       Hook::params,  Hook::compare_group, Hook::result_keys};
  static constexpr std::array result_keys{std::string_view("value")};  // the term: the lobe view's eye, the compare strip
  using Input = ModelInput;
  using Output = ModelOutput;
  static constexpr std::array views{View::orbit3d, View::image, View::lobe};
  static constexpr std::string_view compare_group = "reflection models";
  static std::vector<Param> params() { return lighting_io::model_sliders(); }
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::reference};
  static const std::string example;
  static Input parse(const Json& j) { return lighting_io::parse_model_input(Algo::id, j); }
  static std::vector<Handle> handles() { return {{"/l", Handle::Kind::direction3, 0, "l"}, {"/e", Handle::Kind::direction3, 0, "e"}}; }
  template <class Num> static Prepared<Num> prepare(const Input& in) {
    static const bool bounded = lighting_io::model_row(Algo::id).bounded;  // looked up once, not per sweep sample
    return {in.choice, to_num<Num>(in.n), to_num<Num>(in.l), to_num<Num>(in.e), params_as<Num>(in.p), in.signs, bounded};
  }
  // The image view: the model over a sphere's normals, l and e as given, decisions exact per sample.
  static constexpr std::string_view sweep_caption = "normals of a unit sphere seen from +z, l and e as given";
  static constexpr bool sweep_shaded = true;
  template <class Num> static auto sweeper(const Input& base, const SweepGrid& g) {
    return [base, g](int i, int j, Prepared<Num>& p) {
      const auto n = sphere_normal(g, i, j);
      p.outside = !n;
      if (!n) return;
      Input in = base;
      in.n = *n;
      lighting_io::decide(in);
      p = prepare<Num>(in);
    };
  }
  // Json::array, not a bare {…}: clang 14 never frees the value a braced list replaces in a template.
  static Json sweep_input(Json j, const Input&, const SweepGrid& g, int i, int k) {
    if (const auto n = sphere_normal(g, i, k)) j["n"] = Json::array({n->x.get_d(), n->y.get_d(), n->z.get_d()});
    return j;
  }
  // The lobe view: the eye swept over the plane of incidence, n and l as given.
  template <class Num> static auto lobe_sweeper(const Input& base, const SweepGrid& g) {
    return [base, g, plane = IncidencePlane::of(base)](int i, int, Prepared<Num>& p) {
      Input in = base;
      in.e = sweep_vector(g, plane.at(g.x(i)));
      lighting_io::decide(in);
      p = prepare<Num>(in);
    };
  }
  static std::optional<std::array<double, 2>> lobe_angles(const Input& in) {
    const IncidencePlane plane = IncidencePlane::of(in);
    return std::array{plane.angle(direction_of(in.l)), plane.angle(direction_of(in.e))};
  }
  static Json lobe_input(Json j, const Input& in, const SweepGrid& g, int i) {
    const Vec3<Rational> e = sweep_vector(g, IncidencePlane::of(in).at(g.x(i)));
    j["e"] = Json::array({e.x.get_d(), e.y.get_d(), e.z.get_d()});
    return j;
  }
  static float sweep_value(const Output& o) { return o.outside ? NAN : static_cast<float>(o.value); }
  template <class Num, class Probe> static Output compute(const Prepared<Num>& x, Probe& probe) {
    if (x.outside) {
      Output o;
      o.outside = true;
      return o;
    }
    Frame<Num> f;
    const Num v = evaluate<Algo>(x.choice, x.n, x.l, x.e, x.p, probe, x.signs, &f);
    Output o;
    o.lit = f.lit, o.seen = f.seen;
    auto d3 = [](const Vec3<Num>& a) { return Vec3<double>{num::to_double(a.x), num::to_double(a.y), num::to_double(a.z)}; };
    o.n = d3(f.n), o.l = d3(f.l), o.e = d3(f.e);
    if constexpr (std::is_same_v<Num, Rational>) {
      o.bits = 300;
      o.value = v.get_d();
      o.ref = std::make_shared<const Rational>(v);
      // The reference's own rounding (2^-300 in the unit vectors) may put a term of exactly 1 a hair
      // above 1, or one of exactly 0 a hair below (Schlick's (1 - e.h)^5 at l = e, ior = 1): not failures.
      const Rational hair = Rational(1) / Rational(mpz_class(1) << 250);
      if (v < -hair) o.failure = Failure::negative;
      else if (x.bounded && v > Rational(1) + hair) o.failure = Failure::above_one;
    } else {
      o.bits = std::is_same_v<Num, float> ? 24 : 53;
      o.value = double(v);
      // A frame that is not finite (a squared length underflowed to 0) is a failure even where the
      // term came out finite: pow(Inf, -1) = 0 and pow(NaN, 0) = 1 hide it. Not for toon, whose 0 or
      // 1 is the exact decision whatever the frame's values.
      const bool frame_ok = x.p.toon || (std::isfinite(f.nl) && std::isfinite(f.ne) && std::isfinite(dot(f.l, f.e)));
      if (!std::isfinite(v) || !frame_ok) o.failure = Failure::not_finite;
      else if (v < Num(0)) o.failure = Failure::negative;
      else if (x.bounded && v > Num(1)) o.failure = Failure::above_one;
    }
    return o;
  }
  static Json to_json(const Output& o) {
    Json j = {{"value", o.value}, {"lit", o.lit}, {"seen", o.seen}};
    auto dot3 = [](const Vec3<double>& a, const Vec3<double>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
    // The breakdown, from the mode's unit frame (in double): the cosines and the two highlight
    // cosines, where the frame is lit and seen.
    j["nl"] = dot3(o.n, o.l), j["ne"] = dot3(o.n, o.e), j["le"] = dot3(o.l, o.e);
    if (o.lit && o.seen) {
      const Vec3<double> h = o.l + o.e;
      j["nh"] = dot3(o.n, h) / std::sqrt(dot3(h, h));
      j["re"] = 2 * dot3(o.n, o.l) * dot3(o.n, o.e) - dot3(o.l, o.e);
    }
    if (o.failure != Failure::none) j["failure"] = kFailureNames[static_cast<int>(o.failure)];
    return j;
  }
  static std::size_t ops(const Output&) { return 1; }
  static Output oracle(const Input& in) {
    const auto t = lighting_oracle::term(in.choice, in.n, in.l, in.e, in.p);
    Output o;
    o.lit = t.lit, o.seen = t.seen, o.bits = 400;
    o.value = t.value.get_d();
    o.ref = std::make_shared<const Rational>(t.value);
    o.n = vec_of(t, "n"), o.l = vec_of(t, "l"), o.e = vec_of(t, "e");
    return o;
  }
  static constexpr std::string_view error_unit = "ulps";
  static double error(const Output& got, const Output& ref) {
    if (!ref.ref) return 0;
    if (got.ref) return ulps(*got.ref, *ref.ref, got.bits);  // reference mode: its own value, not the double
    if (got.failure != Failure::none) return 0;              // a failure: counted as a mismatch instead
    return ulps(num::to_rational(got.value), *ref.ref, got.bits);
  }
  static std::vector<BenchSet<Input>> bench_sets();
};

// The examples are the table's (explicit specialisations: initialised in order, before the registrars below).
template <> const std::string ModelSpec<Lambert>::example{lighting_io::model_row(Lambert::id).example};
template <> const std::string ModelSpec<Minnaert>::example{lighting_io::model_row(Minnaert::id).example};
template <> const std::string ModelSpec<OrenNayar>::example{lighting_io::model_row(OrenNayar::id).example};
template <> const std::string ModelSpec<Toon>::example{lighting_io::model_row(Toon::id).example};
template <> const std::string ModelSpec<Phong>::example{lighting_io::model_row(Phong::id).example};
template <> const std::string ModelSpec<BlinnPhong>::example{lighting_io::model_row(BlinnPhong::id).example};
template <> const std::string ModelSpec<Gaussian>::example{lighting_io::model_row(Gaussian::id).example};
template <> const std::string ModelSpec<Beckmann>::example{lighting_io::model_row(Beckmann::id).example};
template <> const std::string ModelSpec<CookTorrance>::example{lighting_io::model_row(CookTorrance::id).example};
template <> const std::string ModelSpec<Ward>::example{lighting_io::model_row(Ward::id).example};

template <class A> std::vector<BenchSet<ModelInput>> ModelSpec<A>::bench_sets() { return lighting_io::model_bench_sets(A::id); }

SW_REGISTER(ModelSpec<Lambert>);
SW_REGISTER(ModelSpec<Minnaert>);
SW_REGISTER(ModelSpec<OrenNayar>);
SW_REGISTER(ModelSpec<Toon>);
SW_REGISTER(ModelSpec<Phong>);
SW_REGISTER(ModelSpec<BlinnPhong>);
SW_REGISTER(ModelSpec<Gaussian>);
SW_REGISTER(ModelSpec<Beckmann>);
SW_REGISTER(ModelSpec<CookTorrance>);
SW_REGISTER(ModelSpec<Ward>);

}  // namespace

}  // namespace sw
