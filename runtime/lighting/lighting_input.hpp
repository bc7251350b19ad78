// Reading the lighting family's inputs: direction vectors (any non-zero length) and the reflection
// models' parameters, each checked with a one-line InputError. Shared by the models' entries
// (model_specs.cpp) and shade (shade_spec.cpp may reuse direction3 and the parameter readers).
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include "input.hpp"
#include "lighting/models.hpp"

namespace sw::lighting_io {

// Inputs beyond this are rejected: a float's squared length of such a vector stays finite (1e30).
inline constexpr double kCoordBound = 1e15;

// obj[key]: [x, y, z], finite, |component| <= kCoordBound, not all zero ("zero-length").
Vec3<Rational> direction3(const Json& obj, const char* key, const std::string& what);
// obj[key]: a number in [lo, hi] (lo excluded when lo_open), numerator and denominator of at most
// 64 bits each.
Rational number_in(const Json& obj, const char* key, const Rational& lo, const Rational& hi, bool lo_open, const std::string& what);
lighting::Fresnel parse_fresnel(const Json& v, const std::string& what);       // "exact", "schlick", "one"

// One model's input: the raw vectors, the parameters, and the decisions made on them exactly.
struct ModelInput {
  lighting::ModelChoice choice;
  Vec3<Rational> n, l, e;
  lighting::ModelParams<Rational> p;
  lighting::FrameSigns signs{};
};
// The input of the model entry `id` (a row of model_table.hpp): {"n","l","e"} plus the row's
// parameters; unknown fields are errors.
ModelInput parse_model_input(std::string_view id, const Json& j);
// Sets in.signs and, for toon, in.p.toon_above: exact on the raw input (toon over minnaert with
// k != 1 or oren-nayar with sigma != 0: on the 300-bit reference value; docs/lighting/semantics.md).
void decide(ModelInput& in);
// The input back as JSON (the bench sets' inputs, the tests' corpora).
Json to_json(const ModelInput& in);

}  // namespace sw::lighting_io
