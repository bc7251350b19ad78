// The z-buffer: triangles in window coordinates drawn in order, each covering the samples the fill
// family's half-space rule covers (triangle-edge, with its tie rule), with depth interpolated
// linearly on the screen as GL does (window z is z/w, linear in x and y), glPolygonOffset, an
// optional fixed-point depth buffer of 16 or 24 bits, and GL_LESS or GL_LEQUAL. Sample (i, j) is
// the point (i, j), GL's pixel centre (i + 1/2, j + 1/2) (docs/pipeline/semantics.md).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "pipeline/depth_plane.hpp"

namespace sw::pipe {

enum class DepthFunc : std::uint8_t { less, lequal };

template <class Num> struct DepthTriangle {
  std::array<Vec3<Num>, 3> v;  // window x, y and depth z in [0, 1]
  std::int64_t id = 0;
  Num factor{}, units{};  // glPolygonOffset
};

template <class Num> struct DepthBuffer {
  std::int64_t width = 0, height = 0;
  std::vector<Num> depth;          // row j at j * width; fixed point: integers in [0, 2^bits - 1]
  std::vector<std::int64_t> id;    // -1: no fragment passed
  std::int64_t fragments = 0, passed = 0, ties = 0;  // ties: a fragment's depth equal to the stored one
};

struct ZBuffer {
  static constexpr std::string_view id = "z-buffer";
  static constexpr std::string_view summary = "Z-buffer: triangle-edge coverage, screen-linear depth, polygon offset, 16/24-bit depth, less/lequal";
#define SW_LINES_Z_BUFFER(X) \
  X(clear, "depth[all] <- the clear depth (in fixed point: round(clear M), M = 2^bits - 1); id[all] <- none") \
  X(plane, "for each triangle t in order: z(x, y) <- the plane through its vertices (zx = dz/dx, zy = dz/dy)") \
  X(offset, "o <- factor max(|zx|, |zy|) + units r        -- glPolygonOffset; r = 1/M, or 2^-24 without bits") \
  X(cover, "S <- the samples of the window triangle-edge covers, with its tie rule") \
  X(fragment, "for each sample (i, j) of S: z <- z(i, j) + o, clamped to [0, 1]; d <- round(z M) in fixed point, else z") \
  X(test, "pass <- d < depth[i, j] (GL_LESS) or d <= depth[i, j] (GL_LEQUAL)") \
  X(write, "if pass: depth[i, j] <- d; id[i, j] <- t") \
  X(done, "done")
  SW_LISTING("Z-buffer", SW_LINES_Z_BUFFER)
#undef SW_LINES_Z_BUFFER
};

// bits: 0 (depth kept in the number type) or the fixed-point depth's bits (16 or 24).
template <NumberType Num, StepProbe Probe = NoProbe>
DepthBuffer<Num> z_buffer(std::int64_t width, std::int64_t height, const std::vector<DepthTriangle<Num>>& tris, int bits,
                          DepthFunc func, const Num& clear, Probe& probe) {
  using L = ZBuffer;
  const Num M = bits == 0 ? Num(1) : Num(std::int64_t(1) << bits) - Num(1);
  const Num r = bits == 0 ? Num(1) / Num(std::int64_t(1) << 24) : Num(1) / M;
  auto stored = [&](const Num& z) { return bits == 0 ? z : Num(num::floor_div(Num(z * M + Num(1) / Num(2)), Num(1))); };
  DepthBuffer<Num> buf{width, height, std::vector<Num>(width * height, stored(clear)), std::vector<std::int64_t>(width * height, -1)};
  if constexpr (Probe::on) probe.step(L::clear, StepKind::init).num("clear", buf.depth.empty() ? clear : buf.depth[0]).num("r", r);
  std::vector<Pixel> samples;
  for (const DepthTriangle<Num>& t : tris) {
    const DepthPlane<Num> plane = depth_plane(t.v);
    const Vec3<Num>&a = t.v[0], &b = t.v[1], &c = t.v[2];
    if (plane.area2 == Num(0)) {  // no sample is covered (triangle-edge's rule); no plane exists
      if constexpr (Probe::on) probe.step(L::plane, StepKind::miss).idx("t", t.id).num("area2", plane.area2);
      continue;
    }
    const Num &zx = plane.zx, &zy = plane.zy;
    if constexpr (Probe::on) {
      const std::array<Vec2<Num>, 3> corners{Vec2<Num>{a.x, a.y}, Vec2<Num>{b.x, b.y}, Vec2<Num>{c.x, c.y}};
      probe.step(L::plane, StepKind::init).idx("t", t.id).num("area2", plane.area2).num("zx", zx).num("zy", zy).geo_list(GeoKind::polygon, std::span(corners)).keep();
    }
    const Num o = polygon_offset(plane, t.factor, t.units, r);
    if constexpr (Probe::on) probe.step(L::offset, StepKind::advance).num("o", o);
    covered_samples(t.v, width, height, samples);
    if constexpr (Probe::on) probe.step(L::cover, StepKind::advance).idx("samples", std::int64_t(samples.size()));
    for (const Pixel& s : samples) {
      const Num z = std::clamp(Num(plane.at(Num(s.x), Num(s.y)) + o), Num(0), Num(1));
      const Num d = stored(z);
      Num& cell = buf.depth[s.y * width + s.x];
      ++buf.fragments;
      if constexpr (Probe::on) probe.step(L::fragment, StepKind::advance).idx("i", s.x).idx("j", s.y).num("z", z).num("d", d);
      const bool pass = func == DepthFunc::less ? d < cell : d <= cell;
      buf.ties += d == cell;
      if constexpr (Probe::on) probe.step(L::test, StepKind::decide).num("d", d).num("depth", cell).idx("pass", pass);
      if (!pass) continue;
      cell = d;
      buf.id[s.y * width + s.x] = t.id;
      ++buf.passed;
      if constexpr (Probe::on) probe.step(L::write, StepKind::plot).idx("id", t.id).pixel(s).value(Num(t.id)).keep();
    }
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("passed", buf.passed).idx("ties", buf.ties);
  return buf;
}

}  // namespace sw::pipe
