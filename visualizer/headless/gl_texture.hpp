// TextureHost over OpenGL 1.1 texture calls, which both GL2 (OSMesa) and GL3 core contexts export.
#pragma once
#include "panels/texture_host.hpp"

namespace sw::vis {

class GlTextureHost final : public TextureHost {
 public:
  ImTextureID create(int w, int h) override;
  void update(ImTextureID tex, int x, int y, int w, int h, const std::uint32_t* rgba, int stride) override;
  void destroy(ImTextureID tex) override;
};

}  // namespace sw::vis
