// The llvmpipe harness for the triangle fills (docs/fill/llvmpipe.md): triangles on llvmpipe's
// sub-pixel grid, its snap, where a sample touches a triangle, and an OSMesa context that renders
// triangles one cell each. The cases and the comparison: llvmpipe_peer.hpp. Link OSMesa, never libGL.
#pragma once
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>
#include "catalog.hpp"
#include "core/number.hpp"
#include "core/vec.hpp"
#include "fill_oracle.hpp"

namespace sw::peer {

// Vertex coordinates are integers over kDen (our coordinates: sample (i, j) is the point (i, j)).
constexpr std::int64_t kDen = 4096;
// llvmpipe's sub-pixel grid: FIXED_ORDER = 8 bits, so 1/256 of a pixel (kDen / kSnap numerators).
constexpr std::int64_t kSnap = kDen / 256;

struct Tri {
  std::array<std::array<std::int64_t, 2>, 3> v{};  // numerators over kDen
};

// Triangles drawn into one cell together: llvmpipe's count per pixel is compared with the sum of
// the oracle's indicators, so a fan or a shared edge also checks for double hits and gaps.
struct Group {
  std::vector<Tri> tris;
  std::string kind;
};

inline bool on_llvmpipe_grid(const Tri& t) {
  for (const auto& p : t.v)
    if (p[0] % kSnap != 0 || p[1] % kSnap != 0) return false;
  return true;
}

// llvmpipe's snap: round to nearest 1/256, ties to even (_mm_cvtps_epi32 in calc_fixed_position).
inline std::int64_t snap_numerator(std::int64_t n) {
  const std::int64_t q = n >= 0 ? n / kSnap : -((-n + kSnap - 1) / kSnap);  // floor
  const std::int64_t r = n - q * kSnap;
  std::int64_t k = q;
  if (2 * r > kSnap || (2 * r == kSnap && (q & 1) != 0)) k = q + 1;
  return k * kSnap;
}
inline Tri snapped(const Tri& t) {
  Tri s = t;
  for (auto& p : s.v) p = {snap_numerator(p[0]), snap_numerator(p[1])};
  return s;
}

inline std::vector<Pixel> oracle_samples(const Tri& t) {
  std::array<Vec2<Rational>, 3> r;
  for (int k = 0; k < 3; ++k) r[k] = {Rational(t.v[k][0], kDen), Rational(t.v[k][1], kDen)};
  for (auto& p : r) p.x.canonicalize(), p.y.canonicalize();
  return oracle::triangle_samples(r);
}

// Where an exact sample lies relative to a triangle's boundary (integer arithmetic, exact).
enum class Contact { none, other_edge, horizontal_edge, vertex };  // by priority
inline Contact contact(const Tri& t, Pixel s) {
  const std::int64_t px = s.x * kDen, py = s.y * kDen;
  for (const auto& v : t.v)
    if (v[0] == px && v[1] == py) return Contact::vertex;
  for (int k = 0; k < 3; ++k) {
    const auto& a = t.v[k];
    const auto& b = t.v[(k + 1) % 3];
    const __int128 cross = __int128(b[0] - a[0]) * (py - a[1]) - __int128(b[1] - a[1]) * (px - a[0]);
    const bool inside_box =
        std::min(a[0], b[0]) <= px && px <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= py && py <= std::max(a[1], b[1]);
    if (cross == 0 && inside_box && !(a == b)) return a[1] == b[1] ? Contact::horizontal_edge : Contact::other_edge;
  }
  return Contact::none;
}

constexpr int kFramebuffer = 1024;  // pixels a side, a power of two

// How cases are laid out in the buffer: square cells of `cell` pixels, the grid of cells moved by
// `shift` pixels. llvmpipe bins into 64 x 64 tiles at multiples of 64: cells of 64 with shift 0 keep
// each case inside one tile, shift 32 makes cases straddle tiles, cells of 256 hold multi-tile cases.
struct Layout {
  int cell = 64, shift = 0;
  int per_row() const { return (kFramebuffer - shift) / cell; }
  int max_extent() const { return cell - 4; }  // a group's bounding box, in samples
};

// An OSMesa (llvmpipe) context with a kFb x kFb RGBA buffer.
class Llvmpipe {
 public:
  static constexpr int kFb = kFramebuffer;

  Llvmpipe() : buffer_(std::size_t(kFb) * kFb * 4), read_(buffer_.size()) {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
    if (!ctx_) throw std::runtime_error("OSMesa could not create a context");
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, kFb, kFb))
      throw std::runtime_error("OSMesa could not make its context current");
    glViewport(0, 0, kFb, kFb);
    glDisable(GL_DITHER);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_MULTISAMPLE);
    glShadeModel(GL_FLAT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnableClientState(GL_VERTEX_ARRAY);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
  }
  ~Llvmpipe() {
    if (ctx_) OSMesaDestroyContext(ctx_);
  }
  Llvmpipe(const Llvmpipe&) = delete;
  Llvmpipe& operator=(const Llvmpipe&) = delete;

  std::string renderer() {
    const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return s ? s : "?";
  }

  // Window coordinate (x_w or y_w) -> NDC, exact in float: kFb is a power of two and x_w has at
  // most 10 integer and 12 fraction bits. The viewport maps it back exactly (scale = offset = kFb/2).
  static float ndc(double window) { return float((window - kFb / 2) / (kFb / 2)); }

  // Per group: llvmpipe's covered samples in our coordinates, with their counts (blended +1 each).
  // mirror_y: draw the triangle mirrored (x, -y) and mirror the samples back.
  std::vector<std::map<Pixel, int>> cover(const std::vector<Group>& groups, bool mirror_y, Layout layout = {}) {
    make_current();
    std::vector<std::map<Pixel, int>> out;
    out.reserve(groups.size());
    const int per_row = layout.per_row(), cell = layout.cell;
    const std::size_t cells = std::size_t(per_row) * std::size_t(per_row);
    for (std::size_t first = 0; first < groups.size(); first += cells) {
      const std::size_t n = std::min(cells, groups.size() - first);
      std::vector<float> verts;
      std::vector<std::array<std::int64_t, 2>> offsets(n);
      for (std::size_t g = 0; g < n; ++g) {
        const Group& group = groups[first + g];
        std::int64_t min_x = INT64_MAX, min_y = INT64_MAX, max_x = INT64_MIN, max_y = INT64_MIN;
        for (const Tri& t : group.tris)
          for (const auto& p : t.v) {
            const std::int64_t y = mirror_y ? -p[1] : p[1];
            min_x = std::min(min_x, p[0]), max_x = std::max(max_x, p[0]);
            min_y = std::min(min_y, y), max_y = std::max(max_y, y);
          }
        const std::int64_t fx = floor_div(min_x), fy = floor_div(min_y);
        if (floor_div(max_x) - fx > layout.max_extent() || floor_div(max_y) - fy > layout.max_extent())
          throw std::runtime_error("llvmpipe peer: a group does not fit its cell");
        // Sample (i, j) -> GL pixel (i + ox, j + oy), whose centre is window (i + ox + 1/2, j + oy + 1/2).
        const std::int64_t ox = std::int64_t(g % std::size_t(per_row)) * cell + layout.shift + 2 - fx;
        const std::int64_t oy = std::int64_t(g / std::size_t(per_row)) * cell + layout.shift + 2 - fy;
        offsets[g] = {ox, oy};
        for (const Tri& t : group.tris)
          for (const auto& p : t.v) {
            const std::int64_t y = mirror_y ? -p[1] : p[1];
            verts.push_back(ndc(double(p[0] + ox * kDen) / kDen + 0.5));
            verts.push_back(ndc(double(y + oy * kDen) / kDen + 0.5));
          }
      }
      glClearColor(0, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT);
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);
      glColor4ub(1, 0, 0, 0);
      glVertexPointer(2, GL_FLOAT, 0, verts.data());
      glDrawArrays(GL_TRIANGLES, 0, GLsizei(verts.size() / 2));
      glFinish();
      glReadPixels(0, 0, kFb, kFb, GL_RGBA, GL_UNSIGNED_BYTE, read_.data());  // row 0 = bottom (GL y up)
      for (std::size_t g = 0; g < n; ++g) {
        std::map<Pixel, int> counts;
        const int cx = int(g % std::size_t(per_row)) * cell + layout.shift,
                  cy = int(g / std::size_t(per_row)) * cell + layout.shift;
        for (int y = cy; y < cy + cell; ++y)
          for (int x = cx; x < cx + cell; ++x) {
            const int c = read_[(std::size_t(y) * kFb + x) * 4];
            if (c == 0) continue;
            const std::int64_t j = y - offsets[g][1];
            counts[Pixel{x - offsets[g][0], mirror_y ? -j : j}] = c;
          }
        out.push_back(std::move(counts));
      }
    }
    return out;
  }

  // Draws the triangles (NDC, 2 floats a vertex) in one call, repeats times, with glFinish after
  // each: returns the best seconds per repeat. No blending: a plain colour write.
  double time_draw(const std::vector<float>& ndc_verts, int repeats) {
    make_current();
    glDisable(GL_BLEND);
    glColor4ub(200, 120, 40, 255);
    glVertexPointer(2, GL_FLOAT, 0, ndc_verts.data());
    double best = 1e30;
    for (int r = 0; r < repeats; ++r) {
      glClear(GL_COLOR_BUFFER_BIT);
      glFinish();
      const auto t0 = std::chrono::steady_clock::now();
      glDrawArrays(GL_TRIANGLES, 0, GLsizei(ndc_verts.size() / 2));
      glFinish();
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
  }

 private:
  // Another OSMesa context (the visualizer tests' host) may have been made current meanwhile.
  void make_current() {
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, kFb, kFb))
      throw std::runtime_error("OSMesa could not make its context current");
  }
  static std::int64_t floor_div(std::int64_t n) { return n >= 0 ? n / kDen : -((-n + kDen - 1) / kDen); }
  OSMesaContext ctx_ = nullptr;
  std::vector<std::uint8_t> buffer_, read_;
};

}  // namespace sw::peer
