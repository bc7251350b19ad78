// A quiz in progress (docs/lessons.md, Quizzes): the questions on the quiz's run, the answers
// given and their grades, the gate that holds a forward move at the first unanswered question,
// and the score. No ImGui: the Session drives it, the narration panel draws it.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>
#include "lessons/quiz.hpp"

namespace sw::vis {

class QuizSession {
 public:
  struct Answered {
    std::size_t step;
    Grade grade;
    Json given;  // in the truth's form ([3, 4], a line name, -1, true); as text: answer_text(question, given)
  };

  bool on() const { return on_; }
  // Starts a quiz on these questions (by step, on the run being stepped through); stop() ends it.
  void start(std::vector<Question> questions);
  void stop() { *this = {}; }

  const std::vector<Question>& questions() const { return questions_; }
  // The question on `step`, answered or not; nullptr if none.
  const Question* at(std::size_t step) const;
  // The answer given at `step`, or nullptr.
  const Answered* answered(std::size_t step) const;
  // The question waiting at `step`: there, and not yet answered.
  const Question* pending(std::size_t step) const;
  // The step whose frame the screen shows at `step`: the waiting question's shown_step, else step.
  std::size_t shown(std::size_t step) const;
  // Whether every question has been answered (the views that show a whole sweep wait for it).
  bool finished() const { return answered_.size() >= questions_.size(); }
  // Where a forward move from `from` to `target` stops: the first unanswered question in
  // [from, target), or target itself.
  std::size_t gate(std::size_t from, std::size_t target) const;
  // Answers the question waiting at `step`: its grade, or nullopt if none waits. Throws
  // InputError for an answer of the wrong form (and records nothing).
  std::optional<Grade> answer(std::size_t step, const Json& answer);
  // Right answers, answers.
  std::pair<int, int> score() const;
  // The answers in the order given (grading.hpp writes them for `stepwise quiz`).
  const std::vector<Answered>& answers() const { return answered_; }

 private:
  bool on_ = false;
  std::vector<Question> questions_;
  std::vector<Answered> answered_;
};

}  // namespace sw::vis
