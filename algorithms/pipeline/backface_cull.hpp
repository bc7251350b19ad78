// Back-face culling, by its two tests side by side: in eye space, whether the eye lies on the front
// side of the triangle's plane (the sign of V.N); on the screen, the winding of the projected
// vertices (the sign of their signed area), which is what GL's glCullFace and glFrontFace use.
// In front of the eye the two signs are equal in exact arithmetic (docs/pipeline/semantics.md has
// the proof); rounded, they part near edge-on, and the trace counts where.
#pragma once
#include <array>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "pipeline/camera.hpp"

namespace sw::pipe {

enum class CullFace : std::uint8_t { back, front, front_and_back };  // glCullFace
enum class FrontFace : std::uint8_t { ccw, cw };                     // glFrontFace

template <class Num> struct Triangle {
  Vec3<Num> a, b, c;
};

struct Facing {
  int toward = 0;   // sign of V.N: > 0 the eye sees the side from which a, b, c run counter-clockwise
  int winding = 0;  // sign of the window area; 0 also when `behind`
  bool behind = false;  // a vertex has w <= 0: the winding is not defined before clipping
  bool front = false, culled = false;
  bool agree = true;  // both tests give the same side (not judged when behind)
  friend bool operator==(const Facing&, const Facing&) = default;
};

struct BackfaceCull {
  static constexpr std::string_view id = "backface-cull";
  static constexpr std::string_view summary = "Back-face culling: the eye-space test V.N against the screen winding, glCullFace";
#define SW_LINES_BACKFACE_CULL(X) \
  X(camera, "the camera's frame, V and P as in transform; the eye E") \
  X(normal, "for each triangle (a, b, c): N <- (b - a) x (c - a)  -- seen from its tip, a, b, c run counter-clockwise") \
  X(toward, "toward <- sign(V . N), V = E - a (orthographic: V = -f)  -- > 0: the eye sees N's side") \
  X(project, "a', b', c' <- the vertices in window coordinates, through P V, the divide and the viewport") \
  X(behind, "if some w <= 0: the winding is undefined until clipping; front from toward (what the clipped polygon gives)") \
  X(winding, "area2 <- (b' - a') x (c' - a')                      -- twice the signed area; > 0: counter-clockwise") \
  X(front, "front <- area2 > 0 (GL_CCW) or area2 < 0 (GL_CW); area2 = 0 is a back face, as in GL") \
  X(agree, "agree <- the winding's side = toward's side           -- exact: always, in front of the eye") \
  X(cull, "culled <- GL_BACK: not front; GL_FRONT: front; GL_FRONT_AND_BACK: always")
  SW_LISTING("Back-face culling", SW_LINES_BACKFACE_CULL)
#undef SW_LINES_BACKFACE_CULL
};

template <NumberType Num, StepProbe Probe = NoProbe>
std::vector<Facing> backface_cull(const Camera<Num>& cam, const std::vector<Triangle<Num>>& tris, CullFace mode, FrontFace front_face,
                                  Probe& probe) {
  using L = BackfaceCull;
  const Frame<Num> fr = look_frame(cam.look);
  const Mat4<Num> C = product(projection_matrix(cam.proj), view_matrix(fr, cam.look.eye));
  if constexpr (Probe::on) probe.step(L::camera, StepKind::init).vec("f", fr.f).point(cam.look.eye).label("eye").keep();
  std::vector<Facing> out(tris.size());
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const Triangle<Num>& t = tris[i];
    Facing& r = out[i];
    const Vec3<Num> n = cross(Vec3<Num>(t.b - t.a), Vec3<Num>(t.c - t.a));
    if constexpr (Probe::on) probe.step(L::normal, StepKind::advance).idx("i", std::int64_t(i)).vec("N", n).triangle(t.a, t.b, t.c).label("triangle").keep();
    const Vec3<Num> v = cam.proj.perspective ? Vec3<Num>(cam.look.eye - t.a) : Vec3<Num>(Num(-1) * fr.f);
    const Num vn = dot(v, n);
    r.toward = num::sign(vn);
    if constexpr (Probe::on) probe.step(L::toward, StepKind::decide).num("V.N", vn).idx("toward", r.toward);
    const std::array<Vec4<Num>, 3> clip{apply(C, t.a), apply(C, t.b), apply(C, t.c)};
    r.behind = !(Num(0) < clip[0].w && Num(0) < clip[1].w && Num(0) < clip[2].w);
    const bool ccw_front = front_face == FrontFace::ccw;
    if (r.behind) {
      if constexpr (Probe::on) probe.step(L::behind, StepKind::decide);
      r.front = ccw_front ? r.toward > 0 : r.toward < 0;
    } else {
      std::array<Vec2<Num>, 3> s;
      for (int k = 0; k < 3; ++k) {
        const Vec3<Num> w = to_window(cam.view, Vec3<Num>{Num(clip[k].x / clip[k].w), Num(clip[k].y / clip[k].w), Num(clip[k].z / clip[k].w)});
        s[k] = {w.x, w.y};
      }
      if constexpr (Probe::on) probe.step(L::project, StepKind::advance).vec("a'", s[0]).vec("b'", s[1]).vec("c'", s[2]);
      const Num area2 = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[1].y - s[0].y) * (s[2].x - s[0].x);
      r.winding = num::sign(area2);
      if constexpr (Probe::on) probe.step(L::winding, StepKind::decide).num("area2", area2).idx("winding", r.winding);
      r.front = ccw_front ? r.winding > 0 : r.winding < 0;
      if constexpr (Probe::on) probe.step(L::front, StepKind::decide).idx("front", r.front);
      r.agree = r.winding == r.toward;
      if constexpr (Probe::on) probe.step(L::agree, StepKind::decide).idx("agree", r.agree);
    }
    r.culled = mode == CullFace::front_and_back || (mode == CullFace::back) != r.front;
    if constexpr (Probe::on) probe.step(L::cull, r.culled ? StepKind::miss : StepKind::hit).idx("culled", r.culled);
  }
  return out;
}

}  // namespace sw::pipe
