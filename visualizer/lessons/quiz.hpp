// Predict-the-next-step quizzes, checked against the exact trace (docs/lessons.md, Quizzes).
// A question sits on a step and asks what the run does next: which pixel it plots, which listing
// line it runs, the sign a variable takes, whether the ray hits or a flag is set; in a lesson that
// compares number types, also whether the compared run (float) does the same next, and at which
// step it first leaves the exact run.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include "lessons/lesson.hpp"
#include "lessons/trace_model.hpp"

namespace sw::vis {

struct Question {
  std::size_t step = 0;
  QuizType type = QuizType::pixel;
  std::string var;                   // QuizType::sign and flag: a variable or a component ("c.r")
  std::string than;                  // QuizType::sign: the number the variable is compared with ("" = 0)
  std::string prompt;
  Json answer;                       // the truth: [x, y], a line name, -1/0/1, true/false, or a step
  std::size_t answer_step = 0;       // the step that shows the truth
  // The step the screen shows until the question is answered: the one before, whose frame cannot
  // give the answer away; the question's own step for a pixel question on a plot step (the pixel
  // plotted there is where the question starts) and at step 0.
  std::size_t shown_step = 0;
  std::vector<std::string> choices;  // QuizType::branch: the listing line names offered
  const Narration* section = nullptr;  // the quiz point that asks it; nullptr for an automatic one
};

std::string_view quiz_type_name(QuizType t);

// The number type a lesson's quiz is checked in: exact where the algorithm has it, else int.
Numeric quiz_numeric(const Lesson& lesson);
// The number type the float questions (same, diverge) compare with it: the lesson's other number
// type, when it compares two of the same algorithm; none otherwise.
std::optional<Numeric> quiz_compared_numeric(const Lesson& lesson);

// The runs a quiz is checked against: the quiz's run and, if the lesson has one, the compared run.
struct QuizRuns {
  std::shared_ptr<const TraceModel> run, compared;
};
QuizRuns record_quiz_runs(const Lesson& lesson, const Budget& budget);

// The question at `step` of `run`: the lesson's quiz point there, or, when the lesson declares
// none, an automatic one at a decide or plot step. nullopt if there is none; *why_not then says
// why a declared point could not be asked (nothing follows to predict). `compared` is the run
// float questions compare with (nullptr: none, and such a point cannot be asked).
std::optional<Question> question_at(const Lesson& lesson, const TraceModel& run, std::size_t step, std::string* why_not = nullptr,
                                    const TraceModel* compared = nullptr);
std::vector<Question> quiz_questions(const Lesson& lesson, const TraceModel& run, const TraceModel* compared = nullptr);

// Grades an answer; throws InputError if it is not of the question's form.
struct Grade {
  bool right = false;
  std::string expected;  // the truth, as text
};
Grade grade(const Question& q, const Json& answer);
// The answer in the truth's form ("negative" -> -1, "hit" -> true); throws InputError as grade does.
Json normal_answer(const Question& q, const Json& answer);
// A normal answer as text: "(3, 4)", a line name, "negative", "hit", "yes", "same", "step 12".
std::string answer_text(const Question& q, const Json& normal);

}  // namespace sw::vis
