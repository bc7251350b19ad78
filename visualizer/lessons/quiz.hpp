// Predict-the-next-step quizzes, checked against the exact trace (docs/lessons.md, Quizzes).
// A question sits on a step and asks what the run does next: which pixel it plots, which listing
// line it runs, the sign a variable takes, or whether the ray hits.
#pragma once
#include <optional>
#include <string>
#include <vector>
#include "lessons/lesson.hpp"
#include "lessons/trace_model.hpp"

namespace sw::vis {

struct Question {
  std::size_t step = 0;
  QuizType type = QuizType::pixel;
  std::string var;                   // QuizType::sign
  std::string prompt;
  Json answer;                       // the truth: [x, y], a line name, -1/0/1, or true/false
  std::size_t answer_step = 0;       // the step that shows the truth
  std::vector<std::string> choices;  // QuizType::branch: the listing line names offered
  const Narration* section = nullptr;  // the quiz point that asks it; nullptr for an automatic one
};

std::string_view quiz_type_name(QuizType t);

// The number type a lesson's quiz is checked in: exact where the algorithm has it, else int.
Numeric quiz_numeric(const Lesson& lesson);

// The question at `step` of `run`: the lesson's quiz point there, or, when the lesson declares
// none, an automatic one at a decide or plot step. nullopt if there is none; *why_not then says
// why a declared point could not be asked (nothing follows to predict).
std::optional<Question> question_at(const Lesson& lesson, const TraceModel& run, std::size_t step, std::string* why_not = nullptr);
std::vector<Question> quiz_questions(const Lesson& lesson, const TraceModel& run);

// Grades an answer; throws InputError if it is not of the question's form.
struct Grade {
  bool right = false;
  std::string expected;  // the truth, as text
};
Grade grade(const Question& q, const Json& answer);
// The answer in the truth's form ("negative" -> -1, "hit" -> true); throws InputError as grade does.
Json normal_answer(const Question& q, const Json& answer);
// A normal answer as text: "(3, 4)", a line name, "negative", "hit".
std::string answer_text(const Question& q, const Json& normal);

}  // namespace sw::vis
