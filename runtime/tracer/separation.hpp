// Exact separation for the planner's shadow rule (docs/tracer/planner.md#shadows-per-light): whether an
// occluder may meet the segments from a receiver to a light, and whether a convex object may
// shadow itself. On the scene's numbers as written (Rational), with a margin; false is a proof.
#pragma once
#include <optional>
#include <vector>
#include "tracer/scene.hpp"

namespace sw::tracer::separation {

// An object as the planner sees it: bounded ones by points whose hull contains them (a sphere or a
// mesh by its box's corners), planes by a point and the normal.
struct Proxy {
  bool bounded = true;
  std::vector<Vec3<Rational>> pts;
  Vec3<Rational> point, normal;  // plane; triangle: its normal too
  bool has_normal = false;
  Vec3<Rational> lo, hi;         // the box of pts
};

struct LightAt {
  bool directional;
  Vec3<Rational> where;  // position, or the direction towards the light
};

// None for a mesh whose file was not loaded.
std::optional<Proxy> proxy_of(const Scene& s, const Object& o);
bool may_shadow(const Proxy& a, const Proxy& b, const LightAt& l, const Rational& margin);
bool may_self_shadow(const Scene& s, std::size_t k, const std::vector<std::optional<Proxy>>& px, const Rational& margin);
bool is_zero(const Vec3<Rational>& v);
Rational abs_q(const Rational& x);

}  // namespace sw::tracer::separation
