// Quiz mode's panel, under the narration: the score, the waiting question's prompt and its answer
// buttons, then the grade and the explanation. The quiz itself is the Session's QuizSession
// (lessons/quiz_session.hpp): its questions, the gate that stops stepping, the answers.
#include <algorithm>
#include "lessons/grading.hpp"
#include "panels/panels.hpp"  // before imgui_stdlib.h, which needs imgui.h first
#include <imgui_stdlib.h>

namespace sw::vis {

namespace {

// The last item's rectangle, noted in *marks under `label`.
void mark(const std::string& label, std::vector<WidgetMark>* marks) {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  marks->push_back({label, {a.x, a.y, b.x, b.y}});
}
// ImGui::Button or SmallButton, its rectangle noted in *marks.
bool marked_button(const std::string& label, std::vector<WidgetMark>* marks, bool small = false) {
  const bool pressed = small ? ImGui::SmallButton(label.c_str()) : ImGui::Button(label.c_str());
  mark(label, marks);
  return pressed;
}

}  // namespace

void draw_quiz(Session& s, const Chrome& c, std::vector<WidgetMark>* marks) {
  ImGui::Separator();
  const QuizSession& quiz = s.quiz_session();
  const std::size_t step = s.step();
  const auto [right, asked] = quiz.score();
  const std::size_t n = quiz.questions().size();
  ImGui::TextColored(theme::kDim, "Quiz: %d of %d right, %zu %s in this lesson", right, asked, n, n == 1 ? "question" : "questions");
  if (!s.answers_file().empty()) {  // answers are saved: under the name typed here
    static std::string name;  // the field's text while it is edited (one quiz panel)
    if (!ImGui::IsAnyItemActive()) name = s.student();
    ImGui::SetNextItemWidth(12 * ImGui::GetFontSize());
    const bool edited = ImGui::InputTextWithHint("Your name##student", "the name your answers carry", &name);
    mark("Your name", marks);
    if (edited && !name.empty()) s.set_student(name);
  }
  if (!s.answers_error().empty()) ImGui::TextColored(theme::kError, "%s", s.answers_error().c_str());
  else if (const auto file = s.answers_file(); !file.empty() && asked > 0) {
    ImGui::TextColored(theme::kDim, "Saved as %s in %s", printable_name(s.student()).c_str(), file.string().c_str());
    if (c.offer_file) {
      ImGui::SameLine();
      if (marked_button("Download answers", marks, true)) c.offer_file(file);
    }
  }
  const QuizSession::Answered* done = quiz.answered(step);
  const Question* q = quiz.pending(step);
  const Question* at = quiz.at(step);
  if ((!q && !done) || !at) return;
  const Question& shown = *at;
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.85f, 1.f, 1));
  ImGui::TextWrapped("%s", shown.prompt.empty() ? "Predict the next step." : shown.prompt.c_str());
  ImGui::PopStyleColor();
  if (q) {
    // One button per choice, wrapped onto the next row rather than clipped at the panel's edge.
    bool first = true;
    auto button = [&](const std::string& label, const Json& value) {
      if (!first) flow(ImGui::CalcTextSize(label.c_str()).x + 2 * ImGui::GetStyle().FramePadding.x);
      first = false;
      if (!marked_button(label, marks)) return false;
      s.answer(value);
      return true;
    };
    switch (q->type) {
      case QuizType::pixel: ImGui::TextDisabled("Click the cell you expect on the canvas."); break;
      case QuizType::sign:
        if (q->than.empty()) button("negative", -1) || button("zero", 0) || button("positive", 1);
        else button("below " + q->than, -1) || button("equal", 0) || button("above " + q->than, 1);
        break;
      case QuizType::hit: button("hit", true) || button("miss", false); break;
      case QuizType::flag: button("yes", true) || button("no", false); break;
      case QuizType::same: button("same", true) || button("differs", false); break;
      case QuizType::diverge: {
        static int guess = 0;  // one question waits at a time
        ImGui::SetNextItemWidth(8 * ImGui::GetFontSize());
        ImGui::InputInt("##diverge", &guess);
        guess = std::max(guess, 0);
        first = false;  // the button goes beside the field when it fits
        button("Answer: step " + std::to_string(guess), Json(static_cast<std::size_t>(guess)));
        break;
      }
      case QuizType::branch:
        for (const std::string& choice : q->choices)
          if (button(choice, choice)) break;
        break;
    }
    return;
  }
  const std::string said = answer_text(shown, done->given);
  if (done->grade.right) ImGui::TextColored(theme::kGood, "Right: %s.", said.c_str());
  else ImGui::TextColored(theme::kError, "You said %s; the %s says %s.", said.c_str(),
                          shown.type == QuizType::same || shown.type == QuizType::diverge ? "pair of runs" : "exact run", done->grade.expected.c_str());
  if (shown.section && !shown.section->text.empty()) draw_markdown(fill_templates(shown.section->text, *s.model(0), step).text, c.fonts);
  ImGui::TextDisabled("Step on (Right arrow) to see it happen.");
}

}  // namespace sw::vis
