#include "lessons/quiz.hpp"
#include <algorithm>
#include <set>

namespace sw::vis {
namespace {

// The next step after `step` in the algorithm's own listing (nested calls skipped), or none.
std::optional<std::size_t> next_own(const TraceModel& run, std::size_t step) {
  for (std::size_t s = step + 1; s < run.size(); ++s)
    if (run.trace().at(s).scope == 0) return s;
  return std::nullopt;
}

std::string line_name(const TraceModel& run, std::uint32_t line) {
  const auto& lines = run.algorithm().listing.lines;
  return line >= 1 && line <= lines.size() ? std::string(lines[line - 1].name) : std::to_string(line);
}

// Fills q's truth; false (and why) if nothing after q.step answers it.
// An automatic branch question needs a line that goes more than one way in the run.
bool find_truth(Question& q, const TraceModel& run, bool declared, std::string& why) {
  const TraceView& t = run.trace();
  switch (q.type) {
    case QuizType::pixel:
      for (const PlotEvent& e : run.plots())
        if (e.step > q.step) {
          q.answer = Json::array({e.cell.x, e.cell.y}), q.answer_step = e.step;
          return true;
        }
      why = "no pixel is plotted after it";
      return false;
    case QuizType::branch: {
      const auto next = next_own(run, q.step);
      if (!next) {
        why = "it is the last step";
        return false;
      }
      q.answer = line_name(run, t.at(*next).line), q.answer_step = *next;
      // Offer the lines that ever follow this one in the run; all lines when it always goes one way.
      std::set<std::uint32_t> seen;
      const std::uint32_t here = t.at(q.step).line;
      for (std::size_t s = 0; s + 1 < run.size(); ++s)
        if (t.at(s).scope == 0 && t.at(s).line == here)
          if (const auto n = next_own(run, s)) seen.insert(t.at(*n).line);
      if (seen.size() < 2 && !declared) {
        why = "it always goes one way";
        return false;
      }
      if (seen.size() < 2)
        for (std::uint32_t l = 1; l <= run.algorithm().listing.lines.size(); ++l) seen.insert(l);
      for (std::uint32_t l : seen) q.choices.push_back(line_name(run, l));
      return true;
    }
    case QuizType::sign:
      for (std::size_t s = q.step + 1; s < run.size(); ++s) {
        const StepRecord& st = t.at(s);
        for (std::uint32_t v = st.var_begin; v < st.var_end; ++v)
          if (t.var_at(v).name == q.var && t.var_at(v).shape == VarShape::scalar) {
            const auto x = exact_value(run, t.var_at(v), 0);
            if (!x) {
              why = "'" + q.var + "' is not finite at step " + std::to_string(s);
              return false;
            }
            q.answer = sgn(*x), q.answer_step = s;
            return true;
          }
      }
      why = "'" + q.var + "' is not recorded as a number after it";
      return false;
    case QuizType::hit:
      for (std::size_t s = q.step + 1; s < run.size(); ++s)
        if (t.at(s).scope == 0 && (t.at(s).kind == StepKind::hit || t.at(s).kind == StepKind::miss)) {
          q.answer = t.at(s).kind == StepKind::hit, q.answer_step = s;
          return true;
        }
      why = "no hit or miss step of its own follows it";
      return false;
  }
  return false;
}

const char* kAutoPrompt[] = {"Which pixel is plotted next?", "Which line runs next?", "", "Does the ray hit?"};

}  // namespace

std::string_view quiz_type_name(QuizType t) {
  static constexpr std::string_view kNames[] = {"pixel", "branch", "sign", "hit"};
  return kNames[static_cast<int>(t)];
}

Numeric quiz_numeric(const Lesson& lesson) {
  if (lesson.algorithm->supports(Numeric::exact)) return Numeric::exact;
  if (lesson.algorithm->supports(Numeric::integer)) return Numeric::integer;
  return lesson.numeric;
}

std::optional<Question> question_at(const Lesson& lesson, const TraceModel& run, std::size_t step, std::string* why_not) {
  if (step >= run.size()) return std::nullopt;
  Question q;
  q.step = step;
  const bool declared = std::any_of(lesson.sections.begin(), lesson.sections.end(), [](const Narration& n) { return n.quiz.has_value(); });
  if (declared) {
    const Narration* n = lesson.quiz_for(run, step);
    if (!n) return std::nullopt;
    q.type = *n->quiz, q.var = n->quiz_var, q.prompt = fill_templates(n->prompt, run, step).text, q.section = n;
  } else {
    const StepRecord& st = run.trace().at(step);
    if (st.scope != 0) return std::nullopt;
    if (st.kind == StepKind::plot) q.type = QuizType::pixel;
    else if (st.kind == StepKind::decide) q.type = QuizType::branch;
    else if (step == 0) q.type = QuizType::hit;
    else return std::nullopt;
    q.prompt = kAutoPrompt[static_cast<int>(q.type)];
  }
  std::string why;
  if (!find_truth(q, run, declared, why)) {
    if (why_not) *why_not = why;
    return std::nullopt;
  }
  return q;
}

std::vector<Question> quiz_questions(const Lesson& lesson, const TraceModel& run) {
  std::vector<Question> out;
  for (std::size_t s = 0; s < run.size(); ++s)
    if (auto q = question_at(lesson, run, s)) out.push_back(std::move(*q));
  return out;
}

std::string answer_text(const Question& q, const Json& a) {
  switch (q.type) {
    case QuizType::pixel: return "(" + a[0].dump() + ", " + a[1].dump() + ")";
    case QuizType::branch: return a.get<std::string>();
    case QuizType::sign: return a.get<int>() < 0 ? "negative" : a.get<int>() > 0 ? "positive" : "zero";
    case QuizType::hit: return a.get<bool>() ? "hit" : "miss";
  }
  return a.dump();
}

Grade grade(const Question& q, const Json& answer) {
  const Json a = normal_answer(q, answer);
  return {a == q.answer, answer_text(q, q.answer)};
}

Json normal_answer(const Question& q, const Json& answer) {
  const std::string at = "the answer at step " + std::to_string(q.step) + " (" + std::string(quiz_type_name(q.type)) + ")";
  Json a = answer;
  switch (q.type) {
    case QuizType::pixel:
      if (!a.is_array() || a.size() != 2 || !a[0].is_number_integer() || !a[1].is_number_integer())
        throw InputError(at + ": expected a cell [x, y] of two integers");
      break;
    case QuizType::branch:
      if (!a.is_string() || std::find(q.choices.begin(), q.choices.end(), a.get<std::string>()) == q.choices.end())
        throw InputError(at + ": expected one of the listing line names offered");
      break;
    case QuizType::sign:
      if (a.is_string()) {
        const std::string s = a.get<std::string>();
        a = s == "negative" || s == "-" ? -1 : s == "zero" || s == "0" ? 0 : s == "positive" || s == "+" ? 1 : 2;
      }
      if (!a.is_number_integer() || a.get<long long>() < -1 || a.get<long long>() > 1)
        throw InputError(at + ": expected -1, 0 or 1 (or negative, zero, positive)");
      break;
    case QuizType::hit:
      if (a.is_string() && (a == "hit" || a == "miss")) a = a == "hit";
      if (!a.is_boolean()) throw InputError(at + ": expected true or false (or hit, miss)");
      break;
  }
  return a;
}

}  // namespace sw::vis
