// The accuracy chart's ImDrawList painter: the app's Accuracy window and the PNG of
// `stepwise bench --plot` (through the OSMesa host) both draw with it.
#pragma once
#include <imgui.h>
#include "panels/chart.hpp"

namespace sw::vis {

// Paints `chart` with its top-left corner at `origin`, clipped to its size; text in `font`
// (ImGui's current font if null) scaled to each item's size.
void paint_chart(ImDrawList* dl, const Chart& chart, ImVec2 origin, ImFont* font = nullptr);

}  // namespace sw::vis
