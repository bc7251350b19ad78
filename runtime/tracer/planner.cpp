// The effect planner (plan.hpp); every rule and its argument: docs/tracer/planner.md. Geometry is
// decided on the scene's numbers as written (Rational), with a margin of 2^-30 of the scene's
// largest coordinate so that a proof also holds for the renderer's rounded points and rays.
#include <algorithm>
#include <charconv>
#include <limits>
#include <optional>
#include <sstream>
#include "tracer/plan.hpp"

namespace sw::tracer {
namespace {

using Q = Rational;
using V = Vec3<Q>;

Q abs_q(const Q& x) { return x < 0 ? Q(-x) : x; }
Q norm1(const V& a) { return abs_q(a.x) + abs_q(a.y) + abs_q(a.z); }
bool is_zero(const V& v) { return sgn(v.x) == 0 && sgn(v.y) == 0 && sgn(v.z) == 0; }

// An object as the planner sees it: bounded ones by points whose hull contains them (a sphere or a
// mesh by its box's corners), planes by a point and the normal.
struct Proxy {
  bool bounded = true;
  std::vector<V> pts;
  V point, normal;  // plane; triangle: its normal too
  bool has_normal = false;
  V lo, hi;         // the box of pts
};

std::vector<V> corners(const V& lo, const V& hi) {
  std::vector<V> c;
  for (int k = 0; k < 8; ++k) c.push_back({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
  return c;
}

std::optional<Proxy> proxy_of(const Scene& s, const Object& o) {
  Proxy p;
  switch (o.kind) {
    case Shape::sphere: {
      const V r{o.radius.q, o.radius.q, o.radius.q};
      p.pts = corners(o.a.q - r, o.a.q + r);
      break;
    }
    case Shape::box: p.pts = corners(o.a.q, o.b.q); break;
    case Shape::triangle:
      p.pts = {o.v[0].q, o.v[1].q, o.v[2].q};
      p.normal = cross(V(o.v[1].q - o.v[0].q), V(o.v[2].q - o.v[0].q)), p.has_normal = true;
      break;
    case Shape::plane:
      p.bounded = false, p.point = o.a.q, p.normal = o.b.q, p.has_normal = true;
      return p;
    case Shape::mesh: {
      const MeshFile& f = s.meshes[static_cast<std::size_t>(o.mesh)];
      if (!f.mesh || f.mesh->v.empty()) return std::nullopt;  // not loaded: no proof
      std::array<double, 3> lo{}, hi{};
      lo.fill(std::numeric_limits<double>::infinity()), hi.fill(-std::numeric_limits<double>::infinity());
      for (const auto& v : f.mesh->v)
        for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
      V l, h;
      for (int k = 0; k < 3; ++k) {  // the placed box: scale * [lo, hi] + translate (scale > 0)
        l[k] = o.scale.q * Q(lo[static_cast<std::size_t>(k)]) + o.translate.q[k];
        h[k] = o.scale.q * Q(hi[static_cast<std::size_t>(k)]) + o.translate.q[k];
      }
      p.pts = corners(l, h);
      break;
    }
  }
  p.lo = p.hi = p.pts[0];
  for (const V& v : p.pts)
    for (int k = 0; k < 3; ++k) p.lo[k] = std::min(p.lo[k], v[k]), p.hi[k] = std::max(p.hi[k], v[k]);
  return p;
}

struct Interval1 {
  Q lo, hi;
  bool lo_inf = false, hi_inf = false;
};
Interval1 project(const std::vector<V>& pts, const V& a) {
  Interval1 r{dot(a, pts[0]), dot(a, pts[0])};
  for (const V& p : pts) {
    const Q x = dot(a, p);
    if (x < r.lo) r.lo = x;
    if (r.hi < x) r.hi = x;
  }
  return r;
}
// Disjoint with a gap wider than the margin on both sides.
bool apart(const Interval1& a, const Interval1& b, const Q& pad) {
  return (!a.hi_inf && !b.lo_inf && a.hi + 2 * pad < b.lo) || (!b.hi_inf && !a.lo_inf && b.hi + 2 * pad < a.lo);
}
V centre(const Proxy& p) { return Q(1, 2) * V(p.lo + p.hi); }
// The side of x relative to the plane (point, normal), with the margin: +1, -1, or 0 (too close).
int side(const Proxy& plane, const V& x, const Q& margin) {
  const Q v = dot(plane.normal, V(x - plane.point)), pad = margin * norm1(plane.normal);
  return v > pad ? 1 : v < -pad ? -1 : 0;
}
int side_all(const Proxy& plane, const std::vector<V>& pts, const Q& margin) {
  const int s0 = side(plane, pts[0], margin);
  for (const V& p : pts)
    if (side(plane, p, margin) != s0) return 0;
  return s0;
}

struct Light {
  bool directional;
  V where;  // position, or the direction towards the light
};

// Whether occluder b might lie between a point of receiver a and the light (a != b); false is a proof.
bool may_shadow(const Proxy& a, const Proxy& b, const Light& l, const Q& margin) {
  if (!a.bounded && !b.bounded) {
    if (!is_zero(cross(a.normal, b.normal))) return true;
    const int light_side = l.directional ? sgn(dot(a.normal, l.where)) : side(a, l.where, margin);
    return light_side == 0 || side(a, b.point, margin) != -light_side;
  }
  if (!a.bounded) {  // b must lie wholly on the far side of a's plane from the light
    const int light_side = l.directional ? sgn(dot(a.normal, l.where)) : side(a, l.where, margin);
    return light_side == 0 || side_all(a, b.pts, margin) != -light_side;
  }
  if (!b.bounded) {  // a and the whole way to the light on one side of b's plane
    const int sa = side_all(b, a.pts, margin);
    if (sa == 0) return true;
    return l.directional ? sgn(dot(b.normal, l.where)) * sa < 0 : side(b, l.where, margin) != sa;
  }
  std::vector<V> axes{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const V da = l.directional ? l.where : V(l.where - centre(a)), db = l.directional ? l.where : V(l.where - centre(b));
  for (int k = 0; k < 3; ++k) axes.push_back(cross(da, axes[static_cast<std::size_t>(k)])), axes.push_back(cross(db, axes[static_cast<std::size_t>(k)]));
  axes.push_back(da), axes.push_back(db), axes.push_back(cross(da, db));
  if (a.has_normal) axes.push_back(a.normal);
  if (b.has_normal) axes.push_back(b.normal);
  for (const V& ax : axes) {
    if (is_zero(ax)) continue;
    Interval1 ra = project(a.pts, ax);
    if (l.directional) {
      const int s = sgn(dot(ax, l.where));
      ra.hi_inf = s > 0, ra.lo_inf = s < 0;
    } else {
      const Q x = dot(ax, l.where);
      if (x < ra.lo) ra.lo = x;
      if (ra.hi < x) ra.hi = x;
    }
    if (apart(ra, project(b.pts, ax), margin * norm1(ax))) return false;
  }
  return true;
}

bool inside_or_on(const Object& o, const V& e) {
  if (o.kind == Shape::sphere) {
    const V f = e - o.a.q;
    return dot(f, f) <= o.radius.q * o.radius.q;
  }
  for (int k = 0; k < 3; ++k)
    if (e[k] < o.a.q[k] || e[k] > o.b.q[k]) return false;
  return true;
}

// A convex object shadows itself only where a ray reaches its inside, or a bump map tilts the normal.
bool may_self_shadow(const Scene& s, std::size_t k, const std::vector<std::optional<Proxy>>& px, const Q& margin) {
  const Object& o = s.objects[k];
  if (o.kind == Shape::plane || o.kind == Shape::triangle) return false;
  if (o.kind == Shape::mesh) return true;
  const Material& m = s.materials[static_cast<std::size_t>(o.material)];
  if (m.bump.on || sgn(m.kt.q) > 0 || inside_or_on(o, s.camera.eye.q)) return true;
  for (std::size_t j = 0; j < px.size(); ++j) {  // a mirror or glass reaching into it could send weighted rays inside
    const Material& mj = s.materials[static_cast<std::size_t>(s.objects[j].material)];
    if (j == k || (sgn(mj.kr.q) == 0 && sgn(mj.kt.q) == 0)) continue;
    if (!px[j]) return true;
    const Proxy& b = *px[j];
    const Proxy& a = *px[k];
    if (!b.bounded) {
      if (side_all(b, a.pts, margin) == 0) return true;
    } else {
      bool overlap = true;
      for (int c = 0; c < 3; ++c) overlap = overlap && !(b.hi[c] + 2 * margin < a.lo[c] || a.hi[c] + 2 * margin < b.lo[c]);
      if (overlap) return true;
    }
  }
  return false;
}

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
  const auto r = std::to_chars(buf, buf + sizeof buf, q.get_d());
  return std::string(buf, r.ptr);
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
  const Light l{li.type == lighting::LightType::directional, li.where};
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
