#include "panels/layout.hpp"
#include <imgui_internal.h>
#include <algorithm>
#include <cstdio>
#include <string>
#include "input.hpp"
#include "panels/theme.hpp"

namespace sw::vis {

PanelLayout layout_panels(const LayoutInput& in) {
  const float W = in.display.x, H = in.display.y, em = in.em;
  PanelLayout l;
  l.em = em;
  // Toolbar and timeline are as tall as their (wrapped) rows, within a third of the height each.
  const float top = std::clamp(in.toolbar_h > 0 ? in.toolbar_h : 5.5f * em, 2.f * em, H / 3);
  const float bottom = std::clamp(in.timeline_h > 0 ? in.timeline_h : 6.5f * em, 3.f * em, H / 3);
  const float mid = std::max(H - top - bottom, 0.f);
  // The side column: listing over state; narrower when presenting, never over 45% of the width.
  const float right =
      std::min(in.presenting ? std::clamp(W * 0.30f, 16 * em, 30 * em) : std::clamp(W * 0.37f, 22 * em, 37 * em), W * 0.45f);
  const float left = W - right;
  // Narration under the canvas; the canvas keeps at least 55% of the middle.
  float narration_h =
      in.lesson ? std::clamp(mid * (in.presenting ? 0.33f : 0.25f), (in.quiz ? 12 : 7) * em, (in.presenting ? 22 : 15) * em) : 5 * em;
  narration_h = std::min(narration_h, mid * 0.45f);
  // The listing as tall as its text (up to 65%), the state panel at least 6 em under it.
  float listing_h = in.presenting ? mid : std::min(in.listing_content_h > 0 ? in.listing_content_h : mid * 0.5f, mid * 0.65f);
  if (!in.presenting) listing_h = std::max(std::min(listing_h, mid - 6 * em), mid * 0.3f);
  l.toolbar = {ImVec2(0, 0), ImVec2(W, top)};
  l.canvas = {ImVec2(0, top), ImVec2(left, mid - narration_h)};
  l.narration = {ImVec2(0, top + mid - narration_h), ImVec2(left, narration_h)};
  l.listing = {ImVec2(left, top), ImVec2(right, listing_h)};
  l.state = {ImVec2(left, top + listing_h), ImVec2(right, in.presenting ? 0 : mid - listing_h)};
  l.timeline = {ImVec2(0, top + mid), ImVec2(W, bottom)};
  return l;
}

void check_scale(double scale) {
  if (!(scale >= theme::kMinScale && scale <= theme::kMaxScale)) {  // also refuses NaN
    char text[48];
    std::snprintf(text, sizeof text, "%g", scale);
    throw InputError("--scale " + std::string(text) + ": expected a UI scale from 0.75 to 3");
  }
}

float content_height() {
  const ImGuiWindow* w = ImGui::GetCurrentWindow();
  return w->DC.CursorMaxPos.y - w->Pos.y + w->WindowPadding.y;
}

void flow(float width, float gap) {
  ImGui::SameLine(0, gap);
  if (ImGui::GetCursorPosX() + width > ImGui::GetWindowContentRegionMax().x) ImGui::NewLine();
}

}  // namespace sw::vis
