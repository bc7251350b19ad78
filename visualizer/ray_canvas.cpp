// [SECTION] the scene from the trace
// [SECTION] editing the ray through its handles
// [SECTION] the canvas: camera input, handles, fit and focus
#include "ray_canvas.hpp"
#include <cmath>
#include "theme.hpp"

namespace sw::vis {

// [SECTION] the scene from the trace

namespace {

std::optional<V3> json_v3(const Json& j) {
  if (!j.is_array() || j.size() != 3) return std::nullopt;
  V3 p;
  double* out[3] = {&p.x, &p.y, &p.z};
  try {
    for (int k = 0; k < 3; ++k) *out[k] = parse_rational(j[k], "p").get_d();
  } catch (const InputError&) {
    return std::nullopt;
  }
  return p;
}

}  // namespace

RayScene RayScene::from_model(const TraceModel& m) {
  RayScene sc;
  const TraceView& t = m.trace();
  std::optional<V3> first_point;
  for (std::size_t s = 0; s < t.size() && (!sc.has_ray || sc.prim == Prim::none); ++s) {
    const StepRecord& st = t.at(s);
    for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g) {
      const GeoRecord& geo = t.geo_at(g);
      auto at = [&](int k) { return V3{t.geo_double(geo, k), t.geo_double(geo, k + 1), t.geo_double(geo, k + 2)}; };
      if (geo.kind == GeoKind::ray3 && !sc.has_ray) sc.has_ray = true, sc.o = at(0), sc.d = at(3);
      if (sc.prim != Prim::none) continue;
      if (geo.kind == GeoKind::sphere) sc.prim = Prim::sphere, sc.v[0] = at(0), sc.r = t.geo_double(geo, 3);
      if (geo.kind == GeoKind::box3) sc.prim = Prim::box, sc.v[0] = at(0), sc.v[1] = at(3);
      if (geo.kind == GeoKind::triangle3) sc.prim = Prim::triangle, sc.v = {at(0), at(3), at(6)};
      if (geo.kind == GeoKind::plane) sc.prim = Prim::plane, sc.v[0] = at(0), sc.v[1] = at(3);
      if (geo.kind == GeoKind::point3 && !first_point) first_point = at(0);
    }
  }
  // sphere-uv records no sphere; camera-ray records its ray only at the end (found above).
  const Json& in = m.input();
  if (in.is_object() && !sc.has_ray && in.contains("ray") && in["ray"].is_object()) {
    const auto o = json_v3(in["ray"].value("o", Json())), d = json_v3(in["ray"].value("d", Json()));
    if (o && d) sc.has_ray = true, sc.o = *o, sc.d = *d;
  }
  if (in.is_object() && sc.prim == Prim::none && in.contains("sphere") && in["sphere"].is_object()) {
    const auto c = json_v3(in["sphere"].value("c", Json()));
    if (c && in["sphere"].contains("r")) {
      try {
        sc.r = parse_rational(in["sphere"]["r"], "r").get_d(), sc.v[0] = *c, sc.prim = Prim::sphere;
      } catch (const InputError&) {
      }
    }
  }
  // Draw the ray a little past the primitive's far side (and at least to the o + d handle).
  const double dd = glm::dot(sc.d, sc.d);
  if (sc.has_ray && dd > 0) {
    double far = 1;
    auto reach = [&](V3 p, double pad) { far = std::max(far, (glm::dot(p - sc.o, sc.d) + pad * std::sqrt(dd)) / dd); };
    switch (sc.prim) {
      case Prim::sphere: reach(sc.v[0], sc.r); break;
      case Prim::box:
        for (int k = 0; k < 8; ++k) reach(V3{sc.v[k & 1].x, sc.v[(k >> 1) & 1].y, sc.v[k >> 2].z}, 0);
        break;
      case Prim::triangle:
        for (const V3& p : sc.v) reach(p, 0);
        break;
      case Prim::plane: reach(sc.v[0], 0); break;
      case Prim::none:
        if (first_point) reach(*first_point, 0);
        break;
    }
    // ...and past the reported hit (a plane's p can be anywhere on it).
    if (m.result().is_object() && m.result().contains("t")) {
      try {
        far = std::max(far, parse_rational(m.result()["t"], "t").get_d());
      } catch (const InputError&) {
      }
    }
    sc.t_max = far * 1.25;
  }
  return sc;
}

void RayScene::bounds(V3& centre, double& radius) const {
  V3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  auto add = [&](V3 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  };
  if (has_ray) add(o), add(o + t_max * d);
  if (prim == Prim::sphere) add(v[0] - V3{r, r, r}), add(v[0] + V3{r, r, r});
  if (prim == Prim::box) add(v[0]), add(v[1]);
  if (prim == Prim::triangle) add(v[0]), add(v[1]), add(v[2]);
  if (prim == Prim::plane) add(v[0]);
  if (lo.x > hi.x) lo = {-1, -1, -1}, hi = {1, 1, 1};
  centre = 0.5 * (lo + hi);
  radius = std::max(0.5 * glm::length(hi - lo), 1e-6);
}

// [SECTION] editing the ray through its handles

std::optional<Json> ray_input_edit(const Json& input, int handle, V3 p, double snap) {
  if (!input.is_object() || !input.contains("ray") || !input["ray"].is_object()) return std::nullopt;
  const auto o = json_v3(input["ray"].value("o", Json()));
  if (!o || (handle != 0 && handle != 1)) return std::nullopt;
  auto snapped = [&](double x) { return snap > 0 ? std::round(x / snap) * snap + 0.0 : x; };  // + 0.0: no -0
  Json out = input;
  if (handle == 0) {
    out["ray"]["o"] = Json::array({snapped(p.x), snapped(p.y), snapped(p.z)});
  } else {
    const V3 d{snapped(p.x - o->x), snapped(p.y - o->y), snapped(p.z - o->z)};
    if (d.x == 0 && d.y == 0 && d.z == 0) return std::nullopt;
    out["ray"]["d"] = Json::array({d.x, d.y, d.z});
  }
  return out;
}

// [SECTION] the canvas: camera input, handles, fit and focus

std::optional<std::array<float, 2>> RayCanvas::screen_of(V3 p) const {
  const auto s = cam_.project(p);
  if (!s || (*s)[0] < cam_.origin[0] || (*s)[1] < cam_.origin[1] || (*s)[0] > cam_.origin[0] + cam_.size[0] ||
      (*s)[1] > cam_.origin[1] + cam_.size[1])
    return std::nullopt;
  return std::array<float, 2>{float((*s)[0]), float((*s)[1])};
}

void RayCanvas::follow(const Canvas& other) {
  if (const auto* o = dynamic_cast<const RayCanvas*>(&other)) {
    const auto origin = cam_.origin, size = cam_.size;
    cam_ = o->cam_;
    cam_.origin = origin, cam_.size = size;
    fit_pending_ = false;
  }
}

// Looks at the ray from its side (a little ahead of square on), so that it never points at the eye.
void RayCanvas::face_ray(const RayScene& sc) {
  orient_pending_ = false;
  if (!sc.has_ray || std::hypot(sc.d.x, sc.d.y) < 1e-3 * glm::length(sc.d)) return;  // vertical ray: any yaw will do
  cam_.yaw = std::atan2(sc.d.y, sc.d.x) - M_PI / 2 + 0.5;
  cam_.pitch = 0.6;
}

void RayCanvas::focus(const TraceModel& m, std::size_t step, double) {
  // Centre on the latest 3D point at or before the step (hit, closest approach), framing the
  // primitive around it: what matters when the whole scene is 1e8 units wide.
  const RayScene sc = RayScene::from_model(m);
  std::optional<V3> at;
  const TraceView& t = m.trace();
  for (std::size_t s = std::min(step, m.last()) + 1; s-- > 0 && !at;)
    for (std::uint32_t g = t.at(s).geo_begin; g < t.at(s).geo_end; ++g)
      if (t.geo_at(g).kind == GeoKind::point3) at = V3{t.geo_double(t.geo_at(g), 0), t.geo_double(t.geo_at(g), 1), t.geo_double(t.geo_at(g), 2)};
  double size = 1;
  if (sc.prim == RayScene::Prim::sphere) size = 2.5 * sc.r, at = at ? at : sc.v[0];
  if (sc.prim == RayScene::Prim::box) size = glm::length(sc.v[1] - sc.v[0]);
  if (sc.prim == RayScene::Prim::triangle) size = std::max({glm::length(sc.v[1] - sc.v[0]), glm::length(sc.v[2] - sc.v[1]), glm::length(sc.v[0] - sc.v[2])}) * 0.6;
  if (!at) {
    fit_pending_ = true;
    return;
  }
  face_ray(sc);
  cam_.frame(*at, std::max(size, 1e-6));
  fit_pending_ = false;
}

void RayCanvas::handle_input(const CanvasInput& in, const RayScene& sc, bool hovered, CanvasEvents& ev) {
  const ImGuiIO& io = ImGui::GetIO();
  if (hovered && io.MouseWheel != 0) cam_.zoom(std::pow(1.2, -io.MouseWheel));
  if (in.keys && !io.WantTextInput) {
    for (ImWchar ch : io.InputQueueCharacters)
      if (ch == 'f' || ch == 'F') fit_pending_ = true;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_PageUp))) cam_.zoom(1 / 1.25);
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_PageDown))) cam_.zoom(1.25);
  }
  const V3 handles[2] = {sc.o, sc.o + sc.d};
  if (ImGui::IsItemActivated()) {
    dragging_ = ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !io.KeyShift ? 2 : 3;
    if (dragging_ == 2 && in.editable && sc.has_ray && in.model && in.model->input().contains("ray"))
      for (int h = 1; h >= 0; --h)  // o + d first: at a tiny d the two overlap and d is the one to pull out
        if (const auto s = cam_.project(handles[h])) {
          const double dx = io.MousePos.x - (*s)[0], dy = io.MousePos.y - (*s)[1];
          if (dx * dx + dy * dy <= 11.0 * 11.0) {
            dragging_ = h, drag_anchor_ = handles[h];
            break;
          }
        }
  }
  if (ImGui::IsItemActive() && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
    if (dragging_ == 2) cam_.orbit(-io.MouseDelta.x * 0.01, io.MouseDelta.y * 0.01);
    if (dragging_ == 3) cam_.pan(io.MouseDelta.x, io.MouseDelta.y);
    if (dragging_ == 0 || dragging_ == 1) {
      // Move in the plane facing the camera through the handle; snap to a power of two about a
      // pixel wide there, so that the numbers stay short and float-representable.
      const V3 p = cam_.unproject_on_facing_plane(io.MousePos.x, io.MousePos.y, drag_anchor_);
      const double snap = std::exp2(std::floor(std::log2(cam_.units_per_pixel(drag_anchor_))));
      if (auto edited = ray_input_edit(in.model->input(), dragging_, p, snap); edited && *edited != in.model->input()) ev.edit = std::move(edited);
    }
  }
  if (ImGui::IsItemDeactivated()) dragging_ = -1;
}

CanvasEvents RayCanvas::draw(const CanvasInput& in, ImVec2 size) {
  CanvasEvents ev;
  size.x = std::max(size.x, 16.f), size.y = std::max(size.y, 16.f);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  cam_.origin = {origin.x, origin.y}, cam_.size = {size.x, size.y};
  ImGui::InvisibleButton("##canvas3d", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), theme::kCanvasBg);
  if (in.model) {
    const RayScene sc = RayScene::from_model(*in.model);
    if (fit_pending_) {
      V3 c;
      double r;
      sc.bounds(c, r);
      if (orient_pending_) face_ray(sc);
      cam_.frame(c, r);
      cam_.pan(0, 0.06 * cam_.size[1]);  // a little lower: the step's values are listed top left
      fit_pending_ = false;
    }
    handle_input(in, sc, hovered, ev);
    draw_ray_scene(dl, cam_, sc, *in.model, in.step, in.editable ? dragging_ : -2);
  }
  const bool can_edit = in.editable && in.model && in.model->input().contains("ray");
  const char* help = "drag: orbit   right/shift-drag: pan   wheel: zoom   F: fit   drag o or o+d: edit the ray";
  if (!can_edit || ImGui::CalcTextSize(help).x > size.x - 16) help = "drag: orbit   right-drag: pan   wheel: zoom   F: fit";
  dl->AddText(ImVec2(origin.x + 8, origin.y + size.y - ImGui::GetFontSize() - 6), theme::kLabel, help);
  corner_label(dl, origin, size, in.label);
  dl->PopClipRect();
  return ev;
}

}  // namespace sw::vis
