// A pixel's whole history: the input of the catalog's `whitted` (one pixel of a scene, traced
// with every step recorded), its untraced colour, and the preview the visualizer's scene view
// shows (the scene rendered once through the pixels' centres). docs/visualizer.md.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include "input.hpp"
#include "tracer/photon_map.hpp"
#include "tracer/plan.hpp"
#include "tracer/render.hpp"
#include "tracer/scene.hpp"

namespace sw::tracer {

struct HistoryInput {
  std::shared_ptr<const Scene> scene;
  std::string scene_name;            // the file as given, or "inline"
  std::int64_t i = 0, j = 0;         // the pixel
  std::int64_t width = 0, height = 0;  // the image it belongs to (default: the scene's resolution)
  Offset offset = Offset::robust;
  bool all_effects = false;
  std::string scene_key;  // what the scene was read from (history_scene shares a scene prepared from the same)
};

// An input's "scene": a scene file relative to the data root (data_root.hpp), or a scene object;
// name is set to the file as given, or "inline". Errors name the input's JSON path.
std::shared_ptr<const Scene> scene_input(const Json& v, std::string* name);

// {"scene": "scenes/x.json" (relative to the data root: data_root.hpp) or a scene object, "pixel": [i, j],
// "size": [w, h], "offset": "robust"|"none"|"epsilon", "all_effects": bool}. Throws InputError
// naming the JSON path ("input.pixel[0]: ...", "input.scene.objects[1].radius: ...").
HistoryInput parse_history_input(const Json& j);

// The scene converted for tracing at the input's size, with its offset mode and plan.
struct HistoryScene {
  TraceScene<double> scene;  // scene.caustics points at photons (so a HistoryScene is not copied)
  Plan plan;
  PhotonMap photons;
  HistoryScene() = default;
  HistoryScene(const HistoryScene&) = delete;
  HistoryScene& operator=(const HistoryScene&) = delete;
};
std::shared_ptr<const HistoryScene> history_scene(const HistoryInput& in);

// The pixel's colour, untraced, through its centre (the history's primary ray).
struct PixelColour {
  Vec3<double> rgb;
  RayCounts counts;
  bool budget_spent = false;
  friend bool operator==(const PixelColour& a, const PixelColour& b) {
    const RayCounts &x = a.counts, &y = b.counts;
    return a.rgb == b.rgb && a.budget_spent == b.budget_spent && x.primary == y.primary && x.shadow == y.shadow &&
           x.shadow_blocked == y.shadow_blocked && x.reflection == y.reflection && x.refraction == y.refraction && x.budget_stops == y.budget_stops;
  }
};
PixelColour pixel_colour(const HistoryScene& s, std::int64_t i, std::int64_t j);

// The scene rendered through the pixel centres at most max_side pixels on a side (keeping the
// aspect); a preview pixel covers scale x scale pixels of the input's image.
struct Preview {
  std::int64_t width = 0, height = 0, scale = 1;
  std::vector<std::uint8_t> rgb;  // 8-bit rows, top first
  Plan plan;
  double seconds = 0;
};
Preview render_preview(const HistoryInput& in, std::int64_t max_side);

// The input with another pixel.
Json with_pixel(Json input, std::int64_t i, std::int64_t j);

}  // namespace sw::tracer
