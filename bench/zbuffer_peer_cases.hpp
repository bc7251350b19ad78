// The z-buffer's llvmpipe peer (docs/pipeline/llvmpipe.md): its cases. Each case is a few window-space
// triangles drawn in order into a window of kWin x kWin samples, with x and y on llvmpipe's 1/256
// sub-pixel grid and z on the 2^-24 grid, so that float carries every vertex exactly to llvmpipe.
#pragma once
#include <algorithm>
#include <array>
#include <stdexcept>
#include <compare>
#include <cstdint>
#include <random>
#include <string>
#include <vector>
#include "core/number.hpp"
#include "pipeline/z_buffer.hpp"
#include "pipeline_oracle.hpp"

namespace sw::zpeer {

constexpr std::int64_t kXY = 256;                   // x, y numerators over 256 (our coordinates)
constexpr std::int64_t kZ = std::int64_t(1) << 24;  // z numerators over 2^24
constexpr std::int64_t kWin = 57;                   // samples 0 .. 56 a side; vertices in [0, 56]

struct ZTri {
  std::array<std::array<std::int64_t, 3>, 3> v{};  // x, y over kXY; z over kZ
  std::int64_t factor = 0, units = 0;              // glPolygonOffset
  bool offset() const { return factor != 0 || units != 0; }
};

// What a case shares with the other cases of its draw: the depth buffer, glDepthFunc, glClearDepth.
struct ZConfig {
  int bits = 24;
  bool lequal = false;
  std::int64_t clear = kZ;  // over kZ
  auto operator<=>(const ZConfig&) const = default;
};

struct ZCase {
  std::vector<ZTri> tris;  // drawn in order; triangle k has id k
  ZConfig cfg;
  std::string set;
};

// Canonical, as GMP's comparisons need.
inline Rational q_over(std::int64_t n, std::int64_t d) {
  Rational q(n, d);
  q.canonicalize();
  return q;
}
inline Rational xy_q(std::int64_t n) { return q_over(n, kXY); }
inline Rational z_q(std::int64_t n) { return q_over(n, kZ); }
inline Rational clear_q(const ZConfig& c) { return z_q(c.clear); }

inline pipeline_oracle::DepthTriangle oracle_tri(const ZTri& t, std::int64_t id) {
  pipeline_oracle::DepthTriangle d;
  for (int k = 0; k < 3; ++k) d.v[k] = {xy_q(t.v[k][0]), xy_q(t.v[k][1]), z_q(t.v[k][2])};
  d.id = id, d.factor = t.factor, d.units = t.units;
  return d;
}

// The case in one of our number types (exact: Rational; float: every value is a float exactly).
template <class Num> std::vector<pipe::DepthTriangle<Num>> our_tris(const ZCase& c) {
  std::vector<pipe::DepthTriangle<Num>> out;
  for (std::size_t k = 0; k < c.tris.size(); ++k) {
    const ZTri& t = c.tris[k];
    pipe::DepthTriangle<Num> d;
    for (int i = 0; i < 3; ++i) {
      const auto& p = t.v[std::size_t(i)];
      if constexpr (std::is_same_v<Num, Rational>) d.v[i] = {xy_q(p[0]), xy_q(p[1]), z_q(p[2])};
      else d.v[i] = {Num(double(p[0]) / kXY), Num(double(p[1]) / kXY), Num(double(p[2]) / kZ)};
    }
    d.id = std::int64_t(k), d.factor = Num(t.factor), d.units = Num(t.units);
    out.push_back(d);
  }
  return out;
}

// ---- the case sets ----

class ZCaseMaker {
 public:
  explicit ZCaseMaker(std::uint64_t seed) : rng_(seed) {}
  std::int64_t uniform(std::int64_t lo, std::int64_t hi) { return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng_); }
  // 16 or 24 bits, GL_LESS or GL_LEQUAL, in rotation; clear depth 1 unless given.
  static ZConfig config(std::size_t k, std::int64_t clear = kZ) { return ZConfig{k % 2 ? 24 : 16, (k / 2) % 2 == 1, clear}; }

  ZTri shuffled(ZTri t) {
    std::shuffle(t.v.begin(), t.v.end(), rng_);  // both orientations
    return t;
  }
  // Random triangles of 1 to 56 px on grids of 1, 1/2, 1/16 and 1/256 px; depths uniform in [0, 1].
  ZCase random(std::size_t k) {
    ZCase c{{}, config(k, k % 8 >= 4 ? uniform(kZ / 2, kZ) : kZ), "random"};  // glClearDepth too
    const std::int64_t n = uniform(4, 24);
    for (std::int64_t t = 0; t < n; ++t) {
      const std::int64_t step = kXY / std::array<std::int64_t, 4>{1, 2, 16, 256}[std::size_t(uniform(0, 3))];
      const std::int64_t size = std::array<std::int64_t, 4>{1, 8, 24, 56}[std::size_t(uniform(0, 3))] * kXY;
      const std::int64_t x0 = uniform(0, (kWin - 1) * kXY - size) / step * step,
                         y0 = uniform(0, (kWin - 1) * kXY - size) / step * step;
      ZTri tri;
      for (auto& p : tri.v) p = {x0 + uniform(0, size / step) * step, y0 + uniform(0, size / step) * step, uniform(0, kZ)};
      c.tris.push_back(tri);
    }
    return c;
  }
  // A square of lo to hi px somewhere in the window: its corner and side, in sixteenths of a pixel.
  std::array<std::int64_t, 3> square(std::int64_t lo_px, std::int64_t hi_px) {
    const std::int64_t side = uniform(lo_px, hi_px) * 16, room = (kWin - 1) * 16 - side;
    return {uniform(0, room), uniform(0, room), side};
  }
  // A convex quad a, b, c, d (counter-clockwise, corners on the 1/16 grid), one per quadrant of a square.
  std::array<std::array<std::int64_t, 2>, 4> quad() {
    for (int attempt = 0; attempt < 10000; ++attempt) {  // one corner per quadrant: nearly always convex
      const auto sq = square(8, 28);
      const std::int64_t x0 = sq[0], y0 = sq[1], side = sq[2];
      const std::int64_t h = side / 2;
      const auto corner = [&](std::int64_t qx, std::int64_t qy) {
        return std::array<std::int64_t, 2>{(x0 + qx * h + uniform(0, h - 1)) * 16, (y0 + qy * h + uniform(0, h - 1)) * 16};
      };
      const std::array<std::array<std::int64_t, 2>, 4> q{corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
      bool convex = true;
      for (int i = 0; i < 4; ++i) {
        const auto &a = q[i], &b = q[(i + 1) % 4], &c = q[(i + 2) % 4];
        convex = convex && (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]) > 0;
      }
      if (convex) return q;
    }
    throw std::logic_error("zbuffer peer cases: no convex quad in 10000 attempts");
  }
  // The quad in the plane z = z0 + gx x + gy y (exact on the 2^-24 grid), drawn as two triangles
  // split along a-c, then as two split along b-d moved by dz (over kZ) and offset by (factor, units).
  ZCase split_quad(std::size_t k, const char* set, std::int64_t dz, std::int64_t factor = 0, std::int64_t units = 0) {
    const auto q = quad();
    const std::int64_t z0 = uniform(kZ / 4, 3 * kZ / 4), gx = uniform(-2048, 2048), gy = uniform(-2048, 2048);
    // x, y over 256 are multiples of 16: z = z0 + g (x / 16) / 2^20, over 2^24.
    const auto at = [&](const std::array<std::int64_t, 2>& p, std::int64_t d) {
      return std::array<std::int64_t, 3>{p[0], p[1], z0 + gx * (p[0] / 16) + gy * (p[1] / 16) + d};
    };
    ZCase c{{}, config(k), set};
    c.tris.push_back(shuffled(ZTri{{at(q[0], 0), at(q[1], 0), at(q[2], 0)}}));
    c.tris.push_back(shuffled(ZTri{{at(q[0], 0), at(q[2], 0), at(q[3], 0)}}));
    c.tris.push_back(shuffled(ZTri{{at(q[0], dz), at(q[1], dz), at(q[3], dz)}, factor, units}));
    c.tris.push_back(shuffled(ZTri{{at(q[1], dz), at(q[2], dz), at(q[3], dz)}, factor, units}));
    return c;
  }
  ZCase coplanar(std::size_t k) { return split_quad(k, "coplanar", 0); }
  // 2^-20 nearer: 16 steps of a 24-bit buffer, a sixteenth of a step of a 16-bit one.
  ZCase near_coplanar(std::size_t k) { return split_quad(k, "near-coplanar 2^-20", -(kZ >> 20)); }
  // Two to four triangles over one square of 12 to 32 px, with random planes that cross inside it.
  ZCase intersecting(std::size_t k) {
    ZCase c{{}, config(k), "intersecting"};
    const auto sq = square(12, 32);
    const std::int64_t x0 = sq[0], y0 = sq[1], side = sq[2];
    const auto at = [&](std::int64_t lo, std::int64_t hi) { return (x0 + uniform(lo * side / 3, hi * side / 3)) * 16; };
    const auto at_y = [&](std::int64_t lo, std::int64_t hi) { return (y0 + uniform(lo * side / 3, hi * side / 3)) * 16; };
    for (std::int64_t t = 0, n = uniform(2, 4); t < n; ++t) {
      ZTri tri{{{{at(0, 1), at_y(0, 1), 0}, {at(2, 3), at_y(0, 2), 0}, {at(0, 3), at_y(2, 3), 0}}}};
      for (auto& p : tri.v) p[2] = uniform(kZ / 5, 4 * kZ / 5);
      c.tris.push_back(shuffled(tri));
    }
    return c;
  }
  // The second pair moved by an odd number of half steps (16 bits) or steps (24 bits), nearer or
  // farther, and offset by glPolygonOffset(factor, units): the units decide against the move.
  ZCase polygon_offset(std::size_t k) {
    // Half a step is 2^-17 (128 over kZ) at 16 bits; at 24 bits the grid's finest move is a step.
    const std::int64_t unit = config(k).bits == 16 ? 128 : 1;
    const std::int64_t dz = (2 * uniform(-4, 3) + 1) * unit;
    const std::int64_t factor = std::array<std::int64_t, 4>{0, 0, 1, -1}[std::size_t(uniform(0, 3))];
    const std::int64_t units = std::array<std::int64_t, 5>{-2, -1, 1, 2, 0}[std::size_t(uniform(0, factor == 0 ? 3 : 4))];
    return split_quad(k, "polygon offset", dz, factor, units);
  }

 private:
  std::mt19937_64 rng_;
};

// About `triangles` triangles in each of the five sets, the configurations in rotation.
inline std::vector<ZCase> z_cases(std::size_t triangles, std::uint64_t seed) {
  ZCaseMaker make(seed);
  std::vector<ZCase> out;
  const auto fill = [&](auto&& next) {
    std::size_t n = 0;
    for (std::size_t k = 0; n < triangles; ++k) out.push_back(next(k)), n += out.back().tris.size();
  };
  fill([&](std::size_t k) { return make.random(k); });
  fill([&](std::size_t k) { return make.coplanar(k); });
  fill([&](std::size_t k) { return make.near_coplanar(k); });
  fill([&](std::size_t k) { return make.intersecting(k); });
  fill([&](std::size_t k) { return make.polygon_offset(k); });
  return out;
}

}  // namespace sw::zpeer
