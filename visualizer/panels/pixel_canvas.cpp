// [SECTION] view transforms
// [SECTION] input: zoom, pan, drag, hover, click
// [SECTION] drawing: texture, grid, geometry
#include "panels/pixel_canvas.hpp"
#include "panels/orbit_canvas.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>
#include "panels/theme.hpp"

namespace sw::vis {

// [SECTION] view transforms

ImVec2 PixelCanvas::to_screen(double x, double y) const {
  return ImVec2(float(origin_.x + size_.x * 0.5 + (x - cx_) * scale_), float(origin_.y + size_.y * 0.5 - (y - cy_) * scale_));
}

std::array<double, 2> PixelCanvas::to_world(ImVec2 p) const {
  return {cx_ + (p.x - origin_.x - size_.x * 0.5) / scale_, cy_ - (p.y - origin_.y - size_.y * 0.5) / scale_};
}

WorldRect PixelCanvas::visible() const {
  const auto a = to_world(origin_), b = to_world(ImVec2(origin_.x + size_.x, origin_.y + size_.y));
  return {a[0], b[1], b[0], a[1]};
}

void PixelCanvas::do_fit(const TraceModel& m) {
  WorldRect b = m.bounds();
  if (b.empty()) b = {-4, -4, 4, 4};
  const double w = std::max(b.x1 - b.x0, 4.0), h = std::max(b.y1 - b.y0, 4.0);
  cx_ = (b.x0 + b.x1) / 2, cy_ = (b.y0 + b.y1) / 2;
  scale_ = std::min(size_.x / (w * 1.15), size_.y / (h * 1.15));
  scale_ = std::clamp(scale_, 1e-6, 96.0);
}

void PixelCanvas::follow(const Canvas& other) {
  if (const auto* o = dynamic_cast<const PixelCanvas*>(&other)) {
    cx_ = o->cx_, cy_ = o->cy_, scale_ = o->scale_;
    fit_pending_ = false;
  }
}

void PixelCanvas::focus(const TraceModel& m, std::size_t step, double min_scale) {
  std::optional<std::array<double, 2>> at = m.point_at(step);
  if (auto px = m.pixel_at(step)) at = std::array<double, 2>{double(px->x), double(px->y)};
  if (!at) return;
  cx_ = (*at)[0], cy_ = (*at)[1];
  scale_ = std::max(scale_, min_scale);
  fit_pending_ = false;
}

std::optional<std::array<float, 4>> PixelCanvas::cell_rect(Pixel c) const {
  const ImVec2 a = to_screen(double(c.x) - 0.5, double(c.y) + 0.5), b = to_screen(double(c.x) + 0.5, double(c.y) - 0.5);
  if (a.x < origin_.x || a.y < origin_.y || b.x > origin_.x + size_.x || b.y > origin_.y + size_.y) return std::nullopt;
  return std::array<float, 4>{a.x, a.y, b.x, b.y};
}

// [SECTION] input: zoom, pan, drag, hover, click

void PixelCanvas::handle_view_input(bool hovered, bool keys) {
  const ImGuiIO& io = ImGui::GetIO();
  auto zoom_at = [&](ImVec2 anchor, double factor) {
    const auto before = to_world(anchor);
    scale_ = std::clamp(scale_ * factor, 1e-6, 400.0);
    const auto after = to_world(anchor);
    cx_ += before[0] - after[0], cy_ += before[1] - after[1];
  };
  if (hovered && io.MouseWheel != 0) zoom_at(io.MousePos, std::pow(1.2, io.MouseWheel));
  if (!keys || io.WantTextInput) return;
  const ImVec2 centre(origin_.x + size_.x / 2, origin_.y + size_.y / 2);
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_PageUp))) zoom_at(centre, 1.25);
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_PageDown))) zoom_at(centre, 1 / 1.25);
  if (io.KeyShift) {  // Shift + arrows pan by a tenth of the view
    const double step = 0.1 * std::min(size_.x, size_.y) / scale_;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow))) cx_ -= step;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow))) cx_ += step;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_UpArrow))) cy_ += step;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_DownArrow))) cy_ -= step;
  }
  for (ImWchar ch : io.InputQueueCharacters)
    if (ch == 'f' || ch == 'F') fit_pending_ = true;
}

CanvasEvents PixelCanvas::draw(const CanvasInput& in, ImVec2 size) {
  CanvasEvents ev;
  size.x = std::max(size.x, 16.f), size.y = std::max(size.y, 16.f);
  origin_ = ImGui::GetCursorScreenPos();
  size_ = size;
  ImGui::InvisibleButton("##canvas", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered(), active = ImGui::IsItemActive();
  handle_view_input(hovered, in.keys);
  // After the keys, so that F fits before the compare view's other canvas follows (and clears) it.
  if (in.model && fit_pending_) do_fit(*in.model), fit_pending_ = false;
  if (in.follow && in.model && !active) {  // playing: pan when the current point leaves the view
    std::optional<std::array<double, 2>> at = in.model->point_at(in.step);
    if (auto px = in.model->pixel_at(in.step)) at = std::array<double, 2>{double(px->x), double(px->y)};
    const WorldRect v = visible();
    const double mx = (v.x1 - v.x0) * 0.05, my = (v.y1 - v.y0) * 0.05;
    if (at && ((*at)[0] < v.x0 + mx || (*at)[0] > v.x1 - mx || (*at)[1] < v.y0 + my || (*at)[1] > v.y1 - my))
      cx_ = (*at)[0], cy_ = (*at)[1];
  }
  const ImGuiIO& io = ImGui::GetIO();
  static const std::vector<std::optional<std::array<double, 2>>> kNone;
  const auto& handles = in.model ? in.model->handle_points() : kNone;

  // A press on a declared handle drags it; anywhere else it pans.
  if (ImGui::IsItemActivated()) {
    moved_ = false;
    dragging_ = -1;
    if (in.editable && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
      for (std::size_t h = 0; h < handles.size(); ++h) {
        if (!handles[h]) continue;
        const ImVec2 p = to_screen((*handles[h])[0], (*handles[h])[1]);
        const float dx = io.MousePos.x - p.x, dy = io.MousePos.y - p.y;
        if (dx * dx + dy * dy <= 10.f * 10.f) dragging_ = static_cast<int>(h);
      }
  }
  if (active && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
    moved_ = true;
    if (dragging_ >= 0) {
      const auto w = to_world(io.MousePos);
      ev.drag = CanvasEvents::Drag{dragging_, w[0], w[1], false};
    } else {
      cx_ -= io.MouseDelta.x / scale_, cy_ += io.MouseDelta.y / scale_;
    }
  }
  if (ImGui::IsItemDeactivated()) {
    if (dragging_ >= 0 && moved_) {
      const auto w = to_world(io.MousePos);
      ev.drag = CanvasEvents::Drag{dragging_, w[0], w[1], true};
    } else if (!moved_ && in.model) {
      const auto w = to_world(io.MousePos);
      const Pixel c{std::int64_t(std::floor(w[0] + 0.5)), std::int64_t(std::floor(w[1] + 0.5))};
      const std::uint32_t s = in.model->step_of_cell(c);
      ev.clicked_cell = c;
      if (s != kNoStep && !(in.hide_future && s > in.step)) ev.jump_to = s;
    }
    dragging_ = -1;
  }

  // [SECTION] drawing: texture, grid, geometry
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(origin_, ImVec2(origin_.x + size.x, origin_.y + size.y), true);
  dl->AddRectFilled(origin_, ImVec2(origin_.x + size.x, origin_.y + size.y), theme::kCanvasBg);
  if (in.model && layer_.prepare(in.model, visible(), scale_, in.step)) {
    const WorldRect w = layer_.window().world();
    dl->AddImage(layer_.texture(), to_screen(w.x0, w.y1), to_screen(w.x1, w.y0));
  }
  draw_grid(dl);
  if (in.model) {
    const WorldRect v = visible();
    outline_.draw(dl, in.model, {v.x0, v.y0, v.x1, v.y1}, 3 / scale_, [&](double x, double y) { return to_screen(x, y); });
  }
  if (in.model) draw_geometry(dl, in);
  draw_marked(dl, in.marked);

  // Hover: which cell, and which step plotted it.
  if (hovered && in.model && dragging_ < 0) {
    const auto w = to_world(io.MousePos);
    const Pixel c{std::int64_t(std::floor(w[0] + 0.5)), std::int64_t(std::floor(w[1] + 0.5))};
    if (const auto r = cell_rect(c); r && scale_ >= 4) {
      dl->AddRect(ImVec2((*r)[0], (*r)[1]), ImVec2((*r)[2], (*r)[3]), theme::kHover, 0, 0, 1.5f);
    }
    std::uint32_t s = in.model->step_of_cell(c);
    if (in.hide_future && s != kNoStep && s > in.step) s = kNoStep;
    ImGui::BeginTooltip();
    ImGui::Text("cell (%lld, %lld)   at x = %.3f, y = %.3f", (long long)c.x, (long long)c.y, w[0], w[1]);
    if (s == kNoStep) ImGui::TextColored(theme::kDim, in.hide_future ? "not plotted so far" : "never plotted");
    else ImGui::Text("plotted at step %u%s - click to jump there", s, s > in.step ? " (later)" : "");
    ImGui::EndTooltip();
  }
  corner_label(dl, origin_, size, in.label);
  dl->PopClipRect();
  return ev;
}

void PixelCanvas::draw_grid(ImDrawList* dl) const {
  const WorldRect v = visible();
  const ImVec2 lo(origin_.x, origin_.y), hi(origin_.x + size_.x, origin_.y + size_.y);
  if (scale_ >= 6) {
    // Cell edges lie at half-integers: pixel (i, j) is [i-1/2, i+1/2) x [j-1/2, j+1/2).
    for (double x = std::floor(v.x0) + 0.5; x <= v.x1; x += 1) {
      const float sx = to_screen(x, 0).x;
      dl->AddLine(ImVec2(sx, lo.y), ImVec2(sx, hi.y), theme::kGrid);
    }
    for (double y = std::floor(v.y0) + 0.5; y <= v.y1; y += 1) {
      const float sy = to_screen(0, y).y;
      dl->AddLine(ImVec2(lo.x, sy), ImVec2(hi.x, sy), theme::kGrid);
    }
  }
  // Pixel centres: the points the DDA samples against.
  if (scale_ >= 14) {
    for (double x = std::ceil(v.x0); x <= v.x1; x += 1)
      for (double y = std::ceil(v.y0); y <= v.y1; y += 1) dl->AddCircleFilled(to_screen(x, y), std::min(2.5f, float(scale_) / 12), theme::kCentre, 6);
  }
  // Index labels on translucent strips along the bottom and left edges, every n-th index with n
  // from 1, 2, 5, 10, 20, ... so that labels never touch.
  auto widest = [](double a, double b) { return ImGui::CalcTextSize(std::to_string((long long)std::max(std::fabs(a), std::fabs(b)) * -1).c_str()).x; };
  const float label_w = widest(v.x0, v.x1) + 14, strip_w = widest(v.y0, v.y1) + 10;
  long long every = 0;
  for (long long base = 1; !every && base < (1LL << 50); base *= 10)
    for (long long m : {1, 2, 5})
      if (!every && double(base * m) * scale_ >= label_w) every = base * m;
  if (!every) return;
  dl->AddRectFilled(ImVec2(lo.x, hi.y - 20), hi, IM_COL32(16, 18, 24, 200));
  dl->AddRectFilled(lo, ImVec2(lo.x + strip_w, hi.y - 20), IM_COL32(16, 18, 24, 200));
  char buf[24];
  for (long long i = (long long)std::ceil(v.x0 / double(every)) * every; double(i) <= v.x1; i += every) {
    const float sx = to_screen(double(i), 0).x;
    std::snprintf(buf, sizeof buf, "%lld", i);
    const float w = ImGui::CalcTextSize(buf).x;
    if (sx - w / 2 > lo.x + strip_w) dl->AddText(ImVec2(sx - w / 2, hi.y - 18), theme::kLabel, buf);
  }
  for (long long j = (long long)std::ceil(v.y0 / double(every)) * every; double(j) <= v.y1; j += every) {
    const float sy = to_screen(0, double(j)).y;
    std::snprintf(buf, sizeof buf, "%lld", j);
    if (sy < hi.y - 26) dl->AddText(ImVec2(lo.x + 4, sy - 8), theme::kLabel, buf);
  }
}

void PixelCanvas::paint_items(ImDrawList* dl, const TraceModel& m, std::size_t step) const {
  const TraceView& t = m.trace();
  // Zoomed out, the pixels are thinner than the lines: draw those faint so that the pixels show.
  const ImU32 line_col = scale_ < 4 ? IM_COL32(240, 240, 245, 110) : theme::kSegment;
  const float thick = scale_ < 4 ? 1.f : 2.f;
  struct Label { ImVec2 at; ImU32 col; std::string text; };
  std::vector<Label> labels;
  for (std::uint32_t g : m.visible_items(step)) {
    const GeoRecord& geo = t.geo_at(g);
    const auto value = t.geo_value(geo);
    const ImU32 col = value ? theme::sign_colour(*value) : line_col;
    auto at = [&](int k) { return to_screen(t.geo_double(geo, k), t.geo_double(geo, k + 1)); };
    ImVec2 label_at;
    switch (geo.kind) {
      case GeoKind::segment2:
      case GeoKind::arrow:
        dl->AddLine(at(0), at(2), col, thick);
        if (geo.kind == GeoKind::arrow) dl->AddCircleFilled(at(2), 3.5f, col, 12);
        label_at = at(2);
        break;
      case GeoKind::polyline:
      case GeoKind::polygon: {
        std::vector<ImVec2> pts;
        for (int k = 0; k + 1 < geo.count; k += 2) pts.push_back(at(k));
        dl->AddPolyline(pts.data(), int(pts.size()), col, geo.kind == GeoKind::polygon ? ImDrawFlags_Closed : ImDrawFlags_None, thick);
        label_at = pts.back();
        break;
      }
      case GeoKind::circle: {
        const float r = float(t.geo_double(geo, 2) * scale_);
        dl->AddCircle(at(0), r, col, std::clamp(int(r), 24, 512), thick);
        label_at = ImVec2(at(0).x + r * 0.71f, at(0).y - r * 0.71f);
        break;
      }
      case GeoKind::rect: dl->AddRect(at(2), at(0), col, 0, 0, thick), label_at = at(2); break;
      case GeoKind::node2: {  // a tree node: its bounds, and its id in the corner
        dl->AddRect(at(4), at(2), col, 0, 0, thick);
        char id[24];
        std::snprintf(id, sizeof id, "%lld", (long long)t.geo_double(geo, 0));
        dl->AddText(ImVec2(at(2).x + 3, at(4).y + 2), theme::kLabel, id);
        label_at = at(4);
        break;
      }
      case GeoKind::span: {  // row j from column i0 to i1, cells included
        const double j = t.geo_double(geo, 0), i0 = t.geo_double(geo, 1), i1 = t.geo_double(geo, 2);
        label_at = to_screen(i1 + 0.5, j + 0.5);
        dl->AddRect(to_screen(i0 - 0.5, j + 0.5), to_screen(i1 + 0.5, j - 0.5), col, 0, 0, thick);
        break;
      }
      case GeoKind::point2:  // the moving point is drawn by draw_geometry; these carry a value or stay
        if (!value && geo.life == Life::step) continue;
        dl->AddCircleFilled(at(0), 5.f, value ? col : theme::kQ, 16);
        dl->AddCircle(at(0), 5.f, IM_COL32(0, 0, 0, 255), 16, 1.5f);
        label_at = at(0);
        break;
      default: continue;  // pixels (the pixel layer) and 3D kinds
    }
    if (!geo.label) continue;
    char buf[64];
    if (value) std::snprintf(buf, sizeof buf, "%s = %.6g", geo.label, *value);
    labels.push_back({ImVec2(label_at.x + 8, label_at.y + 2), value ? col : theme::kLabel, value ? buf : geo.label});
  }
  // Labels last, newest first (the current step's win), and none over another: where many kept
  // items end at one place (lines across a cell), one readable label beats a stack of them.
  std::vector<ImVec4> placed;
  for (auto l = labels.rbegin(); l != labels.rend(); ++l) {
    const ImVec2 size = ImGui::CalcTextSize(l->text.c_str());
    const ImVec4 r(l->at.x, l->at.y, l->at.x + size.x, l->at.y + size.y);
    const bool covers = std::any_of(placed.begin(), placed.end(), [&](const ImVec4& q) { return r.x < q.z && q.x < r.z && r.y < q.w && q.y < r.w; });
    if (covers) continue;
    placed.push_back(r);
    dl->AddText(l->at, l->col, l->text.c_str());
  }
}

void PixelCanvas::draw_geometry(ImDrawList* dl, const CanvasInput& in) const {
  const TraceModel& m = *in.model;
  if (auto px = m.pixel_at(in.step)) {
    const ImVec2 a = to_screen(double(px->x) - 0.5, double(px->y) + 0.5), b = to_screen(double(px->x) + 0.5, double(px->y) - 0.5);
    dl->AddRect(ImVec2(a.x - 1, a.y - 1), ImVec2(b.x + 1, b.y + 1), theme::kCurrentPixel, 0, 0, 2.5f);
  }
  paint_items(dl, m, in.step);
  // The inputs the algorithm declares as handles, where the input holds them.
  const auto& handles = m.handle_points();
  const auto& decl = m.algorithm().handles;
  for (std::size_t h = 0; h < handles.size(); ++h) {
    if (!handles[h]) continue;
    const ImU32 col = h % 2 ? theme::kHandleP1 : theme::kHandleP0;
    const ImVec2 at = to_screen((*handles[h])[0], (*handles[h])[1]);
    dl->AddCircleFilled(at, 6.5f, col, 16);
    dl->AddCircle(at, 6.5f, IM_COL32(0, 0, 0, 255), 16, 1.5f);
    if (in.editable && dragging_ == static_cast<int>(h)) dl->AddCircle(at, 11.f, col, 20, 2.f);
    dl->AddText(ImVec2(at.x + 9, at.y - 20), col, decl[h].label.c_str());
  }
  const char* q_label = nullptr;
  if (auto q = m.point_at(in.step, &q_label)) {
    const ImVec2 p = to_screen((*q)[0], (*q)[1]);
    dl->AddCircleFilled(p, 5.f, theme::kQ, 16);
    dl->AddCircle(p, 5.f, IM_COL32(0, 0, 0, 255), 16, 1.5f);
    if (q_label) dl->AddText(ImVec2(p.x + 8, p.y + 2), theme::kQ, q_label);
  }
}

}  // namespace sw::vis
