// llvmpipe's depth arithmetic in float, step for step: lp_state_setup.c's init_args, calc_coef4 and
// lp_do_offset_tri; lp_bld_interp.c's attribs_update_simple; lp_bld_conv.c's
// lp_build_clamped_float_to_unsigned_norm (read in a Mesa 23.0-devel tree; it reproduces 22.3.6's
// depth buffer bit for bit). Also a first-order bound on its error against the exact plane, and
// that exact plane in integers. docs/pipeline/llvmpipe.md.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include "zbuffer_llvmpipe_harness.hpp"

namespace sw::zpeer {

constexpr double kU = 1.0 / double(1 << 24);  // float's unit roundoff

// A triangle as llvmpipe's setup takes it: window x, y counted down from the top (kFb - GL's y) and
// z, all exact floats; a triangle of negative area there is passed as v1, v0, v2 (lp_setup_tri.c's
// triangle_both with the last vertex provoking).
struct LpTri {
  std::array<std::array<float, 3>, 3> v{};
  float factor = 0, units = 0;  // units already times llvmpipe's 2 r (lp_make_setup_variant_key)
  bool drawn = false;           // zero area: not drawn
};

inline LpTri lp_tri(const ZTri& t, std::array<int, 2> o, int bits) {
  LpTri l;
  for (int k = 0; k < 3; ++k) {
    const auto& p = t.v[std::size_t(k)];
    l.v[std::size_t(k)] = {float(o[0] + double(p[0]) / kXY + 0.5), float(kFb - (o[1] + double(p[1]) / kXY + 0.5)),
                           float(double(p[2]) / kZ)};
  }
  const auto& v = l.v;
  const double area =
      (double(v[0][0]) - v[1][0]) * (double(v[2][1]) - v[0][1]) - (double(v[2][0]) - v[0][0]) * (double(v[0][1]) - v[1][1]);
  if (area < 0) std::swap(l.v[0], l.v[1]);
  l.drawn = area != 0;
  l.factor = float(t.factor);
  l.units = float(double(float(t.units)) * (1.0 / double((std::int64_t(1) << bits) - 1)) * 2);
  return l;
}

// Our sample (i, j) is llvmpipe's pixel (ox + i, kFb - 1 - (oy + j)).
inline std::array<float, 2> lp_pixel(std::array<int, 2> o, std::int64_t i, std::int64_t j) {
  return {float(o[0] + i), float(kFb - 1 - (o[1] + j))};
}

struct LpPlane {
  float a0 = 0, dadx = 0, dady = 0, zoff = 0;
};

// No -mfma here, so the compiler fuses nothing; llvmpipe fuses llvm.fmuladd where the CPU has FMA.
inline bool lp_fused() {
  static const bool fma = __builtin_cpu_supports("fma");
  return fma;
}

inline LpPlane lp_setup(const LpTri& t) {
  const auto &v0 = t.v[0], &v1 = t.v[1], &v2 = t.v[2];
  const float x0c = v0[0] - 0.5f, y0c = v0[1] - 0.5f;
  const float dx01 = v0[0] - v1[0], dy01 = v0[1] - v1[1], dz01 = v0[2] - v1[2];
  const float dx20 = v2[0] - v0[0], dy20 = v2[1] - v0[1], dz20 = v2[2] - v0[2];
  const float e = dx01 * dy20, f = dy01 * dx20;
  const float ooa = 1.0f / (e - f);
  LpPlane p;
  if (t.factor != 0 || t.units != 0) {
    const float r1 = dz20 * dy01 - dy20 * dz01, r2 = dx20 * dz01 - dz20 * dx01;
    const float dzdx = std::fabs(r1 * ooa), dzdy = std::fabs(r2 * ooa);
    p.zoff = t.units + (dzdx > dzdy ? dzdx : dzdy) * t.factor;
  }
  const float dx20o = dx20 * ooa, dy20o = dy20 * ooa, dx01o = dx01 * ooa, dy01o = dy01 * ooa;
  p.dadx = dz01 * dy20o - dz20 * dy01o;
  p.dady = dz20 * dx01o - dz01 * dx20o;
  p.a0 = v0[2] - (p.dadx * x0c + p.dady * y0c);
  return p;
}

// The fragment's depth: a0 + dadx x + dady y at the pixel's integer coordinates, plus the offset,
// clamped to [0, 1] (lp_build_depth_clamp).
inline float lp_depth(const LpPlane& p, std::array<float, 2> px) {
  float z = lp_fused() ? std::fma(p.dady, px[1], std::fma(p.dadx, px[0], p.a0)) : p.dady * px[1] + (p.dadx * px[0] + p.a0);
  z = z + p.zoff;
  return std::min(std::max(z, 0.0f), 1.0f);
}

// Float to a bits-bit integer. 16 bits: z (65535/65536) in float, plus 2^7, whose low 16 bits of
// mantissa hold the result rounded to even. 24 bits: z (2^24 - 1) rounded to float, then to an
// integer (ties to even): two roundings, so one of the two integers nearest z (2^24 - 1).
inline std::uint32_t lp_convert(float z, int bits) {
  if (bits == 16) {
    const float s = z * float(65535.0 / 65536.0) + 128.0f;
    std::uint32_t u;
    std::memcpy(&u, &s, sizeof u);
    return u & 0xffffu;
  }
  return std::uint32_t(std::nearbyint(z * 16777215.0f));
}
// How far lp_convert may land from z M beyond the nearest integer's 1/2, in steps.
inline double convert_slack(int bits) { return bits == 16 ? 1.0 / 256 : 0.5; }

// A first-order bound on the error of a depth evaluated in float as llvmpipe does (and as our float
// mode does; O(u^2) terms left out, and the bench checks it at every fragment): the slopes by
// Cramer's rule from the vertex differences (exact), a0 = the plane at the origin from v0 at
// (x0, y0), then a0 + zx x + zy y at the pixel (x, y), fused or not. The slopes' errors count from
// v0, since a0 is made from the same rounded slopes; kappa, the area's condition, grows for
// slivers; the origin's terms are lp_state_setup.c's FIXME: llvmpipe interpolates from the
// framebuffer's origin, where a0 is large.
inline double float_depth_bound(const std::array<std::array<double, 3>, 3>& v, double x0, double y0, double x, double y,
                                double factor, double units, bool fused) {
  const double dx01 = v[0][0] - v[1][0], dy01 = v[0][1] - v[1][1], dz01 = v[0][2] - v[1][2];
  const double dx20 = v[2][0] - v[0][0], dy20 = v[2][1] - v[0][1], dz20 = v[2][2] - v[0][2];
  const double e = dx01 * dy20, f = dy01 * dx20, det = std::fabs(e - f);
  const double d = kU * ((std::fabs(e) + std::fabs(f)) / det + 4);  // 1/area, then each difference over it
  const double px = (std::fabs(dz01 * dy20) + std::fabs(dz20 * dy01)) / det,
               py = (std::fabs(dz20 * dx01) + std::fabs(dz01 * dx20)) / det;
  const double zx = std::fabs(dz01 * dy20 - dz20 * dy01) / det, zy = std::fabs(dz20 * dx01 - dz01 * dx20) / det;
  const double ex = d * px + kU * zx, ey = d * py + kU * zy;  // the slopes' errors
  const double dx = std::fabs(x - x0), dy = std::fabs(y - y0), z0 = std::fabs(v[0][2]);
  const double origin = zx * std::fabs(x0) + zy * std::fabs(y0);  // |zx x0|, |zy y0|, their sum: at most this
  double err =
      ex * dx + ey * dy + kU * (2 * origin + (z0 + origin) + (z0 + zx * dx + zy * std::fabs(y0)) + (z0 + zx * dx + zy * dy));
  if (!fused) err += kU * (zx * std::fabs(x) + zy * std::fabs(y));  // zx x and zy y rounded before their adds
  const double off = std::fabs(factor) * std::max(zx, zy) + std::fabs(units);
  return err + std::fabs(factor) * (d * std::max(px, py) + kU * std::max(zx, zy)) + 2 * kU * off +
         kU * (z0 + zx * dx + zy * dy + off);
}

inline double lp_bound(const LpTri& t, std::array<float, 2> px) {
  std::array<std::array<double, 3>, 3> v;
  for (int k = 0; k < 3; ++k) v[std::size_t(k)] = {t.v[std::size_t(k)][0], t.v[std::size_t(k)][1], t.v[std::size_t(k)][2]};
  return float_depth_bound(v, v[0][0] - 0.5, v[0][1] - 0.5, px[0], px[1], t.factor, t.units, lp_fused());
}

// Our float mode: z = z_a + zx (i - x_a) + zy (j - y_a) + o, in our coordinates, r = 1/M.
inline double our_float_bound(const ZTri& t, std::int64_t i, std::int64_t j, int bits) {
  std::array<std::array<double, 3>, 3> v;
  for (int k = 0; k < 3; ++k)
    v[std::size_t(k)] = {double(t.v[std::size_t(k)][0]) / kXY, double(t.v[std::size_t(k)][1]) / kXY,
                         double(t.v[std::size_t(k)][2]) / kZ};
  const double units = double(t.units) / double((std::int64_t(1) << bits) - 1);
  return float_depth_bound(v, v[0][0], v[0][1], double(i), double(j), double(t.factor), units, false);
}

// The exact plane of t at sample (i, j) plus glPolygonOffset with r = r_den^-1 per unit, clamped to
// [0, 1]: exact integers, rounded once to long double.
inline long double plane_depth(const ZTri& t, std::int64_t i, std::int64_t j, long double r) {
  using I = __int128;
  const auto &a = t.v[0], &b = t.v[1], &c = t.v[2];
  const I area = I(b[0] - a[0]) * (c[1] - a[1]) - I(b[1] - a[1]) * (c[0] - a[0]);  // over 256^2
  const I nx = I(b[2] - a[2]) * (c[1] - a[1]) - I(c[2] - a[2]) * (b[1] - a[1]);    // zx = nx 256 / area (over kZ)
  const I ny = I(c[2] - a[2]) * (b[0] - a[0]) - I(b[2] - a[2]) * (c[0] - a[0]);
  const I num = nx * (I(i) * kXY - a[0]) + ny * (I(j) * kXY - a[1]);
  long double z = (static_cast<long double>(a[2]) + static_cast<long double>(num) / static_cast<long double>(area)) / kZ;
  const long double slope = static_cast<long double>(std::max(nx < 0 ? -nx : nx, ny < 0 ? -ny : ny)) * kXY /
                            std::fabs(static_cast<long double>(area)) / kZ;
  z += t.factor * slope + t.units * r;
  return std::min(std::max(z, 0.0L), 1.0L);
}

}  // namespace sw::zpeer
