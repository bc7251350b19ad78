#include "lessons/quiz.hpp"
#include <algorithm>
#include <set>
#include "lessons/compare.hpp"

namespace sw::vis {
namespace {

// The next step after `step` in the same listing: the algorithm's own (nested calls skipped), or,
// inside a nested call, the callee's before the call returns to the algorithm's listing.
std::optional<std::size_t> next_in_scope(const TraceModel& run, std::size_t step) {
  const std::uint32_t scope = run.trace().at(step).scope;
  for (std::size_t s = step + 1; s < run.size(); ++s) {
    const std::uint32_t here = run.trace().at(s).scope;
    if (here == scope) return s;
    if (here == 0) break;
  }
  return std::nullopt;
}

std::string line_name(const TraceModel& run, std::uint32_t scope, std::uint32_t line) {
  const auto& lines = (scope ? run.trace().scope_listing(scope) : run.algorithm().listing).lines;
  return line >= 1 && line <= lines.size() ? std::string(lines[line - 1].name) : std::to_string(line);
}

// The next value of `ref` (a scalar variable, or one component: "c.r", "l[2]") after `step`,
// exactly; false (and why) if none.
bool next_value(const TraceModel& run, std::size_t step, const std::string& ref, Rational& value, std::size_t& at, std::string& why) {
  const TraceView& t = run.trace();
  const auto [name, component] = split_ref(ref);
  for (std::size_t s = step + 1; s < run.size(); ++s) {
    const StepRecord& st = t.at(s);
    for (std::uint32_t v = st.var_begin; v < st.var_end; ++v) {
      const VarRecord& var = t.var_at(v);
      if (var.name != name || (component ? *component >= var.count : var.shape != VarShape::scalar)) continue;
      const auto x = exact_value(run, var, component.value_or(0));
      if (!x) {
        why = "'" + ref + "' is not finite at step " + std::to_string(s);
        return false;
      }
      value = *x, at = s;
      return true;
    }
  }
  why = "'" + ref + "' is not recorded as a number after it";
  return false;
}

// Fills q's truth; false (and why) if nothing after q.step answers it.
// An automatic branch question needs a line that goes more than one way in the run.
bool find_truth(Question& q, const TraceModel& run, const TraceModel* compared, bool declared, std::string& why) {
  const TraceView& t = run.trace();
  const bool versus = q.type == QuizType::same || q.type == QuizType::diverge;
  if (versus && !compared) {
    why = "the lesson compares no other number type of its algorithm";
    return false;
  }
  if (versus)  // step numbers pair the runs only while they agree
    for (std::size_t s = 0; s <= q.step; ++s)
      if (!same_decisions_at(run, *compared, s)) {
        why = "the runs already differ at step " + std::to_string(s);
        return false;
      }
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
      const auto next = next_in_scope(run, q.step);
      if (!next) {
        why = "it is the last step of its listing";
        return false;
      }
      const std::uint32_t scope = t.at(q.step).scope, here = t.at(q.step).line;
      q.answer = line_name(run, scope, t.at(*next).line), q.answer_step = *next;
      // Offer the lines that ever follow this one in the run; all lines when it always goes one way.
      std::set<std::uint32_t> seen;
      for (std::size_t s = 0; s + 1 < run.size(); ++s)
        if (t.at(s).scope == scope && t.at(s).line == here)
          if (const auto n = next_in_scope(run, s)) seen.insert(t.at(*n).line);
      if (seen.size() < 2 && !declared) {
        why = "it always goes one way";
        return false;
      }
      const std::size_t lines = (scope ? t.scope_listing(scope) : run.algorithm().listing).lines.size();
      if (seen.size() < 2)
        for (std::uint32_t l = 1; l <= lines; ++l) seen.insert(l);
      for (std::uint32_t l : seen) q.choices.push_back(line_name(run, scope, l));
      return true;
    }
    case QuizType::sign:
    case QuizType::flag: {
      Rational x;
      if (!next_value(run, q.step, q.var, x, q.answer_step, why)) return false;
      if (!q.than.empty()) x -= parse_rational(Json(q.than), "the number after 'vs'");
      q.answer = q.type == QuizType::sign ? Json(sgn(x)) : Json(sgn(x) != 0);
      return true;
    }
    case QuizType::hit:
      for (std::size_t s = q.step + 1; s < run.size(); ++s)
        if (t.at(s).scope == 0 && (t.at(s).kind == StepKind::hit || t.at(s).kind == StepKind::miss)) {
          q.answer = t.at(s).kind == StepKind::hit, q.answer_step = s;
          return true;
        }
      why = "no hit or miss step of its own follows it";
      return false;
    case QuizType::same: {
      const auto next = next_in_scope(run, q.step);
      if (!next) {
        why = "it is the last step of its listing";
        return false;
      }
      bool same = true;
      for (std::size_t s = q.step + 1; s <= *next && same; ++s) same = same_decisions_at(run, *compared, s);
      q.answer = same, q.answer_step = *next;
      return true;
    }
    case QuizType::diverge:
      if (const auto d = compare_traces(run, *compared).first_decision_divergence; d && *d > q.step) {
        q.answer = *d, q.answer_step = std::min(*d, run.last());
        return true;
      }
      why = "the runs never differ after it";
      return false;
  }
  return false;
}

const char* kAutoPrompt[] = {"Which pixel is plotted next?", "Which line runs next?", "", "Does the ray hit?", "", "", ""};

}  // namespace

std::string_view quiz_type_name(QuizType t) {
  static constexpr std::string_view kNames[] = {"pixel", "branch", "sign", "hit", "flag", "same", "diverge"};
  return kNames[static_cast<int>(t)];
}

Numeric quiz_numeric(const Lesson& lesson) {
  if (lesson.algorithm->supports(Numeric::exact)) return Numeric::exact;
  if (lesson.algorithm->supports(Numeric::integer)) return Numeric::integer;
  return lesson.numeric;
}

std::optional<Numeric> quiz_compared_numeric(const Lesson& lesson) {
  if (lesson.compare.other || !lesson.compare.numeric) return std::nullopt;
  const Numeric q = quiz_numeric(lesson);
  if (lesson.numeric != q) return lesson.numeric;
  if (*lesson.compare.numeric != q) return *lesson.compare.numeric;
  return std::nullopt;
}

QuizRuns record_quiz_runs(const Lesson& lesson, const Budget& budget) {
  QuizRuns r;
  r.run = record_model(lesson.run->in(quiz_numeric(lesson)), budget);
  if (const auto c = quiz_compared_numeric(lesson)) r.compared = record_model(lesson.run->in(*c), budget);
  return r;
}

std::optional<Question> question_at(const Lesson& lesson, const TraceModel& run, std::size_t step, std::string* why_not,
                                    const TraceModel* compared) {
  if (step >= run.size()) return std::nullopt;
  Question q;
  q.step = step;
  const bool declared = std::any_of(lesson.sections.begin(), lesson.sections.end(), [](const Narration& n) { return n.quiz.has_value(); });
  if (declared) {
    const Narration* n = lesson.quiz_for(run, step);
    if (!n) return std::nullopt;
    q.type = *n->quiz, q.var = n->quiz_var, q.than = n->quiz_than, q.prompt = fill_templates(n->prompt, run, step).text, q.section = n;
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
  if (!find_truth(q, run, compared, declared, why)) {
    if (why_not) *why_not = why;
    return std::nullopt;
  }
  const bool on_its_pixel = q.type == QuizType::pixel && run.trace().at(step).kind == StepKind::plot;
  q.shown_step = step == 0 || on_its_pixel ? step : step - 1;
  return q;
}

std::vector<Question> quiz_questions(const Lesson& lesson, const TraceModel& run, const TraceModel* compared) {
  std::vector<Question> out;
  for (std::size_t s = 0; s < run.size(); ++s)
    if (auto q = question_at(lesson, run, s, nullptr, compared)) out.push_back(std::move(*q));
  return out;
}

std::string answer_text(const Question& q, const Json& a) {
  switch (q.type) {
    case QuizType::pixel: return "(" + a[0].dump() + ", " + a[1].dump() + ")";
    case QuizType::branch: return a.get<std::string>();
    case QuizType::sign:
      if (!q.than.empty()) return a.get<int>() < 0 ? "below" : a.get<int>() > 0 ? "above" : "equal";
      return a.get<int>() < 0 ? "negative" : a.get<int>() > 0 ? "positive" : "zero";
    case QuizType::hit: return a.get<bool>() ? "hit" : "miss";
    case QuizType::flag: return a.get<bool>() ? "yes" : "no";
    case QuizType::same: return a.get<bool>() ? "same" : "differs";
    case QuizType::diverge: return "step " + a.dump();
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
        a = s == "negative" || s == "below" || s == "-" ? -1 : s == "zero" || s == "equal" || s == "0" ? 0 : s == "positive" || s == "above" || s == "+" ? 1 : 2;
      }
      if (!a.is_number_integer() || a.get<long long>() < -1 || a.get<long long>() > 1)
        throw InputError(at + (q.than.empty() ? ": expected -1, 0 or 1 (or negative, zero, positive)" : ": expected -1, 0 or 1 (or below, equal, above)"));
      break;
    case QuizType::hit:
    case QuizType::flag:
    case QuizType::same: {
      static constexpr const char* kWords[][2] = {{"hit", "miss"}, {"yes", "no"}, {"same", "differs"}};
      const auto& w = kWords[q.type == QuizType::hit ? 0 : q.type == QuizType::flag ? 1 : 2];
      if (a.is_string() && (a == w[0] || a == w[1])) a = a == w[0];
      if (!a.is_boolean()) throw InputError(at + ": expected true or false (or " + w[0] + ", " + w[1] + ")");
      break;
    }
    case QuizType::diverge:
      if (!a.is_number_unsigned()) throw InputError(at + ": expected a step number");
      break;
  }
  return a;
}

}  // namespace sw::vis
