// The ray family, step by step: every variable and geometry item an exact step of ray-plane,
// ray-box and the three ray-sphere tests records, in the order the steps come, against closed
// forms of docs/rays/semantics.md written from the input (not by running the algorithm), for the
// catalog examples, the lessons, the corpus, the generated random and hard sets and seeded small
// rational cases that reach every miss line. A step, variable or geometry item without an
// expectation fails. The expected outcome is also held against the oracle. Triangles:
// test_ray_triangle_steps.cpp; camera-ray and sphere-uv: test_ray_mapping_steps.cpp.
//
// Listing lines no step records, by design: ray-box `axis`, `slab` and `order` (the clip step
// shows the ordered slab interval); ray-sphere-geometric `hit` (the root step is the hit step).
#include <catch2/catch.hpp>
#include <sstream>
#include "catalog.hpp"
#include "ray_steps.hpp"
#include "rays/cases.hpp"
#include "rays_oracle.hpp"
#include "trace_io.hpp"

using namespace sw;
using namespace sw::testing::rays;
using sw::testing::ratio;
using K = StepKind;

namespace {

struct Outcome {
  bool hit = false;
  Val t;
  Q t_near, t_far;
};

Outcome hit_at(const Val& t) {
  Outcome o;
  o.hit = true, o.t = t;
  return o;
}

VV at(const Parsed& p, const Val& t) { return lift(p.o) + t * lift(p.d); }
ExpectedStep& scene_ray(ExpectedStep& s, const Parsed& p) { return s.item2(GeoKind::ray3, lift(p.o), lift(p.d)).keep(); }

// ray-plane: den = n.d; parallel iff den = 0; else num = n.(p - o), t = num / den, a hit iff t > 0.
Outcome plane_expected(const Parsed& p, Expected& e) {
  using L = ray::RayPlane;
  const V3 pp = p.v[0], n = p.v[1];
  const Q den = dotq(n, p.d);
  scene_ray(e.step(L::denom, K::decide).var("den", den), p).item2(GeoKind::plane, lift(pp), lift(n)).keep();
  if (sgn(den) == 0) {
    e.step(L::parallel, K::miss);
    return {};
  }
  const Q num = dotq(n, sub(pp, p.o)), t = num / den;
  e.step(L::num, K::decide).var("num", num);
  if (sgn(t) <= 0) {
    e.step(L::behind, K::miss);
    return {};
  }
  e.step(L::hit, K::hit).var("t", t).point(at(p, t)).label("hit");
  return hit_at(t);
}

// ray-box: axis k with d_k = 0 holds every t iff min_k <= o_k <= max_k; else the ray is in the
// slab for t between the two plane crossings (min_k - o_k) / d_k and (max_k - o_k) / d_k, t1 the
// smaller. The interval [t_near, t_far] is the intersection of the slab intervals so far.
Outcome box_expected(const Parsed& p, Expected& e) {
  using L = ray::RayBox;
  const V3 lo = p.v[0], hi = p.v[1];
  scene_ray(e.step(L::init, K::init), p).item2(GeoKind::box3, lift(lo), lift(hi)).keep();
  static const char* slab[3] = {"x slab", "y slab", "z slab"};
  bool bounded = false;
  Q tn, tf;
  for (int k = 0; k < 3; ++k) {
    if (sgn(p.d[k]) == 0) {
      const bool out = p.o[k] < lo[k] || p.o[k] > hi[k];
      e.step(L::flat, K::decide).flag("k", k).flag("out", out);
      if (out) {
        e.step(L::outside, K::miss);
        return {};
      }
      continue;
    }
    const Q ta = (lo[k] - p.o[k]) / p.d[k], tb = (hi[k] - p.o[k]) / p.d[k];
    const Q t1 = std::min(ta, tb), t2 = std::max(ta, tb);
    tn = bounded ? std::max(tn, t1) : t1, tf = bounded ? std::min(tf, t2) : t2, bounded = true;
    e.step(L::clip, K::advance).flag("k", k).var("t1", t1).var("t2", t2).var("t_near", tn).var("t_far", tf)
        .segment(at(p, t1), at(p, t2)).label(slab[k]).keep()
        .segment(at(p, tn), at(p, tf)).label("[t_near, t_far]").valued(Q(tf - tn)).replace();
  }
  if (tn > tf) {
    e.step(L::empty, K::miss);
    return {};
  }
  if (sgn(tf) <= 0) {
    e.step(L::exit, K::miss);
    return {};
  }
  const Q t = sgn(tn) > 0 ? tn : tf;
  e.step(L::hit, K::hit).var("t", t).point(at(p, t)).label("hit");
  Outcome o = hit_at(t);
  o.t_near = tn, o.t_far = tf;
  return o;
}

// The sphere's closed forms. With f = o - c, a = d.d, b' = f.d, cc = f.f - r^2: the roots of
// |o + t d - c|^2 = r^2 are t-/+ = (-b' -/+ sqrt(D)) / a with D = b'^2 - a cc = a r^2 - |f x d|^2
// (Lagrange's identity: stated by the cross product, independently of the algorithms' forms);
// the line's closest point to c is the foot o - (b'/a) d, at squared distance |f x d|^2 / a.
struct SphereForms {
  Q a, bh, cc, r2, x2, dq;
  VV c, foot;
  Val tm, tp;
  int sm = 0, sp = 0;  // the exact signs of t- and t+
};
SphereForms sphere_forms(const Parsed& p) {
  SphereForms s;
  const V3 f = sub(p.o, p.v[0]), fxd = crossq(f, p.d);
  s.a = dotq(p.d, p.d), s.bh = dotq(f, p.d), s.r2 = p.r * p.r, s.cc = dotq(f, f) - s.r2, s.x2 = dotq(fxd, fxd);
  s.dq = s.a * s.r2 - s.x2;
  s.c = lift(p.v[0]);
  s.foot = lift(p.o) + Val(Q(-s.bh / s.a)) * lift(p.d);
  if (sgn(s.dq) >= 0) {
    const Val root = sqrt_val(s.dq);
    s.tm = (Val(Q(-s.bh)) - root) / Val(s.a), s.tp = (Val(Q(-s.bh)) + root) / Val(s.a);
    s.sm = sign_add_root(Q(-s.bh), -1, s.dq), s.sp = sign_add_root(Q(-s.bh), 1, s.dq);
  }
  return s;
}
ExpectedStep& scene_sphere(ExpectedStep& st, const Parsed& p) {
  return scene_ray(st, p).item(GeoKind::sphere, {p.v[0].x, p.v[0].y, p.v[0].z, p.r}).keep();
}

// ray-sphere-geometric: behind iff the origin is not inside and tca = (c - o).d <= 0; rejected iff
// the line is farther than r from c; else the hit is the smallest positive root.
Outcome geometric_expected(const Parsed& p, Expected& e) {
  using L = ray::RaySphereGeometric;
  const SphereForms s = sphere_forms(p);
  const Q l2 = Q(s.cc + s.r2), tca = -s.bh;
  scene_sphere(e.step(L::oc, K::init).var("L2", l2).var("a", s.a).var("r2", s.r2), p);
  const bool inside = l2 < s.r2;
  e.step(L::inside, K::decide).flag("inside", inside).flag("on", l2 == s.r2);
  e.step(L::tca, K::decide).var("tca", tca).point(s.foot).label("closest").keep();
  if (!inside && sgn(tca) <= 0) {
    e.step(L::behind, K::miss);
    return {};
  }
  const Q m2 = s.x2 / s.a;
  e.step(L::dist, K::decide).var("m2", m2).segment(s.c, s.foot).label("r^2 - m2").valued(Q(s.r2 - m2)).keep();
  if (m2 > s.r2) {
    e.step(L::reject, K::miss);
    return {};
  }
  e.step(L::chord, K::decide).var("h2", s.dq);
  CHECK(s.sp > 0);  // a hit: the far root is positive
  const Val t = s.sm > 0 ? s.tm : s.tp;
  e.step(L::root, K::hit).var("t", t).point(at(p, t)).label("hit");
  return hit_at(t);
}

// ray-sphere-quadratic: b = 2b', D = b^2 - 4 a cc = 4 (a r^2 - |f x d|^2), the closest approach is
// the foot, n = 2a t for both roots; the hit is the smaller root if positive, else the larger if
// positive.
Outcome quadratic_expected(const Parsed& p, Expected& e) {
  using L = ray::RaySphereQuadratic;
  const SphereForms s = sphere_forms(p);
  scene_sphere(e.step(L::coeffs, K::init).var("a", s.a).var("b", Q(2 * s.bh)).var("c", s.cc), p);
  // The closest approach t_c = -b / 2a, and the centre's segment to it valued by D.
  e.step(L::disc, K::decide).var("D", Q(4 * s.dq)).point(s.foot).label("t_c").keep().segment(s.c, s.foot).label("D").valued(Q(4 * s.dq)).keep();
  if (sgn(s.dq) < 0) {
    e.step(L::miss, K::miss);
    return {};
  }
  const Val two_a(Q(2 * s.a));
  e.step(L::roots, K::decide).var("n0", two_a * s.tm).var("n1", two_a * s.tp).var("t0", s.tm).var("t1", s.tp)
      .point(at(p, s.tm)).label("t0").keep().point(at(p, s.tp)).label("t1").keep();
  if (s.sm > 0) {
    e.step(L::near, K::hit).point(at(p, s.tm)).label("hit");
    return hit_at(s.tm);
  }
  if (s.sp > 0) {
    e.step(L::far, K::hit).point(at(p, s.tp)).label("hit");
    return hit_at(s.tp);
  }
  e.step(L::none, K::miss);
  return {};
}

// ray-sphere-stable: l = foot - c; D = a (r^2 - l.l); q = -(b' + sign(b') sqrt(D)) with
// sign(0) = +1, zero only for b' = D = 0; near and far are the smaller and the larger root.
Outcome stable_expected(const Parsed& p, Expected& e) {
  using L = ray::RaySphereStable;
  const SphereForms s = sphere_forms(p);
  scene_sphere(e.step(L::coeffs, K::init).var("a", s.a).var("b'", s.bh).var("c", s.cc), p);
  const VV l = s.foot - s.c;
  e.step(L::foot, K::advance).vec("lx", "ly", "lz", l).point(s.foot).label("foot").keep()
      .segment(s.c, s.foot).label("r^2 - |l|^2").valued(Q(s.r2 - s.x2 / s.a)).keep();
  e.step(L::disc, K::decide).var("D", s.dq);
  if (sgn(s.dq) < 0) {
    e.step(L::miss, K::miss);
    return {};
  }
  const Val root = sqrt_val(s.dq);
  e.step(L::q, K::decide).var("q", -(Val(s.bh) + Val(sgn(s.bh) < 0 ? -1 : 1) * root));
  if (sgn(s.bh) == 0 && sgn(s.dq) == 0) {
    e.step(L::degenerate, K::miss);
    return {};
  }
  e.step(L::order, K::decide).var("near", s.tm).var("far", s.tp).point(at(p, s.tm)).label("near").keep().point(at(p, s.tp)).label("far").keep();
  if (s.sm > 0) {
    e.step(L::near, K::hit).point(at(p, s.tm)).label("hit");
    return hit_at(s.tm);
  }
  if (s.sp > 0) {
    e.step(L::far, K::hit).point(at(p, s.tp)).label("hit");
    return hit_at(s.tp);
  }
  e.step(L::none, K::miss);
  return {};
}

// Seeded small-rational inputs: parallel rays, origins on the primitive, zero direction
// components, flat boxes, tangents and origins on the sphere come up often.
std::vector<Case> small_cases(const std::string& prim, int count, std::uint64_t seed) {
  SmallRng g(seed);
  std::vector<Case> out;
  for (int k = 0; k < count; ++k) {
    Json in;
    if (prim == "plane") {
      in = {{"ray", {{"o", g.vec(-2, 2)}, {"d", g.nonzero_vec(-2, 2, false)}}}, {"plane", {{"p", g.vec(-2, 2)}, {"n", g.nonzero_vec(-1, 1, false)}}}};
    } else if (prim == "box") {
      Json lo = g.vec(-2, 1), hi = Json::array();
      for (int a = 0; a < 3; ++a) hi.push_back(Q(q(lo[a]) + g.pick(0, 2)).get_str());  // 0: a flat box
      Json d = Json::array();
      for (int a = 0; a < 3; ++a) d.push_back(g.one_in(3) ? Json("0") : g.num(-2, 2));
      if (d == Json::array({"0", "0", "0"})) d[0] = "1";
      in = {{"ray", {{"o", g.vec(-3, 3)}, {"d", d}}}, {"box", {{"min", lo}, {"max", hi}}}};
    } else {
      const Json c = g.vec(-2, 2);
      const Q r = std::array{Q(1), Q(2), Q(3), ratio(1, 2), ratio(5, 2)}[g.pick(0, 4)];
      Json o = g.vec(-4, 4);
      if (g.one_in(4)) {  // on the sphere: c + r u for a rational unit vector u
        static const Q units[][3] = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {ratio(3, 5), ratio(4, 5), 0}, {ratio(2, 3), ratio(-2, 3), ratio(1, 3)}};
        const auto& u = units[g.pick(0, 4)];
        for (int a = 0; a < 3; ++a) o[a] = Q(q(c[a]) + r * u[a]).get_str();
      }
      in = {{"ray", {{"o", o}, {"d", g.nonzero_vec(-2, 2, false)}}}, {"sphere", {{"c", c}, {"r", r.get_str()}}}};
    }
    out.push_back({"small " + std::to_string(k), in});
  }
  return out;
}

std::vector<Case> all_cases(std::string_view id, const std::string& prim, std::uint64_t seed) {
  std::vector<Case> out = example_and_lessons(id);
  for (Case& c : corpus_cases(prim)) out.push_back(std::move(c));
  int n = 0;
  for (const Json& j : sw::rays::random_inputs(prim.c_str(), 60, seed)) out.push_back({"random " + std::to_string(n++), j});
  const auto hard = sw::rays::hard_inputs(prim.c_str(), 5);
  for (std::size_t i = 0; i < hard.size(); i += hard.size() / 40 + 1) out.push_back({"hard " + std::to_string(i), hard[i]});
  for (Case& c : small_cases(prim, 300, seed + 1)) out.push_back(std::move(c));
  return out;
}

// The expected outcome against the oracle, and what the algorithm returned against it.
void check_outcome(const std::string& prim, const Parsed& p, const Outcome& want, const Returned& got) {
  oracle::RayResult o = prim == "plane"    ? oracle::ray_plane(p.o, p.d, p.v[0], p.v[1])
                        : prim == "box"    ? oracle::ray_box(p.o, p.d, p.v[0], p.v[1])
                                           : oracle::ray_sphere(p.o, p.d, p.v[0], p.r);
  REQUIRE(o.hit == want.hit);
  CHECK(got.hit == want.hit);
  if (!want.hit) return;
  CHECK(matches(got.t, want.t));
  CHECK(got.t_exact == !want.t.approx);
  CHECK(o.t_exact == !want.t.approx);
  if (o.t_exact) CHECK(o.t == want.t.v);
  else CHECK(abs(Q(o.t - want.t.v)) <= abs(o.t) / Q(mpz_class(1) << 126));  // the oracle's t: 128 bits
  if (prim == "box") {
    CHECK(o.t_near == want.t_near);
    CHECK(o.t_far == want.t_far);
    CHECK(got.t_near == want.t_near);
    CHECK(got.t_far == want.t_far);
  }
}

using ExpectFn = Outcome (*)(const Parsed&, Expected&);

// Replays `id` on every case; returns the lines seen and calls `tally` with each case's outcome.
template <class Tally> std::set<std::string_view> replay(std::string_view id, const std::string& prim, ExpectFn expect, std::uint64_t seed, Tally tally) {
  const auto cases = all_cases(id, prim, seed);
  CHECK(cases.size() >= 380);
  std::set<std::string_view> seen;
  for (const Case& c : cases) {
    INFO(id << ", " << c.name << ": " << c.input.dump());
    const Parsed p = parse(c.input, prim);
    Recorder<Q> t;
    const Returned got = record_direct(id, c.input, t);
    Expected want;
    const Outcome out = expect(p, want);
    require_matches(t, find_algorithm(id).listing, want, seen);
    check_outcome(prim, p, out, got);
    tally(p, out, want);
  }
  return seen;
}

std::uint32_t last_line(const Expected& e) { return e.steps.back().line; }

}  // namespace

TEST_CASE("rays: exact step replay, ray-plane: every value and geometry item matches its closed form", "[rays][steps][replay]") {
  using L = ray::RayPlane;
  const auto seen = replay("ray-plane", "plane", plane_expected, 301, [](const Parsed&, const Outcome&, const Expected&) {});
  CHECK(seen == recorded_lines(L::listing(), {}));
}

TEST_CASE("rays: exact step replay, ray-box: every value and geometry item matches its closed form", "[rays][steps][replay]") {
  using L = ray::RayBox;
  int flat_inside = 0, origin_inside = 0, corner_touch = 0;
  const auto seen = replay("ray-box", "box", box_expected, 302, [&](const Parsed& p, const Outcome& o, const Expected& e) {
    for (const ExpectedStep& s : e.steps) flat_inside += s.line == L::flat && s.vars[1].second.v == 0;
    origin_inside += o.hit && sgn(o.t_near) <= 0;
    corner_touch += o.hit && o.t_near == o.t_far;
    (void)p;
  });
  CHECK(seen == recorded_lines(L::listing(), {"axis", "slab", "order"}));
  CHECK(flat_inside > 0);  // a zero direction component inside its slab
  CHECK(origin_inside > 0);
  CHECK(corner_touch > 0);
}

namespace {
// The sphere cases reach rational and irrational roots, tangents (D = 0) that hit, and origins
// on the sphere.
struct SphereTally {
  int exact_hit = 0, irrational_hit = 0, tangent_hit = 0, on_sphere = 0;
  void operator()(const Parsed& p, const Outcome& o, const Expected&) {
    const SphereForms s = sphere_forms(p);
    exact_hit += o.hit && !o.t.approx;
    irrational_hit += o.hit && o.t.approx;
    tangent_hit += o.hit && sgn(s.dq) == 0;
    on_sphere += sgn(s.cc) == 0;
  }
  void require_reached() const {
    CHECK(exact_hit > 0);
    CHECK(irrational_hit > 0);
    CHECK(tangent_hit > 0);
    CHECK(on_sphere > 0);
  }
};
}  // namespace

TEST_CASE("rays: exact step replay, ray-sphere-geometric: every value and geometry item matches its closed form", "[rays][steps][replay]") {
  SphereTally tally;
  const auto seen = replay("ray-sphere-geometric", "sphere", geometric_expected, 303, std::ref(tally));
  CHECK(seen == recorded_lines(ray::RaySphereGeometric::listing(), {"hit"}));
  tally.require_reached();
}

TEST_CASE("rays: exact step replay, ray-sphere-quadratic: every value and geometry item matches its closed form", "[rays][steps][replay]") {
  SphereTally tally;
  const auto seen = replay("ray-sphere-quadratic", "sphere", quadratic_expected, 304, std::ref(tally));
  CHECK(seen == recorded_lines(ray::RaySphereQuadratic::listing(), {}));
  tally.require_reached();
}

TEST_CASE("rays: exact step replay, ray-sphere-stable: every value and geometry item matches its closed form", "[rays][steps][replay]") {
  SphereTally tally;
  int degenerate = 0;
  const auto seen = replay("ray-sphere-stable", "sphere", stable_expected, 305, [&](const Parsed& p, const Outcome& o, const Expected& e) {
    tally(p, o, e);
    degenerate += last_line(e) == ray::RaySphereStable::degenerate;
  });
  CHECK(seen == recorded_lines(ray::RaySphereStable::listing(), {}));
  tally.require_reached();
  CHECK(degenerate > 0);
}

// The tests above call the headers directly (so that a changed copy of them is what they test);
// the catalog's recording must be that same trace, step for step.
TEST_CASE("rays: exact step replay, the catalog records what the headers record", "[rays][steps]") {
  int compared = 0;
  for (const Algorithm& alg : catalog()) {
    if (alg.family != "rays") continue;
    const bool reference = alg.id == "camera-ray" || alg.id == "sphere-uv";
    std::vector<Case> cases = example_and_lessons(alg.id);
    for (Case& c : corpus_cases("")) cases.push_back(std::move(c));
    for (const Case& c : cases) {
      try {
        alg.validate(c.input, reference ? Numeric::reference : Numeric::exact);
      } catch (const InputError&) {
        continue;  // another primitive's case
      }
      INFO(alg.id << ", " << c.name);
      const Recorded rec = alg.record(c.input, reference ? Numeric::reference : Numeric::exact);
      const auto& a = dynamic_cast<const Recorder<Q>&>(*rec.trace);
      Recorder<Q> b;
      record_direct(alg.id, c.input, b);
      ++compared;
      REQUIRE(a.size() == b.size());
      for (std::size_t s = 0; s < a.size(); ++s) {
        INFO("step " << s);
        CHECK(a.at(s).line == b.at(s).line);
        CHECK(a.at(s).kind == b.at(s).kind);
        const auto va = sw::testing::values_of(a, s), vb = sw::testing::values_of(b, s);
        CHECK(va.v == vb.v);
        const auto ga = sw::testing::geometry_of(a, s), gb = sw::testing::geometry_of(b, s);
        REQUIRE(ga.items.size() == gb.items.size());
        for (std::size_t k = 0; k < ga.items.size(); ++k) {
          CHECK(ga.items[k].kind == gb.items[k].kind);
          CHECK(ga.items[k].values == gb.items[k].values);
          CHECK(ga.items[k].label == gb.items[k].label);
          CHECK(ga.items[k].life == gb.items[k].life);
          CHECK(ga.items[k].value == gb.items[k].value);
        }
      }
    }
  }
  CHECK(compared >= 60);  // every intersection test on its primitive's corpus, the mappings on their examples
}

TEST_CASE("rays: stepwise check accepts exact traces and rejects a tampered one", "[rays]") {
  for (const Json& c : read_jsonl("corpus.jsonl"))
    for (const std::string& id : kAlgs.at(c["primitive"])) {
      std::stringstream ss;
      write_trace(find_algorithm(id), Numeric::exact, c["input"], ss);
      const CheckReport rep = check_trace(ss, false);
      INFO(id << " " << c["name"].get<std::string>() << ": " << rep.message);
      CHECK(rep.status == 0);
    }
  std::stringstream ss;
  const Json in = Json::parse(R"({"ray":{"o":[0,0,5],"d":[0,0,-1]},"sphere":{"c":[0,0,0],"r":1}})");
  write_trace(find_algorithm("ray-sphere-stable"), Numeric::exact, in, ss);
  std::string text = ss.str();
  const auto pos = text.find("\"t\":\"4\"");
  REQUIRE(pos != std::string::npos);
  text.replace(pos, 7, "\"t\":\"5\"");
  std::stringstream bad(text);
  CHECK(check_trace(bad, false).status == 1);
}
