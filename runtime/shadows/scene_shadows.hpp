// The rasterizer's shadows (`scene raster --shadows map|volume`): per pixel, bit i set where light
// i shadows the point the eye sees there, by its shadow map or its stencil volumes, drawn in mode n;
// a pass for every light the effect planner keeps (every light with all_effects), and for the
// others the planner's reason. Semantics: docs/shadows/semantics.md.
#pragma once
#include <memory>
#include <string>
#include <vector>
#include "shadows/projective_shadow_input.hpp"
#include "shadows/shadow_volume_input.hpp"

namespace sw::shadowspec {

enum class ShadowMethod : std::uint8_t { map, volume_zfail, volume_zpass, projective };

struct LightShadows {
  std::size_t light = 0;
  bool pass = false;
  std::string skipped;  // the planner's reason, without a pass
  std::shared_ptr<const MapInput> in;       // the seen points and their exact visibility (and a map's views)
  MapPixels map;                            // ShadowMethod::map
  std::shared_ptr<const VolumeInput> volume_in;
  VolumePixels volume;                      // the volume methods
  std::shared_ptr<const ProjectiveInput> projective_in;
  ProjectivePixels projective;              // ShadowMethod::projective
};
struct SceneShadows {
  ShadowMethod method = ShadowMethod::map;
  std::vector<std::uint32_t> blocked;
  std::vector<LightShadows> lights;
};
// receiver: projective's receiving object (-1: the first plane or triangle); drawn with GL_LESS,
// glPolygonOffset(-1, -1) and the stencil.
SceneShadows scene_shadows(const std::shared_ptr<const RasterScene>& s, ShadowMethod method, const MapOptions& o, Numeric n, bool all_effects,
                           std::int64_t receiver = -1);
inline SceneShadows scene_shadows(const std::shared_ptr<const RasterScene>& s, const MapOptions& o, Numeric n, bool all_effects) {
  return scene_shadows(s, ShadowMethod::map, o, n, all_effects);
}

}  // namespace sw::shadowspec
