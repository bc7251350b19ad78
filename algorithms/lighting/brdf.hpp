// The lighting family's shared vocabulary: the unit frame at a shading point, the reflection
// models by name, their parameters, and the two dispatchers shade calls. One model per header
// (lambert.hpp, ..., cook_torrance.hpp); each is an instrumented generator generic over the
// number type (float, double, and Rational in reference mode: transcendentals in 300-bit MPFR)
// and the probe. Semantics and the deviations from the guide: docs/lighting/.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>
#include "core/probe.hpp"
#include "core/vec.hpp"

namespace sw::lighting {

// The frame a model sees: unit normal n, unit direction to the light l, unit direction to the eye
// e, and their cosines. Built by shading_frame (lighting_common.hpp), which normalises visibly and
// decides the signs (n.l, n.e) exactly on the raw vectors before any rounding.
// The decisions travel with the frame (added by the models' helper; shading_frame sets them):
// lit = N.L > 0, seen = N.E > 0, mirror = r.e > 0, each the exact sign of a polynomial in the raw
// vectors N, L, E. A Frame built by hand keeps the defaults (lit, seen; Phong then decides r.e on
// its rounded value).
template <class Num> struct Frame {
  Vec3<Num> n, l, e;
  Num nl, ne;  // n.l and n.e of the unit vectors
  bool lit = true, seen = true;
  std::optional<bool> mirror;  // sign(2 (N.L)(N.E) - (N.N)(L.E)) > 0: the eye is on the mirror side
};

enum class DiffuseModel : std::uint8_t { lambert, minnaert, oren_nayar };
enum class SpecularModel : std::uint8_t { none, phong, blinn_phong, gaussian, beckmann, cook_torrance, ward };
// How many of each there are (the parsers walk them by name); the last enumerator plus one.
inline constexpr int kDiffuseModels = int(DiffuseModel::oren_nayar) + 1, kSpecularModels = int(SpecularModel::ward) + 1;
enum class Fresnel : std::uint8_t { exact, schlick, one };  // one: F = 1 (the limit test against beckmann)

// Which model an entry runs: a diffuse one (toon: with p.toon set) or a specular one.
struct ModelChoice {
  bool specular = false;
  DiffuseModel diffuse = DiffuseModel::lambert;
  SpecularModel spec = SpecularModel::none;
};

// Every model's parameters (each model reads its own; the runtime checks their ranges).
template <class Num> struct ModelParams {
  Num minnaert_k{1};               // minnaert: k in [0, 1]; k = 1 is Lambert
  Num sigma{0};                    // oren-nayar: roughness sigma in [0, 1] (radians); 0 is Lambert
  std::optional<Num> toon;         // toon: a cutoff on the diffuse term (any model), if set
  std::optional<bool> toon_above;  // toon: the decision d >= cutoff made exactly beforehand (else on the value)
  Num shininess{1};                // phong, blinn-phong: n >= 0
  Num m{Num(0.3)};                 // gaussian, beckmann, cook-torrance, ward: the slope roughness m > 0
  Num ior{Num(1.5)};               // cook-torrance: the relative index of refraction, >= 1 (no total internal reflection)
  Fresnel fresnel = Fresnel::exact;
  bool shadowing = true;  // cook-torrance: the geometric attenuation G (false: G = 1, the limit test)
};

// The dispatchers (defined in models.hpp, which includes every model): the diffuse and the
// specular term of one light at the frame: what multiplies the light's colour and the material's
// kd or ks. Each model's header states its term in the papers' own form; below the horizon
// (n.l <= 0 or n.e <= 0) a term is 0, decided by shading_frame.
template <NumberType Num, StepProbe Probe> Num diffuse_term(DiffuseModel, const Frame<Num>&, const ModelParams<Num>&, Probe&);
template <NumberType Num, StepProbe Probe> Num specular_term(SpecularModel, const Frame<Num>&, const ModelParams<Num>&, Probe&);

std::string_view model_name(DiffuseModel);
std::string_view model_name(SpecularModel);

}  // namespace sw::lighting
