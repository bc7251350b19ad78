// The Lesson menu (the lessons by title in manifest order, Next and Previous) and the View menu
// (presentation mode, fit), in the toolbar's menu bar. The manifest itself is the Session's
// (lessons/session_lessons.cpp).
#include "panels/panels.hpp"

namespace sw::vis {
namespace {

// `text` cut to fit `width` pixels, "..." marking the cut; whole when it fits.
std::string fit_text(std::string text, float width) {
  if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
  while (!text.empty() && ImGui::CalcTextSize((text + "...").c_str()).x > width) {
    while (text.size() > 1 && (text.back() & 0xC0) == 0x80) text.pop_back();  // a whole UTF-8 character
    text.pop_back();
  }
  return text + "...";
}

}  // namespace

void draw_menu_bar(Session& s, Chrome& c) {
  if (!ImGui::BeginMenuBar()) return;
  const std::optional<std::size_t> current = s.lesson_index();
  const std::size_t count = s.lessons().size();
  if (ImGui::BeginMenu("Lesson")) {
    if (!s.lessons_error().empty()) ImGui::TextColored(theme::kError, "%s", s.lessons_error().c_str());
    const auto& titles = s.lesson_titles();
    for (std::size_t k = 0; k < titles.size(); ++k) {
      const std::string item = std::to_string(k + 1) + ". " + titles[k];
      if (ImGui::MenuItem(item.c_str(), nullptr, current == k) && current != k) s.open_manifest_lesson(k);
    }
    ImGui::Separator();
    const bool has_next = !current || *current + 1 < count, has_prev = current && *current > 0;
    if (ImGui::MenuItem("Next lesson", "Ctrl+Right", false, has_next)) s.open_adjacent_lesson(+1);
    if (ImGui::MenuItem("Previous lesson", "Ctrl+Left", false, has_prev)) s.open_adjacent_lesson(-1);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    ImGui::MenuItem("Presentation mode", "P", &c.presenting);
    if (ImGui::MenuItem("Fit the view", "F")) c.fit = true;
    ImGui::EndMenu();
  }
  // The presentation toggle, then the lesson open (its title and place), in the bar itself.
  if (ImGui::MenuItem(c.presenting ? "Exit presentation" : "Present")) c.presenting = !c.presenting;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Presentation mode (P): big fonts; the canvas, listing and narration only");
  if (const Lesson* l = s.lesson()) {
    ImGui::Separator();
    if (current) ImGui::TextDisabled("%zu of %zu", *current + 1, count);
    const float room = ImGui::GetWindowContentRegionMax().x - ImGui::GetCursorPosX() - ImGui::GetStyle().ItemSpacing.x;
    if (room > 3 * ImGui::GetFontSize()) ImGui::TextUnformatted(fit_text(l->title, room).c_str());
  }
  ImGui::EndMenuBar();
}

}  // namespace sw::vis
