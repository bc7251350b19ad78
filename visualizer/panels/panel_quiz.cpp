// Quiz mode's panel, under the narration: the score, the waiting question's prompt and its answer
// buttons, then the grade and the explanation. The quiz itself is the Session's QuizSession
// (lessons/quiz_session.hpp): its questions, the gate that stops stepping, the answers.
#include "lessons/grading.hpp"
#include "panels/panels.hpp"

namespace sw::vis {

void draw_quiz(Session& s, const Chrome& c) {
  ImGui::Separator();
  const QuizSession& quiz = s.quiz_session();
  const std::size_t step = s.step();
  const auto [right, asked] = quiz.score();
  const std::size_t n = quiz.questions().size();
  ImGui::TextColored(theme::kDim, "Quiz: %d of %d right, %zu %s in this lesson", right, asked, n, n == 1 ? "question" : "questions");
  if (!s.answers_error().empty()) ImGui::TextColored(theme::kError, "%s", s.answers_error().c_str());
  else if (const auto file = s.answers_file(); !file.empty() && asked > 0)
    ImGui::TextColored(theme::kDim, "Saved as %s in %s", printable_name(s.student()).c_str(), file.string().c_str());
  const QuizSession::Answered* done = quiz.answered(step);
  const Question* q = quiz.pending(step);
  const Question* at = quiz.at(step);
  if ((!q && !done) || !at) return;
  const Question& shown = *at;
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.85f, 1.f, 1));
  ImGui::TextWrapped("%s", shown.prompt.empty() ? "Predict the next step." : shown.prompt.c_str());
  ImGui::PopStyleColor();
  if (q) {
    auto buttons = [&](std::initializer_list<std::pair<const char*, Json>> options) {
      for (const auto& [label, value] : options) {
        if (ImGui::Button(label)) s.answer(value);
        ImGui::SameLine();
      }
      ImGui::NewLine();
    };
    switch (q->type) {
      case QuizType::pixel: ImGui::TextDisabled("Click the cell you expect on the canvas."); break;
      case QuizType::sign: buttons({{"negative", -1}, {"zero", 0}, {"positive", 1}}); break;
      case QuizType::hit: buttons({{"hit", true}, {"miss", false}}); break;
      case QuizType::branch:
        for (const std::string& choice : q->choices) {
          if (ImGui::Button(choice.c_str())) {
            s.answer(choice);
            break;
          }
          ImGui::SameLine();
        }
        ImGui::NewLine();
        break;
    }
    return;
  }
  const std::string said = answer_text(shown, done->given);
  if (done->grade.right) ImGui::TextColored(theme::kGood, "Right: %s.", said.c_str());
  else ImGui::TextColored(theme::kError, "You said %s; the exact run says %s.", said.c_str(), done->grade.expected.c_str());
  if (shown.section && !shown.section->text.empty()) draw_markdown(fill_templates(shown.section->text, *s.model(0), step).text, c.fonts);
  ImGui::TextDisabled("Step on (Right arrow) to see it happen.");
}

}  // namespace sw::vis
