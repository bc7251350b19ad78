// The effect planner: from a scene, which effects can change a pixel. Each decision is on or off
// with its reason; an effect is off only when a rule of docs/tracer/planner.md proves that
// simulating it adds exactly nothing (geometric facts decided in exact rational arithmetic,
// conservatively: when a proof is not found, the effect stays on).
#pragma once
#include <string>
#include <vector>
#include "input.hpp"
#include "tracer/scene.hpp"
#include "tracer/whitted.hpp"

namespace sw::tracer {

struct Decision {
  std::string effect;   // "shadows", "reflection", "refraction"
  std::string subject;  // "light 1 (directional)", "material 'glass'"
  bool on = true;
  std::string reason;
};

struct Plan {
  EffectPlan effects;
  std::vector<Decision> decisions;
  bool all_effects = false;  // every effect on by request (--all-effects), not planned
};

// Above this many objects the pairwise shadow proof is not attempted (shadows stay on).
inline constexpr std::size_t kPlannerMaxObjects = 256;

Plan plan_scene(const Scene& s);
Plan all_effects_plan(const Scene& s);

Json plan_json(const Plan& p);
std::string plan_text(const Plan& p);

}  // namespace sw::tracer
