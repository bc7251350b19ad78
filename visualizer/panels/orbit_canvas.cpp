// [SECTION] the scene from the trace
// [SECTION] editing the declared 3D handles
// [SECTION] the canvas: camera input, handles, fit and focus
#include "panels/orbit_canvas.hpp"
#include <cmath>
#include "panels/theme.hpp"

namespace sw::vis {

// [SECTION] the scene from the trace

Item3 item_of(const TraceView& t, std::uint32_t g) {
  const GeoRecord& geo = t.geo_at(g);
  Item3 it{geo.kind, {}, geo.label, t.geo_value(geo), false};
  for (std::uint32_t k = 0; k < geo.count; ++k) it.v.push_back(t.geo_double(geo, static_cast<int>(k)));
  return it;
}

namespace {

struct Box3 {
  V3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  void add(V3 p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
  bool empty() const { return lo.x > hi.x; }
  double radius() const { return empty() ? 0 : 0.5 * glm::length(hi - lo); }
};

// The points that bound an item (a sphere by its box; a plane by its point; a ray by its origin).
void add_item(Box3& b, const Item3& it) {
  switch (it.kind) {
    case GeoKind::sphere: {
      const double r = it.v[3];
      b.add(it.at(0) - V3(r)), b.add(it.at(0) + V3(r));
      break;
    }
    case GeoKind::ray3:
    case GeoKind::plane: b.add(it.at(0)); break;
    case GeoKind::node3: b.add(it.at(2)), b.add(it.at(5)); break;  // id, parent, then the bounds
    default:
      if (geo_desc(it.kind).dim == 3)
        for (std::size_t k = 0; k + 2 < it.v.size(); k += 3) b.add(it.at(int(k)));
  }
}

std::optional<V3> json_v3(const Json& j) {
  if (!j.is_array() || j.size() != 3) return std::nullopt;
  try {
    return V3{parse_rational(j[0], "x").get_d(), parse_rational(j[1], "y").get_d(), parse_rational(j[2], "z").get_d()};
  } catch (const InputError&) {
    return std::nullopt;
  }
}

const Json* at_pointer(const Json& input, const std::string& pointer) {
  try {
    const Json::json_pointer p(pointer);
    return input.contains(p) ? &input.at(p) : nullptr;
  } catch (const std::exception&) {
    return nullptr;
  }
}

}  // namespace

Scene3 Scene3::from_model(const TraceModel& m, const std::vector<std::optional<V3>>& handles) {
  Scene3 sc;
  const TraceView& t = m.trace();
  Box3 all, prims;
  std::vector<V3> points;  // every recorded point: the ray is drawn past the farthest
  for (std::uint32_t g : m.lasting_items()) {
    const Item3 it = item_of(t, g);
    if (it.kind == GeoKind::segment3) continue;  // intervals along a ray may reach far: not what to frame
    if (it.kind == GeoKind::ray3 && !sc.first_ray) sc.first_ray = {it.at(0), it.at(3)};
    add_item(all, it);
    if (it.kind != GeoKind::ray3) add_item(prims, it);
    if (it.kind != GeoKind::ray3 && it.kind != GeoKind::plane) points.push_back(it.at(0));
    if (it.kind == GeoKind::sphere) points.push_back(it.at(0) + V3(it.v[3])), points.push_back(it.at(0) - V3(it.v[3]));
    if (it.kind == GeoKind::box3) points.push_back(it.at(3));
    if (it.kind == GeoKind::triangle3) points.push_back(it.at(3)), points.push_back(it.at(6));
  }
  for (std::size_t s = 0; s < t.size(); ++s)  // the hits and other points of single steps
    for (std::uint32_t g = t.at(s).geo_begin; g < t.at(s).geo_end; ++g)
      if (t.geo_at(g).kind == GeoKind::point3 && t.geo_at(g).life == Life::step) points.push_back(item_of(t, g).at(0));
  for (const auto& h : handles)
    if (h) all.add(*h), points.push_back(*h);
  if (sc.first_ray) {
    const auto [o, d] = *sc.first_ray;
    const double dd = glm::dot(d, d);
    double far = 1;
    for (const V3& p : points)
      if (dd > 0) far = std::max(far, glm::dot(p - o, d) / dd);
    sc.ray_length = far * 1.25;
    all.add(o + sc.ray_length * d);
  }
  if (all.empty()) all.add(V3(-1)), all.add(V3(1));
  sc.centre = 0.5 * (all.lo + all.hi);
  sc.radius = std::max(all.radius(), 1e-6);
  sc.primitive_size = prims.empty() ? sc.radius : std::max(prims.radius(), 1e-6);
  sc.primitive_centre = prims.empty() ? sc.centre : 0.5 * (prims.lo + prims.hi);
  return sc;
}

// [SECTION] editing the declared 3D handles

std::vector<std::optional<V3>> handle_points3(const Algorithm& alg, const Json& input) {
  std::vector<std::optional<V3>> out;
  std::optional<V3> base;
  for (const Handle& h : alg.handles) {
    out.emplace_back();
    if (h.kind == Handle::Kind::point2) continue;
    const Json* v = at_pointer(input, h.pointer);
    const auto p = v ? json_v3(*v) : std::nullopt;
    if (h.kind == Handle::Kind::point3) base = p, out.back() = p;
    else if (p) out.back() = base.value_or(V3(0)) + *p;
  }
  return out;
}

std::optional<Json> handle_edit3(const Algorithm& alg, const Json& input, std::size_t k, V3 p, double snap) {
  const auto at = handle_points3(alg, input);
  if (k >= at.size() || !at[k] || alg.handles[k].kind == Handle::Kind::point2) return std::nullopt;
  auto snapped = [&](V3 q) {
    auto s = [&](double x) { return snap > 0 ? std::round(x / snap) * snap + 0.0 : x; };  // + 0.0: no -0
    return V3{s(q.x), s(q.y), s(q.z)};
  };
  V3 value = snapped(p);
  if (alg.handles[k].kind == Handle::Kind::direction3) {
    value = snapped(p - (*at[k] - *json_v3(*at_pointer(input, alg.handles[k].pointer))));  // p minus the base
    if (value == V3(0)) return std::nullopt;
  }
  Json out = input;
  out[Json::json_pointer(alg.handles[k].pointer)] = Json::array({value.x, value.y, value.z});
  return out;
}

// [SECTION] the canvas: camera input, handles, fit and focus

std::optional<std::array<float, 2>> OrbitCanvas::screen_of(V3 p) const {
  const auto s = cam_.project(p);
  if (!s || (*s)[0] < cam_.origin[0] || (*s)[1] < cam_.origin[1] || (*s)[0] > cam_.origin[0] + cam_.size[0] ||
      (*s)[1] > cam_.origin[1] + cam_.size[1])
    return std::nullopt;
  return std::array<float, 2>{float((*s)[0]), float((*s)[1])};
}

void OrbitCanvas::follow(const Canvas& other) {
  if (const auto* o = dynamic_cast<const OrbitCanvas*>(&other)) {
    const auto origin = cam_.origin, size = cam_.size;
    cam_ = o->cam_;
    cam_.origin = origin, cam_.size = size;
    fit_pending_ = false;
  }
}

// Looks at the first ray from its side (a little ahead of square on), so that it never points at
// the eye.
void OrbitCanvas::face(const Scene3& sc) {
  orient_pending_ = false;
  if (!sc.first_ray) return;
  const V3 d = sc.first_ray->second;
  if (std::hypot(d.x, d.y) < 1e-3 * glm::length(d)) return;  // vertical ray: any yaw will do
  cam_.yaw = std::atan2(d.y, d.x) - M_PI / 2 + 0.5;
  cam_.pitch = 0.6;
}

void OrbitCanvas::focus(const TraceModel& m, std::size_t step, double) {
  // Centre on the latest 3D point at or before the step (hit, closest approach), else on the
  // primitives, framing them around it: what matters when the whole scene is 1e8 units wide.
  const Scene3 sc = Scene3::from_model(m, handle_points3(m.algorithm(), m.input()));
  std::optional<V3> at;
  const TraceView& t = m.trace();
  for (std::size_t s = std::min(step, m.last()) + 1; s-- > 0 && !at;)
    for (std::uint32_t g = t.at(s).geo_begin; g < t.at(s).geo_end; ++g)
      if (t.geo_at(g).kind == GeoKind::point3) at = item_of(t, g).at(0);
  if (!at) at = sc.primitive_centre;  // no point yet: the primitive itself
  face(sc);
  cam_.frame(*at, std::min(2.5 * sc.primitive_size, sc.radius));
  fit_pending_ = false;
}

void OrbitCanvas::keep_in_view(const TraceModel& m, std::size_t step) {
  // The step's own points (a hit, a closest approach): if one is off the canvas or behind the
  // eye, look at it from where the camera is (same distance: the zoom stays).
  const TraceView& t = m.trace();
  const StepRecord& st = t.at(std::min(step, m.last()));
  for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g)
    if (t.geo_at(g).kind == GeoKind::point3) {
      const V3 p = item_of(t, g).at(0);
      if (!screen_of(p)) cam_.target = p;
      return;
    }
}

void OrbitCanvas::handle_input(const CanvasInput& in, const std::vector<std::optional<V3>>& handles, bool hovered, CanvasEvents& ev) {
  const ImGuiIO& io = ImGui::GetIO();
  if (hovered && io.MouseWheel != 0) cam_.zoom(std::pow(1.2, -io.MouseWheel));
  if (in.keys && !io.WantTextInput) {
    for (ImWchar ch : io.InputQueueCharacters)
      if (ch == 'f' || ch == 'F') fit_pending_ = true;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_PageUp))) cam_.zoom(1 / 1.25);
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_PageDown))) cam_.zoom(1.25);
  }
  if (ImGui::IsItemActivated()) {
    dragging_ = ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !io.KeyShift ? kOrbit : kPan;
    // The last handle first: at a tiny direction o and o + d overlap, and d is the one to pull out.
    for (std::size_t h = handles.size(); dragging_ == kOrbit && in.editable && h-- > 0;)
      if (const auto s = handles[h] ? cam_.project(*handles[h]) : std::nullopt) {
        const double dx = io.MousePos.x - (*s)[0], dy = io.MousePos.y - (*s)[1];
        if (dx * dx + dy * dy <= 11.0 * 11.0) dragging_ = int(h), drag_anchor_ = *handles[h];
      }
  }
  if (ImGui::IsItemActive() && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
    if (dragging_ == kOrbit) cam_.orbit(-io.MouseDelta.x * 0.01, io.MouseDelta.y * 0.01);
    if (dragging_ == kPan) cam_.pan(io.MouseDelta.x, io.MouseDelta.y);
    if (dragging_ >= 0) {
      // Move in the plane facing the camera through the handle; snap to a power of two about a
      // pixel wide there, so that the numbers stay short and float-representable.
      const V3 p = cam_.unproject_on_facing_plane(io.MousePos.x, io.MousePos.y, drag_anchor_);
      const double snap = std::exp2(std::floor(std::log2(cam_.units_per_pixel(drag_anchor_))));
      const Json& input = in.model->input();
      if (auto edited = handle_edit3(in.model->algorithm(), input, std::size_t(dragging_), p, snap); edited && *edited != input) ev.edit = std::move(edited);
    }
  }
  if (ImGui::IsItemDeactivated()) dragging_ = -1;
}

CanvasEvents OrbitCanvas::draw(const CanvasInput& in, ImVec2 size) {
  CanvasEvents ev;
  size.x = std::max(size.x, 16.f), size.y = std::max(size.y, 16.f);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  cam_.origin = {origin.x, origin.y}, cam_.size = {size.x, size.y};
  ImGui::InvisibleButton("##canvas3d", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), theme::kCanvasBg);
  bool can_edit = false;
  if (in.model) {
    const auto handles = handle_points3(in.model->algorithm(), in.model->input());
    const Scene3 sc = Scene3::from_model(*in.model, handles);
    if (fit_pending_) {
      if (orient_pending_) face(sc);
      cam_.frame(sc.centre, sc.radius);
      cam_.pan(0, 0.06 * cam_.size[1]);  // a little lower: the step's values are listed top left
      fit_pending_ = false;
    }
    handle_input(in, handles, hovered, ev);
    if (in.follow && dragging_ == -1) keep_in_view(*in.model, in.step);
    labels_ = draw_scene3(dl, cam_, sc, *in.model, in.step, handles, in.editable ? dragging_ : -1);
    for (const auto& h : handles) can_edit = can_edit || (in.editable && h);
  }
  const char* help = "drag: orbit   right/shift-drag: pan   wheel: zoom   F: fit   drag a handle: edit the input";
  if (!can_edit || ImGui::CalcTextSize(help).x > size.x - 16) help = "drag: orbit   right-drag: pan   wheel: zoom   F: fit";
  if (ImGui::CalcTextSize(help).x <= size.x - 16) dl->AddText(ImVec2(origin.x + 8, origin.y + size.y - ImGui::GetFontSize() - 6), theme::kLabel, help);
  corner_label(dl, origin, size, in.label);
  dl->PopClipRect();
  return ev;
}

}  // namespace sw::vis
