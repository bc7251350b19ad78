// The ray family, step by step: every variable and geometry item an exact step of ray-plane and
// ray-box records, in the order the steps come, against closed forms of docs/rays/semantics.md
// written from the input (not by running the algorithm), for the catalog examples, the lessons,
// the corpus, the generated random and hard sets and seeded small rational cases that reach every
// miss line. A step, variable or geometry item without an expectation fails. The expected outcome
// is also held against the oracle (ray_replay.hpp). Spheres: test_ray_sphere_steps.cpp;
// triangles: test_ray_triangle_steps.cpp; camera-ray and sphere-uv: test_ray_mapping_steps.cpp;
// that the headers record what the catalog records: test_ray_trace_sources.cpp.
//
// Listing lines no step records, by design: ray-box `axis`, `slab` and `order` (the clip step
// shows the ordered slab interval).
#include <catch2/catch.hpp>
#include "catalog.hpp"
#include "ray_replay.hpp"

using namespace sw;
using namespace sw::testing::rays;
using sw::testing::ratio;
using K = StepKind;

namespace {

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
    e.step(L::clip, K::advance)
        .flag("k", k)
        .var("t1", t1)
        .var("t2", t2)
        .var("t_near", tn)
        .var("t_far", tf)
        .segment(at(p, t1), at(p, t2))
        .label(slab[k])
        .keep()
        .segment(at(p, tn), at(p, tf))
        .label("[t_near, t_far]")
        .valued(Q(tf - tn))
        .replace();
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
