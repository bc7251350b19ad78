#include "panels/lobe_view.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include "lessons/result_keys.hpp"
#include "panels/chart.hpp"  // nice_ceil
#include "panels/theme.hpp"

namespace sw::vis {
namespace {

constexpr double kDegree = 3.141592653589793 / 180;
constexpr double kScaleWithin = 80;  // degrees from the normal that set the outer ring
constexpr ImU32 kModeCurve = IM_COL32(255, 190, 90, 255);
constexpr ImU32 kReferenceCurve = IM_COL32(235, 235, 245, 150);

std::string short_value(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

}  // namespace

ImVec2 LobeCanvas::at(double deg, double value) const {
  // Terms that grow without bound at a grazing eye (Beckmann's 1/(n.e)) are drawn off the canvas,
  // at four outer rings, not at float's largest value.
  const double r = std::min(value / full_ * radius_ * zoom_, 4.0 * radius_);
  return ImVec2(centre_.x + float(r * std::sin(deg * kDegree)), centre_.y - float(r * std::cos(deg * kDegree)));
}

ImVec2 LobeCanvas::sample_point(std::size_t i) const {
  return i < lobe_.mode.size() ? at(lobe_.grid.x(int(i)), lobe_.mode[i]) : ImVec2(NAN, NAN);
}

void LobeCanvas::follow(const Canvas& other) {
  if (const auto* o = dynamic_cast<const LobeCanvas*>(&other)) zoom_ = o->zoom_, other_peak_ = o->peak_;
}

CanvasEvents LobeCanvas::draw(const CanvasInput& in, ImVec2 size) {
  CanvasEvents ev;
  size.x = std::max(size.x, 16.f), size.y = std::max(size.y, 16.f);
  const ImVec2 origin = ImGui::GetCursorScreenPos(), end(origin.x + size.x, origin.y + size.y);
  ImGui::InvisibleButton("##lobe", size, ImGuiButtonFlags_MouseButtonLeft);
  const bool hovered = ImGui::IsItemHovered();
  const ImGuiIO& io = ImGui::GetIO();
  if (in.model) keep_ = in.model;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(origin, end, true);
  dl->AddRectFilled(origin, end, theme::kCanvasBg);
  if (!in.model || !in.model->algorithm().lobe || in.hide_sweep) {
    if (in.hide_sweep) sweep_hidden_note(dl, origin);
    else dl->AddText(ImVec2(origin.x + 10, origin.y + 10), theme::kLabel, "This algorithm declares no lobe.");
    dl->PopClipRect();
    return ev;
  }
  const Algorithm& alg = in.model->algorithm();
  if (hovered && io.MouseWheel != 0) zoom_ = std::clamp(zoom_ * std::pow(1.25, io.MouseWheel), 1e-3, 1e6);
  if (hovered && !io.WantTextInput)
    for (ImWchar ch : io.InputQueueCharacters)
      if (ch == 'f' || ch == 'F') fit();
  if (swept_ != in.model.get()) {
    swept_ = in.model.get();
    SweepGrid g;
    g.w = kDirections, g.h = 1, g.dx = 180.0 / (kDirections - 1), g.dy = 1;
    try {
      lobe_ = sweep_image(*in.model, g, true);
      error_.clear();
    } catch (const std::exception& e) {
      lobe_ = SweepImage{g, {}, {}};
      error_ = e.what();
    }
    // The peak within 80 degrees of the normal sets the scale: some terms grow without bound
    // towards a grazing eye.
    peak_ = 0;
    for (const auto* vs : {&lobe_.exact, &lobe_.mode})
      for (std::size_t i = 0; i < vs->size(); ++i)
        if (std::isfinite((*vs)[i]) && std::fabs(lobe_.grid.x(int(i))) <= kScaleWithin) peak_ = std::max(peak_, double((*vs)[i]));
  }
  // The scale: the outer ring is a round value at or above both curves' peak within 80 degrees
  // of the normal (and the other canvas's, side by side, so that two models share it).
  const double peak = std::max(peak_, other_peak_);
  other_peak_ = 0;  // follow() sets it again every frame while side by side
  full_ = peak > 0 ? nice_ceil(peak) : 1;
  const float label_h = ImGui::GetTextLineHeight();
  centre_ = ImVec2(origin.x + size.x / 2, end.y - 2 * label_h - 8);
  radius_ = std::max(20.f, std::min(size.x / 2 - 30, centre_.y - origin.y - 5 * label_h - 20));
  // Rings at quarters of the outer value, the surface, the normal.
  for (int q = 1; q <= 4; ++q) {
    const double v = full_ * q / 4 / zoom_;
    const float r = radius_ * float(q) / 4;
    dl->PathArcTo(centre_, r, -3.14159265f, 0.f, 48);
    dl->PathStroke(q == 4 ? theme::kGridAxis : theme::kGrid, 0, 1.f);
    dl->AddText(ImVec2(centre_.x + r - 10, centre_.y + 3), theme::kLabel, short_value(v).c_str());
  }
  dl->AddLine(ImVec2(origin.x + 8, centre_.y), ImVec2(end.x - 8, centre_.y), theme::kSegment, 2.f);
  auto ray = [&](double deg, ImU32 col, const char* label, bool dashed) {
    const ImVec2 tip = at(deg, full_ / zoom_ * 1.08);
    if (dashed) {
      for (int k = 0; k < 16; k += 2)
        dl->AddLine(at(deg, full_ / zoom_ * 1.08 * k / 16), at(deg, full_ / zoom_ * 1.08 * (k + 1) / 16), col, 1.5f);
    } else {
      dl->AddLine(centre_, tip, col, 2.f);
    }
    const float w = ImGui::CalcTextSize(label).x;
    dl->AddText(ImVec2(std::clamp(tip.x - 4, origin.x + 4, end.x - w - 4), tip.y - label_h - 2), col, label);
  };
  ray(0, theme::kLabel, "n", false);
  const auto angles = in.model->run().lobe_angles();
  if (angles && std::isfinite((*angles)[0])) {
    ray((*angles)[0], theme::kQ, "l", false);
    ray(-(*angles)[0], theme::kQ, "mirror", true);
  }
  // The curves: the reference under the mode, broken where a direction has no value.
  auto curve = [&](const std::vector<float>& vs, ImU32 col, float width) {
    for (std::size_t i = 0; i < vs.size(); ++i) {
      if (!std::isfinite(vs[i])) {
        if (dl->_Path.Size > 1) dl->PathStroke(col, 0, width);
        dl->PathClear();
        continue;
      }
      dl->PathLineTo(at(lobe_.grid.x(int(i)), vs[i]));
    }
    if (dl->_Path.Size > 1) dl->PathStroke(col, 0, width);
    dl->PathClear();
  };
  const bool self = in.model->numeric() == lobe_.reference;
  if (!self) curve(lobe_.exact, kReferenceCurve, 1.f);
  curve(lobe_.mode, kModeCurve, 2.5f);
  for (std::size_t i = 0; i < lobe_.samples(); ++i)
    if (lobe_.disagreement(i)) dl->AddCircleFilled(at(lobe_.grid.x(int(i)), std::isfinite(lobe_.mode[i]) ? lobe_.mode[i] : 0.f), 3.5f, kSweepFalseHit);
  // The input's own eye, where it lies in the plane.
  if (angles && std::isfinite((*angles)[1])) {
    ray((*angles)[1], theme::kHandleP0, "e", false);
    if (const Json* v = read_result(*in.model, result_reads::lobe_value); v && v->is_number())
      dl->AddCircleFilled(at((*angles)[1], v->get<double>()), 5.f, theme::kHandleP0);
  }
  // Hover: the direction under the mouse; a click traces it.
  if (hovered && lobe_.samples() && io.MousePos.y < centre_.y) {
    const double deg = std::atan2(io.MousePos.x - centre_.x, centre_.y - io.MousePos.y) / kDegree;
    const int i = std::clamp(int(std::lround((deg - lobe_.grid.x(0)) / lobe_.grid.dx)), 0, lobe_.grid.w - 1);
    const double d = lobe_.grid.x(i);
    dl->AddLine(centre_, at(d, full_ / zoom_), theme::kHover, 1.f);
    const std::string mode(numeric_name(in.model->numeric())), ref(numeric_name(lobe_.reference));
    auto say = [](float v) { return std::isfinite(v) ? short_value(v) : std::string("none"); };
    ImGui::SetTooltip("eye at %.1f degrees from the normal\n%s: %s\n%s: %s%s", d, mode.c_str(), say(lobe_.mode[std::size_t(i)]).c_str(), ref.c_str(),
                      say(lobe_.exact[std::size_t(i)]).c_str(), in.editable && alg.lobe.sample ? "\nclick: trace this direction" : "");
    if (ImGui::IsItemClicked() && in.editable && alg.lobe.sample) {
      try {
        ev.edit = in.model->run().lobe_sample(lobe_.grid, i);
      } catch (const std::exception& e) {
        error_ = e.what();
      }
    }
  }
  // The count and the legend.
  const std::string mode(numeric_name(in.model->numeric())), ref(numeric_name(lobe_.reference));
  char lines[3][200];
  if (!error_.empty()) std::snprintf(lines[0], sizeof lines[0], "sweep failed: %s", error_.c_str());
  else if (self) std::snprintf(lines[0], sizeof lines[0], "%s: the term over %zu eye directions", ref.c_str(), lobe_.samples());
  else std::snprintf(lines[0], sizeof lines[0], "%s: %zu of %zu directions off %s by > 1/255", mode.c_str(), lobe_.disagreements(), lobe_.samples(), ref.c_str());
  std::size_t top = lobe_.samples() / 2;  // the reference's peak within 80 degrees of the normal
  bool beyond = false;                    // a value past the outer ring near grazing
  for (std::size_t i = 0; i < lobe_.exact.size(); ++i) {
    if (!std::isfinite(lobe_.exact[i])) continue;
    if (std::fabs(lobe_.grid.x(int(i))) <= kScaleWithin && !(lobe_.exact[i] <= lobe_.exact[top])) top = i;
    beyond = beyond || lobe_.exact[i] > full_ / zoom_;
  }
  const bool eye_in_plane = angles && std::isfinite((*angles)[1]);
  std::snprintf(lines[1], sizeof lines[1], "light at %.1f deg; peak %s at %.1f deg%s", angles ? -(*angles)[0] : NAN,
                lobe_.samples() ? short_value(lobe_.exact[top]).c_str() : "-", lobe_.samples() ? lobe_.grid.x(int(top)) : NAN,
                beyond ? "; past the ring near grazing" : "");
  if (self) std::snprintf(lines[2], sizeof lines[2], "swept in %.1f ms%s", lobe_.mode_ms, eye_in_plane ? "" : "; the eye is off this plane");
  else std::snprintf(lines[2], sizeof lines[2], "swept in %.1f + %.1f ms%s", lobe_.mode_ms, lobe_.exact_ms, eye_in_plane ? "" : "; the eye is off this plane");
  const float y0 = origin.y + (*in.label ? label_h + 8 : 4);  // under the corner label, side by side
  status_plate(dl, ImVec2(origin.x + 4, y0), lines, lobe_.disagreements() || !error_.empty());
  float lx = origin.x + 8;
  const float ly = end.y - label_h - 4;
  auto key = [&](ImU32 col, const std::string& text) {
    dl->AddLine(ImVec2(lx, ly + label_h / 2), ImVec2(lx + 16, ly + label_h / 2), col, 2.5f);
    dl->AddText(ImVec2(lx + 21, ly), theme::kLabel, text.c_str());
    lx += 21 + ImGui::CalcTextSize(text.c_str()).x + 16;
  };
  key(kModeCurve, mode);
  if (!self) key(kReferenceCurve, ref), key(kSweepFalseHit, "differs by > 1/255");
  corner_label(dl, origin, size, in.label);
  dl->PopClipRect();
  return ev;
}

}  // namespace sw::vis
