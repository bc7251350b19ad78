// Colours, fonts and style shared by the panels and both hosts. Constants only: no mutable state.
#pragma once
#include <algorithm>
#include <imgui.h>

namespace sw::vis::theme {

inline constexpr ImU32 kCanvasBg = IM_COL32(24, 26, 33, 255);
inline constexpr ImU32 kGrid = IM_COL32(70, 76, 92, 255);
inline constexpr ImU32 kGridAxis = IM_COL32(110, 118, 140, 255);
inline constexpr ImU32 kCentre = IM_COL32(150, 156, 175, 200);
inline constexpr ImU32 kSegment = IM_COL32(240, 240, 245, 255);
inline constexpr ImU32 kHandleP0 = IM_COL32(90, 220, 140, 255);
inline constexpr ImU32 kHandleP1 = IM_COL32(240, 96, 96, 255);
inline constexpr ImU32 kQ = IM_COL32(255, 225, 70, 255);
inline constexpr ImU32 kCurrentPixel = IM_COL32(255, 255, 255, 255);
inline constexpr ImU32 kHover = IM_COL32(255, 255, 255, 120);
inline constexpr ImU32 kLabel = IM_COL32(170, 176, 195, 255);
inline constexpr ImU32 kMismatch = IM_COL32(255, 40, 220, 255);    // a pixel only one run plotted
inline constexpr ImU32 kDivergence = IM_COL32(255, 80, 70, 255);   // a step whose decisions differ
inline const ImVec4 kChanged = ImVec4(1.00f, 0.80f, 0.30f, 1.f);   // changed variables
inline const ImVec4 kSetSame = ImVec4(0.62f, 0.80f, 1.00f, 1.f);   // set again, same value
inline const ImVec4 kDim = ImVec4(0.60f, 0.62f, 0.68f, 1.f);
inline const ImVec4 kError = ImVec4(1.00f, 0.45f, 0.42f, 1.f);
inline const ImVec4 kGood = ImVec4(0.45f, 0.85f, 0.55f, 1.f);
inline constexpr ImU32 kLineHighlight = IM_COL32(66, 110, 190, 150);
// A geometry item's value colours it by its sign (an edge function's side, P at a midpoint).
inline constexpr ImU32 kPositive = IM_COL32(90, 220, 120, 255), kNegative = IM_COL32(255, 90, 80, 255), kZero = IM_COL32(255, 190, 40, 255);
inline constexpr ImU32 sign_colour(double v) { return v > 0 ? kPositive : v < 0 ? kNegative : kZero; }

// Fonts the panels use; the default font when the TTF files are missing.
struct Fonts {
  ImFont* body = nullptr;
  ImFont* mono = nullptr;
  ImFont* title = nullptr;
  // The same faces kPresentScale times larger, for presentation mode (the default font if missing).
  ImFont* body_big = nullptr;
  ImFont* mono_big = nullptr;
  ImFont* title_big = nullptr;
  Fonts big() const { return {body_big, mono_big, title_big, body_big, mono_big, title_big}; }
};

// Presentation mode's font size over the normal one: a projector's back row reads 15 px as 22.
inline constexpr float kPresentScale = 1.5f;
// --scale's accepted range: below 0.75 the 15 px body font is under 12 px; above 3 a 1024-wide
// window holds too few characters a row.
inline constexpr float kMinScale = 0.75f, kMaxScale = 3.f;

// Call once after ImGui::CreateContext and before the backend builds its font texture.
// `scale` multiplies font sizes and spacing (1 at 1280x800); it must be in [kMinScale, kMaxScale].
Fonts setup_style(float scale = 1.f);

}  // namespace sw::vis::theme

namespace sw::vis {
// Panels sit at fixed places computed each frame: no moving, resizing or remembered layout.
inline constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                                ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
inline void place_next(ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
}
// A canvas's name badge (e.g. its number type), white on a dark plate in the top-right corner.
inline void corner_label(ImDrawList* dl, ImVec2 origin, ImVec2 size, const char* label) {
  if (!label || !*label) return;
  const ImVec2 ts = ImGui::CalcTextSize(label);
  const ImVec2 p(origin.x + size.x - ts.x - 10, origin.y + 6);
  dl->AddRectFilled(ImVec2(p.x - 4, p.y - 2), ImVec2(p.x + ts.x + 4, p.y + ts.y + 2), IM_COL32(0, 0, 0, 170), 3);
  dl->AddText(p, IM_COL32(255, 255, 255, 255), label);
}
// Quiz mode's stand-in for a whole-sweep picture, which would answer its questions.
inline void sweep_hidden_note(ImDrawList* dl, ImVec2 origin) {
  dl->AddText(ImVec2(origin.x + 10, origin.y + 10), theme::kLabel, "Quiz: this view shows every input at once, so it waits until every question is answered.");
}
// A sweep view's status plate at `at`: three lines on a dark plate, the first red when `bad` (the
// mode disagrees, or the sweep failed) and green otherwise, the others grey.
inline void status_plate(ImDrawList* dl, ImVec2 at, const char (&lines)[3][200], bool bad) {
  const float line_h = ImGui::GetTextLineHeight();
  float text_w = 0;
  for (const auto& l : lines) text_w = std::max(text_w, ImGui::CalcTextSize(l).x);
  dl->AddRectFilled(at, ImVec2(at.x + text_w + 10, at.y + 3 * line_h + 8), IM_COL32(0, 0, 0, 190), 3);
  for (int k = 0; k < 3; ++k) {
    const ImU32 col = k ? theme::kLabel : bad ? IM_COL32(255, 130, 120, 255) : IM_COL32(130, 220, 150, 255);
    dl->AddText(ImVec2(at.x + 5, at.y + 3 + float(k) * line_h), col, lines[k]);
  }
}
}  // namespace sw::vis
