// The z-buffer's llvmpipe peer (docs/pipeline/llvmpipe.md): an OSMesa context with a 16- or 24-bit
// depth buffer that draws each case into its own 64 x 64 cell of a 1024^2 buffer and reads back ids
// (colour) and depth; and llvmpipe's depth arithmetic written out in float (lp_state_setup.c,
// lp_bld_interp.c, lp_bld_conv.c), which reproduces its depth buffer bit for bit. OSMesa only, never libGL.
#pragma once
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include "zbuffer_peer_cases.hpp"

namespace sw::zpeer {

constexpr int kFb = 1024, kCell = 64, kMargin = 2, kCells = (kFb / kCell) * (kFb / kCell);

// Case c of a draw sits in cell c: sample (i, j) is GL pixel (ox + i, oy + j), centre (ox + i + 1/2, ...).
inline std::array<int, 2> cell_origin(std::size_t c) {
  return {int(c % (kFb / kCell)) * kCell + kMargin, int(c / (kFb / kCell)) * kCell + kMargin};
}
// Window -> NDC, exact in float: kFb is a power of two and a window x has at most 10 + 9 bits.
inline float ndc_xy(double window) { return float((window - kFb / 2) / (kFb / 2)); }
// z on the 2^-24 grid: 2z - 1 is exact in float, and the viewport's z / 2 + 1/2 gives z back exactly.
inline float ndc_z(std::int64_t z) { return float(double(2 * z - kZ) / kZ); }

struct LpImage {
  std::vector<std::int64_t> ids;     // kWin^2, row j at j * kWin; -1: none
  std::vector<std::uint32_t> depth;  // the stored integers, 0 .. 2^bits - 1
  std::vector<int> covers;           // how many of the case's triangles cover each sample (depth off)
};

class ZLlvmpipe {
 public:
  explicit ZLlvmpipe(int bits) : bits_(bits), buffer_(std::size_t(kFb) * kFb * 4) {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, bits, 0, 0, nullptr);
    if (!ctx_) throw std::runtime_error("OSMesa could not create a context with a depth buffer");
    make_current();
    GLint got = 0;
    glGetIntegerv(GL_DEPTH_BITS, &got);
    if (got != bits) throw std::runtime_error("OSMesa gave " + std::to_string(got) + " depth bits, not " + std::to_string(bits));
    glViewport(0, 0, kFb, kFb);
    glDepthRange(0, 1);
    glDisable(GL_DITHER);
    glDisable(GL_CULL_FACE);
    glDisable(GL_MULTISAMPLE);
    glShadeModel(GL_FLAT);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
  }
  ~ZLlvmpipe() {
    if (ctx_) OSMesaDestroyContext(ctx_);
  }
  ZLlvmpipe(const ZLlvmpipe&) = delete;
  ZLlvmpipe& operator=(const ZLlvmpipe&) = delete;
  int bits() const { return bits_; }
  std::string renderer() {
    make_current();
    const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return s ? s : "?";
  }

  // Draws up to kCells cases of one configuration (this buffer's bits), case c in cell c: first
  // every triangle with the depth test off and additive blending (coverage counts), then in order
  // with the depth test, triangle k of every cell in one glDrawArrays per glPolygonOffset.
  std::vector<LpImage> render(const std::vector<ZCase>& cases) {
    if (cases.size() > std::size_t(kCells)) throw std::runtime_error("z-buffer peer: too many cases for one draw");
    make_current();
    const ZConfig cfg = cases.empty() ? ZConfig{} : cases[0].cfg;
    const std::size_t n = std::size_t(kWin * kWin);
    std::vector<LpImage> out(cases.size(),
                             LpImage{std::vector<std::int64_t>(n, -1), std::vector<std::uint32_t>(n), std::vector<int>(n)});
    std::size_t rounds = 0;
    for (const ZCase& c : cases) {
      if (c.cfg != cfg || c.cfg.bits != bits_) throw std::runtime_error("z-buffer peer: one draw, one configuration");
      rounds = std::max(rounds, c.tris.size());
    }
    // Coverage: the red byte counts the triangles over each pixel.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glDisableClientState(GL_COLOR_ARRAY);
    glColor4ub(1, 0, 0, 0);
    std::vector<float> pos;
    std::vector<std::uint8_t> col;
    for (std::size_t c = 0; c < cases.size(); ++c)
      for (const ZTri& t : cases[c].tris) push(t, cell_origin(c), 0, pos, col);
    draw(pos);
    read(cases.size(), [&](std::size_t c, std::size_t s, const std::uint8_t* px, std::uint32_t) { out[c].covers[s] = px[0]; });
    // The depth test: colour (id + 1) in red and green.
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(cfg.lequal ? GL_LEQUAL : GL_LESS);
    glClearDepth(double(cfg.clear) / kZ);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnableClientState(GL_COLOR_ARRAY);
    for (std::size_t k = 0; k < rounds; ++k) {
      std::map<std::array<std::int64_t, 2>, std::pair<std::vector<float>, std::vector<std::uint8_t>>> by_offset;
      for (std::size_t c = 0; c < cases.size(); ++c)
        if (k < cases[c].tris.size()) {
          const ZTri& t = cases[c].tris[k];
          auto& [p, q] = by_offset[{t.factor, t.units}];
          push(t, cell_origin(c), std::int64_t(k) + 1, p, q);
        }
      for (auto& [off, pq] : by_offset) {
        if (off[0] != 0 || off[1] != 0) glEnable(GL_POLYGON_OFFSET_FILL), glPolygonOffset(float(off[0]), float(off[1]));
        else glDisable(GL_POLYGON_OFFSET_FILL);
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, pq.second.data());
        draw(pq.first);
      }
    }
    glDisableClientState(GL_COLOR_ARRAY);
    read(cases.size(), [&](std::size_t c, std::size_t s, const std::uint8_t* px, std::uint32_t d) {
      out[c].ids[s] = std::int64_t(px[0]) + 256 * std::int64_t(px[1]) - 1;
      out[c].depth[s] = d >> (32 - bits_);  // GL_UNSIGNED_INT scales the stored integer to 32 bits
    });
    return out;
  }

  // Draws the triangles (NDC x, y, z) in one call with the depth test (GL_LESS) and a flat colour,
  // then glFinish: the best seconds of `repeats`, each after a clear outside the timing.
  double time_draw(const std::vector<float>& ndc_xyz, int repeats) {
    make_current();
    glDisable(GL_BLEND);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisableClientState(GL_COLOR_ARRAY);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearDepth(1);
    glColor4ub(200, 120, 40, 255);
    glVertexPointer(3, GL_FLOAT, 0, ndc_xyz.data());
    double best = 1e30;
    for (int r = 0; r < repeats; ++r) {
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glFinish();
      const auto t0 = std::chrono::steady_clock::now();
      glDrawArrays(GL_TRIANGLES, 0, GLsizei(ndc_xyz.size() / 3));
      glFinish();
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
  }

 private:
  static void push(const ZTri& t, std::array<int, 2> o, std::int64_t colour, std::vector<float>& pos,
                   std::vector<std::uint8_t>& col) {
    for (const auto& p : t.v) {
      pos.push_back(ndc_xy(o[0] + double(p[0]) / kXY + 0.5));
      pos.push_back(ndc_xy(o[1] + double(p[1]) / kXY + 0.5));
      pos.push_back(ndc_z(p[2]));
      col.insert(col.end(), {std::uint8_t(colour & 255), std::uint8_t(colour >> 8), 0, 255});
    }
  }
  static void draw(const std::vector<float>& pos) {
    glVertexPointer(3, GL_FLOAT, 0, pos.data());
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(pos.size() / 3));
  }
  // Reads colour and depth back (row 0 at the bottom: GL's y up) and hands each case's samples over.
  template <class F> void read(std::size_t cases, F&& each) {
    glFinish();
    std::vector<std::uint8_t> rgba(std::size_t(kFb) * kFb * 4);
    std::vector<std::uint32_t> depth(std::size_t(kFb) * kFb);
    glReadPixels(0, 0, kFb, kFb, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glReadPixels(0, 0, kFb, kFb, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth.data());
    for (std::size_t c = 0; c < cases; ++c) {
      const auto o = cell_origin(c);
      for (std::int64_t j = 0; j < kWin; ++j)
        for (std::int64_t i = 0; i < kWin; ++i) {
          const std::size_t at = std::size_t(o[1] + j) * kFb + std::size_t(o[0] + i);
          each(c, std::size_t(j * kWin + i), &rgba[at * 4], depth[at]);
        }
    }
  }
  void make_current() {
    // Another OSMesa context (the other depth, the fill peer, the visualizer's tests) may be current.
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, kFb, kFb))
      throw std::runtime_error("OSMesa could not make its context current");
  }
  int bits_;
  OSMesaContext ctx_ = nullptr;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace sw::zpeer
