// shadow-map's llvmpipe peer (docs/shadows/llvmpipe.md): Mesa's llvmpipe through OSMesa draws each
// of the light's views into its 24-bit depth buffer (GL_LESS), copies it into a depth texture
// (GL_TEXTURE_COMPARE_MODE = GL_COMPARE_REF_TO_TEXTURE, GL_LEQUAL, GL_NEAREST), then draws the eye's
// pass and, with GL_EQUAL on the eye's depth, the lookup: each triangle's texture coordinates are
// the view's matrix times its corners, (x + w, y + w, z + w) / 2 and w, the reference moved by
// the bias and the slope times the triangle's own depth slope in the view's window (the offset
// shaders put on the reference, as ours does). PCF's taps are one draw each, the coordinates
// moved by whole texels. Every pixel a view holds is compared with our exact lookup, each
// difference classified by the exact oracle. OSMesa only, never libGL.
#pragma once
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>
#include "osmesa_context.hpp"
#include "shadows/shadow_map_input.hpp"

namespace sw::mappeer {

// What llvmpipe made of one input: its eye ids and, per view, its light-pass depths (24-bit
// integers, rows bottom up as our maps) and per tap (k x k, row-major from (-h, -h)) its
// verdict at every pixel (rows top down).
struct LpLookup {
  std::vector<std::int32_t> objects;
  std::vector<std::vector<std::uint32_t>> depth;
  std::vector<std::vector<std::vector<std::uint8_t>>> lit;  // [view][tap][pixel]
};

class MapLlvmpipe {
 public:
  MapLlvmpipe(int width, int height, int map) : gl_(std::max(width, map), std::max(height, map)) {}
  std::string renderer() { return gl_.renderer(); }

  // views: each view's matrix; slopes[v][t]: triangle t's depth slope in view v's window.
  LpLookup draw(const pipe::Mat4<double>& eye, const std::vector<pipe::Mat4<double>>& views, const std::vector<pipe::RasterTriangle<float>>& tris,
                const std::vector<std::vector<double>>& slopes, int w, int h, int size, double bias, double slope, int pcf) {
    LpLookup out;
    std::vector<GLuint> tex(views.size());
    gl_.make_current();
    glGenTextures(GLsizei(tex.size()), tex.data());
    for (std::size_t v = 0; v < views.size(); ++v) {
      gl_.eye_pass(views[v], tris, size, size);  // load_matrix rounds to float
      std::vector<std::uint32_t> z(std::size_t(size) * std::size_t(size));
      glFinish();
      glReadPixels(0, 0, size, size, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, z.data());
      for (auto& d : z) d >>= 8;  // GL's 32-bit depth: the 24-bit integer stored, shifted left (docs/pipeline/llvmpipe.md)
      out.depth.push_back(std::move(z));
      glBindTexture(GL_TEXTURE_2D, tex[v]);
      glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 0, 0, size, size, 0);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);  // GL 3's GL_COMPARE_REF_TO_TEXTURE
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
      glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    }
    gl_.eye_pass(eye, tris, w, h);
    out.objects = gl_.object_ids(w, h);
    // The lookups: the eye's depths kept, colour the texture's verdict (white: lit).
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_EQUAL);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    const int half = pcf / 2;
    for (std::size_t v = 0; v < views.size(); ++v) {
      glBindTexture(GL_TEXTURE_2D, tex[v]);
      out.lit.emplace_back();
      for (int b = -half; b <= half; ++b)
        for (int a = -half; a <= half; ++a) {
          glClear(GL_COLOR_BUFFER_BIT);
          glBegin(GL_TRIANGLES);
          for (std::size_t t = 0; t < tris.size(); ++t) {
            const double offset = bias + slope * slopes[v][t];
            for (const auto& x : tris[t].x) {
              const pipe::Vec4<double> c = pipe::apply(views[v], pipe::Vec4<double>{x.x, x.y, x.z, x.w});
              glTexCoord4d((c.x + c.w) / 2 + a * c.w / size, (c.y + c.w) / 2 + b * c.w / size, (c.z + c.w) / 2 - offset * c.w, c.w);
              glVertex4f(x.x, x.y, x.z, x.w);
            }
          }
          glEnd();
          out.lit.back().push_back(gl_.read_bytes(GL_RED, w, h));
        }
    }
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(GLsizei(tex.size()), tex.data());
    return out;
  }

 private:
  peer::OsmesaContext gl_;
};

// A triangle's depth slope in the window of the view with matrix M (size x size), from a point of
// it the view has in front (w > 0): a corner, or a finite corner moved along the others; 0 when no
// such point is found (the view then draws none of it).
inline double triangle_slope(const pipe::Mat4<double>& M, std::int64_t size, const pipe::RasterTriangle<float>& t) {
  std::vector<Vec3<double>> finite, dirs;
  for (const auto& x : t.x) {
    if (x.w != 0) finite.push_back({x.x / x.w, x.y / x.w, x.z / x.w});
    else dirs.push_back({x.x, x.y, x.z});  // a point at infinity: a direction along the plane
  }
  if (finite.empty()) return 0;
  const Vec3<double> P = finite[0];
  for (std::size_t k = 1; k < finite.size(); ++k) dirs.push_back(finite[k] - P);
  if (dirs.size() < 2) return 0;
  for (const double reach : {0.0, 0.25, 1.0, 16.0, 1024.0}) {
    const Vec3<double> Q = P + (reach / 2) * (dirs[0] + dirs[1]);
    if (pipe::apply(M, pipe::Vec4<double>{Q.x, Q.y, Q.z, 1.0}).w > 1e-9) return shadow::window_slope<double>(M, size, size, {Q, dirs[0], dirs[1]});
  }
  return 0;
}

// llvmpipe against our exact lookup on one input, at every pixel whose point a view holds. Each
// difference of the own-texel verdict is classified: eye, llvmpipe's eye pass shows another
// object; map, its light pass stored another depth at the texel; tie, the reference lies within
// 2^-20 of the stored depth (llvmpipe interpolates it in float); texel, the point lies within
// 2^-8 of a texel's edge (float may pick the neighbour); other, none of these.
// right: of the differences, those where llvmpipe's verdict is exact visibility. A differing
// PCF fraction is classified alike over its taps: eye, map (a tap's texel), tie (a tap's), other.
struct Comparison {
  std::int64_t pixels = 0, differ = 0, eye = 0, map = 0, tie = 0, texel = 0, other = 0, llvmpipe_right = 0;
  std::int64_t acne = 0, peter_panning = 0;         // llvmpipe's, against exact visibility, facing points
  std::int64_t our_acne = 0, our_peter_panning = 0;  // ours (exact mode), likewise
  std::int64_t pcf_pixels = 0, pcf_differ = 0;       // PCF fractions compared (all taps on the map), and differing
  std::int64_t pcf_eye = 0, pcf_map = 0, pcf_tie = 0, pcf_other = 0;
  void add(const Comparison& o) {
    pixels += o.pixels, differ += o.differ, eye += o.eye, map += o.map, tie += o.tie, texel += o.texel, other += o.other;
    llvmpipe_right += o.llvmpipe_right, acne += o.acne, peter_panning += o.peter_panning, our_acne += o.our_acne;
    our_peter_panning += o.our_peter_panning, pcf_pixels += o.pcf_pixels, pcf_differ += o.pcf_differ;
    pcf_eye += o.pcf_eye, pcf_map += o.pcf_map, pcf_tie += o.pcf_tie, pcf_other += o.pcf_other;
  }
};

inline Comparison compare(MapLlvmpipe& gl, const shadowspec::MapInput& in) {
  const auto& s = *in.scene;
  const auto& o = in.options;
  if (o.bits != 24) throw std::invalid_argument("the llvmpipe peer compares 24-bit maps only");
  NoProbe none;
  std::vector<pipe::RasterCamera<Rational>> views = in.views.views;
  const auto exact = shadow::shadow_map(views, in.views.cube, in.views.position, s.tris, shadowspec::map_points<Rational>(in), shadowspec::map_params<Rational>(o), none);
  const pipespec::RasterPixels eye = pipespec::raster_pixels(s, pipe::scene_raster<Rational>(s.camera, s.tris, none));
  const std::vector<pipe::RasterTriangle<float>> tris = pipespec::triangles_in<float>(s.tris);
  auto doubled = [](const pipe::Mat4<Rational>& q) {
    pipe::Mat4<double> d;
    for (std::size_t r = 0; r < 4; ++r)
      for (std::size_t c = 0; c < 4; ++c) d[r][c] = q[r][c].get_d();
    return d;
  };
  std::vector<pipe::Mat4<Rational>> Mq;
  std::vector<pipe::Mat4<double>> M;
  std::vector<std::vector<double>> slopes;
  for (const auto& v : views) {
    Mq.push_back(pipe::raster_matrix(v)), M.push_back(doubled(Mq.back()));
    slopes.emplace_back();
    for (const auto& t : tris) slopes.back().push_back(triangle_slope(M.back(), o.size, t));
  }
  const pipe::Mat4<double> E = doubled(pipe::raster_matrix(s.camera));
  const int size = int(o.size), k = o.pcf, half = k / 2;
  const LpLookup lp = gl.draw(E, M, tris, slopes, int(s.width), int(s.height), size, o.bias.get_d(), o.slope.get_d(), k);
  // Our exact maps, 24-bit integers, rows bottom up: the light's pass the lookup above made.
  std::vector<std::vector<Rational>> ours;
  for (const auto& v : views) ours.push_back(pipe::scene_raster<Rational>(v, s.tris, none, pipe::DepthSettings<Rational>{0, 0, 24}).buffer.depth);
  const Rational scale = Rational((mpz_class(1) << 24) - 1), near_tie = Rational(1, 1 << 20);
  auto texel_differs = [&](std::size_t v, std::size_t at) { return Rational(std::int64_t(lp.depth[v][at])) != ours[v][at]; };
  Comparison c;
  for (std::size_t p = 0; p < in.points.size(); ++p) {
    const auto& r = exact[p];
    if (r.outside) continue;
    const std::size_t px = in.points[p].pixel, v = std::size_t(r.view);
    const std::size_t centre = std::size_t(half * k + half);
    const bool lp_lit = lp.lit[v][centre][px] > 127, reach = in.reaches[p];
    ++c.pixels;
    if (in.faces[p]) c.acne += reach && !lp_lit, c.peter_panning += !reach && lp_lit, c.our_acne += reach && !r.lit, c.our_peter_panning += !reach && r.lit;
    if (r.i >= half && r.j >= half && r.i + half < size && r.j + half < size) {
      std::int64_t pass = 0;
      for (std::size_t tap = 0; tap < std::size_t(k * k); ++tap) pass += lp.lit[v][tap][px] > 127;
      ++c.pcf_pixels;
      if (Rational(pass) / Rational(k * k) != r.fraction) {
        ++c.pcf_differ;
        bool map = false, tie = false;
        for (std::int64_t b = r.j - half; b <= r.j + half; ++b)
          for (std::int64_t a = r.i - half; a <= r.i + half; ++a) {
            const std::size_t at = std::size_t(b * size + a);
            map = map || texel_differs(v, at), tie = tie || abs(r.ref - ours[v][at] / scale) <= near_tie;
          }
        if (lp.objects[px] != eye.objects[px]) ++c.pcf_eye;
        else if (map) ++c.pcf_map;
        else if (tie) ++c.pcf_tie;
        else ++c.pcf_other;
      }
    }
    if (lp_lit == r.lit) continue;
    ++c.differ, c.llvmpipe_right += lp_lit == reach;
    const std::size_t texel = std::size_t(r.j * size + r.i);
    const Vec3<Rational>& P = in.points[p].p;
    const pipe::Vec4<Rational> h = pipe::apply(Mq[v], pipe::Vec4<Rational>{P.x, P.y, P.z, Rational(1)});
    auto off_edge = [&](const Rational& ndc) {  // the distance of (ndc + 1) size / 2 from a whole number
      const Rational u = (ndc + 1) * size / 2;
      const Rational f = u - Rational(num::floor_int(u));
      return std::min(f, Rational(1) - f);
    };
    if (lp.objects[px] != eye.objects[px]) ++c.eye;
    else if (texel_differs(v, texel)) ++c.map;
    else if (abs(r.ref - r.stored) <= near_tie) ++c.tie;
    else if (std::min(off_edge(h.x / h.w), off_edge(h.y / h.w)) <= Rational(1, 256)) ++c.texel;
    else ++c.other;
  }
  return c;
}

}  // namespace sw::mappeer
