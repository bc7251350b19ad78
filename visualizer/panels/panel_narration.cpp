// The narration under the canvas: the lesson's intro (collapsible, always there), then the section
// each run shows at the current step, with its values filled in (one per run when two runs show
// different text), then the quiz. Markdown comes from md4c and is laid out here word by word.
#include "panels/panels.hpp"
#include "lessons/markdown.hpp"

namespace sw::vis {
namespace {

ImVec4 span_colour(std::uint8_t style) {
  if (style & MdSpan::link) return ImVec4(0.45f, 0.7f, 1.f, 1);
  if (style & MdSpan::code) return ImVec4(0.80f, 0.90f, 0.70f, 1);
  if (style & MdSpan::strong) return ImVec4(1, 1, 1, 1);
  if (style & MdSpan::em) return ImVec4(0.85f, 0.80f, 1.f, 1);
  return ImGui::GetStyleColorVec4(ImGuiCol_Text);
}

// Lays spans out left to right, breaking lines between words at the region's right edge.
// `left` is the cursor x lines start at; after a list marker the first word joins the marker's line.
void wrapped_spans(const std::vector<MdSpan>& spans, ImFont* mono, float left, bool after_marker = false) {
  const float right = ImGui::GetWindowContentRegionMax().x;
  float x = left;
  bool line_started = false;
  if (after_marker) ImGui::SameLine(0, 0);
  ImGui::SetCursorPosX(left);
  for (const MdSpan& s : spans) {
    const bool code = s.style & MdSpan::code;
    if (code && mono) ImGui::PushFont(mono);
    ImGui::PushStyleColor(ImGuiCol_Text, span_colour(s.style));
    std::size_t i = 0;
    while (i < s.text.size()) {
      if (s.text[i] == '\n') {
        x = right + 1, ++i;  // a hard break: the next word starts a line
        continue;
      }
      std::size_t j = s.text.find_first_of(" \n", i);
      if (j == std::string::npos) j = s.text.size();
      else if (s.text[j] == ' ') ++j;  // a word carries its trailing space
      const std::string word = s.text.substr(i, j - i);
      const float w = ImGui::CalcTextSize(word.c_str()).x;
      const float ink = word.back() == ' ' ? ImGui::CalcTextSize(word.c_str(), word.c_str() + word.size() - 1).x : w;  // the trailing space may overhang
      if (line_started && x + ink > right) {  // the last item ended its line: the cursor is already on the next
        ImGui::SetCursorPosX(left);
        x = left;
      } else if (line_started) {
        ImGui::SameLine(0, 0);
      }
      ImGui::TextUnformatted(word.c_str());
      if (s.style & MdSpan::link && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", s.href.c_str());
      x += w, line_started = true, i = j;
    }
    ImGui::PopStyleColor();
    if (code && mono) ImGui::PopFont();
  }
}

}  // namespace

void draw_markdown(const std::string& text, const theme::Fonts& fonts) {
  const float left = ImGui::GetCursorPosX();
  for (const MdBlock& b : parse_markdown(text)) {
    switch (b.kind) {
      case MdBlock::Kind::code:
        ImGui::PushFont(fonts.mono);
        for (const MdSpan& s : b.spans) ImGui::TextUnformatted(s.text.c_str());
        ImGui::PopFont();
        break;
      case MdBlock::Kind::heading:
        ImGui::PushFont(fonts.title);
        wrapped_spans(b.spans, fonts.mono, left);
        ImGui::PopFont();
        break;
      case MdBlock::Kind::item: {
        const float indent = left + 22.f * float(b.depth);
        ImGui::SetCursorPosX(indent - ImGui::CalcTextSize(b.marker.c_str()).x - 6.f);
        ImGui::TextUnformatted(b.marker.c_str());
        wrapped_spans(b.spans, fonts.mono, indent, true);
        break;
      }
      default:
        wrapped_spans(b.spans, fonts.mono, left + (b.kind == MdBlock::Kind::quote ? 14.f : 22.f * float(b.depth)));
        break;
    }
    ImGui::Dummy(ImVec2(0, 3));
  }
}

NarrationMarks draw_narration(Session& s, const Chrome& c, const PanelRect& r) {
  place_next(r.pos, r.size);
  const Lesson* lesson = s.lesson();
  NarrationMarks marks;
  ImGui::Begin(lesson ? "Lesson###Narration" : "About###Narration", nullptr, kPanelFlags);
  if (lesson) {
    ImGui::PushFont(c.fonts.title);
    ImGui::TextUnformatted(lesson->title.c_str());
    ImGui::PopFont();
    ImGui::SameLine();
    bool quiz = s.quiz();
    if (ImGui::Checkbox("Quiz (Q)", &quiz)) s.set_quiz(quiz);
    lesson = s.lesson();
    // The question first, then the step's text, then the intro: what the step says stays in view
    // on a small window, above a long introduction.
    if (s.quiz()) draw_quiz(s, c, &marks.quiz_widgets), marks.quiz_bottom = ImGui::GetItemRectMax().y;
    const std::size_t step = s.shown_step();
    marks.text_y = ImGui::GetCursorScreenPos().y;
    if (const TraceModel* a = s.model(0)) {
      // Each run narrates its own step; two runs that say the same thing say it once.
      const TraceModel* b = s.model(1);
      const std::string ta = narrate(*lesson, *a, std::min(step, a->last()));
      const std::string tb = b ? narrate(*lesson, *b, std::min(step, b->last())) : std::string();
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.93f, 0.75f, 1));
      if (!tb.empty() && tb != ta) {
        ImGui::TextColored(theme::kDim, "%s:", s.run_name(0).c_str());
        draw_markdown(ta.empty() ? "*(no narration at this step)*" : ta, c.fonts);
        ImGui::TextColored(theme::kDim, "%s:", s.run_name(1).c_str());
        draw_markdown(tb, c.fonts);
      } else {
        draw_markdown(ta, c.fonts);
      }
      ImGui::PopStyleColor();
    }
    if (!lesson->intro.empty() && ImGui::CollapsingHeader("Introduction", step == lesson->start_step ? ImGuiTreeNodeFlags_DefaultOpen : 0))
      draw_markdown(lesson->intro, c.fonts);
  } else if (const Algorithm* alg = s.algorithm()) {
    ImGui::TextWrapped("%s", std::string(alg->summary).c_str());
    ImGui::TextDisabled("No lesson open: pick one in the Lesson menu for narration.");
  }
  ImGui::End();
  return marks;
}

}  // namespace sw::vis
