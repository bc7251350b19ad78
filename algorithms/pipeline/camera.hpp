// The pipeline family's camera, shared by its algorithms: gluLookAt's frame, glFrustum's and
// glOrtho's projections and glViewport's mapping, generic over the number type. Conventions
// (docs/pipeline/semantics.md): eye space has the eye at 0 looking down -z with y up; clip and
// normalized device coordinates are GL's; window coordinates have their origin at the bottom left
// and depth in [dn, df] (glDepthRange).
#pragma once
#include <array>
#include "core/functions.hpp"
#include "core/vec.hpp"

namespace sw::pipe {

template <class Num> struct Vec4 {
  Num x{}, y{}, z{}, w{};
};

// gluLookAt's parameters. Preconditions: target != eye, up not parallel to target - eye.
template <class Num> struct LookAt {
  Vec3<Num> eye, target, up;
};

// glFrustum(l, r, b, t, n, f) or glOrtho(l, r, b, t, n, f). Preconditions: l < r, b < t, n < f,
// and 0 < n for perspective.
template <class Num> struct Projection {
  bool perspective = true;
  Num l{}, r{}, b{}, t{}, n{}, f{};
};

// glViewport(x, y, w, h) and glDepthRange(dn, df).
template <class Num> struct Viewport {
  Num x{}, y{}, w{}, h{}, dn{}, df{};
};

template <class Num> struct Camera {
  LookAt<Num> look;
  Projection<Num> proj;
  Viewport<Num> view;
};

// The camera's orthonormal frame: s to the right, u up, f forward (the eye looks along f).
template <class Num> struct Frame {
  Vec3<Num> s, u, f;
};

template <class Num> Vec3<Num> unit(const Vec3<Num>& a) { return (Num(1) / num::sqrt_of(dot(a, a))) * a; }

// gluLookAt's frame. In rationals it is exact when |target - eye| and |(target - eye) x up| are
// rational (the runtime admits only such cameras in exact mode).
template <class Num> Frame<Num> look_frame(const LookAt<Num>& c) {
  const Vec3<Num> f = unit(Vec3<Num>(c.target - c.eye));
  const Vec3<Num> s = unit(cross(f, c.up));
  return {s, cross(s, f), f};
}

// A 4x4 matrix by rows, applied to column vectors as GL does.
template <class Num> using Mat4 = std::array<std::array<Num, 4>, 4>;

template <class Num> Mat4<Num> identity() {
  Mat4<Num> m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m[i][j] = Num(i == j ? 1 : 0);
  return m;
}

// m (x, 1): a point through a matrix.
template <class Num> Vec4<Num> apply(const Mat4<Num>& m, const Vec3<Num>& x) {
  std::array<Num, 4> out;
  for (int k = 0; k < 4; ++k) out[k] = Num(m[k][0] * x.x + m[k][1] * x.y + m[k][2] * x.z + m[k][3]);
  return {out[0], out[1], out[2], out[3]};
}

template <class Num> Mat4<Num> product(const Mat4<Num>& a, const Mat4<Num>& b) {
  Mat4<Num> out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out[i][j] = Num(a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j] + a[i][3] * b[3][j]);
  return out;
}

// gluLookAt's matrix: world to eye space, the eye at 0 looking down -z.
template <class Num> Mat4<Num> view_matrix(const Frame<Num>& fr, const Vec3<Num>& eye) {
  const Num O(0), I(1);
  return {{{fr.s.x, fr.s.y, fr.s.z, Num(-dot(fr.s, eye))},
           {fr.u.x, fr.u.y, fr.u.z, Num(-dot(fr.u, eye))},
           {Num(-fr.f.x), Num(-fr.f.y), Num(-fr.f.z), dot(fr.f, eye)},
           {O, O, O, I}}};
}

// glFrustum's or glOrtho's matrix: eye to clip space.
template <class Num> Mat4<Num> projection_matrix(const Projection<Num>& p) {
  const Num O(0), I(1), two(2), rl = p.r - p.l, tb = p.t - p.b, fn = p.f - p.n;
  if (p.perspective)
    return {{{Num(two * p.n / rl), O, Num((p.r + p.l) / rl), O},
             {O, Num(two * p.n / tb), Num((p.t + p.b) / tb), O},
             {O, O, Num(-(p.f + p.n) / fn), Num(Num(-2) * p.f * p.n / fn)},
             {O, O, Num(-1), O}}};
  return {{{Num(two / rl), O, O, Num(-(p.r + p.l) / rl)},
           {O, Num(two / tb), O, Num(-(p.t + p.b) / tb)},
           {O, O, Num(Num(-2) / fn), Num(-(p.f + p.n) / fn)},
           {O, O, O, I}}};
}

// glFrustum's matrix as f goes to infinity: the third row tends to (0, 0, -1, -2n), so a point at
// eye depth e > 0 gets z_ndc = 1 - 2n/e, and a point at infinity (w = 0) z_ndc = 1. Nothing in
// front of the near plane is cut away, and a plane is drawn to its horizon.
template <class Num> Mat4<Num> infinite_projection_matrix(const Num& l, const Num& r, const Num& b, const Num& t, const Num& n) {
  Projection<Num> p{true, l, r, b, t, n, Num(n + n)};  // f only shapes the third row, replaced below
  Mat4<Num> m = projection_matrix(p);
  m[2] = {Num(0), Num(0), Num(-1), Num(Num(-2) * n)};
  return m;
}

// m x for a homogeneous point x (w = 0: a point at infinity, a direction).
template <class Num> Vec4<Num> apply(const Mat4<Num>& m, const Vec4<Num>& x) {
  std::array<Num, 4> out;
  for (int k = 0; k < 4; ++k) out[k] = Num(m[k][0] * x.x + m[k][1] * x.y + m[k][2] * x.z + m[k][3] * x.w);
  return {out[0], out[1], out[2], out[3]};
}

// Normalized device coordinates in window coordinates (glViewport, glDepthRange).
template <class Num> Vec3<Num> to_window(const Viewport<Num>& v, const Vec3<Num>& ndc) {
  return {Num(v.x + (ndc.x + Num(1)) * v.w / Num(2)), Num(v.y + (ndc.y + Num(1)) * v.h / Num(2)),
          Num(v.dn + (ndc.z + Num(1)) * (v.df - v.dn) / Num(2))};
}

// The view volume's eight corners in the world: near then far, each (l, b), (r, b), (r, t), (l, t).
template <class Num> std::array<Vec3<Num>, 8> frustum_corners(const Camera<Num>& c, const Frame<Num>& fr) {
  const Projection<Num>& p = c.proj;
  std::array<Vec3<Num>, 8> out;
  for (int k = 0; k < 2; ++k) {
    const Num depth = k == 0 ? p.n : p.f;
    const Num scale = p.perspective ? Num(depth / p.n) : Num(1);  // the window grows with depth in perspective
    const std::array<Num, 4> xs{p.l, p.r, p.r, p.l}, ys{p.b, p.b, p.t, p.t};
    for (int i = 0; i < 4; ++i)
      out[4 * k + i] = c.look.eye + Vec3<Num>(depth * fr.f) + Vec3<Num>(Num(scale * xs[i]) * fr.s) + Vec3<Num>(Num(scale * ys[i]) * fr.u);
  }
  return out;
}

// The view volume's twelve edges as pairs of frustum_corners' indices.
inline constexpr std::array<std::array<int, 2>, 12> kFrustumEdges{
    {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

}  // namespace sw::pipe
