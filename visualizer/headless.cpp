#include "headless.hpp"
#include <GL/osmesa.h>
#include <backends/imgui_impl_opengl2.h>
#include <stdexcept>
#include "gl_texture.hpp"

namespace sw::vis {

struct HeadlessHost::Impl {
  OSMesaContext ctx = nullptr;
  ImGuiContext* imgui = nullptr;
  GlTextureHost textures;
  bool backend = false;
};

HeadlessHost::HeadlessHost(int width, int height, std::filesystem::path lessons_dir)
    : impl_(std::make_unique<Impl>()), w_(width), h_(height), pixels_(std::size_t(width) * height * 4) {
  impl_->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!impl_->ctx) throw std::runtime_error("OSMesa could not create a context");
  if (!OSMesaMakeCurrent(impl_->ctx, pixels_.data(), GL_UNSIGNED_BYTE, width, height))
    throw std::runtime_error("OSMesa could not make its context current");
  OSMesaPixelStore(OSMESA_Y_UP, 0);  // row 0 of the buffer is the top of the picture
  impl_->imgui = ImGui::CreateContext();
  ImGui::SetCurrentContext(impl_->imgui);
  const theme::Fonts fonts = theme::setup_style();
  ImGui::GetIO().DisplaySize = ImVec2(float(width), float(height));
  for (int k = 0; k < ImGuiKey_COUNT; ++k) ImGui::GetIO().KeyMap[k] = k;  // scripted keys index KeysDown directly
  if (!ImGui_ImplOpenGL2_Init()) throw std::runtime_error("ImGui's OpenGL2 backend failed to start");
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
    app_->frame(io.DeltaTime);
    ImGui::Render();
    glViewport(0, 0, w_, h_);
    glClearColor(0.1f, 0.1f, 0.12f, 1.f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
  }
  glFinish();
  for (ImGuiKey k : keys_) io.KeysDown[k] = false;
  keys_.clear();
  chars_.clear();
  return pixels_;
}

std::uint32_t HeadlessHost::pixel(int x, int y) const {
  const std::uint8_t* p = &pixels_[(std::size_t(y) * w_ + x) * 4];
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

}  // namespace sw::vis
