#include "rays_oracle.hpp"
#include <CGAL/determinant.h>
#include <mpfr.h>
#include "cgal_bridge.hpp"

namespace sw::oracle {
namespace {

Vec3<Rational> add(const Vec3<Rational>& a, const Vec3<Rational>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3<Rational> sub(const Vec3<Rational>& a, const Vec3<Rational>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Q dotq(const Vec3<Rational>& a, const Vec3<Rational>& b) { return q(a.x) * q(b.x) + q(a.y) * q(b.y) + q(a.z) * q(b.z); }

// sqrt(x) for rational x >= 0: exact if x is a rational square.
bool rational_sqrt(const Rational& x, Rational& out) {
  if (!mpz_perfect_square_p(x.get_num_mpz_t()) || !mpz_perfect_square_p(x.get_den_mpz_t())) return false;
  mpz_class n, d;
  mpz_sqrt(n.get_mpz_t(), x.get_num_mpz_t());
  mpz_sqrt(d.get_mpz_t(), x.get_den_mpz_t());
  out = Rational(n, d);
  return true;
}

// (p + s sqrt(disc)) / den, or num / (p + s sqrt(disc)), in 512-bit MPFR with p and s sqrt(disc)
// of one sign (no cancellation), rounded to kSphereTBits bits.
Rational root_expr(const Rational& p, int s, const Rational& disc, const Rational& other, bool divide_other) {
  mpfr_t m, w, out;
  mpfr_inits2(512, m, w, static_cast<mpfr_ptr>(nullptr));
  mpfr_init2(out, kSphereTBits);
  mpfr_set_q(m, disc.get_mpq_t(), MPFR_RNDN);
  mpfr_sqrt(m, m, MPFR_RNDN);
  if (s < 0) mpfr_neg(m, m, MPFR_RNDN);
  mpfr_set_q(w, p.get_mpq_t(), MPFR_RNDN);
  mpfr_add(m, m, w, MPFR_RNDN);
  mpfr_set_q(w, other.get_mpq_t(), MPFR_RNDN);
  if (divide_other) mpfr_div(out, w, m, MPFR_RNDN);
  else mpfr_div(out, m, w, MPFR_RNDN);
  Rational t;
  mpfr_get_q(t.get_mpq_t(), out);
  mpfr_clears(m, w, out, static_cast<mpfr_ptr>(nullptr));
  return t;
}

}  // namespace

Rational triple(const Vec3<Rational>& a, const Vec3<Rational>& b, const Vec3<Rational>& c) {
  return r(CGAL::determinant(q(a.x), q(a.y), q(a.z), q(b.x), q(b.y), q(b.z), q(c.x), q(c.y), q(c.z)));
}

int orient3d(const Vec3<Rational>& p, const Vec3<Rational>& q1, const Vec3<Rational>& r1, const Vec3<Rational>& s) {
  return static_cast<int>(CGAL::orientation(point(p), point(q1), point(r1), point(s)));
}

RayResult ray_triangle(const Vec3<Rational>& o, const Vec3<Rational>& d, const std::array<Vec3<Rational>, 3>& v) {
  RayResult res;
  const Vec3<Rational> o2 = add(o, d);
  // The line o -> o + d against each edge (v1 v2, v2 v0, v0 v1): the same sign (zeros allowed) for
  // all three means the line meets the closed triangle; all zero means it lies in the plane.
  int s[3];
  for (int i = 0; i < 3; ++i) s[i] = orient3d(o, o2, v[(i + 1) % 3], v[(i + 2) % 3]);
  const bool any_pos = s[0] > 0 || s[1] > 0 || s[2] > 0, any_neg = s[0] < 0 || s[1] < 0 || s[2] < 0;
  if (any_pos == any_neg) return res;  // straddles an edge, or coplanar
  // The plane crossing is ahead: the origin lies strictly on the side of the plane that d leaves.
  const int side_o = orient3d(v[0], v[1], v[2], o), side_d = orient3d(v[0], v[1], v[2], add(v[0], d));
  if (side_o == 0 || side_d != -side_o) return res;
  res.hit = true;
  const Vec3<Rational> e1 = sub(v[1], v[0]), e2 = sub(v[2], v[0]);
  res.t = triple(e1, e2, sub(v[0], o)) / triple(e1, e2, d);
  Rational w[3], sum = 0;
  for (int i = 0; i < 3; ++i) sum += (w[i] = triple(d, sub(v[(i + 1) % 3], o), sub(v[(i + 2) % 3], o)));
  for (int i = 0; i < 3; ++i) res.b[i] = w[i] / sum;
  return res;
}

RayResult ray_sphere(const Vec3<Rational>& o, const Vec3<Rational>& d, const Vec3<Rational>& c, const Rational& rad) {
  RayResult res;
  const Vec3<Rational> f = sub(o, c);
  const Q a = dotq(d, d), b = dotq(f, d), cc = dotq(f, f) - q(rad) * q(rad);
  const Vec3<Rational> fxd = {f.y * d.z - f.z * d.y, f.z * d.x - f.x * d.z, f.x * d.y - f.y * d.x};
  const Q disc = q(rad) * q(rad) * a - dotq(fxd, fxd);  // a * (r^2 - squared distance of the line from c)
  if (CGAL::sign(disc) < 0) return res;
  // Roots t- <= t+ of a t^2 + 2 b t + cc = 0; t- t+ = cc / a, t- + t+ = -2b / a.
  bool far_root;
  if (CGAL::sign(cc) < 0) far_root = true;  // inside: t- < 0 < t+
  else if (CGAL::sign(cc) == 0) {           // on the surface: roots 0 and -2b/a
    if (CGAL::sign(b) >= 0) return res;
    res.hit = true;
    res.t = r(Q(-2) * b / a);
    return res;
  } else {                                  // outside: both roots share a sign, that of -b
    if (CGAL::sign(b) >= 0) return res;
    far_root = false;
  }
  res.hit = true;
  const Rational ra = r(a), rb = r(b), rc = r(cc), rd = r(disc);
  Rational root;
  if (rational_sqrt(rd, root)) {
    res.t = far_root ? Rational((-rb + root) / ra) : Rational((-rb - root) / ra);
    return res;
  }
  res.t_exact = false;
  // t = (-b + s sqrt(disc)) / a, or by Vieta cc / (-b - s sqrt(disc)), whichever does not cancel.
  const int s = far_root ? 1 : -1;
  if (sgn(-rb) * s >= 0) res.t = root_expr(-rb, s, rd, ra, false);
  else res.t = root_expr(-rb, -s, rd, rc, true);
  return res;
}

RayResult ray_box(const Vec3<Rational>& o, const Vec3<Rational>& d, const Vec3<Rational>& lo, const Vec3<Rational>& hi) {
  RayResult res;
  // {t : lo_k <= o_k + t d_k <= hi_k} per axis: all t, none, or a closed interval.
  bool any = false;
  Q t_lo, t_hi;
  for (int k = 0; k < 3; ++k) {
    const Q ok = q(o[k]), dk = q(d[k]), lk = q(lo[k]), hk = q(hi[k]);
    if (CGAL::sign(dk) == 0) {
      if (ok < lk || ok > hk) return res;
      continue;
    }
    Q a = (lk - ok) / dk, b = (hk - ok) / dk;
    if (CGAL::sign(dk) < 0) std::swap(a, b);
    if (!any || a > t_lo) t_lo = a;
    if (!any || b < t_hi) t_hi = b;
    any = true;
  }
  if (t_lo > t_hi || CGAL::sign(t_hi) <= 0) return res;
  res.hit = true;
  res.t_near = r(t_lo), res.t_far = r(t_hi);
  res.t = CGAL::sign(t_lo) > 0 ? res.t_near : res.t_far;
  return res;
}

RayResult ray_plane(const Vec3<Rational>& o, const Vec3<Rational>& d, const Vec3<Rational>& p, const Vec3<Rational>& n) {
  RayResult res;
  const Q den = dotq(n, d);
  if (CGAL::sign(den) == 0) return res;
  const Q t = dotq(n, sub(p, o)) / den;
  if (CGAL::sign(t) <= 0) return res;
  res.hit = true;
  res.t = r(t);
  return res;
}

}  // namespace sw::oracle
