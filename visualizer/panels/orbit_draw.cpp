// [SECTION] painting helpers: 3D lines, dots and labels through the camera
// [SECTION] painters by geometry kind
// [SECTION] draw_scene3
// Every item is painted by its kind; its label is drawn beside it, its value prints after the
// label and its sign picks the colour (an edge function's side). Nothing here reads variables.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include "panels/orbit_canvas.hpp"
#include "panels/theme.hpp"

namespace sw::vis {
namespace {

constexpr ImU32 kPrim = IM_COL32(120, 170, 235, 255), kPrimDim = IM_COL32(120, 170, 235, 70), kPrimFill = IM_COL32(90, 140, 220, 60);
constexpr ImU32 kRay = IM_COL32(240, 240, 245, 255), kPoint = IM_COL32(255, 225, 70, 255), kKept = IM_COL32(80, 220, 230, 255);
constexpr ImU32 kAxis[3] = {IM_COL32(240, 100, 100, 255), IM_COL32(110, 220, 120, 255), IM_COL32(110, 150, 255, 255)};
// Labelled items without a value take a colour from their label, so that "x slab" keeps its
// colour from step to step.
constexpr ImU32 kLabelled[5] = {IM_COL32(240, 120, 110, 255), IM_COL32(120, 220, 130, 255), IM_COL32(120, 160, 255, 255),
                                IM_COL32(255, 200, 90, 255), IM_COL32(210, 130, 240, 255)};

ImVec2 v2(const std::array<double, 2>& s) { return ImVec2(float(s[0]), float(s[1])); }

ImU32 label_colour(const char* label, ImU32 fallback) {
  if (!label) return fallback;
  std::uint32_t h = 2166136261u;  // FNV-1a
  for (const char* c = label; *c; ++c) h = (h ^ std::uint8_t(*c)) * 16777619u;
  return kLabelled[h % 5];
}

struct Painter {
  ImDrawList* dl;
  const OrbitCamera& cam;
  std::vector<ImVec4>* placed;  // label rectangles so far (x0, y0, x1, y1), pairwise disjoint

  void line(V3 a, V3 b, ImU32 col, float thick = 1.5f, float offset_px = 0) const {
    auto s = cam.project_segment(a, b);
    if (!s) return;
    ImVec2 p{float((*s)[0]), float((*s)[1])}, q{float((*s)[2]), float((*s)[3])};
    if (offset_px != 0) {  // shift sideways in screen space so that intervals along one line stay apart
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
  // Text on a dark backing so that it reads over lines and fills. Greedy placement: the first of a
  // few boxes near `at` (as asked, then a row lower or higher, then mirrored to the anchor's left)
  // that lies inside the canvas and clear of every label placed so far; none: the label is
  // dropped. A box moved off `at` gets a leader line from `anchor`. Returns whether it was drawn.
  bool text(ImVec2 at, ImU32 col, const char* s, std::optional<ImVec2> anchor = std::nullopt) const {
    const ImVec2 ts = ImGui::CalcTextSize(s);
    const float x_min = float(cam.origin[0]) + 3, y_min = float(cam.origin[1]) + 1;
    const float x_max = float(cam.origin[0] + cam.size[0]) - 3, y_max = float(cam.origin[1] + cam.size[1]) - 1;
    constexpr float kRows[] = {0, 1, -1, 2, -2, 3, -3};
    for (int side = 0; side < 2; ++side)
      for (float row : kRows) {
        ImVec2 q(at.x, at.y + row * (ts.y + 4));
        if (side) q.x = (anchor ? 2 * anchor->x - at.x : at.x) - ts.x;  // mirrored about the anchor
        q.x = std::clamp(q.x, x_min, x_max - ts.x);
        const ImVec4 box(q.x - 3, q.y - 1, q.x + ts.x + 3, q.y + ts.y + 1);
        if (box.x < x_min - 3 || box.y < y_min || box.w > y_max) continue;  // wider or out of the canvas
        bool clear = true;
        for (const ImVec4& r : *placed) clear = clear && (box.z <= r.x || r.z <= box.x || box.w <= r.y || r.w <= box.y);
        if (!clear) continue;
        placed->push_back(box);
        if (anchor && (row != 0 || side)) {  // a leader from the anchor to the box's nearest point
          const ImVec2 near(std::clamp(anchor->x, box.x, box.z), std::clamp(anchor->y, box.y, box.w));
          dl->AddLine(*anchor, near, (col & 0x00FFFFFFu) | 0xA0000000u, 1.f);
        }
        dl->AddRectFilled(ImVec2(box.x, box.y), ImVec2(box.z, box.w), IM_COL32(16, 18, 24, 170), 3);
        dl->AddText(q, col, s);
        return true;
      }
    return false;
  }
  void label(V3 p, ImU32 col, const char* s, float dx = 9, float dy = -20) const {
    const auto sp = cam.project(p);
    if (sp && (*sp)[0] >= cam.origin[0] && (*sp)[0] <= cam.origin[0] + cam.size[0] && (*sp)[1] >= cam.origin[1] && (*sp)[1] <= cam.origin[1] + cam.size[1])
      text(ImVec2(float((*sp)[0]) + dx, float((*sp)[1]) + dy), col, s, v2(*sp));
  }
};

// "label" or "label = value".
std::string caption(const Item3& it) {
  if (!it.label) return "";
  if (!it.value) return it.label;
  char buf[64];
  std::snprintf(buf, sizeof buf, " = %.6g", *it.value);
  return it.label + std::string(buf);
}

// [SECTION] painters by geometry kind

void paint_sphere(const Painter& p, V3 c, double r) {
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

void paint_box(const Painter& p, V3 lo, V3 hi) {
  auto corner = [&](int i) { return V3{(i & 1 ? hi : lo).x, (i & 2 ? hi : lo).y, (i & 4 ? hi : lo).z}; };
  for (int a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k)
      if (!(a >> k & 1)) p.line(corner(a), corner(a | (1 << k)), kPrim, 2.f);  // the edge from corner a along axis k
}

void paint_triangle(const Painter& p, const Item3& it) {
  std::array<ImVec2, 3> s;
  for (int i = 0; i < 3; ++i) {
    const auto q = p.cam.project(it.at(3 * i));
    if (!q) return;
    s[std::size_t(i)] = v2(*q);
  }
  // A labelled triangle takes its label's colour (a shadow volume's caps and sides, the scene).
  const ImU32 edge = label_colour(it.label, kPrim), fill = it.label ? (edge & ~IM_COL32_A_MASK) | (ImU32(60) << IM_COL32_A_SHIFT) : kPrimFill;
  p.dl->AddTriangleFilled(s[0], s[1], s[2], fill);
  for (int i = 0; i < 3; ++i) p.line(it.at(3 * i), it.at(3 * ((i + 1) % 3)), edge, 1.5f);
}

// A grid square on the plane around the foot of the scene's centre, and the normal at its point.
void paint_plane(const Painter& p, const Scene3& sc, V3 at, V3 normal) {
  const V3 n = unit(normal), foot = sc.centre - glm::dot(sc.centre - at, n) * n;
  const V3 u = unit(glm::cross(n, std::fabs(n.z) < 0.9 ? V3{0, 0, 1} : V3{1, 0, 0})), w = glm::cross(n, u);
  const double h = std::max(1.0, sc.radius);
  for (int k = -5; k <= 5; ++k) {
    const double f = h * k / 5;
    p.line(foot + f * u - h * w, foot + f * u + h * w, k == 0 ? kPrim : kPrimDim, k == 0 ? 1.5f : 1.f);
    p.line(foot - h * u + f * w, foot + h * u + f * w, k == 0 ? kPrim : kPrimDim, k == 0 ? 1.5f : 1.f);
  }
  p.line(at, at + (0.3 * h) * n, kPrim, 2.f);
  p.label(at + (0.3 * h) * n, kPrim, "n");
}

void paint_ray(const Painter& p, const Scene3& sc, const Item3& it) {
  const V3 o = it.at(0), d = it.at(3), end = o + sc.ray_length * d;
  p.line(o, end, kRay, 2.f);
  if (const auto s = p.cam.project_segment(o + (0.97 * sc.ray_length) * d, end)) {  // the arrow head, in screen space
    const float dx = float((*s)[2] - (*s)[0]), dy = float((*s)[3] - (*s)[1]), n = std::max(std::sqrt(dx * dx + dy * dy), 1e-3f);
    const ImVec2 tip{float((*s)[2]), float((*s)[3])}, b(tip.x - dx / n * 14, tip.y - dy / n * 14);
    p.dl->AddTriangleFilled(tip, ImVec2(b.x - dy / n * 6, b.y + dx / n * 6), ImVec2(b.x + dy / n * 6, b.y - dx / n * 6), kRay);
  }
  if (it.label) p.label(end, kRay, it.label, 9, 4);
}

// A segment lying on the first ray (an interval of t) is drawn beside it, each label on its own
// lane, so that overlapping intervals stay apart; `lane` counts them.
void paint_segment(const Painter& p, const Scene3& sc, const Item3& it, std::vector<const char*>& lanes) {
  const V3 a = it.at(0), b = it.at(3);
  const ImU32 col = it.value ? theme::sign_colour(*it.value) : label_colour(it.label, kPoint);
  float offset = 0;
  if (sc.first_ray && it.label) {
    const V3 o = sc.first_ray->first, d = sc.first_ray->second;  // not a structured binding: clang 14 cannot capture one
    auto off_line = [&](V3 q) { return glm::length(glm::cross(q - o, d)) / std::max(glm::length(d), 1e-300); };
    if (std::max(off_line(a), off_line(b)) <= 1e-9 * sc.radius) {
      std::size_t lane = 0;
      while (lane < lanes.size() && std::strcmp(lanes[lane], it.label) != 0) ++lane;
      if (lane == lanes.size()) lanes.push_back(it.label);
      offset = -7.f * float(lane + 1);
    }
  }
  p.line(a, b, col, offset != 0 ? 4.f : it.value ? 3.f : 2.f, offset);
  if (offset != 0) p.dot(a, 3.f, col, false), p.dot(b, 3.f, col, false);
  if (it.label) p.label(0.4 * a + 0.6 * b, col, caption(it).c_str(), 6, offset != 0 ? 6 - offset : 2);
}

void paint_point(const Painter& p, const Item3& it, bool hit_step) {
  const bool hit = hit_step && it.current;
  const ImU32 col = hit ? kHitColour : it.current ? kPoint : kKept;
  if (p.dot(it.at(0), hit ? 7.5f : it.current ? 5.f : 4.f, col) && it.label) p.label(it.at(0), col, caption(it).c_str(), 11, 6);
}

}  // namespace

// [SECTION] draw_scene3

std::vector<std::array<float, 4>> draw_scene3(ImDrawList* dl, const OrbitCamera& cam, const Scene3& sc, const TraceModel& m, std::size_t step,
                                              const std::vector<std::optional<V3>>& handles, int active_handle) {
  std::vector<ImVec4> placed;
  const Painter p{dl, cam, &placed};
  const TraceView& t = m.trace();
  step = std::min(step, m.last());
  const StepRecord& st = t.at(step);
  std::vector<Item3> items;
  for (std::uint32_t g : m.visible_items(step)) {
    items.push_back(item_of(t, g));
    items.back().current = g >= st.geo_begin;
  }
  // The step's labelled items as text, top left: their boxes are reserved first (drawn last, over
  // the scene), then the axes and the help line at the bottom; scene labels avoid them all.
  std::vector<std::string> info;
  char buf[200];
  for (const Item3& it : items) {
    if (!it.current || !it.label) continue;
    if (it.value) info.push_back(caption(it));
    else if (it.kind == GeoKind::point3) std::snprintf(buf, sizeof buf, "%s at (%.9g, %.9g, %.9g)", it.label, it.v[0], it.v[1], it.v[2]), info.push_back(buf);
  }
  if (st.kind == StepKind::miss) info.push_back("miss");
  const float fs = ImGui::GetFontSize(), x0 = float(cam.origin[0]), y1 = float(cam.origin[1] + cam.size[1]);
  for (std::size_t k = 0; k < info.size(); ++k) {
    const ImVec2 at(x0 + 10, float(cam.origin[1] + 8) + float(k) * (fs + 4)), ts = ImGui::CalcTextSize(info[k].c_str());
    placed.push_back(ImVec4(at.x - 3, at.y - 1, at.x + ts.x + 3, at.y + ts.y + 1));
  }
  const std::size_t reserved = placed.size() + 2;
  placed.push_back(ImVec4(x0 + 8, y1 - fs - 76, x0 + 72, y1 - fs - 12));                        // the axes
  placed.push_back(ImVec4(x0, y1 - fs - 8, float(cam.origin[0] + cam.size[0]), y1));           // the help line
  // Layers: surfaces, rays, segments, then the handles (so that they can be grabbed over the
  // scene), then points, so that the step's markers (a hit at o + d) stay visible.
  std::vector<const char*> lanes;
  auto handles_layer = [&] {
    for (std::size_t h = 0; h < handles.size(); ++h) {
      const ImU32 col = h % 2 ? theme::kHandleP1 : theme::kHandleP0;
      if (const auto at = handles[h] ? p.dot(*handles[h], 6.5f, col) : std::nullopt) {
        if (active_handle == int(h)) p.dl->AddCircle(*at, 11.f, col, 20, 2.f);
        p.text(ImVec2(at->x + 9, at->y - 22), col, m.algorithm().handles[h].label.c_str());
      }
    }
  };
  for (int layer = 0; layer < 4; ++layer) {
    if (layer == 3) handles_layer();
    for (const Item3& it : items) {
      const GeoKind k = it.kind;
      const int want = k == GeoKind::ray3 ? 1 : k == GeoKind::segment3 ? 2 : k == GeoKind::point3 ? 3 : 0;
      if (want != layer) continue;
      switch (k) {
        case GeoKind::sphere: paint_sphere(p, it.at(0), it.v[3]); break;
        case GeoKind::box3: paint_box(p, it.at(0), it.at(3)); break;
        case GeoKind::node3: paint_box(p, it.at(2), it.at(5)); break;  // a tree node's bounds
        case GeoKind::triangle3: paint_triangle(p, it); break;
        case GeoKind::plane: paint_plane(p, sc, it.at(0), it.at(3)); break;
        case GeoKind::ray3: paint_ray(p, sc, it); break;
        case GeoKind::segment3: paint_segment(p, sc, it, lanes); break;
        case GeoKind::point3: paint_point(p, it, st.kind == StepKind::hit); break;
        default: break;  // 2D kinds belong to plane2d
      }
    }
  }

  // The step's values, top left, in the boxes reserved for them.
  for (std::size_t k = 0; k < info.size(); ++k) {
    const ImVec4& r = placed[k];
    dl->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.z, r.w), IM_COL32(16, 18, 24, 170), 3);
    dl->AddText(ImVec2(r.x + 3, r.y + 1), info[k] == "miss" ? theme::kNegative : theme::kLabel, info[k].c_str());
  }
  // Orientation: x, y, z axes in the bottom-left corner.
  const ImVec2 base(x0 + 40, y1 - fs - 44);  // above the help line
  const V3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int k = 0; k < 3; ++k) {
    const ImVec2 tip(base.x + float(glm::dot(axes[k], cam.right())) * 24, base.y - float(glm::dot(axes[k], cam.up())) * 24);
    dl->AddLine(base, tip, kAxis[k], 2.f);
    dl->AddText(ImVec2(tip.x - 3, tip.y - 8), kAxis[k], k == 0 ? "x" : k == 1 ? "y" : "z");
  }
  std::vector<std::array<float, 4>> labels;  // the info boxes and the scene's labels
  for (std::size_t k = 0; k < placed.size(); ++k)
    if (k < info.size() || k >= reserved) labels.push_back({placed[k].x, placed[k].y, placed[k].z, placed[k].w});
  return labels;
}

}  // namespace sw::vis
