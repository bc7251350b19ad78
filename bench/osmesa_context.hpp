// One OSMesa context (Mesa's llvmpipe) with an RGBA buffer, 24-bit depth and 8-bit stencil, as the
// shadow family's peers draw into it. Link OSMesa, never libGL.
#pragma once
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace sw::peer {

// A 4 x 4 matrix as GL's column-major array.
template <class M> void load_matrix(const M& m) {
  float a[16];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) a[c * 4 + r] = float(m[std::size_t(r)][std::size_t(c)]);
  glLoadMatrixf(a);
}

class OsmesaContext {
 public:
  OsmesaContext(int width, int height) : w_(width), h_(height), buffer_(std::size_t(width) * std::size_t(height) * 4) {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    if (!ctx_) throw std::runtime_error("OSMesa could not create a context with depth and stencil");
    make_current();
    GLint depth = 0, stencil = 0;
    glGetIntegerv(GL_DEPTH_BITS, &depth);
    glGetIntegerv(GL_STENCIL_BITS, &stencil);
    if (depth != 24 || stencil != 8) throw std::runtime_error("OSMesa gave " + std::to_string(depth) + " depth and " + std::to_string(stencil) + " stencil bits");
  }
  ~OsmesaContext() {
    if (ctx_) OSMesaDestroyContext(ctx_);
  }
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;
  std::string renderer() {
    make_current();
    const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return s ? s : "?";
  }
  void make_current() {
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, w_, h_)) throw std::runtime_error("OSMesa could not make its context current");
  }
  int width() const { return w_; }

  // The eye's pass into the lower-left w x h pixels: every buffer cleared (colour 0, depth 1,
  // stencil 0), M as the projection, GL_LESS, each triangle's object id + 1 in red and green.
  template <class Matrix, class Triangles> void eye_pass(const Matrix& M, const Triangles& tris, int w, int h) {
    make_current();
    glViewport(0, 0, w, h);
    glDepthRange(0, 1);
    glDisable(GL_DITHER);
    glDisable(GL_BLEND);
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    glShadeModel(GL_FLAT);
    glMatrixMode(GL_PROJECTION);
    load_matrix(M);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDepthMask(GL_TRUE);  // glClear honours the masks a last pass left
    glColorMask(1, 1, 1, 1);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glBegin(GL_TRIANGLES);
    for (const auto& t : tris) {
      const int id = t.object + 1;
      glColor4ub(GLubyte(id & 255), GLubyte(id >> 8), 0, 255);
      for (const auto& x : t.x) glVertex4f(x.x, x.y, x.z, x.w);
    }
    glEnd();
  }
  // One byte per pixel of the lower-left w x h (GL_STENCIL_INDEX, GL_RED, ...), rows top down.
  std::vector<std::uint8_t> read_bytes(GLenum format, int w, int h) {
    glFinish();
    std::vector<std::uint8_t> gl(std::size_t(w) * std::size_t(h)), out(gl.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, format, GL_UNSIGNED_BYTE, gl.data());
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) out[std::size_t(h - 1 - j) * std::size_t(w) + std::size_t(i)] = gl[std::size_t(j) * std::size_t(w) + std::size_t(i)];
    return out;
  }
  // The eye pass's object ids (-1: nothing drawn), rows top down.
  std::vector<std::int32_t> object_ids(int w, int h) {
    const std::vector<std::uint8_t> r = read_bytes(GL_RED, w, h), g = read_bytes(GL_GREEN, w, h);
    std::vector<std::int32_t> out(r.size());
    for (std::size_t k = 0; k < r.size(); ++k) out[k] = std::int32_t(r[k]) + 256 * std::int32_t(g[k]) - 1;
    return out;
  }
  int height() const { return h_; }

 private:
  int w_, h_;
  OSMesaContext ctx_ = nullptr;
  std::vector<std::uint8_t> buffer_;
};

// A peer drawn through OSMesa (it has renderer()), or null when no context opens or the renderer
// is not llvmpipe.
template <class Peer, class... A> std::unique_ptr<Peer> llvmpipe_peer(A... args) {
  try {
    auto gl = std::make_unique<Peer>(args...);
    return gl->renderer().find("llvmpipe") != std::string::npos ? std::move(gl) : nullptr;
  } catch (const std::exception&) {
    return nullptr;
  }
}

}  // namespace sw::peer
