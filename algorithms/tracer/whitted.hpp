// Whitted's recursive ray tracer over a TraceScene: the closest hit (scene-hit), the surface and
// its texture, a shadow ray per light that faces the point, the local lighting of the lighting
// family (shade, `models` convention, blocked lights adding their ambient term only), then a
// mirror ray and a transmitted ray weighted by kr, kt and Fresnel's split (refract).
// Which effects run is the EffectPlan's: the planner's (docs/tracer/planner.md) or all of them.
// A skipped effect adds exactly what the full computation would: a skipped ray has weight 0, or
// the planner proved its outcome. Recursion stops at max_depth, and a pixel's rays of non-zero
// weight stop at its budget (a ray of weight 0 costs no budget, so both plans spend it alike).
// Semantics: docs/tracer/renderer.md.
#pragma once
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>
#include "lighting/shade.hpp"
#include "rays/camera_ray.hpp"
#include "tracer/photon_map.hpp"
#include "tracer/refraction.hpp"
#include "tracer/surface.hpp"
#include "tracer/texture.hpp"

namespace sw::tracer {

template <class Num> struct TraceMaterial {
  lighting::Material<Num> shading;
  Num kr{}, kt{}, ior{1.5};
  int texture = -1;
  TraceBump bump;
};

// Where a secondary ray starts. robust: offset by the hit point's error bound, and the flat surface
// left behind is not tested (surface.hpp, trace_scene.hpp); none: at the computed point, every
// surface tested; epsilon: the classic fixed 1e-4 along the normal. The last two are the naive
// variants a lesson shows failing (shadow acne, and a light leak when the epsilon is too large).
enum class Offset : std::uint8_t { robust, none, epsilon };

template <class Num> struct TraceScene : TraceObjects<Num> {
  ray::Camera<Num> camera;
  std::vector<TraceMaterial<Num>> materials;
  std::vector<TraceTexture> textures;
  std::vector<lighting::Light<Num>> lights;
  Vec3<Num> background, ambient;
  int max_depth = 5;
  std::int64_t budget = 1024;  // a pixel's rays of non-zero weight
  Offset offset = Offset::robust;
  const PhotonMap* caustics = nullptr;  // photon_trace.hpp; none: no caustic term
};

// What to simulate. `shadows` per light, `reflection` and `refraction` per material.
struct EffectPlan {
  std::vector<char> shadows, reflection, refraction;
  bool caustics = true;
  bool zero_weight = false;  // cast rays of weight 0 too (--all-effects: the naive tracer)
  static EffectPlan all(std::size_t lights, std::size_t materials) {
    return {std::vector<char>(lights, 1), std::vector<char>(materials, 1), std::vector<char>(materials, 1), true, true};
  }
};

struct RayCounts {
  std::uint64_t primary = 0, shadow = 0, reflection = 0, refraction = 0, photon = 0;
  std::uint64_t shadow_blocked = 0;  // shadow rays that found an occluder
  std::uint64_t budget_stops = 0;    // secondary rays not cast because their pixel's budget was spent
  RayCounts& operator+=(const RayCounts& o) {
    primary += o.primary, shadow += o.shadow, shadow_blocked += o.shadow_blocked, reflection += o.reflection,
        refraction += o.refraction, photon += o.photon, budget_stops += o.budget_stops;
    return *this;
  }
  std::uint64_t total() const { return primary + shadow + reflection + refraction + photon; }
};

struct Whitted {
  static constexpr std::string_view id = "whitted";
  static constexpr std::string_view summary =
      "Whitted ray tracing: closest hit, shadow rays, local lighting, mirror and transmitted rays, as planned";
#define SW_TRACER_WHITTED(X) \
  X(closest, "hit <- the ray's closest hit (scene-hit)") \
  X(background, "if none: return the background colour") \
  X(surface, "P, its error box, N <- the surface at the hit; N faces the ray; (u, v)") \
  X(texture, "kd, ka <- the texture at (u, v) or at P; N <- N tilted by the bump map") \
  X(shadow, "for each light i with N.L > 0, if its shadows are planned: blocked_i <- any hit from P (offset) before the light") \
  X(local, "c <- shade(P, N, eye = the ray's origin), blocked lights adding their ambient term only") \
  X(caustic, "if caustics are planned and kd != 0: c <- c + kd E, E the irradiance of the caustic photons near P (photon map)") \
  X(deep, "if depth = max_depth: return c") \
  X(split, "if refraction is planned: TIR, T, F <- refract(d, N, n1, n2); else F <- 0") \
  X(reflect, "wr <- kr + kt F; if reflection is planned: c <- c + wr trace(the mirror ray from P, depth + 1)") \
  X(transmit, "wt <- kt (1 - F); if refraction is planned and not TIR: c <- c + wt trace(T from P, depth + 1)") \
  X(budget, \
    "    a ray of weight > 0 is cast while the pixel's budget lasts; one of weight 0 adds nothing: cast only for " \
    "--all-effects, within as many again") \
  X(done, "return c")
  SW_LISTING("Whitted ray tracer", SW_TRACER_WHITTED)
#undef SW_TRACER_WHITTED
};

// Towards light li from p: its position - p (point, spot), or its direction; 0 when it sits at p.
template <class Num> Vec3<Num> towards(const lighting::Light<Num>& li, const Vec3<Num>& p) {
  return li.type != lighting::LightType::directional ? Vec3<Num>(li.where - p) : li.where;
}
// The shadow ray from origin o towards li, and the t before which a hit blocks it (the light's
// position at t = 1; a directional light at infinity).
template <class Num> std::pair<ray::Ray3<Num>, Num> shadow_ray(const lighting::Light<Num>& li, const Vec3<Num>& o) {
  const bool positional = li.type != lighting::LightType::directional;
  return {{o, towards(li, o)}, positional ? Num(1) : std::numeric_limits<Num>::infinity()};
}

// One pixel's tracer (construct one per pixel: the budget is the pixel's).
template <NumberType Num, StepProbe Probe = NoProbe> class WhittedTracer {
 public:
  WhittedTracer(const TraceScene<Num>& s, const EffectPlan& plan, RayCounts& counts, Probe& probe)
      : s_(s), plan_(plan), counts_(counts), probe_(probe), budget_(s.budget), spare_(s.budget) {
    shading_.lights = s.lights;
    shading_.scene_ambient = s.ambient;
    shading_.convention = lighting::Convention::models;
  }

  // The colour seen through image point (i + di, j + dj); a fisheye's point outside its circle
  // sees the background.
  Vec3<Num> sample(std::int64_t i, std::int64_t j, const Num& di, const Num& dj) {
    const ray::CameraRay<Num> cr = [&] {
      const auto call = nested<ray::CameraRayAlgo>(probe_);
      return ray::camera_ray_at(s_.camera, i, j, di, dj, probe_);
    }();
    if (!cr.valid) return s_.background;
    ++counts_.primary;
    --budget_;
    return trace(cr.ray, 1, Num(1), Leaving{});
  }

  Vec3<Num> trace(const ray::Ray3<Num>& r, int depth, const Num& weight, const Leaving& from) {
    using L = Whitted;
    const Hit<Num> h = [&] {
      const auto call = nested<SceneHit>(probe_);
      return scene_hit(s_, r, false, Num(0), from, probe_);
    }();
    if constexpr (Probe::on) {
      auto& st = probe_.step(L::closest, h.hit ? StepKind::hit : StepKind::miss)
                     .idx("depth", depth)
                     .num("weight", weight)
                     .idx("object", h.object)
                     .num("t", h.t);
      // The ray tree: each ray to its hit, labelled by depth; the primary also shows the scene.
      const char* label = kDepthLabels[depth < kDepthLabelCount ? depth : kDepthLabelCount - 1];
      if (h.hit) st.segment(r.o, Vec3<Num>(r.o + h.t * r.d)).label(label).keep();
      else st.ray(r.o, r.d).label(label).keep();
      if (depth == 1 && s_.objects.size() <= 64) record_objects(st);
    }
    if (!h.hit) {
      if constexpr (Probe::on) probe_.step(L::background, StepKind::done).colour("c", s_.background);
      return s_.background;
    }
    const Prim<Num>& obj = s_.objects[static_cast<std::size_t>(h.object)];
    const TraceMaterial<Num>& m = s_.materials[static_cast<std::size_t>(obj.material)];
    const Surface<Num> sf = surface_at(s_, r, h);
    const bool entering = dot(r.d, sf.n) < Num(0);  // the ray meets the front (outside)
    const Vec3<Num> nf = entering ? sf.n : Num(-1) * sf.n;
    if constexpr (Probe::on)
      probe_.step(L::surface, StepKind::init)
          .vec("P", sf.p)
          .vec("err", sf.err)
          .vec("N", nf)
          .num("u", sf.u)
          .num("v", sf.v)
          .idx("entering", entering)
          .point(sf.p)
          .label("P")
          .keep()
          .segment(sf.p, Vec3<Num>(sf.p + nf))
          .label("N")
          .keep();
    lighting::Material<Num> mat = m.shading;
    if (m.texture >= 0) {
      const Vec3<Num> tc = texture_colour(s_.textures[static_cast<std::size_t>(m.texture)], sf.u, sf.v, sf.p);
      mat.kd = tc, mat.ka = tc;
    }
    const Vec3<Num> ns = m.bump.on ? bumped(m.bump, nf, sf.p) : nf;
    if constexpr (Probe::on)
      if (m.texture >= 0 || m.bump.on) probe_.step(L::texture, StepKind::init).colour("kd", mat.kd).vec("Ns", ns);
    const Leaving here = s_.offset == Offset::robust ? Leaving{h.object, h.prim} : Leaving{};
    shading_.blocked = shadows(sf, ns, here);
    shading_.p = sf.p, shading_.n = ns, shading_.eye = r.o, shading_.material = mat;
    Vec3<Num> c = [&] {
      const auto call = nested<lighting::Shade>(probe_);
      return lighting::shade(shading_, probe_).rgb;
    }();
    if constexpr (Probe::on) probe_.step(L::local, StepKind::init).colour("c", c);
    if (plan_.caustics && s_.caustics && !(mat.kd == Vec3<Num>{})) {
      const Vec3<Num> e = caustic_irradiance(*s_.caustics, sf.p);
      if (!(e == Vec3<Num>{})) c = c + lighting::times(mat.kd, e);
      if constexpr (Probe::on) probe_.step(L::caustic, StepKind::advance).colour("E", e).colour("c", c);
    }
    if (depth >= s_.max_depth) {
      if constexpr (Probe::on) probe_.step(L::deep, StepKind::done).colour("c", c);
      return c;
    }
    const std::size_t mi = static_cast<std::size_t>(obj.material);
    Transmission<Num> tr;
    tr.fresnel = Num(0), tr.tir = true;
    if (plan_.refraction[mi]) {
      const Num n1 = entering ? Num(1) : m.ior, n2 = entering ? m.ior : Num(1);
      {
        const auto call = nested<Refract>(probe_);
        tr = refract(r.d, ns, n1, n2, m.shading.params.fresnel, probe_);
      }
      if constexpr (Probe::on) probe_.step(L::split, StepKind::decide).idx("tir", tr.tir).num("F", tr.fresnel);
    }
    const Num wr = m.kr + m.kt * tr.fresnel, wt = m.kt * (Num(1) - tr.fresnel);
    if (plan_.reflection[mi]) {
      const Vec3<Num> dir = r.d - (Num(2) * dot(r.d, ns) / dot(ns, ns)) * ns;
      if constexpr (Probe::on) probe_.step(L::reflect, StepKind::advance).num("wr", wr).ray(sf.p, dir).label("mirror").value(wr);
      add(c, wr, weight, sf, here, dir, depth, counts_.reflection);
    }
    if (plan_.refraction[mi] && !tr.tir) {
      if constexpr (Probe::on) probe_.step(L::transmit, StepKind::advance).num("wt", wt).ray(sf.p, tr.dir).label("T").value(wt);
      add(c, wt, weight, sf, here, tr.dir, depth, counts_.refraction);
    }
    if constexpr (Probe::on) probe_.step(L::done, StepKind::done).colour("c", c);
    return c;
  }

 private:
  // Bit i set: light i faces P (N.L > 0), its shadows are planned, and a ray towards it is blocked.
  std::uint32_t shadows(const Surface<Num>& sf, const Vec3<Num>& ns, const Leaving& here) {
    using L = Whitted;
    std::uint32_t blocked = 0;
    for (std::size_t i = 0; i < s_.lights.size(); ++i) {
      const lighting::Light<Num>& li = s_.lights[i];
      const bool positional = li.type != lighting::LightType::directional;
      const Vec3<Num> to_light = towards(li, sf.p);
      if (!plan_.shadows[i] || to_light == Vec3<Num>{} || lighting::sign_dot(ns, to_light) <= 0) continue;
      const auto [sr, t_max] = shadow_ray(li, origin(sf, to_light));
      ++counts_.shadow;
      bool hit = false;
      {
        const auto call = nested<SceneHit>(probe_);
        hit = scene_hit(s_, sr, true, t_max, here, probe_).hit;
      }
      if constexpr (Probe::on) {
        auto& st = probe_.step(L::shadow, hit ? StepKind::hit : StepKind::miss).idx("i", std::int64_t(i)).idx("blocked", hit);
        if (positional) st.segment(sr.o, Vec3<Num>(sr.o + sr.d)).label(hit ? "blocked" : "lit").keep();  // to the light
        else st.ray(sr.o, sr.d).label(hit ? "blocked" : "lit").keep();
      }
      if (hit) blocked |= 1u << i, ++counts_.shadow_blocked;
    }
    return blocked;
  }

  // c <- c + w trace(the ray from the surface in direction dir). A ray of weight 0 (itself, or under
  // an ancestor of weight 0) adds nothing: only --all-effects casts it, from its own allowance, so
  // both plans spend the pixel's budget on the same rays.
  void add(Vec3<Num>& c, const Num& w, const Num& weight, const Surface<Num>& sf, const Leaving& here, const Vec3<Num>& dir,
           int depth, std::uint64_t& count) {
    const Num path = weight * w;
    std::int64_t& allowance = path > Num(0) ? budget_ : spare_;
    if (!(path > Num(0)) && !plan_.zero_weight) return;
    if (allowance <= 0) {
      if (path > Num(0)) ++counts_.budget_stops;
      if constexpr (Probe::on) probe_.step(Whitted::budget, StepKind::miss).idx("budget", allowance);
      return;
    }
    --allowance;
    ++count;
    const Vec3<Num> sub = [&] {
      const auto call = nested<Whitted>(probe_);
      return trace({origin(sf, dir), dir}, depth + 1, path, here);
    }();
    if (w > Num(0)) c = c + w * sub;
  }

  // Labels of the ray tree's rays by depth (string literals: the recorder keeps the pointer).
  static constexpr const char* kDepthLabels[] = {"ray",      "primary",  "depth 2",  "depth 3",  "depth 4",  "depth 5",
                                                 "depth 6",  "depth 7",  "depth 8",  "depth 9",  "depth 10", "depth 11",
                                                 "depth 12", "depth 13", "depth 14", "depth 15", "depth 16"};
  static constexpr int kDepthLabelCount = int(sizeof kDepthLabels / sizeof *kDepthLabels);
  // The scene's objects as kept geometry (meshes by their BVH's root box).
  template <class Step> void record_objects(Step& st) const {
    for (const Prim<Num>& o : s_.objects) {
      switch (o.shape) {
        case Shape::sphere: st.sphere(o.a, o.radius).keep(); break;
        case Shape::plane: st.plane(o.a, o.b).keep(); break;
        case Shape::box: st.box(o.a, o.b).keep(); break;
        case Shape::triangle: st.triangle(o.v[0], o.v[1], o.v[2]).keep(); break;
        case Shape::mesh: {
          const auto& nodes = s_.meshes[static_cast<std::size_t>(o.mesh)].bvh.nodes;
          if (nodes.empty()) break;
          const auto& b = nodes[0].box;
          st.box(Vec3<Num>{b.lo[0], b.lo[1], b.lo[2]}, Vec3<Num>{b.hi[0], b.hi[1], b.hi[2]}).keep();
          break;
        }
      }
    }
  }

  Vec3<Num> origin(const Surface<Num>& sf, const Vec3<Num>& dir) const {
    switch (s_.offset) {
      case Offset::robust: return offset_origin(sf, dir);
      case Offset::none: return sf.p;
      case Offset::epsilon: return sf.p + Num(dot(dir, sf.n) < Num(0) ? -1e-4 : 1e-4) * sf.n;
    }
    return sf.p;
  }

  const TraceScene<Num>& s_;
  const EffectPlan& plan_;
  RayCounts& counts_;
  Probe& probe_;
  std::int64_t budget_, spare_;  // rays of weight > 0 left; rays of weight 0 left (--all-effects)
  lighting::ShadeScene<Num> shading_;
};

}  // namespace sw::tracer
