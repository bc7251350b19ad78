// The Lesson menu (the lessons by title in manifest order, Next and Previous) and the View menu
// (presentation mode, fit), in the toolbar's menu bar.
#include "panels/app.hpp"

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

const std::vector<std::string>& App::lesson_titles() {
  if (lesson_titles_.size() == lessons_.size()) return lesson_titles_;
  lesson_titles_.clear();
  for (const auto& path : lessons_) {
    try {
      lesson_titles_.push_back(load_lesson(path).title);
    } catch (const InputError& e) {  // still listed, so that choosing it shows the error
      lesson_titles_.push_back(path.filename().string() + " (" + e.what() + ")");
    }
  }
  return lesson_titles_;
}

bool App::open_adjacent_lesson(int delta) {
  if (lessons_.empty()) return false;
  // Where we are: the lesson open, else the one last tried (it may have failed to load).
  std::optional<std::size_t> at = lesson_pos_;
  for (std::size_t k = 0; lesson_ && k < lessons_.size(); ++k)
    if (lessons_[k] == lesson_->path) at = k;
  const long next = at ? long(*at) + delta : delta > 0 ? 0 : -1;
  if (next < 0 || next >= long(lessons_.size())) return false;
  lesson_pos_ = std::size_t(next);
  return open_lesson(lessons_[*lesson_pos_]);
}

void App::draw_menu_bar() {
  if (!ImGui::BeginMenuBar()) return;
  std::optional<std::size_t> current;
  for (std::size_t k = 0; lesson_ && k < lessons_.size(); ++k)
    if (lessons_[k] == lesson_->path) current = k;
  if (ImGui::BeginMenu("Lesson")) {
    if (!lessons_error_.empty()) ImGui::TextColored(theme::kError, "%s", lessons_error_.c_str());
    const auto& titles = lesson_titles();
    for (std::size_t k = 0; k < titles.size(); ++k) {
      const std::string item = std::to_string(k + 1) + ". " + titles[k];
      if (ImGui::MenuItem(item.c_str(), nullptr, current == k) && current != k) lesson_pos_ = k, open_lesson(lessons_[k]);
    }
    ImGui::Separator();
    const bool has_next = !current || *current + 1 < lessons_.size(), has_prev = current && *current > 0;
    if (ImGui::MenuItem("Next lesson", "Ctrl+Right", false, has_next)) open_adjacent_lesson(+1);
    if (ImGui::MenuItem("Previous lesson", "Ctrl+Left", false, has_prev)) open_adjacent_lesson(-1);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    ImGui::MenuItem("Presentation mode", "P", &presenting_);
    if (ImGui::MenuItem("Fit the view", "F") && canvases_[0]) canvases_[0]->fit();
    ImGui::EndMenu();
  }
  // The presentation toggle, then the lesson open (its title and place), in the bar itself.
  if (ImGui::MenuItem(presenting_ ? "Exit presentation" : "Present")) presenting_ = !presenting_;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Presentation mode (P): big fonts; the canvas, listing and narration only");
  if (lesson_) {
    ImGui::Separator();
    if (current) ImGui::TextDisabled("%zu of %zu", *current + 1, lessons_.size());
    const float room = ImGui::GetWindowContentRegionMax().x - ImGui::GetCursorPosX() - ImGui::GetStyle().ItemSpacing.x;
    if (room > 3 * ImGui::GetFontSize()) ImGui::TextUnformatted(fit_text(lesson_->title, room).c_str());
  }
  ImGui::EndMenuBar();
}

}  // namespace sw::vis
