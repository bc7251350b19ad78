// What the ray-sphere tests return, and the steps they share: the first ends with the scene (the
// ray and the sphere, kept on the view), and the root-choosing tests (quadratic, stable) end with
// the hit at t on the near root or the far one, or a miss. Semantics: docs/rays/semantics.md.
#pragma once
#include "core/probe.hpp"
#include "rays/ray_common.hpp"

namespace sw::ray {

template <class Num> struct SphereHit {
  bool hit = false;
  Num t{};
  bool t_exact = true;  // false when t went through a rounded square root
};

// `step` is what the probe's step() returned (a summarised callee's steps go elsewhere).
template <class Step, class Num> void record_sphere_scene(Step& step, const Ray3<Num>& r, const Vec3<Num>& c, const Num& radius) {
  step.ray(r.o, r.d).keep().sphere(c, radius).keep();
}
// The last step on listing L's line near, far or none.
template <class L, class Num, class Probe>
void record_sphere_end(Probe& probe, const Ray3<Num>& r, const Num& t, bool near_hit, bool far_hit) {
  if (near_hit) probe.step(L::near, StepKind::hit).point(Vec3<Num>(r.o + t * r.d)).label("hit");
  else if (far_hit) probe.step(L::far, StepKind::hit).point(Vec3<Num>(r.o + t * r.d)).label("hit");
  else probe.step(L::none, StepKind::miss);
}

}  // namespace sw::ray
