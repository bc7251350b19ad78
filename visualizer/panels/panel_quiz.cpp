// Quiz mode: the questions of the open lesson on its exact run, the gate that stops stepping at an
// unanswered one, and the prompt with its answer buttons under the narration.
#include <algorithm>
#include "panels/app.hpp"

namespace sw::vis {

bool App::set_quiz(bool on) {
  if (on == quiz_.on) return true;
  if (!lesson_) return false;
  const Lesson& l = *lesson_;
  // The quiz is checked against the exact run, so that is the run the student steps through.
  if (std::string err = load(*l.algorithm, l.input, on ? quiz_numeric(l) : l.numeric, on ? Comparison{} : l.compare, true); !err.empty()) {
    error_ = err;
    return false;
  }
  quiz_ = {};
  quiz_.on = on;
  if (on) quiz_.questions = quiz_questions(l, *a_);
  playing_ = false;
  step_ = 0;
  set_step(on ? 0 : l.start_step);
  return true;
}

const App::QuizState::Answered* App::quiz_answered(std::size_t step) const {
  for (const auto& a : quiz_.answered)
    if (a.step == step) return &a;
  return nullptr;
}

const Question* App::quiz_pending() const {
  if (!quiz_.on) return nullptr;
  auto it = std::lower_bound(quiz_.questions.begin(), quiz_.questions.end(), step_, [](const Question& q, std::size_t s) { return q.step < s; });
  return it != quiz_.questions.end() && it->step == step_ && !quiz_answered(step_) ? &*it : nullptr;
}

std::size_t App::quiz_gate(std::size_t target) {
  if (target <= step_) return target;
  for (const Question& q : quiz_.questions)
    if (q.step >= step_ && q.step < target && !quiz_answered(q.step)) {
      playing_ = false;
      return q.step;
    }
  return target;
}

std::optional<Grade> App::answer(const Json& a) {
  const Question* q = quiz_pending();
  if (!q) return std::nullopt;
  const Grade g = grade(*q, a);
  quiz_.answered.push_back({q->step, g, answer_text(*q, normal_answer(*q, a))});
  return g;
}

std::pair<int, int> App::quiz_score() const {
  const auto right = std::count_if(quiz_.answered.begin(), quiz_.answered.end(), [](const auto& a) { return a.grade.right; });
  return {static_cast<int>(right), static_cast<int>(quiz_.answered.size())};
}

void App::draw_quiz() {
  ImGui::Separator();
  const auto [right, asked] = quiz_score();
  ImGui::TextColored(theme::kDim, "Quiz: %d of %d right, %zu questions in this lesson", right, asked, quiz_.questions.size());
  const auto* done = quiz_answered(step_);
  const Question* q = quiz_pending();
  if (!q && !done) return;
  const Question& shown = q ? *q : *std::find_if(quiz_.questions.begin(), quiz_.questions.end(), [&](const Question& x) { return x.step == step_; });
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.85f, 1.f, 1));
  ImGui::TextWrapped("%s", shown.prompt.empty() ? "Predict the next step." : shown.prompt.c_str());
  ImGui::PopStyleColor();
  if (q) {
    auto buttons = [&](std::initializer_list<std::pair<const char*, Json>> options) {
      for (const auto& [label, value] : options) {
        if (ImGui::Button(label)) answer(value);
        ImGui::SameLine();
      }
      ImGui::NewLine();
    };
    switch (q->type) {
      case QuizType::pixel: ImGui::TextDisabled("Click the cell you expect on the canvas."); break;
      case QuizType::sign: buttons({{"negative", -1}, {"zero", 0}, {"positive", 1}}); break;
      case QuizType::hit: buttons({{"hit", true}, {"miss", false}}); break;
      case QuizType::branch:
        for (const std::string& c : q->choices) {
          if (ImGui::Button(c.c_str())) {
            answer(c);
            break;
          }
          ImGui::SameLine();
        }
        ImGui::NewLine();
        break;
    }
    return;
  }
  if (done->grade.right) ImGui::TextColored(theme::kGood, "Right: %s.", done->answer.c_str());
  else ImGui::TextColored(theme::kError, "You said %s; the exact run says %s.", done->answer.c_str(), done->grade.expected.c_str());
  if (shown.section && !shown.section->text.empty()) draw_markdown(fill_templates(shown.section->text, *a_, step_).text);
  ImGui::TextDisabled("Step on (Right arrow) to see it happen.");
}

}  // namespace sw::vis
