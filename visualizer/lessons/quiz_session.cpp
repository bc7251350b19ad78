#include "lessons/quiz_session.hpp"
#include <algorithm>

namespace sw::vis {

void QuizSession::start(std::vector<Question> questions) {
  on_ = true;
  questions_ = std::move(questions);
  answered_.clear();
}

const Question* QuizSession::at(std::size_t step) const {
  auto it =
      std::lower_bound(questions_.begin(), questions_.end(), step, [](const Question& q, std::size_t s) { return q.step < s; });
  return it != questions_.end() && it->step == step ? &*it : nullptr;
}

const QuizSession::Answered* QuizSession::answered(std::size_t step) const {
  for (const Answered& a : answered_)
    if (a.step == step) return &a;
  return nullptr;
}

const Question* QuizSession::pending(std::size_t step) const {
  if (!on_) return nullptr;
  const Question* q = at(step);
  return q && !answered(step) ? q : nullptr;
}

std::size_t QuizSession::shown(std::size_t step) const {
  const Question* q = pending(step);
  return q ? q->shown_step : step;
}

std::size_t QuizSession::gate(std::size_t from, std::size_t target) const {
  if (!on_ || target <= from) return target;
  for (const Question& q : questions_)
    if (q.step >= from && q.step < target && !answered(q.step)) return q.step;
  return target;
}

std::optional<Grade> QuizSession::answer(std::size_t step, const Json& a) {
  const Question* q = pending(step);
  if (!q) return std::nullopt;
  const Grade g = grade(*q, a);
  answered_.push_back({q->step, g, normal_answer(*q, a)});
  return g;
}

std::pair<int, int> QuizSession::score() const {
  const auto right = std::count_if(answered_.begin(), answered_.end(), [](const Answered& a) { return a.grade.right; });
  return {static_cast<int>(right), static_cast<int>(answered_.size())};
}

}  // namespace sw::vis
