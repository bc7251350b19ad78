// The GL lighting equation written out in MPFR from the spec's formulas (lighting_shade_oracle.hpp).
#include "lighting_shade_oracle.hpp"
#include <mpfr.h>

namespace sw::oracle {
namespace {

// An MPFR number at a fixed precision, with the few operations the equation needs.
class F {
 public:
  explicit F(int bits = kShadeOracleBits) { mpfr_init2(v_, bits); mpfr_set_ui(v_, 0, MPFR_RNDN); }
  F(const Rational& q, int bits = kShadeOracleBits) { mpfr_init2(v_, bits); mpfr_set_q(v_, q.get_mpq_t(), MPFR_RNDN); }
  F(const F& o) { mpfr_init2(v_, mpfr_get_prec(o.v_)); mpfr_set(v_, o.v_, MPFR_RNDN); }
  F& operator=(const F& o) { mpfr_set(v_, o.v_, MPFR_RNDN); return *this; }
  ~F() { mpfr_clear(v_); }
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }
  friend F operator+(const F& a, const F& b) { F r(int(mpfr_get_prec(a.v_))); mpfr_add(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend F operator*(const F& a, const F& b) { F r(int(mpfr_get_prec(a.v_))); mpfr_mul(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend F operator/(const F& a, const F& b) { F r(int(mpfr_get_prec(a.v_))); mpfr_div(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  Rational q() const { Rational r; mpfr_get_q(r.get_mpq_t(), v_); return r; }
  int sign() const { return mpfr_sgn(v_); }

 private:
  mpfr_t v_;
};

F fsqrt(const F& a) { F r(int(mpfr_get_prec(a.get()))); mpfr_sqrt(r.get(), a.get(), MPFR_RNDN); return r; }
F fpow(const F& a, const Rational& s) {
  F r(int(mpfr_get_prec(a.get())));
  if (sgn(s) == 0) { mpfr_set_ui(r.get(), 1, MPFR_RNDN); return r; }  // x^0 = 1, also 0^0 (C's pow)
  const F e(s, int(mpfr_get_prec(a.get())));
  mpfr_pow(r.get(), a.get(), e.get(), MPFR_RNDN);
  return r;
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
  F cosine(cutoff, bits), pi(bits);
  mpfr_const_pi(pi.get(), MPFR_RNDN);
  cosine = cosine * pi / F(Rational(180), bits);
  mpfr_cos(cosine.get(), cosine.get(), MPFR_RNDN);
  const F c = F(dotq(d, s), bits) / fsqrt(F(Rational(dotq(d, d) * dotq(s, s)), bits));
  F diff(bits);
  mpfr_sub(diff.get(), c.get(), cosine.get(), MPFR_RNDN);
  F tol(bits);
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
