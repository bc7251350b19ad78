// The full local lighting model at one point: emission + scene ambient x ka + the sum over the
// lights of attenuation x spot x (ambient + diffuse + specular), each term a light colour times a
// material colour (lights.hpp: point, directional and spot lights, OpenGL's attenuation and cone).
// Two conventions: `gl` is the OpenGL 1.x fixed-function equation (spec 2.14.1: Lambert and
// Blinn-Phong, the specular term gated by n.l > 0 only, h = l + e with e = (0, 0, 1)-like for an
// infinite viewer), checked against Mesa (bench/peer_gl_lighting.cpp); `models` takes any diffuse
// and specular model of the family through the dispatchers (brdf.hpp), both terms 0 below either
// horizon. The decisions are signs of polynomials in the raw input: n.l > 0 and n.e > 0 exact in
// every mode (sign_dot, lighting_common.hpp), the spot cone in the mode's arithmetic (exact in
// reference mode; float and double may decide wrongly on the boundary, and the bench counts it). Semantics and the conventions: docs/lighting/shade.md.
#pragma once
#include <algorithm>
#include <string_view>
#include <vector>
#include "core/functions.hpp"
#include "core/probe.hpp"
#include "lighting/brdf.hpp"
#include "lighting/lights.hpp"
#include "lighting/lighting_common.hpp"
#include "lighting/models.hpp"

namespace sw::lighting {

enum class Convention : std::uint8_t { gl, models };

template <class Num> struct Material {
  Vec3<Num> emission, ka, kd, ks;
  DiffuseModel diffuse = DiffuseModel::lambert;
  SpecularModel specular = SpecularModel::blinn_phong;
  ModelParams<Num> params;  // params.shininess is GL's exponent s
};

template <class Num> struct ShadeScene {
  Vec3<Num> p, n;                // the point and its normal (any length > 0)
  Vec3<Num> eye;                 // the eye's position, or (eye_at_infinity) the direction towards it
  bool eye_at_infinity = false;  // GL: LIGHT_MODEL_LOCAL_VIEWER false is eye = (0, 0, 1) at infinity
  Vec3<Num> scene_ambient;
  std::vector<Light<Num>> lights;
  Material<Num> material;
  Convention convention = Convention::gl;
  std::uint32_t blocked = 0;  // bit i: a shadow ray found light i occluded (the ray tracer): no diffuse or specular from it
};

template <class Num> struct LightTerms {
  bool at_point = false;  // the light sits at the shading point: it adds nothing
  bool lit = false;       // n.l > 0, decided on the raw vectors
  bool blocked = false;   // occluded (ShadeScene::blocked): lit, but only its ambient term is added
  bool inside = true;     // inside the spot cone (always, for other lights)
  Num attenuation{0}, spot{0}, diffuse{0}, specular{0};
  Vec3<Num> rgb;  // what the light adds
};

template <class Num> struct Shaded {
  bool facing_eye = true;  // n.e > 0 (the `models` convention zeroes every light's terms otherwise)
  Vec3<Num> ambient, rgb;  // emission + scene ambient x ka; the total (not clamped)
  std::vector<LightTerms<Num>> lights;
};

struct Shade {
  static constexpr std::string_view id = "shade";
  static constexpr std::string_view summary =
      "Full local lighting: ambient + lights x (diffuse + specular), point/directional/spot, attenuation";
#define SW_LIGHTING_SHADE(X) \
  X(normal, "n <- (N/m)/|N/m|, m = max |N_k|                          -- N as given, any length") \
  X(view, "e <- (E - P)/|E - P|, or E/|E| for an eye at infinity; facing <- N.(E - P) > 0 (or N.E > 0)") \
  X(ambient, "c <- emission + ambient_scene ka") \
  X(lights, "for each light i:") \
  X(to_light, "    L <- position - P (point, spot), or the direction (directional)") \
  X(at_point, "    if L = 0: the light sits at P: it adds nothing; next light") \
  X(facing, "    lit <- N.L > 0                                        -- the raw vectors: exact in reference mode") \
  X(blocked, "    if a shadow ray found light i occluded: diff <- 0, spec <- 0 (it adds its ambient term only)") \
  X(unit, "    m <- max |L_k|; d <- m |L/m|; l <- (L/m)/|L/m|          -- no overflow or underflow") \
  X(atten, "    att <- 1/(k0 + k1 d + k2 d^2)   (directional: 1)") \
  X(cone, \
    "    spot: D <- -L/m, S <- S/max|S_k|; inside <- D.S >= 0 and (D.S)^2 >= cos^2(cut-off) |D|^2 |S|^2; spot <- inside ? " \
    "(D.S/(|D||S|))^exponent : 0") \
  X(diffuse, "    diff <- lit ? (gl: max(n.l, 0); models: the diffuse model if facing) : 0") \
  X(specular, "    spec <- lit ? (gl: h <- l + e; max(n.h/|h|, 0)^s, 0^0 = 1; models: the specular model if facing) : 0") \
  X(add, "    c <- c + att spot (Ia ka + diff Id kd + spec Is ks)") \
  X(done, "rgb <- c                                                  -- not clamped")
  SW_LISTING("Full local lighting model", SW_LIGHTING_SHADE)
#undef SW_LIGHTING_SHADE
};

// v divided by its largest |component| (v != 0): a vector whose squared length neither overflows
// nor underflows, in the same direction (exactly, in reference mode). Then unit() and |v| =
// m |v/m| stay accurate for huge, tiny and subnormal vectors.
template <class Num> Num max_abs(const Vec3<Num>& v) { return std::max({num::abs(v.x), num::abs(v.y), num::abs(v.z)}); }
template <class Num> Vec3<Num> prescaled(const Vec3<Num>& v) {
  const Num m = max_abs(v);
  return {v.x / m, v.y / m, v.z / m};
}
template <class Num> Vec3<Num> times(const Vec3<Num>& a, const Vec3<Num>& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

// Preconditions (validated by the runtime): N != 0; E != P (local eye) or E != 0; every light's
// colours, attenuation (k >= 0, not all 0), cone (cut-off in [0, 90] or 180, exponent >= 0) and
// spot direction S != 0 valid.
template <NumberType Num, StepProbe Probe = NoProbe> Shaded<Num> shade(const ShadeScene<Num>& s, Probe& probe) {
  using L = Shade;
  const Material<Num>& m = s.material;
  Shaded<Num> out;
  const Vec3<Num> n = unit(prescaled(s.n));
  if constexpr (Probe::on)
    probe.step(L::normal, StepKind::init)
        .vec("N", s.n)
        .vec("n", n)
        .point(s.p)
        .label("P")
        .keep()
        .segment(s.p, Vec3<Num>(s.p + n))
        .label("n")
        .keep();
  const Vec3<Num> to_eye = s.eye_at_infinity ? s.eye : Vec3<Num>(s.eye - s.p);
  const Vec3<Num> e = unit(prescaled(to_eye));
  out.facing_eye = sign_dot(s.n, to_eye) > 0;
  if constexpr (Probe::on) {
    auto& st = probe.step(L::view, StepKind::decide)
                   .vec("e", e)
                   .idx("facing", out.facing_eye)
                   .segment(s.p, Vec3<Num>(s.p + e))
                   .label("e")
                   .keep();
    if (!s.eye_at_infinity) st.point(s.eye).label("eye").keep();
  }
  out.ambient = m.emission + times(s.scene_ambient, m.ka);
  out.rgb = out.ambient;
  if constexpr (Probe::on) probe.step(L::ambient, StepKind::init).colour("c", out.rgb);
  out.lights.reserve(s.lights.size());
  for (std::size_t i = 0; i < s.lights.size(); ++i) {
    const Light<Num>& li = s.lights[i];
    LightTerms<Num> t;
    const bool positional = li.type != LightType::directional;
    if constexpr (Probe::on)
      probe.step(L::lights, StepKind::advance).idx("i", std::int64_t(i)).idx("type", std::int64_t(li.type));
    const Vec3<Num> to_light = positional ? Vec3<Num>(li.where - s.p) : li.where;
    if constexpr (Probe::on) {
      auto& st = probe.step(L::to_light, StepKind::init).vec("L", to_light);
      if (positional) st.point(li.where).label("light").keep().segment(s.p, li.where).label("L");
      else st.ray(s.p, to_light).label("L");
    }
    t.at_point = to_light == Vec3<Num>{};  // exact in every mode: x - y = 0 only if x = y (gradual underflow)
    if (t.at_point) {
      t.inside = false;
      if constexpr (Probe::on) probe.step(L::at_point, StepKind::miss).idx("i", std::int64_t(i));
      out.lights.push_back(t);
      continue;
    }
    t.lit = sign_dot(s.n, to_light) > 0;
    if constexpr (Probe::on) probe.step(L::facing, StepKind::decide).num("NL", dot(s.n, to_light)).idx("lit", t.lit);
    t.blocked = (s.blocked >> i) & 1u;
    if constexpr (Probe::on)
      if (t.blocked && t.lit) probe.step(L::blocked, StepKind::miss).idx("i", std::int64_t(i));
    const Num scale = max_abs(to_light);
    const Vec3<Num> lm = prescaled(to_light);
    const Num dm = num::sqrt_of(dot(lm, lm)), d = scale * dm, d2 = d * d;
    const Vec3<Num> l = (Num(1) / dm) * lm;
    if constexpr (Probe::on) probe.step(L::unit, StepKind::init).num("d", d).vec("l", l);
    t.attenuation = positional ? attenuation(li, d, d2) : Num(1);
    if constexpr (Probe::on) probe.step(L::atten, StepKind::init).num("att", t.attenuation);
    t.spot = Num(1);
    if (li.type == LightType::spot && !li.cone.all) {
      const Vec3<Num> sm = prescaled(li.spot_dir);  // D/|D|_max and S/|S|_max: the same cone test, no overflow
      const Num ds = -dot(lm, sm), q = dot(lm, lm) * dot(sm, sm);
      t.inside = cone_contains(ds, q, li.cone);
      t.spot = t.inside ? num::pow(ds / num::sqrt_of(q), li.cone.exponent) : Num(0);
      if constexpr (Probe::on)
        probe.step(L::cone, StepKind::decide)
            .num("DS", ds)
            .num("q", q)
            .idx("inside", t.inside)
            .num("spot", t.spot)
            .ray(li.where, li.spot_dir)
            .label("S");
    }
    if (t.lit && !t.blocked) {
      const FrameSigns sg{t.lit, out.facing_eye, sign_mirror(s.n, to_light, to_eye) > 0};  // lit and facing: decided above
      const Frame<Num> f{n, l, e, dot(n, l), dot(n, e), sg.lit, sg.seen, sg.mirror};
      if (s.convention == Convention::gl) {
        t.diffuse = Num(0) < f.nl ? f.nl : Num(0);
      } else if (out.facing_eye) {
        t.diffuse = diffuse_term(m.diffuse, f, m.params, probe);
      }
      if constexpr (Probe::on) probe.step(L::diffuse, StepKind::init).num("diff", t.diffuse);
      if (s.convention == Convention::gl) {
        const Vec3<Num> h = l + e;
        const Num hh = dot(h, h);
        const Num nh = hh == Num(0) ? Num(0) : dot(n, h) / num::sqrt_of(hh);
        t.specular = num::pow(Num(0) < nh ? nh : Num(0), m.params.shininess);  // 0^0 = 1: shininess 0 is ks Is wherever lit
        if constexpr (Probe::on) probe.step(L::specular, StepKind::init).vec("h", h).num("nh", nh).num("spec", t.specular);
      } else {
        if (out.facing_eye) t.specular = specular_term(m.specular, f, m.params, probe);
        if constexpr (Probe::on) probe.step(L::specular, StepKind::init).num("spec", t.specular);
      }
    }
    const Num w = t.attenuation * t.spot;
    t.rgb = w * (times(li.ambient, m.ka) + t.diffuse * times(li.diffuse, m.kd) + t.specular * times(li.specular, m.ks));
    out.rgb = out.rgb + t.rgb;
    if constexpr (Probe::on) probe.step(L::add, StepKind::advance).colour("light", t.rgb).colour("c", out.rgb);
    out.lights.push_back(t);
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).colour("rgb", out.rgb);
  return out;
}

}  // namespace sw::lighting
