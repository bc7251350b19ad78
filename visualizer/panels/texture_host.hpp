// The one thing the panels need from a graphics backend: RGBA textures they can update in part.
// Each host implements it (gl_texture.cpp works for both GL2 under OSMesa and GL3 core under GLFW).
#pragma once
#include <cstdint>
#include <imgui.h>

namespace sw::vis {

class TextureHost {
 public:
  virtual ~TextureHost() = default;
  // A new w x h RGBA8 texture with nearest filtering, contents undefined.
  virtual ImTextureID create(int w, int h) = 0;
  // Replaces the sub-rectangle [x, x+w) x [y, y+h) with rows of `stride` pixels starting at `rgba`.
  virtual void update(ImTextureID tex, int x, int y, int w, int h, const std::uint32_t* rgba, int stride) = 0;
  virtual void destroy(ImTextureID tex) = 0;
};

}  // namespace sw::vis
