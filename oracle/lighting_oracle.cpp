#include "lighting_oracle.hpp"
#include <stdexcept>
#include <utility>
#include "mpfr_value.hpp"

namespace sw::lighting_oracle {
namespace {

constexpr int kBits = 400;

// 400-bit MPFR numbers, for the formulas below.
using Big = oracle::Mpfr<kBits>;

Big sqrt_b(const Big& a) { return Big::fn(mpfr_sqrt, a); }
Big acos_b(const Big& a) { return Big::fn(mpfr_acos, a); }
Big sin_b(const Big& a) { return Big::fn(mpfr_sin, a); }
Big cos_b(const Big& a) { return Big::fn(mpfr_cos, a); }
Big tan_b(const Big& a) { return Big::fn(mpfr_tan, a); }
Big exp_b(const Big& a) { return Big::fn(mpfr_exp, a); }
Big pow_b(const Big& a, const Big& b) { return Big::fn2(mpfr_pow, a, b); }
Big atan2_b(const Big& y, const Big& x) { return Big::fn2(mpfr_atan2, y, x); }
Big pi_b() { return Big::pi(); }
Big max_b(const Big& a, const Big& b) { return a < b ? b : a; }
Big min_b(const Big& a, const Big& b) { return a < b ? a : b; }
// A cosine clamped into [-1, 1] (a rounded ratio of exact 1 may land a hair outside).
Big clamp1(const Big& a) { return a < Big(-1) ? Big(-1) : Big(1) < a ? Big(1) : a; }

struct BV {
  Big x, y, z;
};
BV lift(const Vec3<Rational>& v) { return {Big(v.x), Big(v.y), Big(v.z)}; }
Big dotb(const BV& a, const BV& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
BV scale(const Big& s, const BV& a) { return {s * a.x, s * a.y, s * a.z}; }
BV add(const BV& a, const BV& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
BV sub(const BV& a, const BV& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
BV normalised(const BV& a) { return scale(Big(1) / sqrt_b(dotb(a, a)), a); }
BV crossb(const BV& a, const BV& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

struct Builder {
  OracleTerm out;
  void put(const std::string& k, const Big& v) { out.named[k] = v.q(); }
  void put(const std::string& k, const BV& v) { put(k + ".x", v.x), put(k + ".y", v.y), put(k + ".z", v.z); }
};

}  // namespace

OracleTerm term(const lighting::ModelChoice& c, const Vec3<Rational>& N, const Vec3<Rational>& L,
                const Vec3<Rational>& E, const lighting::ModelParams<Rational>& p) {
  Builder b;
  OracleTerm& o = b.out;
  // The decisions: exact signs of the raw polynomials.
  const Rational NL = N.x * L.x + N.y * L.y + N.z * L.z, NE = N.x * E.x + N.y * E.y + N.z * E.z;
  const Rational NN = N.x * N.x + N.y * N.y + N.z * N.z, LL = L.x * L.x + L.y * L.y + L.z * L.z, EE = E.x * E.x + E.y * E.y + E.z * E.z;
  const Rational LE = L.x * E.x + L.y * E.y + L.z * E.z;
  o.lit = sgn(NL) > 0, o.seen = sgn(NE) > 0;
  const bool mirror_front = sgn(Rational(2 * NL * NE - NN * LE)) > 0;
  const BV n = normalised(lift(N)), l = normalised(lift(L)), e = normalised(lift(E));
  b.put("n", n), b.put("l", l), b.put("e", e);
  // The cosines from the raw vectors (not from the unit ones).
  const Big ci = Big(NL) / sqrt_b(Big(NN) * Big(LL)), cr = Big(NE) / sqrt_b(Big(NN) * Big(EE));
  const Big cle = Big(LE) / sqrt_b(Big(LL) * Big(EE));
  b.put("nl", ci), b.put("ne", cr), b.put("lit", Big(o.lit)), b.put("seen", Big(o.seen));
  if (!(o.lit && o.seen)) {
    o.value = 0;
    b.put("term", Big(0));
    return o;
  }
  const Big ti = acos_b(clamp1(ci)), tr = acos_b(clamp1(cr));
  auto diffuse_value = [&](lighting::DiffuseModel m) -> Big {
    switch (m) {
      case lighting::DiffuseModel::lambert: return ci;
      case lighting::DiffuseModel::minnaert: {
        const Big a = pow_b(ci, Big(p.minnaert_k)), bb = pow_b(cr, Big(Rational(p.minnaert_k - 1)));
        b.put("a", a), b.put("b", bb);
        return a * bb;
      }
      case lighting::DiffuseModel::oren_nayar: {
        // Oren & Nayar 1994, qualitative model: angles and azimuths in a tangent frame of n.
        const Big s2 = Big(p.sigma) * Big(p.sigma);
        const Big A = Big(1) - Big(Rational(1, 2)) * s2 / (s2 + Big(Rational(33, 100)));
        const Big B = Big(Rational(45, 100)) * s2 / (s2 + Big(Rational(9, 100)));
        b.put("A", A), b.put("B", B);
        const BV axis = mpfr_cmpabs(n.x.get(), n.z.get()) > 0 ? BV{Big(0), Big(0), Big(1)} : BV{Big(1), Big(0), Big(0)};
        const BV t = normalised(crossb(n, axis)), bt = crossb(n, t);
        const Big pi_ = atan2_b(dotb(l, bt), dotb(l, t)), pr = atan2_b(dotb(e, bt), dotb(e, t));
        const Big alpha = max_b(ti, tr), beta = min_b(ti, tr);
        const Big cphi = cos_b(pr - pi_);
        b.put("g", sin_b(ti) * sin_b(tr) * cphi);
        return ci * (A + B * max_b(Big(0), cphi) * sin_b(alpha) * tan_b(beta));
      }
    }
    throw std::logic_error("diffuse model");
  };
  // The half vector's angle from n: cos(alpha_h) = (cos ti + cos tr)/|l + e|, |l + e| = sqrt(2 + 2 cos(l, e)).
  const Big len_h = sqrt_b(Big(2) + Big(2) * cle);
  const Big ch = (ci + cr) / len_h;
  // The half vector's angle itself from atan2(|n x (l + e)|, n.(l + e)): acos(ch) near ch = 1
  // would lose half the bits.
  const BV le = add(l, e), nxh = crossb(n, le);
  const Big alpha_h = atan2_b(sqrt_b(dotb(nxh, nxh)), dotb(n, le));
  auto half = [&] {
    b.put("h", normalised(add(l, e)));
    b.put("c", ch);
  };
  // Beckmann's D from the angle alpha_h, with tan from the angle.
  auto beckmann_d = [&]() -> Big {
    const Big t = tan_b(alpha_h), m2 = Big(p.m) * Big(p.m);
    const Big D = exp_b(-(t * t) / m2) / (pi_b() * m2 * ch * ch * ch * ch);
    b.put("t2", t * t), b.put("D", D);
    return D;
  };
  Big value;
  using lighting::SpecularModel;
  const lighting::DiffuseModel diffuse = c.diffuse;
  if (!c.specular && !p.toon) {
    value = diffuse_value(diffuse);
    b.put("d", value);
  } else if (!c.specular) {  // toon over the diffuse model
    const Big d = diffuse_value(diffuse);
    const Rational cut = *p.toon;
    const bool lambert_like = diffuse == lighting::DiffuseModel::lambert || (diffuse == lighting::DiffuseModel::minnaert && p.minnaert_k == 1) ||
                              (diffuse == lighting::DiffuseModel::oren_nayar && sgn(p.sigma) == 0);
    const bool above = lambert_like ? NL * NL >= cut * cut * NN * LL : !(d < Big(cut));
    b.put("d", d), b.put("above", Big(above)), b.put("t", Big(above));
    value = Big(above);
  } else if (c.spec == SpecularModel::phong) {
    // Phong 1975: cos^n of the angle between the mirror direction and the eye;
    // cos = 2 cos(ti) cos(tr) - cos(l, e).
    const Big rc = Big(2) * ci * cr - cle;
    b.put("r", sub(scale(Big(2) * ci, n), l)), b.put("c", rc), b.put("front", Big(mirror_front));
    value = mirror_front ? pow_b(rc, Big(p.shininess)) : Big(0);
    if (sgn(p.shininess) == 0 && mirror_front) value = Big(1);
    b.put("s", value);
  } else if (c.spec == SpecularModel::blinn_phong) {
    half();
    value = sgn(p.shininess) == 0 ? Big(1) : pow_b(ch, Big(p.shininess));
    b.put("s", value);
  } else if (c.spec == SpecularModel::gaussian) {
    half();
    const Big q = alpha_h / Big(p.m);
    b.put("alpha", alpha_h);
    value = exp_b(-(q * q));
    b.put("s", value);
  } else if (c.spec == SpecularModel::beckmann) {
    half();
    value = pi_b() * beckmann_d() / (Big(4) * cr);
    b.put("s", value);
  } else if (c.spec == SpecularModel::cook_torrance) {
    half();
    const Big D = beckmann_d();
    // The facet sees the light at the half angle: cos = |l + e|/2.
    const Big ce = len_h / Big(2), eta = Big(p.ior);
    b.put("eh", ce);
    Big F(1);
    if (p.fresnel == lighting::Fresnel::exact) {  // Cook & Torrance 1982, unpolarised
      const Big g = sqrt_b(eta * eta + ce * ce - Big(1));
      const Big u = (g - ce) / (g + ce), v = (ce * (g + ce) - Big(1)) / (ce * (g - ce) + Big(1));
      F = Big(Rational(1, 2)) * u * u * (Big(1) + v * v);
    } else if (p.fresnel == lighting::Fresnel::schlick) {  // Schlick 1994
      const Big r0 = (eta - Big(1)) / (eta + Big(1)), f0 = r0 * r0;
      F = f0 + (Big(1) - f0) * pow_b(Big(1) - ce, Big(5));
    }
    if (p.fresnel != lighting::Fresnel::one) b.put("F", F);
    Big G(1);
    if (p.shadowing) {
      G = min_b(Big(1), min_b(Big(2) * ch * cr / ce, Big(2) * ch * ci / ce));
      b.put("G", G);
    }
    value = pi_b() * D * F * G / (Big(4) * cr);
    b.put("s", value);
  } else if (c.spec == SpecularModel::ward) {
    // Ward 1992, isotropic: f = exp(-tan^2(delta)/a^2) / (4 pi a^2 sqrt(cos(ti) cos(tr))), delta the
    // half vector's angle from n; the term is pi f cos(ti).
    half();
    const Big t = tan_b(alpha_h), a2 = Big(p.m) * Big(p.m);
    const Big g = exp_b(-(t * t) / a2);
    b.put("t2", t * t), b.put("g", g);
    value = pi_b() * (g / (Big(4) * pi_b() * a2 * sqrt_b(ci * cr))) * ci;
    b.put("s", value);
  } else {
    throw std::invalid_argument("lighting oracle: unknown model");
  }
  o.value = value.q();
  return o;
}

}  // namespace sw::lighting_oracle
