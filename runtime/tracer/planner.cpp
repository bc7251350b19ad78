// The effect planner (plan.hpp); every rule and its argument: docs/tracer/planner.md. Geometry is
// decided on the scene's numbers as written (Rational), with a margin of 2^-30 of the scene's
// largest coordinate so that a proof also holds for the renderer's rounded points and rays.
#include <algorithm>
#include <charconv>
#include <limits>
#include <optional>
#include <sstream>
#include "tracer/plan.hpp"
#include "tracer/separation.hpp"

namespace sw::tracer {
namespace {

using Q = Rational;
using V = Vec3<Q>;
using namespace separation;

std::string light_name(const Scene& s, std::size_t i) {
  static constexpr const char* names[] = {"point", "directional", "spot"};
  return "light " + std::to_string(i) + " (" + names[static_cast<int>(s.lights[i].type)] + ")";
}
std::string object_name(const Scene& s, std::size_t k) { return "object " + std::to_string(k) + " (" + std::string(kind_name(s.objects[k].kind)) + ")"; }
// An integer, a short fraction, or the double the number was written as.
std::string q_text(const Q& q) {
  if (q.get_den() == 1) return q.get_num().get_str();
  if (q.get_den() < 1000000) return q.get_str();
  char buf[32];
  return std::string(buf, shortest_chars(buf, buf + sizeof buf, q.get_d()));
}

Decision shadow_decision(const Scene& s, std::size_t i, const std::vector<std::optional<Proxy>>& px, const Q& margin) {
  const lighting::Light<Q>& li = s.lights[i];
  Decision d{"shadows", light_name(s, i), true, ""};
  if (is_zero(li.diffuse) && is_zero(li.specular)) {
    d.on = false, d.reason = "it has no diffuse or specular colour: a blocked light adds the same ambient term as a lit one";
    return d;
  }
  if (s.objects.size() > kPlannerMaxObjects) {
    d.reason = "more than " + std::to_string(kPlannerMaxObjects) + " objects: the pairwise proof is not attempted";
    return d;
  }
  const LightAt l{li.type == lighting::LightType::directional, li.where};
  for (std::size_t a = 0; a < px.size(); ++a) {
    if (!px[a]) {
      d.reason = object_name(s, a) + " has no bounds (its mesh was not loaded)";
      return d;
    }
    if (may_self_shadow(s, a, px, margin)) {
      d.reason = object_name(s, a) + " can shadow itself (" +
                 (s.objects[a].kind == Shape::mesh ? std::string("a mesh need not be convex") : std::string("a ray can reach its inside, or a bump map tilts its normal")) + ")";
      return d;
    }
    for (std::size_t b = 0; b < px.size(); ++b) {
      if (a == b || !px[b]) continue;
      if (may_shadow(*px[a], *px[b], l, margin)) {
        d.reason = object_name(s, b) + " may lie between " + object_name(s, a) + " and the light";
        return d;
      }
    }
  }
  d.on = false;
  d.reason = std::string(l.directional ? "it is directional and " : "") +
             "no object can lie between a lit point and the light: every object is convex and seen only from outside, and every pair is separated exactly";
  return d;
}

}  // namespace

Plan all_effects_plan(const Scene& s) {
  Plan p;
  p.effects = EffectPlan::all(s.lights.size(), s.materials.size());
  p.all_effects = true;
  for (std::size_t i = 0; i < s.lights.size(); ++i) p.decisions.push_back({"shadows", light_name(s, i), true, "--all-effects"});
  for (const Material& m : s.materials) {
    p.decisions.push_back({"reflection", "material '" + m.name + "'", true, "--all-effects"});
    p.decisions.push_back({"refraction", "material '" + m.name + "'", true, "--all-effects"});
  }
  p.decisions.push_back({"caustics", "the scene", true, "--all-effects"});
  return p;
}

// Caustics need a light that emits photons, a mirror or glass to bend them, a diffuse surface to
// catch them, and two bounces; without any of these the photon map stays empty.
Decision caustics_decision(const Scene& s) {
  Decision d{"caustics", "the scene", false, ""};
  auto find_material = [&](auto pred) -> const Material* {
    for (const Material& m : s.materials)
      if (pred(m)) return &m;
    return nullptr;
  };
  bool emits = false;
  for (const auto& l : s.lights) emits = emits || (l.type != lighting::LightType::directional && !is_zero(l.diffuse));
  const Material* specular = find_material([](const Material& m) { return sgn(m.kr.q) > 0 || sgn(m.kt.q) > 0; });
  const Material* diffuse = find_material([](const Material& m) { return m.texture >= 0 || !is_zero(m.shading.kd); });
  if (s.photons.count == 0) d.reason = "photons.count is 0";
  else if (!emits) d.reason = "no point or spot light with a diffuse colour emits photons";
  else if (!specular) d.reason = "no material has kr > 0 or kt > 0: no photon is ever bent, so none is stored";
  else if (!diffuse) d.reason = "no material is diffuse: no surface catches a photon";
  else if (s.max_depth < 2) d.reason = "max_depth is 1: a caustic path needs a mirror or glass bounce, then a diffuse hit";
  else d.on = true, d.reason = "material '" + specular->name + "' bends light and material '" + diffuse->name + "' is diffuse";
  return d;
}

Plan plan_scene(const Scene& s) {
  Plan p;
  p.effects = EffectPlan::all(s.lights.size(), s.materials.size());
  p.effects.zero_weight = false;  // a ray of weight 0 adds nothing: only --all-effects casts it
  Q extent = 0;  // the largest coordinate of the geometry and the lights' positions
  std::vector<std::optional<Proxy>> px;
  if (s.objects.size() <= kPlannerMaxObjects) {
    for (const Object& o : s.objects) {
      px.push_back(proxy_of(s, o));
      if (!px.back()) continue;
      for (const V& v : px.back()->pts) extent = std::max({extent, abs_q(v.x), abs_q(v.y), abs_q(v.z)});
      const V& q = px.back()->point;
      extent = std::max({extent, abs_q(q.x), abs_q(q.y), abs_q(q.z)});
    }
    for (const auto& l : s.lights)
      if (l.type != lighting::LightType::directional) extent = std::max({extent, abs_q(l.where.x), abs_q(l.where.y), abs_q(l.where.z)});
  }
  const Q margin = (sgn(extent) > 0 ? extent : Q(1)) / Q(mpz_class(1) << 30);
  for (std::size_t i = 0; i < s.lights.size(); ++i) {
    p.decisions.push_back(shadow_decision(s, i, px, margin));
    p.effects.shadows[i] = p.decisions.back().on;
  }
  for (std::size_t k = 0; k < s.materials.size(); ++k) {
    const Material& m = s.materials[k];
    const std::string name = "material '" + m.name + "'";
    const bool refl = sgn(m.kr.q) > 0 || sgn(m.kt.q) > 0, refr = sgn(m.kt.q) > 0;
    p.decisions.push_back({"reflection", name, refl,
                           refl ? (sgn(m.kr.q) > 0 ? "kr = " + q_text(m.kr.q) : "kt = " + q_text(m.kt.q) + ": Fresnel reflects a part")
                                : "kr = 0 and kt = 0: the mirror ray's weight kr + kt F is 0"});
    p.decisions.push_back({"refraction", name, refr, refr ? "kt = " + q_text(m.kt.q) : "kt = 0: the transmitted ray's weight kt (1 - F) is 0"});
    p.effects.reflection[k] = refl, p.effects.refraction[k] = refr;
  }
  p.decisions.push_back(caustics_decision(s));
  p.effects.caustics = p.decisions.back().on;
  return p;
}

Json plan_json(const Plan& p) {
  Json out = Json::object();
  out["all_effects"] = p.all_effects;
  Json list = Json::array();
  for (const Decision& d : p.decisions) list.push_back(Json{{"effect", d.effect}, {"subject", d.subject}, {"on", d.on}, {"reason", d.reason}});
  out["decisions"] = list;
  return out;
}

std::string plan_text(const Plan& p) {
  std::ostringstream o;
  for (const Decision& d : p.decisions) o << d.effect << " for " << d.subject << ": " << (d.on ? "on" : "off") << " — " << d.reason << '\n';
  return o.str();
}

}  // namespace sw::tracer
