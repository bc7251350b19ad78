// shadow-volume's llvmpipe peer (docs/shadows/llvmpipe.md): Mesa's llvmpipe through OSMesa draws the
// eye's pass (24-bit depth, each object's id as its colour) and then the volumes' faces shadow-volume
// made, into an 8-bit stencil with GL_INCR_WRAP / GL_DECR_WRAP, by z-pass or z-fail, with the eye's
// matrix as GL's projection and points at infinity as w = 0. Every pixel whose point the eye sees
// is compared with our exact counts and with exact visibility. OSMesa only, never libGL.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>
#include "osmesa_context.hpp"
#include "shadows/shadow_volume_input.hpp"

namespace sw::volpeer {

struct LpStencil {
  std::vector<std::int32_t> objects;  // rows top down, as VolumePixels; -1: nothing drawn
  std::vector<std::uint8_t> stencil;
};

class VolumeLlvmpipe {
 public:
  VolumeLlvmpipe(int width, int height) : gl_(width, height) {}
  std::string renderer() { return gl_.renderer(); }

  // The eye's pass of the scene's triangles, then the faces' stencil counts by z-fail or z-pass.
  LpStencil draw(const pipe::Mat4<float>& M, const std::vector<pipe::RasterTriangle<float>>& tris,
                 const std::vector<shadow::VolumeFace<float>>& faces, bool zfail) {
    const int w = gl_.width(), h = gl_.height();
    gl_.eye_pass(M, tris, w, h);
    // The volumes: no depth or colour writes, the stencil counting by facing.
    glDepthMask(GL_FALSE);
    glColorMask(0, 0, 0, 0);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glEnable(GL_CULL_FACE);
    for (const bool flipped : {false, true}) {
      glFrontFace(flipped ? GL_CW : GL_CCW);  // a turned near cap counts the other way, its corners unchanged
      for (const bool fronts : {true, false}) {
        glCullFace(fronts ? GL_BACK : GL_FRONT);
        const GLenum up = fronts ? GL_INCR_WRAP : GL_DECR_WRAP, down = fronts ? GL_DECR_WRAP : GL_INCR_WRAP;
        if (zfail) glStencilOp(GL_KEEP, down, GL_KEEP);
        else glStencilOp(GL_KEEP, GL_KEEP, up);
        glBegin(GL_TRIANGLES);
        for (const auto& f : faces)
          if (f.flip == flipped)
            for (const auto& x : f.x) glVertex4f(x.x, x.y, x.z, x.w);
        glEnd();
      }
    }
    glFrontFace(GL_CCW);
    return {gl_.object_ids(w, h), gl_.read_bytes(GL_STENCIL_INDEX, w, h)};
  }

 private:
  peer::OsmesaContext gl_;
};

// llvmpipe against the exact counts on one input, every pixel a point is seen at: how many differ,
// and why by the exact oracle. eye: llvmpipe shows another object there (its eye pass differs);
// away: the point faces away from the light (a shadow changes nothing); llvmpipe_wrong: our exact
// count is exact visibility and llvmpipe's is not; ours_wrong: the reverse (never, for z-fail).
struct Comparison {
  std::int64_t pixels = 0, differ = 0, eye = 0, away = 0, llvmpipe_wrong = 0, ours_wrong = 0, counts_differ = 0;
  std::int64_t float_wrong = 0;     // our float mode's verdict against exact visibility, facing points
  std::int64_t llvmpipe_exact = 0;  // llvmpipe's verdict against exact visibility, facing points
  void add(const Comparison& o) {
    llvmpipe_exact += o.llvmpipe_exact;
    pixels += o.pixels, differ += o.differ, eye += o.eye, away += o.away, llvmpipe_wrong += o.llvmpipe_wrong, ours_wrong += o.ours_wrong;
    counts_differ += o.counts_differ, float_wrong += o.float_wrong;
  }
};

inline Comparison compare(VolumeLlvmpipe& gl, const shadowspec::VolumeInput& in) {
  const auto& s = *in.seen->scene;
  NoProbe none;
  const auto exact = shadow::shadow_volume<Rational>(s.camera, s.tris, in.mesh, in.light, in.zfail, none);
  const shadowspec::VolumePixels ours = shadowspec::stencil_pixels(in, exact), fl = shadowspec::stenciled(in, Numeric::f32);
  const pipespec::RasterPixels eye = pipespec::raster_pixels(s, pipe::scene_raster<Rational>(s.camera, s.tris, none));
  std::vector<shadow::VolumeFace<float>> faces;
  for (const auto& f : exact.faces_drawn) {
    shadow::VolumeFace<float> g{{}, f.flip};
    for (int k = 0; k < 3; ++k) {
      const auto& x = f.x[std::size_t(k)];
      g.x[std::size_t(k)] = {float(x.x.get_d()), float(x.y.get_d()), float(x.z.get_d()), float(x.w.get_d())};
    }
    faces.push_back(g);
  }
  const pipe::Mat4<Rational> Mq = pipe::raster_matrix(s.camera);
  pipe::Mat4<float> M;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) M[std::size_t(r)][std::size_t(c)] = float(Mq[std::size_t(r)][std::size_t(c)].get_d());
  const LpStencil lp = gl.draw(M, pipespec::triangles_in<float>(s.tris), faces, in.zfail);
  Comparison c;
  const auto& m = *in.seen;
  for (std::size_t k = 0; k < m.points.size(); ++k) {
    const std::size_t px = m.points[k].pixel;
    ++c.pixels;
    const std::int64_t count = in.zfail ? ours.zfail[px] : ours.zpass[px];
    c.counts_differ += std::uint8_t(count) != lp.stencil[px];  // the 8-bit stencil wraps
    const bool lp_lit = lp.stencil[px] == 0, our_lit = ours.lit[px] == 1, reach = m.reaches[k];
    if (m.faces[k]) c.float_wrong += (fl.lit[px] == 1) != reach, c.llvmpipe_exact += lp_lit != reach;
    if (lp_lit == our_lit) continue;
    ++c.differ;
    if (lp.objects[px] != eye.objects[px]) ++c.eye;
    else if (!m.faces[k]) ++c.away;
    else if (our_lit == reach) ++c.llvmpipe_wrong;
    else ++c.ours_wrong;
  }
  return c;
}

}  // namespace sw::volpeer
