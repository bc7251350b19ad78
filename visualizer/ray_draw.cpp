// [SECTION] painting helpers: 3D lines, dots and labels through the camera
// [SECTION] primitives and the ray
// [SECTION] quantities of the current step: sphere, box, triangle
// [SECTION] draw_ray_scene
#include <cmath>
#include <cstdio>
#include <gmpxx.h>
#include "ray_canvas.hpp"
#include "theme.hpp"

namespace sw::vis {
namespace {

constexpr ImU32 kPrim = IM_COL32(120, 170, 235, 255), kPrimDim = IM_COL32(120, 170, 235, 70), kPrimFill = IM_COL32(90, 140, 220, 60);
constexpr ImU32 kRay = IM_COL32(240, 240, 245, 255), kClosest = IM_COL32(255, 225, 70, 255), kRoot = IM_COL32(80, 220, 230, 255);
constexpr ImU32 kPos = IM_COL32(90, 220, 120, 255), kNeg = IM_COL32(255, 90, 80, 255), kZero = IM_COL32(255, 190, 40, 255);
constexpr ImU32 kAxis[3] = {IM_COL32(240, 100, 100, 255), IM_COL32(110, 220, 120, 255), IM_COL32(110, 150, 255, 255)};

ImVec2 v2(const std::array<double, 2>& s) { return ImVec2(float(s[0]), float(s[1])); }

struct Painter {
  ImDrawList* dl;
  const OrbitCamera& cam;
  std::vector<ImVec4>* placed;  // label rectangles so far: a new label moves down until it is clear

  void line(V3 a, V3 b, ImU32 col, float thick = 1.5f, float offset_px = 0) const {
    auto s = cam.project_segment(a, b);
    if (!s) return;
    ImVec2 p{float((*s)[0]), float((*s)[1])}, q{float((*s)[2]), float((*s)[3])};
    if (offset_px != 0) {  // shift sideways in screen space so that parallel intervals stay apart
      const float dx = q.x - p.x, dy = q.y - p.y, n = std::max(std::sqrt(dx * dx + dy * dy), 1e-3f);
      p.x += -dy / n * offset_px, p.y += dx / n * offset_px, q.x += -dy / n * offset_px, q.y += dx / n * offset_px;
    }
    dl->AddLine(p, q, col, thick);
  }
  std::optional<ImVec2> dot(V3 p, float r, ImU32 col, bool outline = true) const {
    const auto s = cam.project(p);
    if (!s) return std::nullopt;
    if (outline) dl->AddCircleFilled(v2(*s), r + 1.5f, IM_COL32(0, 0, 0, 255), 16);
    dl->AddCircleFilled(v2(*s), r, col, 16);
    return v2(*s);
  }
  // Text on a dark backing so that it reads over lines and fills.
  void text(ImVec2 at, ImU32 col, const char* s, bool avoid = true) const {
    const ImVec2 ts = ImGui::CalcTextSize(s);
    at.x = std::min(at.x, float(cam.origin[0] + cam.size[0]) - ts.x - 6);  // keep it inside the canvas
    for (int tries = 0; avoid && tries < 6; ++tries) {
      bool clear = true;
      for (const ImVec4& r : *placed) clear = clear && (at.x + ts.x + 3 < r.x || at.x - 3 > r.z || at.y + ts.y + 1 < r.y || at.y - 1 > r.w);
      if (clear) break;
      at.y += ts.y + 3;
    }
    placed->push_back(ImVec4(at.x - 3, at.y - 1, at.x + ts.x + 3, at.y + ts.y + 1));
    dl->AddRectFilled(ImVec2(at.x - 3, at.y - 1), ImVec2(at.x + ts.x + 3, at.y + ts.y + 1), IM_COL32(16, 18, 24, 170), 3);
    dl->AddText(at, col, s);
  }
  void label(V3 p, ImU32 col, const char* s, float dx = 9, float dy = -20) const {
    const auto sp = cam.project(p);
    if (sp && (*sp)[0] >= cam.origin[0] && (*sp)[0] <= cam.origin[0] + cam.size[0] && (*sp)[1] >= cam.origin[1] && (*sp)[1] <= cam.origin[1] + cam.size[1])
      text(ImVec2(float((*sp)[0]) + dx, float((*sp)[1]) + dy), col, s);
  }
};

// The latest value of a named variable at the step, if it has been set by then.
struct Vars {
  std::vector<VarState> st;
  const VarState* find(std::string_view n) const {
    for (const VarState& v : st)
      if (v.name == n) return &v;
    return nullptr;
  }
  std::optional<double> get(std::string_view n) const {
    const VarState* v = find(n);
    return v ? std::optional(v->value) : std::nullopt;
  }
};

int sign_of(double x) { return x > 0 ? 1 : x < 0 ? -1 : 0; }

// [SECTION] primitives and the ray

void draw_sphere(const Painter& p, V3 c, double r) {
  const V3 e = p.cam.eye(), ax = unit(e - c);
  const double dist = glm::length(e - c);
  // Latitude and longitude circles (z is the pole), faint: they give the sphere its depth.
  for (int lat = -60; lat <= 60; lat += 30)
    for (int k = 0; k < 48; ++k) {
      const double phi = lat * M_PI / 180, a0 = k * M_PI / 24, a1 = (k + 1) * M_PI / 24;
      auto at = [&](double a) { return c + r * V3{std::cos(phi) * std::cos(a), std::cos(phi) * std::sin(a), std::sin(phi)}; };
      p.line(at(a0), at(a1), kPrimDim, 1.f);
    }
  for (int lon = 0; lon < 180; lon += 30)
    for (int k = 0; k < 48; ++k) {
      const double th = lon * M_PI / 180, a0 = k * M_PI / 24, a1 = (k + 1) * M_PI / 24;
      auto at = [&](double a) { return c + r * V3{std::cos(a) * std::cos(th), std::cos(a) * std::sin(th), std::sin(a)}; };
      p.line(at(a0), at(a1), kPrimDim, 1.f);
    }
  if (dist <= r * 1.0001) return;  // inside: no silhouette
  // The silhouette: the circle of tangency seen from the eye, centre c + (r^2/D) ax, radius r sqrt(1 - r^2/D^2).
  const V3 cc = c + (r * r / dist) * ax, u = unit(glm::cross(ax, std::fabs(ax.z) < 0.9 ? V3{0, 0, 1} : V3{1, 0, 0})), w = glm::cross(ax, u);
  const double rr = r * std::sqrt(std::max(0.0, 1 - (r / dist) * (r / dist)));
  std::vector<ImVec2> pts;
  for (int k = 0; k < 96; ++k) {
    const double a = k * M_PI / 48;
    if (const auto s = p.cam.project(cc + rr * std::cos(a) * u + rr * std::sin(a) * w)) pts.push_back(v2(*s));
  }
  if (pts.size() == 96) {
    p.dl->AddConvexPolyFilled(pts.data(), int(pts.size()), kPrimFill);
    p.dl->AddPolyline(pts.data(), int(pts.size()), kPrim, ImDrawFlags_Closed, 2.f);
  }
}

void draw_primitive(const Painter& p, const RayScene& sc) {
  switch (sc.prim) {
    case RayScene::Prim::sphere: draw_sphere(p, sc.v[0], sc.r); break;
    case RayScene::Prim::box:
      for (int a = 0; a < 8; ++a)
        for (int k = 0; k < 3; ++k)
          if (!(a >> k & 1)) {  // the edge from corner a along axis k
            const int b = a | (1 << k);
            auto corner = [&](int i) { return V3{sc.v[i & 1].x, sc.v[(i >> 1) & 1].y, sc.v[(i >> 2) & 1].z}; };
            p.line(corner(a), corner(b), kPrim, 2.f);
          }
      break;
    case RayScene::Prim::triangle: {
      std::array<ImVec2, 3> s;
      for (int i = 0; i < 3; ++i) {
        const auto q = p.cam.project(sc.v[i]);
        if (!q) return;
        s[i] = v2(*q);
      }
      p.dl->AddTriangleFilled(s[0], s[1], s[2], kPrimFill);
      break;  // the edges are drawn with the edge tests
    }
    case RayScene::Prim::plane: {
      const V3 n = unit(sc.v[1]);
      const V3 foot = sc.has_ray ? sc.o - glm::dot(sc.o - sc.v[0], n) * n : sc.v[0];
      const V3 u = unit(glm::cross(n, std::fabs(n.z) < 0.9 ? V3{0, 0, 1} : V3{1, 0, 0})), w = glm::cross(n, u);
      const double h = std::max({1.0, glm::length(sc.o - foot), sc.has_ray ? 0.6 * sc.t_max * glm::length(sc.d) : 1.0});
      for (int k = -5; k <= 5; ++k) {
        const double f = h * k / 5;
        p.line(foot + f * u - h * w, foot + f * u + h * w, k == 0 ? kPrim : kPrimDim, k == 0 ? 1.5f : 1.f);
        p.line(foot - h * u + f * w, foot + h * u + f * w, k == 0 ? kPrim : kPrimDim, k == 0 ? 1.5f : 1.f);
      }
      p.line(sc.v[0], sc.v[0] + (0.3 * h) * n, kPrim, 2.f);
      p.label(sc.v[0] + (0.3 * h) * n, kPrim, "n");
      break;
    }
    case RayScene::Prim::none: break;
  }
}

void draw_ray(const Painter& p, const RayScene& sc) {
  if (!sc.has_ray) return;
  const V3 end = sc.o + sc.t_max * sc.d;
  p.line(sc.o, end, kRay, 2.f);
  // Arrow head at the end, in screen space.
  const auto s = p.cam.project_segment(sc.o + (0.97 * sc.t_max) * sc.d, end);
  if (s) {
    const float dx = float((*s)[2] - (*s)[0]), dy = float((*s)[3] - (*s)[1]), n = std::max(std::sqrt(dx * dx + dy * dy), 1e-3f);
    const ImVec2 tip{float((*s)[2]), float((*s)[3])}, b(tip.x - dx / n * 14, tip.y - dy / n * 14);
    p.dl->AddTriangleFilled(tip, ImVec2(b.x - dy / n * 6, b.y + dx / n * 6), ImVec2(b.x + dy / n * 6, b.y - dx / n * 6), kRay);
  }
}

// The handles go over the step's quantities, so that they can always be grabbed.
void draw_handles(const Painter& p, const RayScene& sc, int active) {
  if (!sc.has_ray) return;
  const V3 h[2] = {sc.o, sc.o + sc.d};
  const ImU32 col[2] = {kRayOrigin, kRayDir};
  const char* name[2] = {"o", "o + d"};
  for (int i = 0; i < 2; ++i)
    if (const auto at = p.dot(h[i], 6.5f, col[i])) {
      if (active == i) p.dl->AddCircle(*at, 11.f, col[i], 20, 2.f);
      p.text(ImVec2(at->x + 9, at->y - 22), col[i], name[i]);
    }
}

// [SECTION] quantities of the current step: sphere, box, triangle

void sphere_quantities(const Painter& p, const RayScene& sc, const Vars& vars, std::vector<std::string>& info) {
  const double a = glm::dot(sc.d, sc.d);
  char buf[160];
  // Closest approach, once the algorithm has projected the centre onto the ray (tca, b or b').
  if (sc.has_ray && a > 0 && (vars.find("tca") || vars.find("b") || vars.find("b'"))) {
    const double tc = glm::dot(sc.v[0] - sc.o, sc.d) / a;
    const V3 pc = sc.o + tc * sc.d;
    const double d2 = vars.get("m2").value_or(glm::dot(pc - sc.v[0], pc - sc.v[0]));
    p.line(sc.v[0], pc, kClosest, 1.5f);
    p.dot(sc.v[0], 3.5f, kPrim);
    p.dot(pc, 4.5f, kClosest);
    p.label(pc, kClosest, "t_c", 9, -24);
    std::snprintf(buf, sizeof buf, "d^2 = %.4g", d2);
    p.label(0.5 * (sc.v[0] + pc), kClosest, buf, 8, -8);
    std::snprintf(buf, sizeof buf, "t_c = %.9g   d^2 = %.9g   r^2 = %.9g", tc, d2, sc.r * sc.r);
    info.push_back(buf);
  }
  // The roots, under whichever names the variant uses.
  const std::pair<const char*, const char*> pairs[] = {{"t0", "t1"}, {"near", "far"}};
  for (const auto& [n0, n1] : pairs)
    for (const char* n : {n0, n1})
      if (const auto t = vars.get(n)) {
        p.dot(sc.o + *t * sc.d, 4.5f, kRoot);
        p.label(sc.o + *t * sc.d, kRoot, n, n == n0 ? -24.f : 9.f, n == n0 ? -24.f : 6.f);
        std::snprintf(buf, sizeof buf, "%s = %.9g", n, *t);
        info.push_back(buf);
      }
  if (const auto dsc = vars.get("D")) {
    std::snprintf(buf, sizeof buf, "D = %.9g  (%s)", *dsc, *dsc < 0 ? "< 0: miss" : ">= 0: the line meets the sphere");
    info.push_back(buf);
  }
}

void box_quantities(const Painter& p, const RayScene& sc, const TraceModel& m, std::size_t step, const Vars& vars, std::vector<std::string>& info) {
  // Each axis' slab interval [t1, t2] as recorded by its clip step up to now (a short trace).
  const TraceView& t = m.trace();
  std::array<std::optional<std::array<double, 2>>, 3> slab;
  for (std::size_t s = 0; s <= step && s < t.size(); ++s) {
    const StepRecord& st = t.at(s);
    std::optional<std::int64_t> k;
    std::optional<double> t1, t2;
    for (std::uint32_t v = st.var_begin; v < st.var_end; ++v) {
      const VarRecord& vr = t.var_at(v);
      if (vr.name == std::string_view("k")) k = t.int_value(vr.slot);
      if (vr.name == std::string_view("t1")) t1 = t.value_double(vr);
      if (vr.name == std::string_view("t2")) t2 = t.value_double(vr);
    }
    if (k && *k >= 0 && *k < 3 && t1 && t2) slab[std::size_t(*k)] = std::array<double, 2>{*t1, *t2};
  }
  char buf[160];
  static const char* axis[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    if (!slab[k]) continue;
    const auto [t1, t2] = *slab[k];
    p.line(sc.o + t1 * sc.d, sc.o + t2 * sc.d, kAxis[k], 4.f, -7.f * float(k + 1));  // above the ray; labels go below
    p.dot(sc.o + t1 * sc.d, 3.f, kAxis[k], false);
    p.dot(sc.o + t2 * sc.d, 3.f, kAxis[k], false);
    std::snprintf(buf, sizeof buf, "%s slab: t in [%.7g, %.7g]", axis[k], t1, t2);
    info.push_back(buf);
  }
  const auto tn = vars.get("t_near"), tf = vars.get("t_far");
  if (tn && tf) {
    const bool empty = *tn > *tf;
    p.line(sc.o + *tn * sc.d, sc.o + *tf * sc.d, empty ? kNeg : kClosest, 5.f);
    p.label(sc.o + *tn * sc.d, kClosest, "t_near", -56, 28);
    p.label(sc.o + *tf * sc.d, kClosest, "t_far", 9, 28);
    std::snprintf(buf, sizeof buf, "[t_near, t_far] = [%.7g, %.7g]%s", *tn, *tf, empty ? ": empty, miss" : "");
    info.push_back(buf);
  }
}

// The sign of 1 - x - y as the algorithm's own number type decides u + v > 1.
int sign_one_minus(const VarState& x, const VarState& y, Numeric n) {
  if (n == Numeric::exact) {
    try {
      const mpq_class s = mpq_class(x.text) + mpq_class(y.text);
      return sgn(mpq_class(1 - s));
    } catch (const std::exception&) {
    }
  }
  if (n == Numeric::f32) return sign_of(1.0 - double(float(float(x.value) + float(y.value))));
  return sign_of(1.0 - (x.value + y.value));
}

void triangle_quantities(const Painter& p, const RayScene& sc, const TraceModel& m, const Vars& vars, std::vector<std::string>& info) {
  // e[i] is the edge function of the edge opposite v_i (where b_i = 0): watertight U, V, W;
  // Moller-Trumbore 1 - u - v, u, v; the implementor's guide 1 - beta - gamma, beta, gamma.
  std::array<std::optional<int>, 3> sign;
  std::array<std::string, 3> text;
  char buf[160];
  auto set = [&](int i, const char* name) {
    if (const VarState* v = vars.find(name)) {
      sign[i] = sign_of(v->value);
      std::snprintf(buf, sizeof buf, "%s = %.3g", name, v->value);
      text[i] = buf;
    }
  };
  const char* names[3][3] = {{"U", "V", "W"}, {nullptr, "u", "v"}, {nullptr, "beta", "gamma"}};
  for (const auto& row : names)
    if (vars.find(row[1])) {
      for (int i = 0; i < 3; ++i)
        if (row[i]) set(i, row[i]);
      if (!row[0]) {
        if (const VarState *x = vars.find(row[1]), *y = vars.find(row[2]); x && y) {
          sign[0] = sign_one_minus(*x, *y, m.numeric());
          std::snprintf(buf, sizeof buf, "1 - %s - %s %s 0", row[1], row[2], *sign[0] > 0 ? ">" : *sign[0] < 0 ? "<" : "=");
          text[0] = buf;
        }
      }
      break;
    }
  for (int i = 0; i < 3; ++i) {
    const V3 a = sc.v[(i + 1) % 3], b = sc.v[(i + 2) % 3];
    const ImU32 col = !sign[i] ? kPrim : *sign[i] > 0 ? kPos : *sign[i] < 0 ? kNeg : kZero;
    p.line(a, b, col, sign[i] ? 3.f : 2.f);
    if (!text[i].empty()) {
      p.label(0.3 * a + 0.7 * b, col, text[i].c_str(), 6, 2);
      info.push_back("edge opposite v" + std::to_string(i) + ": " + text[i]);
    }
  }
  // Vertex names, with the barycentric weight once it is known.
  std::array<std::optional<double>, 3> bw = {vars.get("b0"), vars.get("b1"), vars.get("b2")};
  if (!bw[1]) bw[1] = vars.get("u") ? vars.get("u") : vars.get("beta");
  if (!bw[2]) bw[2] = vars.get("v") ? vars.get("v") : vars.get("gamma");
  const bool hit_known = vars.find("b0") != nullptr;
  for (int i = 0; i < 3; ++i) {
    if (hit_known && bw[i]) std::snprintf(buf, sizeof buf, "v%d  b%d = %.7g", i, i, *bw[i]);
    else std::snprintf(buf, sizeof buf, "v%d", i);
    p.dot(sc.v[i], 3.5f, kPrim, false);
    p.label(sc.v[i], kPrim, buf, 8, 4);
  }
}

}  // namespace

// [SECTION] draw_ray_scene

void draw_ray_scene(ImDrawList* dl, const OrbitCamera& cam, const RayScene& sc, const TraceModel& m, std::size_t step, int active_handle) {
  std::vector<ImVec4> placed;
  const Painter p{dl, cam, &placed};
  step = std::min(step, m.last());
  const Vars vars{m.state_at(step)};
  std::vector<std::string> info;
  draw_primitive(p, sc);
  draw_ray(p, sc);
  if (sc.prim == RayScene::Prim::sphere && sc.has_ray) sphere_quantities(p, sc, vars, info);
  if (sc.prim == RayScene::Prim::box && sc.has_ray) box_quantities(p, sc, m, step, vars, info);
  if (sc.prim == RayScene::Prim::triangle) triangle_quantities(p, sc, m, vars, info);
  draw_handles(p, sc, active_handle);

  // The points this step records: the hit (magenta), or others (the watertight test's A, B, C
  // are the vertices relative to o: drawn as vectors from o).
  const TraceView& t = m.trace();
  const StepRecord& st = t.at(step);
  std::vector<V3> pts;
  for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g)
    if (t.geo_at(g).kind == GeoKind::point3) pts.push_back({t.geo_double(t.geo_at(g), 0), t.geo_double(t.geo_at(g), 1), t.geo_double(t.geo_at(g), 2)});
  // Without a ray (sphere-uv) the input point and its normal segment stay on screen for every step.
  for (std::size_t s = 0; !sc.has_ray && s <= step; ++s)
    for (std::uint32_t g = t.at(s).geo_begin; g < t.at(s).geo_end; ++g) {
      const GeoRecord& geo = t.geo_at(g);
      auto at = [&](int k) { return V3{t.geo_double(geo, k), t.geo_double(geo, k + 1), t.geo_double(geo, k + 2)}; };
      if (geo.kind == GeoKind::segment3) p.line(at(0), at(3), kClosest, 2.f), p.label(at(3), kClosest, "N");
      if (geo.kind == GeoKind::point3 && s != step) pts.push_back(at(0));
    }
  char buf[160];
  if (sc.prim == RayScene::Prim::triangle && pts.size() == 3 && sc.has_ray) {
    for (int i = 0; i < 3; ++i) {
      p.line(sc.o, sc.o + pts[std::size_t(i)], kClosest, 1.f);
      const char nm[2] = {char('A' + i), 0};
      p.label(0.5 * (sc.o + sc.o + pts[std::size_t(i)]), kClosest, nm, 4, -16);
    }
  } else {
    for (const V3& q : pts) {
      const bool hit = st.kind == StepKind::hit;
      if (p.dot(q, hit ? 7.5f : 5.f, hit ? kRayHit : kClosest)) {
        std::snprintf(buf, sizeof buf, "%s(%.9g, %.9g, %.9g)", hit ? "hit at " : "", q.x, q.y, q.z);
        p.label(q, hit ? kRayHit : kClosest, hit ? "hit" : buf, 11, 6);
        if (hit) info.push_back(buf);
      }
    }
  }
  if (st.kind == StepKind::miss) info.push_back("miss");

  // Orientation: x, y, z axes in the bottom-left corner.
  const ImVec2 base(float(cam.origin[0] + 40), float(cam.origin[1] + cam.size[1] - 60));
  const V3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int k = 0; k < 3; ++k) {
    const ImVec2 tip(base.x + float(glm::dot(axes[k], cam.right())) * 24, base.y - float(glm::dot(axes[k], cam.up())) * 24);
    dl->AddLine(base, tip, kAxis[k], 2.f);
    dl->AddText(ImVec2(tip.x - 3, tip.y - 8), kAxis[k], k == 0 ? "x" : k == 1 ? "y" : "z");
  }
  // The step's quantities as text, top left.
  float y = float(cam.origin[1] + 8);
  for (const std::string& s : info) {
    p.text(ImVec2(float(cam.origin[0] + 10), y), s == "miss" ? kNeg : theme::kLabel, s.c_str(), false);
    y += ImGui::GetFontSize() + 4;
  }
}

}  // namespace sw::vis
