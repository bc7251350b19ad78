// The ray family's per-step expectations: expected values that are exact rationals or, where the
// semantics' closed form is irrational (a square root, pi, trigonometry), a 640-bit MPFR value
// computed here from the exact input; the steps a recording must match; and the inputs (the
// catalog example, the lessons, the corpus, the generated sets and seeded small-rational cases that
// reach every miss line).
#pragma once
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <mpfr.h>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>
#include "catalog.hpp"
#include "ray_test_support.hpp"
#include "step_values.hpp"
#include "rays/camera_ray.hpp"
#include "rays/ray_box.hpp"
#include "rays/ray_plane.hpp"
#include "rays/ray_sphere_geometric.hpp"
#include "rays/ray_sphere_quadratic.hpp"
#include "rays/ray_sphere_stable.hpp"
#include "rays/ray_triangle_barycentric.hpp"
#include "rays/ray_triangle_mt.hpp"
#include "rays/ray_triangle_watertight.hpp"
#include "rays/sphere_uv.hpp"

namespace sw::testing::rays {

using Q = Rational;

// An expected number: exact, or `approx` (the closed form is irrational here, or the reference
// rounds on its way): then v is the value to 640 bits and a recorded value must lie within
// 2^-200 max(|v|, 1) of it. An exact zero times anything is an exact zero, as in rationals.
struct Val {
  Q v;
  bool approx = false;
  Val() = default;
  Val(const Q& x, bool a = false) : v(x), approx(a) {}
  Val(int x) : v(x) {}
  bool exact_zero() const { return !approx && sgn(v) == 0; }
};
inline Val operator+(const Val& a, const Val& b) { return {Q(a.v + b.v), a.approx || b.approx}; }
inline Val operator-(const Val& a, const Val& b) { return {Q(a.v - b.v), a.approx || b.approx}; }
inline Val operator-(const Val& a) { return {Q(-a.v), a.approx}; }
inline Val operator*(const Val& a, const Val& b) {
  if (a.exact_zero() || b.exact_zero()) return Val(0);
  return {Q(a.v * b.v), a.approx || b.approx};
}
inline Val operator/(const Val& a, const Val& b) {
  if (a.exact_zero()) return Val(0);
  return {Q(a.v / b.v), a.approx || b.approx};
}
inline std::ostream& operator<<(std::ostream& os, const Val& x) {
  if (!x.approx) return os << x.v.get_str();
  std::ostringstream d;
  d << std::setprecision(17) << "~" << x.v.get_d();
  return os << d.str();
}
using VV = Vec3<Val>;
inline VV lift(const V3& a) { return {Val(a.x), Val(a.y), Val(a.z)}; }

inline bool matches(const Q& got, const Val& want) {
  if (!want.approx) return got == want.v;
  Q tol = abs(want.v) > 1 ? Q(abs(want.v)) : Q(1);
  mpq_div_2exp(tol.get_mpq_t(), tol.get_mpq_t(), 200);
  return abs(Q(got - want.v)) <= tol;
}

// High-precision closed forms, on MPFR directly (not the algorithms' num:: functions).
inline constexpr int kMpBits = 640;
enum class Fn { sqrt, sin, cos, tan, atan2, pi };
inline Q mp(Fn f, const Q& x = Q(0), const Q& y = Q(1)) {
  mpfr_t a, b;
  mpfr_inits2(kMpBits, a, b, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_q(a, x.get_mpq_t(), MPFR_RNDN);
  mpfr_set_q(b, y.get_mpq_t(), MPFR_RNDN);
  switch (f) {
    case Fn::sqrt: mpfr_sqrt(a, a, MPFR_RNDN); break;
    case Fn::sin: mpfr_sin(a, a, MPFR_RNDN); break;
    case Fn::cos: mpfr_cos(a, a, MPFR_RNDN); break;
    case Fn::tan: mpfr_tan(a, a, MPFR_RNDN); break;
    case Fn::atan2: mpfr_atan2(a, a, b, MPFR_RNDN); break;  // atan2(x, y): x is the y-coordinate
    case Fn::pi: mpfr_const_pi(a, MPFR_RNDN); break;
  }
  Q r;
  mpfr_get_q(r.get_mpq_t(), a);
  mpfr_clears(a, b, static_cast<mpfr_ptr>(nullptr));
  return r;
}
// sqrt(x), x >= 0: exact when x is the square of a rational.
inline Val sqrt_val(const Q& x) {
  REQUIRE(sgn(x) >= 0);
  if (mpz_perfect_square_p(x.get_num_mpz_t()) && mpz_perfect_square_p(x.get_den_mpz_t())) {
    mpz_class n, d;
    mpz_sqrt(n.get_mpz_t(), x.get_num_mpz_t());
    mpz_sqrt(d.get_mpz_t(), x.get_den_mpz_t());
    return Val(Q(n) / Q(d));
  }
  return {mp(Fn::sqrt, x), true};
}
// sin 0 = 0, cos 0 = 1, tan 0 = 0 and atan2(0, x >= 0) = 0 are exact (also in MPFR); else approx.
// (An approx x is a positive root here, never 0.)
inline Val sin_val(const Val& x) { return x.exact_zero() ? Val(0) : Val(mp(Fn::sin, x.v), true); }
inline Val cos_val(const Val& x) { return x.exact_zero() ? Val(1) : Val(mp(Fn::cos, x.v), true); }
inline Val tan_val(const Val& x) { return x.exact_zero() ? Val(0) : Val(mp(Fn::tan, x.v), true); }
inline Val atan2_val(const Val& y, const Val& x) {
  if (y.exact_zero() && sgn(x.v) >= 0) return Val(0);
  return {mp(Fn::atan2, y.v, x.v), true};
}
inline Val pi_val() { return {mp(Fn::pi), true}; }

// The sign of p + s sqrt(q) (s = +1 or -1, q >= 0), exactly.
inline int sign_add_root(const Q& p, int s, const Q& q) {
  if (sgn(q) == 0) return sgn(p);
  if (sgn(p) == 0 || sgn(p) == s) return s;
  const int c = cmp(Q(p * p), q);
  return c > 0 ? sgn(p) : c < 0 ? s : 0;
}

// One geometry item and one step as the semantics calls for them.
struct ExpectedItem {
  GeoKind kind;
  std::vector<Val> values;
  std::string label, life;  // empty: none, this step only
  std::optional<Val> value;
};
struct ExpectedStep {
  std::uint32_t line;
  StepKind kind;
  std::vector<std::pair<std::string, Val>> vars;
  std::vector<ExpectedItem> geo;
  ExpectedStep& var(const char* name, const Val& v) {
    vars.push_back({name, v});
    return *this;
  }
  ExpectedStep& flag(const char* name, std::int64_t v) { return var(name, Val(Q(v))); }
  ExpectedStep& vec(const char* x, const char* y, const char* z, const VV& v) { return var(x, v.x).var(y, v.y).var(z, v.z); }
  ExpectedStep& item(GeoKind kind, std::vector<Val> values) {
    geo.push_back({kind, std::move(values), {}, {}, {}});
    return *this;
  }
  // Modifiers of the last item: its label, its lifetime, its value.
  ExpectedStep& label(const char* text) {
    geo.back().label = text;
    return *this;
  }
  ExpectedStep& keep() {
    geo.back().life = "keep";
    return *this;
  }
  ExpectedStep& replace() {
    geo.back().life = "replace";
    return *this;
  }
  ExpectedStep& valued(const Val& v) {
    geo.back().value = v;
    return *this;
  }
  ExpectedStep& point(const VV& p) { return item(GeoKind::point3, {p.x, p.y, p.z}); }
  ExpectedStep& segment(const VV& a, const VV& b) { return item(GeoKind::segment3, {a.x, a.y, a.z, b.x, b.y, b.z}); }
  ExpectedStep& item2(GeoKind kind, const VV& a, const VV& b) { return item(kind, {a.x, a.y, a.z, b.x, b.y, b.z}); }
};
struct Expected {
  std::vector<ExpectedStep> steps;
  ExpectedStep& step(std::uint32_t line, StepKind kind) {
    steps.push_back({line, kind, {}, {}});
    return steps.back();
  }
};

// Replays a recording against the expectation: the same lines, kinds and order; every recorded
// variable and geometry item (kind, values, label, lifetime, value) equal to its closed form, and
// none without one.
inline void require_matches(const Recorder<Q>& t, const Listing& listing, const Expected& want,
                            std::set<std::string_view>& seen) {
  for (std::size_t s = 0; s < t.size(); ++s) {
    const std::string_view line = listing.lines[t.at(s).line - 1].name;
    seen.insert(line);
    INFO("step " << s << " (" << line << ")");
    REQUIRE(s < want.steps.size());  // a step the semantics does not call for
    const ExpectedStep& w = want.steps[s];
    INFO("expected line " << listing.lines[w.line - 1].name);
    REQUIRE(t.at(s).line == w.line);
    CHECK(kind_name(t.at(s).kind) == kind_name(w.kind));
    CHECK(t.at(s).scope == 0);
    StepValues sv = values_of(t, s);
    for (const auto& [name, v] : w.vars) {
      const Q& got = sv[name];
      INFO("variable " << name << " = " << got << " (" << got.get_d() << "), expected " << v);
      CHECK(matches(got, v));
    }
    require_all_checked(sv, s);
    StepGeometry g = geometry_of(t, s);
    for (const ExpectedItem& wi : w.geo) {
      const GeoItem& item = g.take(wi.kind);
      INFO("a " << geo_name(wi.kind) << " expected with label '" << wi.label << "'");
      CHECK(item.label == wi.label);
      CHECK(item.life == wi.life);
      REQUIRE(item.values.size() == wi.values.size());
      for (std::size_t k = 0; k < wi.values.size(); ++k) {
        INFO("value " << k << " = " << item.values[k] << ", expected " << wi.values[k]);
        CHECK(matches(item.values[k], wi.values[k]));
      }
      CHECK(item.value.has_value() == wi.value.has_value());
      if (item.value && wi.value) {
        INFO("item value " << *item.value << ", expected " << *wi.value);
        CHECK(matches(*item.value, *wi.value));
      }
    }
    require_all_geometry_checked(g, s);
  }
  CHECK(t.size() == want.steps.size());  // no step the semantics calls for is missing
}

// The listing's lines, less those no step records by design.
inline std::set<std::string_view> recorded_lines(const Listing& l, std::set<std::string_view> never) {
  std::set<std::string_view> out;
  for (const ListingLine& line : l.lines)
    if (!never.count(line.name)) out.insert(line.name);
  return out;
}

// An input with where it came from.
struct Case {
  std::string name;
  Json input;
};

// The catalog example and the inputs of the lessons that show algorithm `id`.
inline std::vector<Case> example_and_lessons(std::string_view id) {
  std::vector<Case> out{{"the example", Json::parse(find_algorithm(id).example)}};
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(SW_SOURCE_DIR) / "lessons")) {
    if (entry.path().extension() != ".md") continue;
    std::ifstream f(entry.path());
    std::string line, algorithm, input;
    for (int n = 0; n < 20 && std::getline(f, line); ++n) {
      if (line.rfind("algorithm: ", 0) == 0) algorithm = line.substr(11);
      if (line.rfind("input: ", 0) == 0) input = line.substr(7);
    }
    if (algorithm == id) out.push_back({"lesson " + entry.path().filename().string(), Json::parse(input)});
  }
  return out;
}

// The files' cases whose input holds `key` (a primitive, "camera", "point"; empty: every case).
inline std::vector<Case> corpus_cases(const std::string& key) {
  std::vector<Case> out;
  for (const char* file : {"corpus.jsonl", "coverage.jsonl"})
    for (const Json& c : read_jsonl(file))
      if (key.empty() || c["input"].contains(key))
        out.push_back({std::string(file) + ": " + c["name"].get<std::string>(), c["input"]});
  return out;
}

// Seeded small rationals: an integer in [lo, hi] over 1, 1, 2 or 3, as an exact string.
struct SmallRng {
  std::mt19937_64 rng;
  explicit SmallRng(std::uint64_t seed) : rng(seed) {}
  int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  bool one_in(int n) { return pick(1, n) == 1; }
  Json num(int lo, int hi, bool fractions = true) {
    const int den = fractions ? std::array{1, 1, 2, 3}[pick(0, 3)] : 1;
    return Q(Q(pick(lo * den, hi * den)) / den).get_str();
  }
  Json vec(int lo, int hi, bool fractions = true) {
    return Json::array({num(lo, hi, fractions), num(lo, hi, fractions), num(lo, hi, fractions)});
  }
  Json nonzero_vec(int lo, int hi, bool fractions = true) {
    for (;;) {
      Json v = vec(lo, hi, fractions);
      if (v != Json::array({"0", "0", "0"})) return v;
    }
  }
};

// What an intersection test returned.
struct Returned {
  bool hit = false, t_exact = true;
  Q t, t_near, t_far;
  std::array<Q, 3> b;
};

// The camera as the catalog prepares it: the field of view in radians with the reference's pi.
struct CameraCase {
  ray::Camera<Q> cam;
  std::int64_t i = 0, j = 0;
  Q fov_deg;
};
inline CameraCase camera_of(const Json& in) {
  CameraCase c;
  const Json& j = in["camera"];
  c.cam.eye = parse_point3(j, "eye"), c.cam.vpn = parse_point3(j, "vpn"), c.cam.vup = parse_point3(j, "vup");
  c.cam.dist = q(j["d"]), c.fov_deg = j.contains("fov") ? q(j["fov"]) : Q(60);
  c.cam.fov = c.fov_deg * num::pi<Q>() / 180;
  if (j.contains("window")) {
    c.cam.has_window = true;
    for (std::size_t k = 0; k < 4; ++k) c.cam.window[k] = q(j["window"][k]);
  }
  c.cam.width = in["size"][0].get<std::int64_t>(), c.cam.height = in["size"][1].get<std::int64_t>();
  c.i = in["pixel"][0].get<std::int64_t>(), c.j = in["pixel"][1].get<std::int64_t>();
  const std::string proj = in["projection"];
  c.cam.projection = proj == "fisheye"       ? ray::Projection::fisheye
                     : proj == "cylindrical" ? ray::Projection::cylindrical
                                             : ray::Projection::perspective;
  return c;
}

// Records algorithm `id` on `in` in exact (reference) rationals by calling its header directly,
// so that a test built against a changed copy of the headers sees the change.
inline Returned record_direct(std::string_view id, const Json& in, Recorder<Q>& t) {
  Returned out;
  if (id == "camera-ray") {
    const CameraCase c = camera_of(in);
    out.hit = ray::camera_ray<Q>(c.cam, c.i, c.j, t).valid;
    return out;
  }
  if (id == "sphere-uv") {
    ray::sphere_uv<Q>(parse_point3(in["sphere"], "c"), parse_point3(in, "point"), t);
    return out;
  }
  std::string prim;
  for (const auto& [p, ids] : kAlgs)
    for (const std::string& x : ids)
      if (x == id) prim = p;
  REQUIRE(!prim.empty());
  const Parsed p = parse(in, prim);
  const ray::Ray3<Q> r{p.o, p.d};
  auto take = [&](const auto& h) { out.hit = h.hit, out.t = h.t; };
  if (id == "ray-plane") take(ray::ray_plane<Q>(r, p.v[0], p.v[1], t));
  if (id == "ray-box") {
    const auto h = ray::ray_box<Q>(r, p.v[0], p.v[1], t);
    take(h), out.t_near = h.t_near, out.t_far = h.t_far;
  }
  auto sphere = [&](const auto& h) { take(h), out.t_exact = h.t_exact; };
  if (id == "ray-sphere-geometric") sphere(ray::ray_sphere_geometric<Q>(r, p.v[0], p.r, t));
  if (id == "ray-sphere-quadratic") sphere(ray::ray_sphere_quadratic<Q>(r, p.v[0], p.r, t));
  if (id == "ray-sphere-stable") sphere(ray::ray_sphere_stable<Q>(r, p.v[0], p.r, t));
  auto triangle = [&](const auto& h) { take(h), out.b = h.b; };
  if (id == "ray-triangle-barycentric") triangle(ray::ray_triangle_barycentric<Q>(r, p.v, t));
  if (id == "ray-triangle-mt") triangle(ray::ray_triangle_mt<Q>(r, p.v, t));
  if (id == "ray-triangle-watertight") triangle(ray::ray_triangle_watertight<Q>(r, p.v, t));
  return out;
}

}  // namespace sw::testing::rays
