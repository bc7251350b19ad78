// The narration under the canvas: the section for the current step (its listing line, else its
// kind), or the lesson's intro where no section applies. Markdown is rendered plainly: paragraphs, "- " bullets,
// `code` and **bold** markers dropped.
#include <sstream>
#include "app.hpp"

namespace sw::vis {
namespace {

std::string strip_markers(std::string s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '`') continue;
    if (s[i] == '*' && i + 1 < s.size() && s[i + 1] == '*') {
      ++i;
      continue;
    }
    out += s[i];
  }
  return out;
}

void markdown(const std::string& text) {
  std::istringstream in(text);
  std::string paragraph;
  auto flush = [&] {
    if (!paragraph.empty()) ImGui::TextWrapped("%s", strip_markers(paragraph).c_str());
    paragraph.clear();
  };
  for (std::string l; std::getline(in, l);) {
    if (l.find_first_not_of(" \t") == std::string::npos) {
      flush();
      continue;
    }
    if (l.rfind("- ", 0) == 0 || l.rfind("* ", 0) == 0) {
      flush();
      ImGui::Bullet();
      ImGui::SameLine();
      ImGui::TextWrapped("%s", strip_markers(l.substr(2)).c_str());
      continue;
    }
    paragraph += (paragraph.empty() ? "" : " ") + l;
  }
  flush();
}

}  // namespace

void App::draw_narration(ImVec2 pos, ImVec2 size) {
  place_next(pos, size);
  ImGui::Begin(lesson_ ? "Lesson###Narration" : "About###Narration", nullptr, kPanelFlags);
  if (lesson_) {
    // The section for this step (its line, else its kind); the intro where there is none.
    ImGui::PushFont(fonts_.title);
    ImGui::TextUnformatted(lesson_->title.c_str());
    ImGui::PopFont();
    const Narration* n = nullptr;
    if (a_) {
      const StepRecord& st = a_->trace().at(step_);
      n = lesson_->narration_for(st.scope ? 0 : st.line, st.kind);  // line names are the algorithm's own
    }
    if (n) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.93f, 0.75f, 1));
      markdown(n->text);
      ImGui::PopStyleColor();
    } else if (const Narration* intro = lesson_->intro()) {
      markdown(intro->text);
    }
  } else if (alg_) {
    ImGui::TextWrapped("%s", std::string(alg_->summary).c_str());
    ImGui::TextDisabled("No lesson open: pick one in the Lesson menu for narration.");
  }
  ImGui::End();
}

}  // namespace sw::vis
