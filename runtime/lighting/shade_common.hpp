// What shade_spec.cpp, gouraud.cpp, the tests and the GL peer share: shade's output (doubles of the
// mode's values, and the reference's rationals), its JSON, its error, and the seeded scenes (random
// ones in GL's ranges with float inputs, and the hard set: spots exactly on their cut-off, grazing
// lights and eyes, lights at the point, non-unit, huge, tiny and subnormal vectors).
#pragma once
#include <array>
#include <memory>
#include <vector>
#include "catalog.hpp"
#include "input.hpp"
#include "lighting/shade.hpp"

namespace sw::lighting {

struct ShadeOutput {
  int bits = 53;
  bool facing = true;
  std::vector<std::array<bool, 3>> flags;    // per light: at_point, lit, inside (the decisions)
  std::array<double, 3> rgb{}, ambient{};
  std::vector<std::array<double, 7>> terms;  // per light: attenuation, spot, diffuse, specular, r, g, b
  std::shared_ptr<const std::vector<Rational>> ref;  // reference mode and the oracle: rgb exactly
  // Equal decisions (the values are compared by shade_error).
  friend bool operator==(const ShadeOutput& a, const ShadeOutput& b) { return a.facing == b.facing && a.flags == b.flags; }
};

template <class Num> ShadeOutput shade_output(const Shaded<Num>& s) {
  ShadeOutput o;
  if constexpr (std::is_same_v<Num, float>) o.bits = 24;
  o.facing = s.facing_eye;
  for (int k = 0; k < 3; ++k) o.rgb[k] = num::to_double(s.rgb[k]), o.ambient[k] = num::to_double(s.ambient[k]);
  for (const auto& t : s.lights) {
    o.flags.push_back({t.at_point, t.lit, t.inside});
    o.terms.push_back({num::to_double(t.attenuation), num::to_double(t.spot), num::to_double(t.diffuse), num::to_double(t.specular),
                       num::to_double(t.rgb.x), num::to_double(t.rgb.y), num::to_double(t.rgb.z)});
  }
  if constexpr (std::is_same_v<Num, Rational>) o.ref = std::make_shared<const std::vector<Rational>>(std::vector<Rational>{s.rgb.x, s.rgb.y, s.rgb.z});
  return o;
}

Json shade_json(const ShadeOutput& o);
// The sliders of shade and gouraud-vs-phong: the material's parameters and the first light's cone,
// each shown when the input has its key.
std::vector<Param> shade_params();
// max_k |got.rgb[k] - ref[k]| in units of 2^-bits (the mode's ulp at 1; colours are about 1).
double shade_error(const ShadeOutput& got, const ShadeOutput& ref);

// Random scenes in GL convention inside OpenGL's ranges (exponents <= 128, cut-off in [0, 90] or
// 180, up to 3 lights), every value a float, the eye at (0, 0, 0) or at infinity along +z as GL's
// eye coordinates have it: the GL peer's configurations.
std::vector<ShadeScene<Rational>> shade_random_scenes(std::size_t count, std::uint64_t seed);
// The hard set (docs/lighting/shade.md lists its groups); group names in `groups` if given.
std::vector<ShadeScene<Rational>> shade_hard_scenes(std::vector<std::string>* groups = nullptr);
// A scene as the JSON `shade` reads (exact strings), for the CLI, the corpus and the peer.
Json scene_json(const ShadeScene<Rational>& s);

}  // namespace sw::lighting
