// The rasterized scene's colours: the local lighting of the lighting family (`shade`, the tracer's
// `models` convention, with the tracer's materials, textures and bump maps), per vertex and
// interpolated (Gouraud) or per fragment from interpolated normals (Phong). A rasterizer draws
// local lighting only: no shadow, mirror, glass or caustic. Rules: docs/pipeline/semantics.md#scene-raster.
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>
#include "pipeline/raster_scene.hpp"

namespace sw::pipespec {

enum class Shading : std::uint8_t { gouraud, phong };
std::string_view shading_name(Shading s);

// Per pixel, row 0 at the top: the background where nothing was drawn. Interpolation is
// perspective-correct: the weights are those of the point the pixel's ray meets on the
// triangle's plane. A plane has no vertices to light (its wedges reach infinity), so it is lit per
// fragment in both modes.
// blocked: per pixel, bit i set where light i is shadowed (it adds its ambient term only, as in
// the tracer), and then also where the point's own face turns away from light i (a tessellated
// surface shadows itself there, though its interpolated normal may face the light); none: no
// shadows, every light reaches every pixel.
std::vector<Vec3<double>> shade_pixels(const RasterScene& s, const RasterPixels& px, Shading mode, const std::vector<std::uint32_t>* blocked = nullptr);

// The depth buffer as grey levels, rows top first: near black, far white, nothing drawn white.
// Window depth d = 1 - n/e is hyperbolic in the eye depth e, so the grey is log(e/n) = -log(1 - d),
// stretched over the drawn pixels' range: a floor reaching the horizon stays readable.
std::vector<std::uint8_t> depth_grey(const RasterPixels& px);

}  // namespace sw::pipespec
