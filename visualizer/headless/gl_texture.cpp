#include "headless/gl_texture.hpp"
#include <GL/gl.h>

namespace sw::vis {

static GLuint gl_name(ImTextureID t) { return static_cast<GLuint>(reinterpret_cast<std::intptr_t>(t)); }

ImTextureID GlTextureHost::create(int w, int h) {
  GLint previous = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  // Nearest: a texel is a pixel of the grid, its edges must stay sharp at any zoom.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
  return reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(tex));
}

void GlTextureHost::update(ImTextureID t, int x, int y, int w, int h, const std::uint32_t* rgba, int stride) {
  if (w <= 0 || h <= 0) return;
  GLint previous = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
  glBindTexture(GL_TEXTURE_2D, gl_name(t));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, stride);
  glTexSubImage2D(GL_TEXTURE_2D, 0, x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
}

void GlTextureHost::destroy(ImTextureID t) {
  GLuint tex = gl_name(t);
  glDeleteTextures(1, &tex);
}

}  // namespace sw::vis
