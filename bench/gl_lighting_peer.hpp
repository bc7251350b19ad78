// OpenGL fixed-function lighting in Mesa (through OSMesa) as shade's peer, shared by
// bench/peer_gl_lighting.cpp and tests/lighting/test_shade_gl.cpp: each scene's point is drawn as
// one GL_POINTS vertex in feedback mode (GL_3D_COLOR returns the lit vertex colour) with the same
// lights and material in eye coordinates (modelview identity; the projection maps every vertex to
// the origin of clip space so nothing is clipped; GL_NORMALIZE on), and vertex colour clamping off
// (glClampColor(GL_CLAMP_VERTEX_COLOR, GL_FALSE)) when Mesa allows it, so that colours compare
// before clamping. Link OSMesa, never libGL. Results: docs/lighting/shade.md.
#pragma once
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <algorithm>
#include <cstdlib>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>
#include "lighting/shade_common.hpp"
#include "lighting/shade_input.hpp"
#include "lighting/shade_oracle_case.hpp"

namespace sw::peer {

using lighting::ShadeScene;

class GlLighting {
 public:
  // llvm false: DRAW_USE_LLVM=0, Mesa's draw module interprets the same fixed-function vertex
  // program instead of compiling it with LLVM per state key (about 25 ms a compile; the fast test
  // uses it). Read once per process by Mesa: set before the first context.
  explicit GlLighting(bool llvm = true) : pixels_(4 * 4 * 4) {
    if (!llvm) setenv("DRAW_USE_LLVM", "0", 1);
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!ctx_) throw std::runtime_error("OSMesa could not create a context");
    if (!OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, 4, 4)) throw std::runtime_error("OSMesa could not make its context current");
    using ClampFn = void (*)(GLenum, GLenum);
    auto clamp = reinterpret_cast<ClampFn>(OSMesaGetProcAddress("glClampColor"));
    if (!clamp) clamp = reinterpret_cast<ClampFn>(OSMesaGetProcAddress("glClampColorARB"));
    if (clamp) {
      clamp(GL_CLAMP_VERTEX_COLOR, GL_FALSE);
      unclamped_ = glGetError() == GL_NO_ERROR;
    }
    renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    version_ = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  }
  ~GlLighting() { OSMesaDestroyContext(ctx_); }
  GlLighting(const GlLighting&) = delete;
  GlLighting& operator=(const GlLighting&) = delete;

  bool unclamped() const { return unclamped_; }
  const std::string& renderer() const { return renderer_; }
  const std::string& version() const { return version_; }

  // The lit colour of the scene's point (GL convention; every value a float), or NaN if Mesa
  // returned no vertex.
  std::array<float, 3> light(const ShadeScene<Rational>& s) {
    auto f3 = [](const Vec3<Rational>& v, float w) { return std::array<float, 4>{float(v.x.get_d()), float(v.y.get_d()), float(v.z.get_d()), w}; };
    glMatrixMode(GL_PROJECTION);
    const GLfloat to_origin[16] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
    glLoadMatrixf(to_origin);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_LIGHTING);
    glEnable(GL_NORMALIZE);
    glDisable(GL_COLOR_MATERIAL);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, f3(s.scene_ambient, 1).data());
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, s.eye_at_infinity ? GL_FALSE : GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
    const auto& m = s.material;
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, f3(m.emission, 1).data());
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, f3(m.ka, 1).data());
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, f3(m.kd, 1).data());
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, f3(m.ks, 1).data());
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, float(m.params.shininess.get_d()));
    for (int i = 0; i < 8; ++i) glDisable(GLenum(GL_LIGHT0 + i));
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
      const auto& l = s.lights[i];
      const GLenum id = GLenum(GL_LIGHT0 + int(i));
      glEnable(id);
      const bool directional = l.type == lighting::LightType::directional;
      glLightfv(id, GL_POSITION, f3(l.where, directional ? 0.f : 1.f).data());
      glLightfv(id, GL_AMBIENT, f3(l.ambient, 1).data());
      glLightfv(id, GL_DIFFUSE, f3(l.diffuse, 1).data());
      glLightfv(id, GL_SPECULAR, f3(l.specular, 1).data());
      glLightf(id, GL_CONSTANT_ATTENUATION, float(l.k0.get_d()));
      glLightf(id, GL_LINEAR_ATTENUATION, float(l.k1.get_d()));
      glLightf(id, GL_QUADRATIC_ATTENUATION, float(l.k2.get_d()));
      const bool spot = l.type == lighting::LightType::spot;
      glLightfv(id, GL_SPOT_DIRECTION, spot ? f3(l.spot_dir, 0).data() : std::array<float, 4>{0, 0, -1, 0}.data());
      glLightf(id, GL_SPOT_CUTOFF, spot ? float(l.cone.degrees.get_d()) : 180.f);
      glLightf(id, GL_SPOT_EXPONENT, spot ? float(l.cone.exponent.get_d()) : 0.f);
    }
    GLfloat buf[64];
    glFeedbackBuffer(64, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    const auto n = f3(s.n, 0), p = f3(s.p, 1);
    glBegin(GL_POINTS);
    glNormal3f(n[0], n[1], n[2]);
    glVertex3f(p[0], p[1], p[2]);
    glEnd();
    const GLint count = glRenderMode(GL_RENDER);
    if (count < 8 || buf[0] != GLfloat(GL_POINT_TOKEN)) return {NAN, NAN, NAN};
    return {buf[4], buf[5], buf[6]};
  }

 private:
  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> pixels_;
  bool unclamped_ = false;
  std::string renderer_, version_;
};

// The comparison over a set of scenes, in units of 1/255, per class of scene.
struct GlRow {
  std::string what;
  std::size_t cases = 0;
  double mesa_vs_double = 0;   // max |Mesa - shade in double|
  double mesa_vs_ref = 0;      // max |Mesa - reference|
  double float_vs_ref = 0;     // max |shade in float - reference|
  double oracle_vs_ref = 0;    // max |independent MPFR oracle - shade in reference mode|
  std::size_t mesa_closer = 0, float_closer = 0, tied = 0;  // which is nearer the reference (largest channel)
  std::size_t decision_flips = 0;
  std::size_t flips_shininess0 = 0;  // of those, the material's shininess is 0
  std::size_t s0_differ = 0;         // shininess 0 and more than 1/255 from GL's formula (the reference)
  std::size_t s0_explained = 0;      // of those: within 1/255 of mesa_shininess0 (Mesa's own code path)
  double s0_mesa_vs_model = 0;       // max |Mesa - mesa_shininess0| over the shininess-0 scenes
  std::size_t no_vertex = 0;
};

struct GlComparison {
  std::vector<GlRow> rows;  // shininess > 0: all, local viewer, infinite viewer, spots, attenuation; shininess 0
  std::vector<std::string> examples;  // the first few large differences, as JSON input lines
};

// Mesa's colour for a material of shininess 0, from its fixed-function vertex program (Mesa 22.3,
// src/mesa/main/ffvertex_prog.c, build_lighting): with shininess 0 it never forms n.h and puts n.l
// in every component of the vector it hands to LIT. A light with a spot cone or distance
// attenuation (k0 != 1, k1 or k2 != 0: Mesa's light_attenuated) takes the LIT path, whose specular
// factor is then max(n.l, 0)^(n.l) (0.692 ... 1) where GL specifies (n.h)^0 = 1; any other light takes
// a reduced LIT that gives 1. This is GL's formula with that one substitution, in double.
inline std::array<double, 3> mesa_shininess0(const ShadeScene<Rational>& s, const lighting::Shaded<Rational>& ref,
                                             const lighting::Shaded<double>& dbl) {
  std::array<double, 3> out{ref.rgb.x.get_d(), ref.rgb.y.get_d(), ref.rgb.z.get_d()};
  for (std::size_t i = 0; i < s.lights.size(); ++i) {
    const auto& l = s.lights[i];
    const auto& t = dbl.lights[i];
    const bool positional = l.type != lighting::LightType::directional;
    const bool attenuated = float(l.k0.get_d()) != 1.f || sgn(l.k1) != 0 || sgn(l.k2) != 0;
    if (!t.lit || !((l.type == lighting::LightType::spot && !l.cone.all) || (positional && attenuated))) continue;
    const double factor = std::pow(t.diffuse, t.diffuse);  // GL's convention: diffuse = n.l where lit
    for (int k = 0; k < 3; ++k)
      out[std::size_t(k)] -= (1 - factor) * t.attenuation * t.spot * l.specular[k].get_d() * s.material.ks[k].get_d();
  }
  return out;
}

// The largest of |a - b| over r, g, b, in units of 1/255.
inline double max_channel_gap(const std::array<float, 3>& a, const std::array<double, 3>& b) {
  double m = 0;
  for (std::size_t k = 0; k < 3; ++k) m = std::max(m, std::fabs(double(a[k]) - b[k]) * 255);
  return m;
}

// with_oracle: also run the independent MPFR oracle (slow: about as long as the reference).
inline GlComparison compare_gl(GlLighting& gl, std::vector<ShadeScene<Rational>> scenes, bool with_oracle = true) {
  // Mesa compiles a vertex program (LLVM) per fixed-function state key: light count and types,
  // local viewer, spot and attenuation on or off. Scenes sorted by that key reuse its cache
  // (measured: 6.4 s for 220 scenes unsorted).
  auto key = [](const ShadeScene<Rational>& s) {
    std::string k(1, s.eye_at_infinity ? 'i' : 'l');
    for (const auto& l : s.lights) k += char('0' + int(l.type)), k += l.cone.all ? 'a' : 'c', k += sgn(l.k1) || sgn(l.k2) ? 'q' : '1';
    return k;
  };
  std::stable_sort(scenes.begin(), scenes.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
  GlComparison c;
  c.rows = {{"all, shininess > 0"}, {"local viewer"}, {"infinite viewer"}, {"with a spot (cut-off < 180)"}, {"with attenuation (k1 or k2 > 0)"},
            {"shininess 0 (apart)"}};
  for (const auto& s : scenes) {
    NoProbe none;
    const auto mesa = gl.light(s);
    const auto ref = lighting::shade<Rational>(lighting::convert_scene<Rational>(s), none);
    const auto dbl = lighting::shade<double>(lighting::convert_scene<double>(s), none);
    const auto flt = lighting::shade<float>(lighting::convert_scene<float>(s), none);
    const auto orc = with_oracle ? oracle::shade_gl(lighting::oracle_case(s)) : oracle::ShadeResult{{ref.rgb.x, ref.rgb.y, ref.rgb.z}, {}};
    bool spot = false, att = false;
    for (const auto& l : s.lights) {
      spot = spot || (l.type == lighting::LightType::spot && !l.cone.all);
      att = att || (l.type != lighting::LightType::directional && (sgn(l.k1) > 0 || sgn(l.k2) > 0));
    }
    double md = 0, mr = 0, fr = 0, orr = 0;
    for (int k = 0; k < 3; ++k) {
      const double r = ref.rgb[k].get_d();
      md = std::max(md, std::fabs(mesa[std::size_t(k)] - dbl.rgb[k]) * 255);
      mr = std::max(mr, std::fabs(mesa[std::size_t(k)] - r) * 255);
      fr = std::max(fr, std::fabs(double(flt.rgb[k]) - r) * 255);
      orr = std::max(orr, std::fabs(Rational(orc.rgb[std::size_t(k)] - ref.rgb[k]).get_d()) * 255);
    }
    const bool missing = !std::isfinite(mesa[0]);
    const bool large = !missing && mr > 4;  // more than 4/255: a side of a decision, or a convention
    const double s0_model = sgn(s.material.params.shininess) == 0 ? max_channel_gap(mesa, mesa_shininess0(s, ref, dbl)) : 0;
    auto add = [&](GlRow& row) {
      ++row.cases;
      if (missing) { ++row.no_vertex; return; }
      if (sgn(s.material.params.shininess) == 0) {
        row.s0_mesa_vs_model = std::max(row.s0_mesa_vs_model, s0_model);
        if (mr > 1) ++row.s0_differ, row.s0_explained += s0_model <= 1;
      }
      if (large) {
        ++row.decision_flips;
        if (sgn(s.material.params.shininess) == 0) ++row.flips_shininess0;
        return;
      }
      row.mesa_vs_double = std::max(row.mesa_vs_double, md);
      row.mesa_vs_ref = std::max(row.mesa_vs_ref, mr);
      row.float_vs_ref = std::max(row.float_vs_ref, fr);
      row.oracle_vs_ref = std::max(row.oracle_vs_ref, orr);
      (mr < fr ? row.mesa_closer : fr < mr ? row.float_closer : row.tied)++;
    };
    if (large && c.examples.size() < 3 && sgn(s.material.params.shininess) > 0)
      c.examples.push_back("mesa " + std::to_string(mesa[0]) + " " + std::to_string(mesa[1]) + " " + std::to_string(mesa[2]) + " ref " +
                           std::to_string(ref.rgb.x.get_d()) + " " + std::to_string(ref.rgb.y.get_d()) + " " + std::to_string(ref.rgb.z.get_d()) + ": " +
                           lighting::scene_json(s).dump());
    if (sgn(s.material.params.shininess) == 0) {  // apart: Mesa's (n.h)^0 is not always 1 (mesa_shininess0)
      add(c.rows[5]);
      continue;
    }
    add(c.rows[0]);
    add(c.rows[s.eye_at_infinity ? 2 : 1]);
    if (spot) add(c.rows[3]);
    if (att) add(c.rows[4]);
  }
  return c;
}

}  // namespace sw::peer
