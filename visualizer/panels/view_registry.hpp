// The views the visualizer can build, by the View an algorithm declares (runtime/views.hpp): one
// canvas factory and one tab label per view. The app never asks which family an algorithm is.
#pragma once
#include <memory>
#include "panels/canvas.hpp"

namespace sw::vis {

struct ViewInfo {
  View view;
  const char* label;  // the tab's text
  const char* help;   // its tooltip
  std::unique_ptr<Canvas> (*make)(TextureHost& textures);
};

// Every view the registry knows, in View order.
const ViewInfo& view_info(View view);

}  // namespace sw::vis
