// The three ray-sphere tests, step by step: every variable and geometry item an exact step of
// ray-sphere-geometric, -quadratic and -stable records, against closed forms of
// docs/rays/semantics.md written from the input (the inputs and the replay: ray_replay.hpp). Roots
// are required exactly when the discriminant is a rational square, else within 2^-200 of their
// 640-bit MPFR value.
//
// Listing lines no step records, by design: ray-sphere-geometric `hit` (the root step is the hit
// step).
#include <catch2/catch.hpp>
#include "catalog.hpp"
#include "ray_replay.hpp"

using namespace sw;
using namespace sw::testing::rays;
using K = StepKind;

namespace {

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
  e.step(L::disc, K::decide)
      .var("D", Q(4 * s.dq))
      .point(s.foot)
      .label("t_c")
      .keep()
      .segment(s.c, s.foot)
      .label("D")
      .valued(Q(4 * s.dq))
      .keep();
  if (sgn(s.dq) < 0) {
    e.step(L::miss, K::miss);
    return {};
  }
  const Val two_a(Q(2 * s.a));
  e.step(L::roots, K::decide)
      .var("n0", two_a * s.tm)
      .var("n1", two_a * s.tp)
      .var("t0", s.tm)
      .var("t1", s.tp)
      .point(at(p, s.tm))
      .label("t0")
      .keep()
      .point(at(p, s.tp))
      .label("t1")
      .keep();
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
  e.step(L::foot, K::advance)
      .vec("lx", "ly", "lz", l)
      .point(s.foot)
      .label("foot")
      .keep()
      .segment(s.c, s.foot)
      .label("r^2 - |l|^2")
      .valued(Q(s.r2 - s.x2 / s.a))
      .keep();
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
  e.step(L::order, K::decide)
      .var("near", s.tm)
      .var("far", s.tp)
      .point(at(p, s.tm))
      .label("near")
      .keep()
      .point(at(p, s.tp))
      .label("far")
      .keep();
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

TEST_CASE("rays: exact step replay, ray-sphere-geometric: every value and geometry item matches its closed form",
          "[rays][steps][replay]") {
  SphereTally tally;
  const auto seen = replay("ray-sphere-geometric", "sphere", geometric_expected, 303, std::ref(tally));
  CHECK(seen == recorded_lines(ray::RaySphereGeometric::listing(), {"hit"}));
  tally.require_reached();
}

TEST_CASE("rays: exact step replay, ray-sphere-quadratic: every value and geometry item matches its closed form",
          "[rays][steps][replay]") {
  SphereTally tally;
  const auto seen = replay("ray-sphere-quadratic", "sphere", quadratic_expected, 304, std::ref(tally));
  CHECK(seen == recorded_lines(ray::RaySphereQuadratic::listing(), {}));
  tally.require_reached();
}

TEST_CASE("rays: exact step replay, ray-sphere-stable: every value and geometry item matches its closed form",
          "[rays][steps][replay]") {
  SphereTally tally;
  int degenerate = 0;
  const auto seen =
      replay("ray-sphere-stable", "sphere", stable_expected, 305, [&](const Parsed& p, const Outcome& o, const Expected& e) {
        tally(p, o, e);
        degenerate += last_line(e) == ray::RaySphereStable::degenerate;
      });
  CHECK(seen == recorded_lines(ray::RaySphereStable::listing(), {}));
  tally.require_reached();
  CHECK(degenerate > 0);
}
