#include "headless/quiz_command.hpp"
#include "budget.hpp"
#include <filesystem>
#include <iostream>
#include "lessons/grading.hpp"
#include "lessons/quiz.hpp"

namespace sw::vis {

CLI::App* add_quiz_command(CLI::App& app, QuizOptions& o) {
  auto* q = app.add_subcommand("quiz", "Grade a lesson's predict-the-next-step answers against the exact trace");
  q->add_option("lesson", o.lesson, "Lesson file (lessons/*.md)")->required();
  auto* answers = q->add_option("--answers", o.answers, "Answer files or directories of them (JSONL: one {\"step\": N, \"answer\": ...} per line; a file is one student's unless lines name \"student\")");
  auto* list = q->add_flag("--list", o.list, "Print the questions instead: step, type, prompt, choices");
  answers->excludes(list);
  auto* json = q->add_flag("--json", o.json, "One JSON object per line");
  q->add_flag("--csv", o.csv, "Grades as CSV: a row per student, a column per question")->excludes(json)->excludes(list);
  q->add_option("--max-steps", o.max_steps, "Refuse lessons whose run implies more steps (default 4000000)")->check(CLI::Validator(budget_count_error, "COUNT"));
  return q;
}

namespace {

// Per student (their answers, then the score), per question (how many got it right), and the
// class: as text, JSON lines or CSV.
void print_grades(const ClassGrades& g, const std::vector<Question>& questions, const QuizOptions& o) {
  // Tallies per student and per question, and each student's answer to each question (grade_class
  // keeps one at most), counted once.
  const std::size_t nq = questions.size();
  std::vector<int> right(g.students.size()), answered(g.students.size()), q_right(nq), q_answered(nq);
  std::vector<const GradedAnswer*> cell(g.students.size() * nq);
  int total_right = 0;
  for (const GradedAnswer& a : g.answers) {
    const auto q = static_cast<std::size_t>(a.question - questions.data());
    right[a.student] += a.right, ++answered[a.student], q_right[q] += a.right, ++q_answered[q], total_right += a.right;
    cell[a.student * nq + q] = &a;
  }
  auto label = [](const Question& q) { return "step " + std::to_string(q.step) + " " + std::string(quiz_type_name(q.type)); };
  if (o.csv) {
    std::cout << "student,right,answered";
    for (const Question& q : questions) std::cout << ',' << csv_field(label(q));
    std::cout << '\n';
    for (std::size_t s = 0; s < g.students.size(); ++s) {
      std::cout << csv_field(g.students[s]) << ',' << right[s] << ',' << answered[s];
      for (std::size_t q = 0; q < nq; ++q) {
        const GradedAnswer* a = cell[s * nq + q];
        std::cout << ',' << (!a ? "" : a->right ? "right" : "wrong");
      }
      std::cout << '\n';
    }
    return;
  }
  for (std::size_t s = 0; s < g.students.size(); ++s) {
    Json list = Json::array();
    if (!o.json) std::cout << printable_name(g.students[s]) << ": " << right[s] << " of " << answered[s] << " answered right\n";
    for (std::size_t q = 0; q < nq; ++q) {
      if (!cell[s * nq + q]) continue;
      const GradedAnswer& a = *cell[s * nq + q];
      if (o.json) list.push_back({{"step", a.question->step}, {"type", quiz_type_name(a.question->type)}, {"right", a.right}, {"answer", a.given}, {"expected", a.expected}});
      else std::cout << "  " << label(*a.question) << ": " << (a.right ? "right: " + a.expected : "wrong: answered " + a.given + ", the truth is " + a.expected) << '\n';
    }
    if (o.json)
      std::cout << Json{{"student", g.students[s]}, {"right", right[s]}, {"answered", answered[s]}, {"answers", list}}.dump(-1, ' ', false, Json::error_handler_t::replace) << '\n';
  }
  for (std::size_t k = 0; k < nq; ++k) {
    const Question& q = questions[k];
    const int r = q_right[k], n = q_answered[k];
    if (o.json) std::cout << Json{{"question", q.step}, {"type", quiz_type_name(q.type)}, {"prompt", q.prompt}, {"right", r}, {"answered", n}}.dump() << '\n';
    else std::cout << label(q) << ": " << (n ? std::to_string(r) + " of " + std::to_string(n) + " right" : std::string("not answered")) << '\n';
  }
  const std::string plural_q = questions.size() == 1 ? " question" : " questions", plural_s = g.students.size() == 1 ? " student" : " students";
  if (o.json)
    std::cout << Json{{"class", {{"students", g.students.size()}, {"right", total_right}, {"answered", g.answers.size()}, {"questions", questions.size()}, {"skipped", g.skipped.size()}}}}.dump() << '\n';
  else
    std::cout << "class: " << total_right << " of " << g.answers.size() << " answers right; " << g.students.size() << plural_s << ", " << questions.size()
              << plural_q << " in the lesson" << (g.skipped.empty() ? "" : "; " + std::to_string(g.skipped.size()) + " lines skipped (listed on stderr)") << '\n';
}

}  // namespace

int run_quiz(const QuizOptions& o) {
  if (o.answers.empty() == !o.list) throw InputError("quiz: give --answers FILE.jsonl... or --list");
  const Lesson lesson = load_lesson(o.lesson);
  Budget budget;
  budget.max_steps = o.max_steps;
  const QuizRuns runs = record_quiz_runs(lesson, budget);
  const std::vector<Question> questions = quiz_questions(lesson, *runs.run, runs.compared.get());
  if (o.list) {
    for (const Question& q : questions) {
      if (o.json) {
        std::cout << Json{{"step", q.step}, {"type", quiz_type_name(q.type)}, {"prompt", q.prompt}, {"choices", q.choices}}.dump() << '\n';
        continue;
      }
      std::cout << "step " << q.step << "  " << quiz_type_name(q.type) << (q.var.empty() ? "" : " " + q.var) << (q.than.empty() ? "" : " vs " + q.than) << "  " << q.prompt;
      if (!q.choices.empty()) {
        std::cout << "  [";
        for (std::size_t i = 0; i < q.choices.size(); ++i) std::cout << (i ? ", " : "") << q.choices[i];
        std::cout << "]";
      }
      std::cout << '\n';
    }
    return 0;
  }
  std::vector<std::filesystem::path> files;
  for (const std::string& path : o.answers)
    for (auto& f : answer_files(path)) files.push_back(std::move(f));
  const ClassGrades g = grade_class(questions, files);
  print_grades(g, questions, o);
  for (const std::string& line : g.skipped) std::cerr << "stepwise: skipped " << line << '\n';
  return g.skipped.empty() ? 0 : 1;
}

CLI::App* add_lint_command(CLI::App& group, LintOptions& o) {
  auto* l = group.add_subcommand("lint", "Check lessons: every section reachable, every template and condition resolving");
  l->add_option("files", o.files, "Lesson files")->required();
  l->add_option("--max-steps", o.max_steps, "Refuse lessons whose runs imply more steps (default 4000000)")->check(CLI::Validator(budget_count_error, "COUNT"));
  return l;
}

int run_lint(const LintOptions& o) {
  Budget budget;
  budget.max_steps = o.max_steps;
  int bad = 0;
  for (const std::string& f : o.files) {
    if (!std::filesystem::is_regular_file(f)) throw InputError("cannot read lesson file '" + f + "'");
    const auto problems = lint_lesson(f, budget);
    for (const std::string& p : problems) std::cout << one_line(p) << '\n';
    bad += !problems.empty();
  }
  std::cerr << "stepwise: " << o.files.size() - static_cast<std::size_t>(bad) << " of " << o.files.size() << " lessons clean\n";
  return bad ? 1 : 0;
}

}  // namespace sw::vis
