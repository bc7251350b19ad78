// The fill and clip family's registration: the fills (fills.cpp), perspective-correct and affine
// interpolation (interp.cpp), rasterization-time clipping (raster_clip.cpp) and the clippers
// (clip_segment.cpp, clip_polygon.cpp).
// Semantics: docs/fill/semantics.md.
#include "catalog.hpp"

namespace sw {

void register_fills(std::vector<Algorithm>& out);  // fills.cpp
void register_clip_segment(std::vector<Algorithm>& out);  // clip_segment.cpp
void register_clip_polygon(std::vector<Algorithm>& out);  // clip_polygon.cpp
void register_interp(std::vector<Algorithm>& out);  // interp.cpp
void register_raster_clip(std::vector<Algorithm>& out);  // raster_clip.cpp

void register_fill(std::vector<Algorithm>& out) {
  register_fills(out);
  register_interp(out);
  register_raster_clip(out);
  register_clip_segment(out);
  register_clip_polygon(out);
}

}  // namespace sw
