// Transform: vertices from object space to the window, as GL's fixed pipeline takes them: the model
// matrix, gluLookAt's view, glFrustum's or glOrtho's projection, the clip-space test, the divide by
// w and glViewport's mapping (the guide's section 1.2). The depth it writes is where precision is
// lost: in perspective, window depth is hyperbolic in the eye's distance, so float's 24 bits crowd
// near the far plane, and a nearer near plane makes that worse (docs/pipeline/semantics.md).
#pragma once
#include <array>
#include <span>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "pipeline/camera.hpp"

namespace sw::pipe {

// One vertex's way through the pipeline. `projected` is false for a vertex on or behind the eye's
// plane (w <= 0): GL clips such a primitive before the divide, so it has no window position.
template <class Num> struct Transformed {
  Vec4<Num> clip;
  bool inside = false, projected = false;
  Vec3<Num> ndc, win;
};

struct TransformAlgo {
  static constexpr std::string_view id = "transform";
  static constexpr std::string_view summary = "Transform: model, view, projection, clip test, divide, viewport";
#define SW_LINES_TRANSFORM(X) \
  X(frame, "f <- (target - eye)/|target - eye|; s <- (f x up)/|f x up|; u <- s x f  -- gluLookAt's frame") \
  X(matrices, "V <- rows (s, -s.eye), (u, -u.eye), (-f, f.eye), (0, 1); P <- glFrustum's or glOrtho's matrix") \
  X(model, "for each vertex p: m <- M (p, 1)                 -- the model matrix places it in the world") \
  X(eye, "e <- V m                                           -- eye space: the eye at 0, looking down -z") \
  X(clip, "c <- P e                                          -- clip space: w = -e.z in perspective, 1 in orthographic") \
  X(inside, "inside <- -c.w <= c.x, c.y, c.z <= c.w           -- in the view volume") \
  X(behind, "if c.w <= 0: no window position                  -- on or behind the eye's plane: GL clips first") \
  X(divide, "ndc <- (c.x, c.y, c.z) / c.w                      -- the perspective divide") \
  X(window, "win <- (vx + (ndc.x+1) vw/2, vy + (ndc.y+1) vh/2, dn + (ndc.z+1)(df-dn)/2)  -- glViewport, glDepthRange")
  SW_LISTING("Transform", SW_LINES_TRANSFORM)
#undef SW_LINES_TRANSFORM
};

// Every vertex of `points` through M (an affine model matrix: last row 0 0 0 1) and the camera.
template <NumberType Num, StepProbe Probe = NoProbe>
std::vector<Transformed<Num>> transform(const Mat4<Num>& M, const Camera<Num>& cam, const std::vector<Vec3<Num>>& points, Probe& probe) {
  using L = TransformAlgo;
  const Frame<Num> fr = look_frame(cam.look);
  if constexpr (Probe::on) {
    probe.step(L::frame, StepKind::init).vec("f", fr.f).vec("s", fr.s).vec("u", fr.u).point(cam.look.eye).label("eye").keep();
    probe.segment(cam.look.eye, Vec3<Num>(cam.look.eye + fr.f)).label("f").keep();
    probe.segment(cam.look.eye, Vec3<Num>(cam.look.eye + fr.u)).label("u").keep();
  }
  const Mat4<Num> V = view_matrix(fr, cam.look.eye), P = projection_matrix(cam.proj);
  if constexpr (Probe::on) {
    auto& s = probe.step(L::matrices, StepKind::init);
    const auto corner = frustum_corners(cam, fr);
    for (const auto& e : kFrustumEdges) {  // one label for the twelve edges keeps the view legible
      s.segment(corner[e[0]], corner[e[1]]).keep();
      if (&e == &kFrustumEdges[0]) s.label("frustum");
    }
  }
  std::vector<Transformed<Num>> out(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    Transformed<Num>& t = out[i];
    const Vec4<Num> m4 = apply(M, points[i]);
    const Vec3<Num> m{m4.x, m4.y, m4.z};
    if constexpr (Probe::on) probe.step(L::model, StepKind::advance).idx("i", std::int64_t(i)).vec("m", m).point(m).label("m").keep();
    const Vec4<Num> e4 = apply(V, m);
    const Vec3<Num> e{e4.x, e4.y, e4.z};
    if constexpr (Probe::on) probe.step(L::eye, StepKind::advance).vec("e", e);
    t.clip = apply(P, e);
    const Vec4<Num>& c = t.clip;
    if constexpr (Probe::on) {
      const std::array<Num, 4> cs{c.x, c.y, c.z, c.w};
      probe.step(L::clip, StepKind::advance).list("c", std::span<const Num>(cs));
    }
    t.inside = -c.w <= c.x && c.x <= c.w && -c.w <= c.y && c.y <= c.w && -c.w <= c.z && c.z <= c.w;
    if constexpr (Probe::on) probe.step(L::inside, StepKind::decide).idx("inside", t.inside);
    if (c.w <= Num(0)) {
      if constexpr (Probe::on) probe.step(L::behind, StepKind::miss);
      continue;
    }
    t.projected = true;
    t.ndc = {Num(c.x / c.w), Num(c.y / c.w), Num(c.z / c.w)};
    if constexpr (Probe::on) probe.step(L::divide, StepKind::advance).vec("ndc", t.ndc);
    t.win = to_window(cam.view, t.ndc);
    if constexpr (Probe::on) probe.step(L::window, StepKind::plot).vec("win", t.win).num("depth", t.win.z);
  }
  return out;
}

}  // namespace sw::pipe
