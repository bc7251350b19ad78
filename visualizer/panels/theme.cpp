#include "panels/theme.hpp"
#include <filesystem>

namespace sw::vis::theme {

Fonts setup_style(float scale) {
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // layouts are fixed; nothing to remember between runs
  Fonts f;
  const char* dir = "/usr/share/fonts/truetype/dejavu/";
  const auto sans = std::filesystem::path(dir) / "DejaVuSans.ttf";
  const auto mono = std::filesystem::path(dir) / "DejaVuSansMono.ttf";
  const auto bold = std::filesystem::path(dir) / "DejaVuSans-Bold.ttf";
  if (std::filesystem::exists(sans) && std::filesystem::exists(mono) && std::filesystem::exists(bold)) {
    ImFontConfig cfg;
    cfg.OversampleH = 2;
    // Latin-1, the dashes, quotes, bullet and ellipsis of narration, and the "≈" of exact values.
    static constexpr ImWchar kRanges[] = {0x0020, 0x00FF, 0x2013, 0x2026, 0x2248, 0x2248, 0};
    f.body = io.Fonts->AddFontFromFileTTF(sans.c_str(), 15.f * scale, &cfg, kRanges);
    f.mono = io.Fonts->AddFontFromFileTTF(mono.c_str(), 14.f * scale, &cfg, kRanges);
    f.title = io.Fonts->AddFontFromFileTTF(bold.c_str(), 16.f * scale, &cfg, kRanges);
    const float big = scale * kPresentScale;
    f.body_big = io.Fonts->AddFontFromFileTTF(sans.c_str(), 15.f * big, &cfg, kRanges);
    f.mono_big = io.Fonts->AddFontFromFileTTF(mono.c_str(), 14.f * big, &cfg, kRanges);
    f.title_big = io.Fonts->AddFontFromFileTTF(bold.c_str(), 16.f * big, &cfg, kRanges);
  }
  if (!f.body || !f.mono || !f.title || !f.body_big || !f.mono_big || !f.title_big) {
    io.Fonts->Clear();
    ImFontConfig cfg;
    cfg.SizePixels = 13.f * scale;  // the built-in bitmap font, scaled (blurry but readable)
    f.body = f.mono = f.title = io.Fonts->AddFontDefault(&cfg);
    cfg.SizePixels = 13.f * scale * kPresentScale;
    f.body_big = f.mono_big = f.title_big = io.Fonts->AddFontDefault(&cfg);
  }
  ImGui::StyleColorsDark();
  ImGuiStyle& s = ImGui::GetStyle();
  s.WindowRounding = 0;
  s.FrameRounding = 3;
  s.GrabRounding = 3;
  s.WindowBorderSize = 1;
  s.FramePadding = ImVec2(6, 4);
  s.ItemSpacing = ImVec2(8, 6);
  s.WindowPadding = ImVec2(10, 8);
  s.ScaleAllSizes(scale);
  ImVec4* c = s.Colors;
  c[ImGuiCol_WindowBg] = ImVec4(0.13f, 0.14f, 0.17f, 1.f);
  c[ImGuiCol_ChildBg] = ImVec4(0.11f, 0.12f, 0.15f, 1.f);
  c[ImGuiCol_TitleBg] = c[ImGuiCol_TitleBgActive] = ImVec4(0.18f, 0.20f, 0.25f, 1.f);
  c[ImGuiCol_TitleBgCollapsed] = c[ImGuiCol_TitleBg];
  c[ImGuiCol_Border] = ImVec4(0.26f, 0.28f, 0.34f, 1.f);
  c[ImGuiCol_FrameBg] = ImVec4(0.20f, 0.22f, 0.27f, 1.f);
  c[ImGuiCol_Button] = ImVec4(0.24f, 0.30f, 0.42f, 1.f);
  c[ImGuiCol_ButtonHovered] = ImVec4(0.30f, 0.40f, 0.58f, 1.f);
  c[ImGuiCol_ButtonActive] = ImVec4(0.36f, 0.48f, 0.70f, 1.f);
  c[ImGuiCol_Text] = ImVec4(0.92f, 0.93f, 0.95f, 1.f);
  return f;
}

}  // namespace sw::vis::theme
