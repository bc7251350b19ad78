// The full local lighting model in OpenGL's convention (GL 1.x spec 2.14.1; docs/lighting/shade.md),
// stated independently of algorithms/lighting/: every quantity in MPFR at kShadeOracleBits from
// the exact rational input, the decisions (n.l > 0, a light at the point, the spot cone) on exact
// rationals where they are polynomial signs. The cone is decided by comparing d.s/(|d||s|) with
// cos(cut-off) at kShadeConeBits; a difference under 2^-(kShadeConeBits - 24) counts as on the
// boundary, which is inside (it happens only when the two are equal: cos^2 of the cut-off is then
// rational, 0, 30, 45, 60 or 90 degrees).
#pragma once
#include <array>
#include <vector>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::oracle {

using Rgb = std::array<Rational, 3>;

struct ShadeLight {
  enum class Type { point, directional, spot } type = Type::point;
  Vec3<Rational> where;     // point, spot: the position; directional: the direction towards the light
  Vec3<Rational> spot_dir;  // spot: from the light along the cone's axis
  Rational cutoff{180}, exponent{0};
  Rational k0{1}, k1{0}, k2{0};
  Rgb ambient, diffuse, specular;
  bool blocked = false;  // a ray tracer's shadow ray found it occluded: its ambient term only
};

struct ShadeCase {
  Vec3<Rational> p, n, eye;  // eye: a point, or the direction towards it when eye_at_infinity
  bool eye_at_infinity = false;
  Rgb scene_ambient, emission, ka, kd, ks;
  Rational shininess{0};
  std::vector<ShadeLight> lights;
};

struct ShadeLightResult {
  bool at_point = false, lit = false, inside = true;  // lit: n.l > 0 (an occluded light may be lit and add no diffuse)
  Rational attenuation, spot, diffuse, specular;  // rounded from kShadeOracleBits
  Rgb rgb;
};
struct ShadeResult {
  Rgb rgb;  // not clamped
  std::vector<ShadeLightResult> lights;
};

inline constexpr int kShadeOracleBits = 256;
inline constexpr int kShadeConeBits = 1024;

// Preconditions as the runtime validates them: n != 0, the eye direction (or eye - p) != 0, S != 0.
ShadeResult shade_gl(const ShadeCase& c);

}  // namespace sw::oracle
