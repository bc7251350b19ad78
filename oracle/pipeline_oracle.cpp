// The pipeline family's oracle (pipeline_oracle.hpp).
#include "pipeline_oracle.hpp"
#include <stdexcept>
#include <mpfr.h>
#include <CGAL/Plane_3.h>
#include <CGAL/squared_distance_3.h>
#include "cgal_bridge.hpp"
#include "fill_oracle.hpp"

namespace sw::pipeline_oracle {
namespace {

using V3 = std::array<Rational, 3>;

Rational dot3(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 cross3(const V3& a, const V3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
V3 v3(const Vec3<Rational>& a) { return {a.x, a.y, a.z}; }

// f(x) to 400 bits (MPFR), as a rational: more than reference mode's 300, so the two differ.
Rational mpfr400(int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t), const Rational& x) {
  mpfr_t m;
  mpfr_init2(m, 400);
  mpfr_set_q(m, x.get_mpq_t(), MPFR_RNDN);
  f(m, m, MPFR_RNDN);
  Rational r;
  mpfr_get_q(r.get_mpq_t(), m);
  mpfr_clear(m);
  return r;
}

// sqrt(x), x > 0: exact for the square of a rational, else to 400 bits (an irrational camera's frame).
Rational root(const Rational& x) {
  if (mpz_perfect_square_p(x.get_num_mpz_t()) && mpz_perfect_square_p(x.get_den_mpz_t())) {
    mpz_class n, d;
    mpz_sqrt(n.get_mpz_t(), x.get_num_mpz_t());
    mpz_sqrt(d.get_mpz_t(), x.get_den_mpz_t());
    return Rational(n, d);
  }
  return mpfr400(mpfr_sqrt, x);
}

V3 normalized(const V3& a) {
  const Rational len = root(dot3(a, a));
  return {a[0] / len, a[1] / len, a[2] / len};
}

struct CameraFrame {
  V3 fwd, right, up;
};

CameraFrame frame_of(const Camera& cam) {
  const V3 fwd = normalized(sub(v3(cam.look.target), v3(cam.look.eye)));
  const V3 right = normalized(cross3(fwd, v3(cam.look.up)));
  return {fwd, right, cross3(right, fwd)};
}

using K = oracle::ExactKernel;
K::Point_3 kpoint(const V3& p) { return {oracle::q(p[0]), oracle::q(p[1]), oracle::q(p[2])}; }

std::array<K::Point_3, 8> corner_points(const Camera& cam) {
  std::array<K::Point_3, 8> out;
  const auto c = corners(cam);
  for (int k = 0; k < 8; ++k) out[k] = kpoint(c[k]);
  return out;
}

// The view volume's six planes through its corners, each oriented with the volume's centre on its
// positive side.
std::array<K::Plane_3, 6> volume_planes(const Camera& cam) {
  // Corners: near then far, each (l, b), (r, b), (r, t), (l, t).
  const auto p = corner_points(cam);
  const K::Point_3 centre = CGAL::midpoint(p[0], p[6]);  // the midpoint of a diagonal lies inside
  std::array<K::Plane_3, 6> out{K::Plane_3(p[0], p[3], p[4]), K::Plane_3(p[1], p[5], p[2]), K::Plane_3(p[0], p[4], p[1]),
                                K::Plane_3(p[3], p[2], p[7]), K::Plane_3(p[0], p[1], p[3]), K::Plane_3(p[4], p[7], p[5])};
  for (auto& pl : out)
    if (pl.oriented_side(centre) == CGAL::ON_NEGATIVE_SIDE) pl = pl.opposite();
  return out;
}

Cull combine(const std::array<Cull, 6>& per_plane) {
  Cull out = Cull::inside;
  for (Cull c : per_plane) {
    if (c == Cull::outside) return Cull::outside;
    if (c == Cull::straddles) out = Cull::straddles;
  }
  return out;
}

}  // namespace

Frame frame(const Camera& cam) {
  const CameraFrame f = frame_of(cam);
  return {f.fwd, f.right, f.up};
}

std::array<std::array<Rational, 3>, 8> corners(const Camera& cam) {
  const CameraFrame fr = frame_of(cam);
  const pipe::Projection<Rational>& P = cam.proj;
  // (x, y) on the near plane's window, carried to `depth` along the ray from the eye in
  // perspective, straight back in orthographic.
  auto corner = [&](const Rational& depth, const Rational& x, const Rational& y) {
    const Rational k = P.perspective ? depth / P.n : Rational(1);
    V3 p = v3(cam.look.eye);
    for (int a = 0; a < 3; ++a) p[a] += depth * fr.fwd[a] + k * x * fr.right[a] + k * y * fr.up[a];
    return p;
  };
  return {corner(P.n, P.l, P.b), corner(P.n, P.r, P.b), corner(P.n, P.r, P.t), corner(P.n, P.l, P.t),
          corner(P.f, P.l, P.b), corner(P.f, P.r, P.b), corner(P.f, P.r, P.t), corner(P.f, P.l, P.t)};
}

std::array<Plane, 6> planes(const Camera& cam) {
  std::array<Plane, 6> out;
  const auto v = volume_planes(cam);
  for (int k = 0; k < 6; ++k) out[k] = {{oracle::r(v[k].a()), oracle::r(v[k].b()), oracle::r(v[k].c())}, oracle::r(v[k].d())};
  return out;
}

Facing facing(const Camera& cam, const std::array<std::array<Rational, 3>, 3>& tri) {
  Facing out;
  const auto a = kpoint(tri[0]), b = kpoint(tri[1]), c = kpoint(tri[2]);
  V3 from = v3(cam.look.eye);
  if (!cam.proj.perspective) from = sub(tri[0], frame_of(cam).fwd);  // a point toward the eye from a
  out.toward = static_cast<int>(CGAL::orientation(a, b, c, kpoint(from)));
  const pipe::Mat4<Rational> identity = pipe::identity<Rational>();
  std::array<K::Point_2, 3> w;
  for (int k = 0; k < 3; ++k) {
    const Vertex v = transform(identity, cam, tri[k]);
    if (!v.win || v.clip[3] <= 0) return out;
    w[k] = {oracle::q((*v.win)[0]), oracle::q((*v.win)[1])};
  }
  out.winding = static_cast<int>(CGAL::orientation(w[0], w[1], w[2]));
  return out;
}

Cull cull_sphere(const Camera& cam, const std::array<Rational, 3>& c, const Rational& r) {
  const auto centre = kpoint(c);
  const oracle::Q r2 = oracle::q(r * r);
  std::array<Cull, 6> per;
  const auto planes = volume_planes(cam);
  for (int k = 0; k < 6; ++k) {
    const bool negative = planes[k].oriented_side(centre) == CGAL::ON_NEGATIVE_SIDE;
    const oracle::Q d2 = CGAL::squared_distance(centre, planes[k]);
    per[k] = negative && d2 > r2 ? Cull::outside : !negative && d2 >= r2 ? Cull::inside : Cull::straddles;
  }
  return combine(per);
}

Cull cull_corners(const Camera& cam, const std::array<std::array<Rational, 3>, 8>& corners) {
  std::array<Cull, 6> per;
  const auto planes = volume_planes(cam);
  for (int k = 0; k < 6; ++k) {
    int negative = 0;
    for (const auto& p : corners) negative += planes[k].oriented_side(kpoint(p)) == CGAL::ON_NEGATIVE_SIDE;
    per[k] = negative == 8 ? Cull::outside : negative == 0 ? Cull::inside : Cull::straddles;
  }
  return combine(per);
}

std::vector<Pixel> window_samples(const std::array<std::array<Rational, 3>, 3>& v, std::int64_t width, std::int64_t height) {
  std::array<K::Point_2, 3> p;
  for (int k = 0; k < 3; ++k) p[k] = {oracle::q(v[k][0]), oracle::q(v[k][1])};
  const CGAL::Orientation turn = CGAL::orientation(p[0], p[1], p[2]);
  if (turn == CGAL::COLLINEAR) return {};
  if (turn == CGAL::RIGHT_TURN) std::swap(p[1], p[2]);  // counter-clockwise from here on
  auto covered = [&](const K::Point_2& s) {
    for (int k = 0; k < 3; ++k) {
      const K::Point_2 &a = p[k], &b = p[(k + 1) % 3];
      const CGAL::Orientation o = CGAL::orientation(a, b, s);
      if (o == CGAL::RIGHT_TURN) return false;
      // On the edge: covered on a left edge (running down) or a bottom edge (running right).
      if (o == CGAL::COLLINEAR && !(b.y() < a.y() || (b.y() == a.y() && b.x() > a.x()))) return false;
    }
    return true;
  };
  auto bound = [&](int axis, bool hi) {
    Rational m = v[0][axis];
    for (int k = 1; k < 3; ++k) m = hi ? std::max(m, v[k][axis]) : std::min(m, v[k][axis]);
    mpz_class f;
    if (hi) mpz_fdiv_q(f.get_mpz_t(), m.get_num_mpz_t(), m.get_den_mpz_t());
    else mpz_cdiv_q(f.get_mpz_t(), m.get_num_mpz_t(), m.get_den_mpz_t());
    return std::clamp<std::int64_t>(num::int64_of(f), -1, (axis == 0 ? width : height));
  };
  std::vector<Pixel> out;
  for (std::int64_t j = std::max<std::int64_t>(0, bound(1, false)); j <= std::min(height - 1, bound(1, true)); ++j)
    for (std::int64_t i = std::max<std::int64_t>(0, bound(0, false)); i <= std::min(width - 1, bound(0, true)); ++i)
      if (covered(K::Point_2(i, j))) out.push_back({i, j});
  return out;
}

DepthImage z_buffer(std::int64_t width, std::int64_t height, const std::vector<DepthTriangle>& tris, int bits, bool lequal,
                    const Rational& clear) {
  const Rational M = bits == 0 ? Rational(1) : Rational((mpz_class(1) << bits) - 1);
  const Rational r = bits == 0 ? Rational(1, mpz_class(1) << 24) : 1 / M;
  auto stored = [&](const Rational& z) {
    if (bits == 0) return z;
    const Rational x = z * M + Rational(1, 2);
    mpz_class f;
    mpz_fdiv_q(f.get_mpz_t(), x.get_num_mpz_t(), x.get_den_mpz_t());
    return Rational(f);
  };
  DepthImage out{std::vector<std::int64_t>(width * height, -1), std::vector<Rational>(width * height, stored(clear))};
  for (const DepthTriangle& t : tris) {
    std::array<K::Point_2, 3> p;
    std::array<K::Point_3, 3> p3;
    for (int k = 0; k < 3; ++k) {
      p[k] = {oracle::q(t.v[k][0]), oracle::q(t.v[k][1])};
      p3[k] = kpoint(t.v[k]);
    }
    const CGAL::Orientation turn = CGAL::orientation(p[0], p[1], p[2]);
    if (turn == CGAL::COLLINEAR) continue;
    if (turn == CGAL::RIGHT_TURN) std::swap(p[1], p[2]);  // counter-clockwise from here on
    // The depth's slopes from the plane through the three vertices: a x + b y + c z + d = 0.
    const K::Plane_3 plane(p3[0], p3[1], p3[2]);
    const Rational zx = -oracle::r(plane.a()) / oracle::r(plane.c()), zy = -oracle::r(plane.b()) / oracle::r(plane.c());
    const Rational offset = t.factor * std::max(Rational(abs(zx)), Rational(abs(zy))) + t.units * r;
    const Rational area = oracle::r(CGAL::area(p[0], p[1], p[2]));
    for (const Pixel& px : window_samples(t.v, width, height)) {
      const std::int64_t i = px.x, j = px.y;
      const K::Point_2 s(i, j);
      // Barycentric weights: each the area opposite its vertex over the whole.
      const Rational la = oracle::r(CGAL::area(s, p[1], p[2])) / area, lb = oracle::r(CGAL::area(p[0], s, p[2])) / area;
      const Rational lc = 1 - la - lb;
      auto depth_of = [&](const K::Point_2& q) {
        for (int k = 0; k < 3; ++k)
          if (t.v[k][0] == oracle::r(q.x()) && t.v[k][1] == oracle::r(q.y())) return t.v[k][2];
        throw std::logic_error("z-buffer oracle: a vertex lost");
      };
      Rational z = la * depth_of(p[0]) + lb * depth_of(p[1]) + lc * depth_of(p[2]) + offset;
      z = std::clamp(z, Rational(0), Rational(1));
      const Rational d = stored(z);
      Rational& cell = out.depth[j * width + i];
      ++out.fragments;
      out.ties += d == cell;
      if (lequal ? d <= cell : d < cell) cell = d, out.ids[j * width + i] = t.id, ++out.passed;
      }
  }
  return out;
}

std::vector<std::array<Rational, 3>> blend(std::int64_t width, std::int64_t height, const std::vector<BlendTriangle>& tris,
                                           const std::vector<std::size_t>& order, const std::array<Rational, 3>& background,
                                           bool depth_write) {
  // Each triangle's covered samples once, then each pixel on its own.
  std::vector<std::vector<Pixel>> covered(tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t) {
    covered[t] = window_samples(tris[t].v, width, height);
    std::sort(covered[t].begin(), covered[t].end());
  }
  std::vector<std::array<Rational, 3>> out(width * height, background);
  for (std::int64_t j = 0; j < height; ++j)
    for (std::int64_t i = 0; i < width; ++i) {
      Rational depth = 1;
      std::array<Rational, 3>& c = out[j * width + i];
      for (std::size_t t : order) {
        if (!std::binary_search(covered[t].begin(), covered[t].end(), Pixel{i, j})) continue;
        std::array<Vec2<Rational>, 3> xy;
        std::array<Rational, 3> zs;
        for (int k = 0; k < 3; ++k) xy[k] = {tris[t].v[k][0], tris[t].v[k][1]}, zs[k] = tris[t].v[k][2];
        const Rational z = oracle::linear_at(xy, zs, Pixel{i, j});
        if (!(z < depth)) continue;
        for (int a = 0; a < 3; ++a) c[a] = tris[t].alpha * tris[t].rgb[a] + (1 - tris[t].alpha) * c[a];
        if (depth_write) depth = z;
      }
    }
  return out;
}

Rational fog_factor(int mode, const Rational& start, const Rational& end, const Rational& density, const Rational& c) {
  const Rational dc = density * c;
  const Rational f = mode == 0 ? Rational((end - c) / (end - start)) : sgn(dc) == 0 ? Rational(1) : mpfr400(mpfr_exp, mode == 1 ? Rational(-dc) : Rational(-dc * dc));
  return std::clamp(f, Rational(0), Rational(1));
}

Vertex transform(const pipe::Mat4<Rational>& M, const Camera& cam, const std::array<Rational, 3>& p) {
  V3 world;
  for (int k = 0; k < 3; ++k) world[k] = M[k][0] * p[0] + M[k][1] * p[1] + M[k][2] * p[2] + M[k][3];
  // The camera: forward, right and up as unit vectors (gluLookAt's definition).
  const CameraFrame fr = frame_of(cam);
  const V3 q = sub(world, v3(cam.look.eye));
  const Rational x = dot3(fr.right, q), y = dot3(fr.up, q), d = dot3(fr.fwd, q);  // d: how far in front of the eye
  const pipe::Projection<Rational>& P = cam.proj;
  Vertex out;
  out.world = world;
  out.eye = {x, y, -d};
  out.distance = d;
  // Where the point lands in the window's frame [l, r] x [b, t] x [n, f]: on the near plane by
  // similar triangles in perspective, straight across in orthographic; then each range onto [-1, 1].
  auto unit_range = [](const Rational& v, const Rational& lo, const Rational& hi) { return 2 * (v - lo) / (hi - lo) - 1; };
  Rational w = 1;
  std::array<Rational, 3> ndc_if_ahead;
  if (P.perspective) {
    w = d;
    out.inside = d > 0 && P.n <= d && d <= P.f && P.l * d <= P.n * x && P.n * x <= P.r * d && P.b * d <= P.n * y && P.n * y <= P.t * d;
    if (d > 0) {
      // Depth is linear in 1/d: -1 at the near plane, 1 at the far one.
      ndc_if_ahead = {unit_range(P.n * x / d, P.l, P.r), unit_range(P.n * y / d, P.b, P.t),
                      2 * (1 / P.n - 1 / d) / (1 / P.n - 1 / P.f) - 1};
    }
    // Clip coordinates are the NDC scaled by w = d; written out so that they exist for d <= 0 too.
    out.clip = {(2 * P.n * x - (P.r + P.l) * d) / (P.r - P.l), (2 * P.n * y - (P.t + P.b) * d) / (P.t - P.b),
                ((P.f + P.n) * d - 2 * P.f * P.n) / (P.f - P.n), d};
  } else {
    out.inside = P.l <= x && x <= P.r && P.b <= y && y <= P.t && P.n <= d && d <= P.f;
    ndc_if_ahead = {unit_range(x, P.l, P.r), unit_range(y, P.b, P.t), unit_range(d, P.n, P.f)};
    out.clip = {ndc_if_ahead[0], ndc_if_ahead[1], ndc_if_ahead[2], Rational(1)};
  }
  if (w > 0) {
    out.ndc = ndc_if_ahead;
    const auto& v = cam.view;
    out.win = std::array<Rational, 3>{v.x + v.w * (ndc_if_ahead[0] + 1) / 2, v.y + v.h * (ndc_if_ahead[1] + 1) / 2,
                                      v.dn + (v.df - v.dn) * (ndc_if_ahead[2] + 1) / 2};
  }
  return out;
}

}  // namespace sw::pipeline_oracle
