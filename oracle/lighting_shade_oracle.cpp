// The GL lighting equation written out in MPFR from the spec's formulas (lighting_shade_oracle.hpp).
#include "lighting_shade_oracle.hpp"
#include "mpfr_value.hpp"

namespace sw::oracle {
namespace {

// MPFR numbers at kShadeOracleBits (the cone test: kShadeConeBits).
using F = Mpfr<kShadeOracleBits>;

F fsqrt(const F& a) { return F::fn(mpfr_sqrt, a); }
F fpow(const F& a, const Rational& s) {
  if (sgn(s) == 0) return F(1, a.bits());  // x^0 = 1, also 0^0 (C's pow)
  return F::fn2(mpfr_pow, a, F(s, a.bits()));
}

Rational dotq(const Vec3<Rational>& a, const Vec3<Rational>& b) { return Rational(a.x * b.x + a.y * b.y + a.z * b.z); }

// The unit vector of v (v != 0), in MPFR.
std::array<F, 3> unit(const Vec3<Rational>& v) {
  const F len = fsqrt(F(dotq(v, v)));
  return {F(v.x) / len, F(v.y) / len, F(v.z) / len};
}
F fdot(const std::array<F, 3>& a, const std::array<F, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// d.s/(|d||s|) >= cos(cut-off), ties (within 2^-(bits - 24)) inside.
bool in_cone(const Vec3<Rational>& d, const Vec3<Rational>& s, const Rational& cutoff) {
  const int bits = kShadeConeBits;
  const F cosine = F::fn(mpfr_cos, F(cutoff, bits) * F::pi(bits) / F(Rational(180), bits));
  const F c = F(dotq(d, s), bits) / fsqrt(F(Rational(dotq(d, d) * dotq(s, s)), bits));
  const F diff = c - cosine;
  F tol(0, bits);
  mpfr_set_ui_2exp(tol.get(), 1, -(bits - 24), MPFR_RNDN);
  if (mpfr_cmpabs(diff.get(), tol.get()) <= 0) return true;
  return diff.sign() > 0;
}

Rgb times(const Rgb& a, const Rgb& b) { return {Rational(a[0] * b[0]), Rational(a[1] * b[1]), Rational(a[2] * b[2])}; }

}  // namespace

ShadeResult shade_gl(const ShadeCase& c) {
  ShadeResult out;
  const auto n = unit(c.n);
  const auto e = unit(c.eye_at_infinity ? c.eye : Vec3<Rational>(c.eye - c.p));
  std::array<F, 3> sum{F(Rational(c.emission[0] + c.scene_ambient[0] * c.ka[0])), F(Rational(c.emission[1] + c.scene_ambient[1] * c.ka[1])),
                       F(Rational(c.emission[2] + c.scene_ambient[2] * c.ka[2]))};
  for (const ShadeLight& L : c.lights) {
    ShadeLightResult r;
    const bool positional = L.type != ShadeLight::Type::directional;
    const Vec3<Rational> vp = positional ? Vec3<Rational>(L.where - c.p) : L.where;  // V -> P_pli
    const Rational d2 = dotq(vp, vp);
    if (sgn(d2) == 0) {  // the light at the point: no direction, nothing added
      r.at_point = true;
      r.inside = false;
      r.rgb = {0, 0, 0};
      out.lights.push_back(r);
      continue;
    }
    r.lit = sgn(dotq(c.n, vp)) > 0;
    const auto l = unit(vp);
    const F d = fsqrt(F(d2));
    F att(Rational(1));
    if (positional) att = F(Rational(1)) / (F(L.k0) + F(L.k1) * d + F(Rational(L.k2 * d2)));
    F spot(Rational(1));
    if (L.type == ShadeLight::Type::spot && L.cutoff != 180) {
      const Vec3<Rational> pv = Vec3<Rational>(Rational(-1) * vp);  // P_pli -> V
      r.inside = in_cone(pv, L.spot_dir, L.cutoff);
      if (r.inside) {
        F cosang = fdot(unit(pv), unit(L.spot_dir));
        if (cosang.sign() < 0) cosang = F(Rational(0));
        spot = fpow(cosang, L.exponent);
      } else {
        spot = F(Rational(0));
      }
    }
    F diff(Rational(0)), spec(Rational(0));
    if (r.lit && !L.blocked) {
      diff = fdot(n, l);
      if (diff.sign() < 0) diff = F(Rational(0));
      std::array<F, 3> h{l[0] + e[0], l[1] + e[1], l[2] + e[2]};
      const F hh = fdot(h, h);
      F nh(Rational(0));  // h = 0 (l = -e): n.h = 0
      if (hh.sign() > 0) nh = fdot(n, h) / fsqrt(hh);
      if (nh.sign() < 0) nh = F(Rational(0));
      spec = fpow(nh, c.shininess);  // GL: (n (.) h)^s with (.) = max(dot, 0), and 0^0 = 1
    }
    const F w = att * spot;
    const Rgb a = times(L.ambient, c.ka), dk = times(L.diffuse, c.kd), sk = times(L.specular, c.ks);
    for (int k = 0; k < 3; ++k) {
      const F add = w * (F(a[k]) + diff * F(dk[k]) + spec * F(sk[k]));
      r.rgb[k] = add.q();
      sum[k] = sum[k] + add;
    }
    r.attenuation = att.q(), r.spot = spot.q(), r.diffuse = diff.q(), r.specular = spec.q();
    out.lights.push_back(r);
  }
  for (int k = 0; k < 3; ++k) out.rgb[k] = sum[k].q();
  return out;
}

}  // namespace sw::oracle
