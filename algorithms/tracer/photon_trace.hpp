// Caustics by photon mapping (Jensen): photons leave the point and spot lights, bounce off mirrors
// and glass by Russian roulette on the weights the tracer uses (kr + kt F, kt (1 - F)), and are
// stored where they reach a diffuse surface after at least one such bounce (light, specular,
// diffuse: the caustic paths Whitted's tracer cannot follow). Each photon's numbers come from its
// own seeded sequence, so the map does not depend on the thread count. Directional lights emit no
// photons. Semantics and units: docs/tracer/renderer.md#caustics.
#pragma once
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>
#include "tracer/whitted.hpp"

namespace sw::tracer {

struct PhotonTrace {
  static constexpr std::string_view id = "photon-trace";
  static constexpr std::string_view summary =
      "Caustic photons: emitted from the lights, bounced by mirrors and glass (Russian roulette), stored on diffuse surfaces";
#define SW_TRACER_PHOTON_TRACE(X) \
  X(emit, \
    "for each photon k of light i: a direction in the cone around a mirror or glass object, from its seeded sequence; power <- " \
    "I Omega / (n m)") \
  X(hit, "    hit <- the closest hit (scene-hit); none: the photon is lost; the first: power <- power d^2 / att(d)") \
  X(store, "    if it has bounced off a mirror or glass and the surface is diffuse: store (P, power)") \
  X(roulette, "    u <- its next number; u < kr + kt F: reflect; u < kr + kt: transmit (not under TIR); else: absorbed") \
  X(tree, "a kd-tree over the stored photons (kd-build)")
  SW_LISTING("Caustic photon map", SW_TRACER_PHOTON_TRACE)
#undef SW_TRACER_PHOTON_TRACE
};

namespace photon_detail {
inline double unit_random(std::uint64_t& state) { return double(splitmix64(state) >> 11) * 0x1p-53; }
// A direction with cos(angle to axis) uniform in [c0, 1]: uniform over that cap of the sphere.
inline Vec3<double> in_cap(const Vec3<double>& axis, double c0, std::uint64_t& state) {
  const double c = c0 + (1 - c0) * unit_random(state), s = std::sqrt(std::max(0.0, 1 - c * c)),
               phi = 6.283185307179586 * unit_random(state);
  const Vec3<double> w = unit3(axis), a = std::abs(w.x) > 0.5 ? Vec3<double>{0, 1, 0} : Vec3<double>{1, 0, 0};
  const Vec3<double> u = unit3(cross(a, w)), v = cross(w, u);
  return (s * std::cos(phi)) * u + (s * std::sin(phi)) * v + c * w;
}
inline bool diffuse(const TraceMaterial<double>& m) { return m.texture >= 0 || !(m.shading.kd == Vec3<double>{}); }
}  // namespace photon_detail

// Where a light aims its photons (Jensen's projection maps): the cones from the light around each
// bounded mirror or glass object's bounding sphere; the whole sphere of directions when such an
// object is unbounded (a plane) or holds the light. Photons that meet no mirror or glass first
// are never stored, so aiming loses none; a direction in m cones is weighted 1/m.
struct EmitCone {
  Vec3<double> axis;  // unit
  double c0 = -1;     // cos of the half-angle; -1: the whole sphere
};
inline std::vector<EmitCone> emit_cones(const TraceScene<double>& s, const Vec3<double>& light) {
  std::vector<EmitCone> cones;
  for (const Prim<double>& o : s.objects) {
    const TraceMaterial<double>& m = s.materials[static_cast<std::size_t>(o.material)];
    if (!(m.kr > 0 || m.kt > 0)) continue;
    if (o.shape == Shape::plane) return {EmitCone{}};
    Vec3<double> c = o.a;
    double r2 = o.radius * o.radius;
    auto around = [&](const auto& pts) {
      Vec3<double> lo = pts[0], hi = pts[0];
      for (const auto& p : pts)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
      c = 0.5 * (lo + hi);
      r2 = 0;
      for (const auto& p : pts) r2 = std::max(r2, dot(Vec3<double>(p - c), Vec3<double>(p - c)));
    };
    if (o.shape == Shape::box) around(std::vector<Vec3<double>>{o.a, o.b});
    if (o.shape == Shape::triangle) around(o.v);
    if (o.shape == Shape::mesh) {
      std::vector<Vec3<double>> pts;
      for (const auto& t : s.meshes[static_cast<std::size_t>(o.mesh)].tris) pts.insert(pts.end(), t.begin(), t.end());
      around(pts);
    }
    r2 *= 1 + 1e-9;  // rounding: the cone must contain the sphere
    const Vec3<double> to = c - light;
    const double d2 = dot(to, to);
    if (d2 <= r2) return {EmitCone{}};
    cones.push_back({unit3(to), std::sqrt(1 - r2 / d2)});
  }
  return cones;
}

// Traces photons [first, last) of light li (n in all for that light), appending the stored ones.
inline void trace_photons(const TraceScene<double>& s, std::size_t li, std::int64_t first, std::int64_t last, std::int64_t n,
                          std::uint32_t seed, std::vector<Vec3<double>>& at, std::vector<Vec3<double>>& power,
                          std::uint64_t& rays) {
  using namespace photon_detail;
  const lighting::Light<double>& l = s.lights[li];
  const bool spot = l.type == lighting::LightType::spot && !l.cone.all;
  const std::vector<EmitCone> cones = emit_cones(s, l.where);
  if (cones.empty()) return;
  const auto nc = static_cast<std::int64_t>(cones.size());
  NoProbe none;
  for (std::int64_t k = first; k < last; ++k) {
    std::uint64_t state = (std::uint64_t(seed) << 32) ^ (std::uint64_t(li) << 56) ^ std::uint64_t(k);
    const EmitCone& cone = cones[static_cast<std::size_t>(k % nc)];
    const std::int64_t in_cone = n / nc + (k % nc < n % nc ? 1 : 0);  // photons aimed into this cone
    const Vec3<double> d = in_cap(cone.c0 < -0.5 ? Vec3<double>{0, 0, 1} : cone.axis, cone.c0, state);
    int m = 0;
    for (const EmitCone& c : cones) m += c.c0 < -0.5 || dot(d, c.axis) >= c.c0;
    const Vec3<double> sd = spot ? unit3(l.spot_dir) : Vec3<double>{};
    if (spot && dot(d, sd) < l.cone.cos) continue;  // outside the spot's cone: no light that way
    const double spot_factor = spot ? std::pow(dot(d, sd), l.cone.exponent) : 1.0;
    const double solid = 6.283185307179586 * (1 - cone.c0);
    Vec3<double> photon = (solid * spot_factor / (double(in_cone) * std::max(m, 1))) * l.diffuse;
    ray::Ray3<double> r{l.where, d};
    Leaving from{};
    bool caustic = false;
    for (int bounce = 0; bounce < s.max_depth; ++bounce) {  // bounded by max_depth
      ++rays;
      const Hit<double> h = scene_hit(s, r, false, 0.0, from, none);
      if (!h.hit) break;
      const Prim<double>& o = s.objects[static_cast<std::size_t>(h.object)];
      const TraceMaterial<double>& m = s.materials[static_cast<std::size_t>(o.material)];
      const Surface<double> sf = surface_at(s, r, h);
      if (bounce == 0) {  // density falls as 1/d^2; shade's direct light as 1/att(d): match them at the first hit
        const double d = h.t * std::sqrt(dot(r.d, r.d));
        photon = (d * d / (l.k0 + l.k1 * d + l.k2 * d * d)) * photon;
      }
      if (caustic && diffuse(m)) at.push_back(sf.p), power.push_back(photon);
      const bool entering = dot(r.d, sf.n) < 0;
      const Vec3<double> nf = entering ? sf.n : -1.0 * sf.n;
      Transmission<double> tr;
      if (m.kt > 0) tr = refract(r.d, nf, entering ? 1.0 : m.ior, entering ? m.ior : 1.0, m.shading.params.fresnel, none);
      else tr.fresnel = 0, tr.tir = true;
      const double pr = m.kr + m.kt * tr.fresnel, pt = tr.tir ? 0.0 : m.kt * (1 - tr.fresnel), u = unit_random(state);
      Vec3<double> next;
      if (u < pr) next = r.d - (2 * dot(r.d, nf) / dot(nf, nf)) * nf;
      else if (u < pr + pt) next = tr.dir;
      else break;
      caustic = true;
      from = s.offset == Offset::robust ? Leaving{h.object, h.prim} : Leaving{};
      r = {offset_origin(sf, next), next};
    }
  }
}

}  // namespace sw::tracer
