#include "headless/headless.hpp"
#include <GL/osmesa.h>
#include <backends/imgui_impl_opengl2.h>
#include <cstdint>
#include <stdexcept>
#include "headless/gl_texture.hpp"

namespace sw::vis {

namespace {

// Draws ImGui's lists with GL 1.1 arrays, as ImGui's GL2 backend does, but honouring each command's
// VtxOffset: our ImGui has 16-bit indices, and a canvas with 10^4 tree nodes or mesh triangles goes
// past 65536 vertices in one list, which ImGui splits into commands only for a renderer that
// declares RendererHasVtxOffset. The GL2 backend still makes the font texture.
void render_draw_data(const ImDrawData& d, int width, int height) {
  glViewport(0, 0, width, height);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(d.DisplayPos.x, d.DisplayPos.x + d.DisplaySize.x, d.DisplayPos.y + d.DisplaySize.y, d.DisplayPos.y, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  for (int n = 0; n < d.CmdListsCount; ++n) {
    const ImDrawList& list = *d.CmdLists[n];
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      if (cmd.UserCallback) {  // none of ours adds one; ImGui's own reset needs nothing here
        if (cmd.UserCallback != ImDrawCallback_ResetRenderState) cmd.UserCallback(&list, &cmd);
        continue;
      }
      const ImVec4 c(cmd.ClipRect.x - d.DisplayPos.x, cmd.ClipRect.y - d.DisplayPos.y, cmd.ClipRect.z - d.DisplayPos.x, cmd.ClipRect.w - d.DisplayPos.y);
      if (c.z <= c.x || c.w <= c.y) continue;
      const char* v = reinterpret_cast<const char*>(list.VtxBuffer.Data + cmd.VtxOffset);
      glVertexPointer(2, GL_FLOAT, sizeof(ImDrawVert), v + IM_OFFSETOF(ImDrawVert, pos));
      glTexCoordPointer(2, GL_FLOAT, sizeof(ImDrawVert), v + IM_OFFSETOF(ImDrawVert, uv));
      glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(ImDrawVert), v + IM_OFFSETOF(ImDrawVert, col));
      glScissor(int(c.x), int(float(height) - c.w), int(c.z - c.x), int(c.w - c.y));
      glBindTexture(GL_TEXTURE_2D, GLuint(reinterpret_cast<std::intptr_t>(cmd.GetTexID())));
      glDrawElements(GL_TRIANGLES, GLsizei(cmd.ElemCount), sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT, list.IdxBuffer.Data + cmd.IdxOffset);
    }
  }
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace

struct HeadlessHost::Impl {
  OSMesaContext ctx = nullptr;
  ImGuiContext* imgui = nullptr;
  GlTextureHost textures;
  bool backend = false;
};

HeadlessHost::HeadlessHost(int width, int height, std::filesystem::path lessons_dir, float scale)
    : impl_(std::make_unique<Impl>()), w_(width), h_(height), pixels_(std::size_t(width) * height * 4) {
  impl_->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!impl_->ctx) throw std::runtime_error("OSMesa could not create a context");
  if (!OSMesaMakeCurrent(impl_->ctx, pixels_.data(), GL_UNSIGNED_BYTE, width, height))
    throw std::runtime_error("OSMesa could not make its context current");
  OSMesaPixelStore(OSMESA_Y_UP, 0);  // row 0 of the buffer is the top of the picture
  impl_->imgui = ImGui::CreateContext();
  ImGui::SetCurrentContext(impl_->imgui);
  const theme::Fonts fonts = theme::setup_style(scale);
  ImGui::GetIO().DisplaySize = ImVec2(float(width), float(height));
  for (int k = 0; k < ImGuiKey_COUNT; ++k) ImGui::GetIO().KeyMap[k] = k;  // scripted keys index KeysDown directly
  if (!ImGui_ImplOpenGL2_Init()) throw std::runtime_error("ImGui's OpenGL2 backend failed to start");
  ImGui::GetIO().BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;  // render_draw_data honours it
  impl_->backend = true;
  app_ = std::make_unique<App>(impl_->textures, fonts, std::move(lessons_dir));
}

HeadlessHost::~HeadlessHost() {
  OSMesaMakeCurrent(impl_->ctx, pixels_.data(), GL_UNSIGNED_BYTE, w_, h_);
  ImGui::SetCurrentContext(impl_->imgui);
  app_.reset();  // frees its textures while the context is current
  if (impl_->backend) ImGui_ImplOpenGL2_Shutdown();
  if (impl_->imgui) ImGui::DestroyContext(impl_->imgui);
  if (impl_->ctx) OSMesaDestroyContext(impl_->ctx);
}

const std::vector<std::uint8_t>& HeadlessHost::render(int frames) {
  OSMesaMakeCurrent(impl_->ctx, pixels_.data(), GL_UNSIGNED_BYTE, w_, h_);
  ImGui::SetCurrentContext(impl_->imgui);
  ImGuiIO& io = ImGui::GetIO();
  for (int f = 0; f < frames; ++f) {
    io.DeltaTime = 1.f / 60.f;
    io.MousePos = mouse_ ? *mouse_ : ImVec2(-FLT_MAX, -FLT_MAX);  // by default no hover effects in pictures
    io.MouseDown[0] = mouse_down_;
    for (ImGuiKey k : keys_) io.KeysDown[k] = f == 0;
    if (f == 0)
      for (char c : chars_) io.AddInputCharacter(static_cast<unsigned>(c));
    ImGui_ImplOpenGL2_NewFrame();
    ImGui::NewFrame();
    if (paint_) paint_();
    else app_->frame(io.DeltaTime);
    ImGui::Render();
    glViewport(0, 0, w_, h_);
    glClearColor(0.1f, 0.1f, 0.12f, 1.f);
    glClear(GL_COLOR_BUFFER_BIT);
    render_draw_data(*ImGui::GetDrawData(), w_, h_);
  }
  glFinish();
  for (ImGuiKey k : keys_) io.KeysDown[k] = false;
  keys_.clear();
  chars_.clear();
  return pixels_;
}

const std::vector<std::uint8_t>& HeadlessHost::render_with(const std::function<void()>& paint, int frames) {
  paint_ = paint;
  try {
    render(frames);
  } catch (...) {
    paint_ = nullptr;
    throw;
  }
  paint_ = nullptr;
  return pixels_;
}

std::uint32_t HeadlessHost::pixel(int x, int y) const {
  const std::uint8_t* p = &pixels_[(std::size_t(y) * w_ + x) * 4];
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

}  // namespace sw::vis
