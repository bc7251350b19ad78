#include "headless/quiz_command.hpp"
#include "budget.hpp"
#include <iostream>
#include "lessons/quiz.hpp"

namespace sw::vis {

CLI::App* add_quiz_command(CLI::App& app, QuizOptions& o) {
  auto* q = app.add_subcommand("quiz", "Grade a lesson's predict-the-next-step answers against the exact trace");
  q->add_option("lesson", o.lesson, "Lesson file (lessons/*.md)")->required();
  auto* answers = q->add_option("--answers", o.answers, "JSONL: one {\"step\": N, \"answer\": ...} per line");
  auto* list = q->add_flag("--list", o.list, "Print the questions instead: step, type, prompt, choices");
  answers->excludes(list);
  q->add_flag("--json", o.json, "One JSON object per line");
  q->add_option("--max-steps", o.max_steps, "Refuse lessons whose run implies more steps (default 4000000)")->check(CLI::Validator(budget_count_error, "COUNT"));
  return q;
}

int run_quiz(const QuizOptions& o) {
  if (o.answers.empty() == !o.list) throw InputError("quiz: give --answers FILE.jsonl or --list");
  const Lesson lesson = load_lesson(o.lesson);
  Budget budget;
  budget.max_steps = o.max_steps;
  const auto run = record_model(lesson.run->in(quiz_numeric(lesson)), budget);
  const std::vector<Question> questions = quiz_questions(lesson, *run);
  if (o.list) {
    for (const Question& q : questions) {
      if (o.json) {
        std::cout << Json{{"step", q.step}, {"type", quiz_type_name(q.type)}, {"prompt", q.prompt}, {"choices", q.choices}}.dump() << '\n';
        continue;
      }
      std::cout << "step " << q.step << "  " << quiz_type_name(q.type) << (q.var.empty() ? "" : " " + q.var) << "  " << q.prompt;
      if (!q.choices.empty()) {
        std::cout << "  [";
        for (std::size_t i = 0; i < q.choices.size(); ++i) std::cout << (i ? ", " : "") << q.choices[i];
        std::cout << "]";
      }
      std::cout << '\n';
    }
    return 0;
  }
  // Read and grade everything before printing, so that a bad line prints nothing but its error.
  std::ifstream in = open_input_file(o.answers, "answers file");
  std::vector<std::string> out;
  int right = 0, graded = 0;
  std::string line;
  for (std::size_t n = 1; read_line(in, line, 1 << 16, "answers line " + std::to_string(n)); ++n) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string at = o.answers + ":" + std::to_string(n);
    try {
      const Json a = parse_json_text(line, "answer");
      if (!a.is_object()) throw InputError("expected {\"step\": N, \"answer\": ...}");
      only_keys_optional(a, {"step", "answer"}, {"student"}, "answer");
      if (a.contains("student") && !a["student"].is_string()) throw InputError("\"student\" must be a string");
      const auto step = static_cast<std::size_t>(parse_integer(a["step"], "step", 0, std::int64_t{1} << 40));
      const auto q = std::find_if(questions.begin(), questions.end(), [&](const Question& x) { return x.step == step; });
      if (q == questions.end()) throw InputError("no question at step " + std::to_string(step) + " (see --list)");
      const Grade g = grade(*q, a["answer"]);
      right += g.right, ++graded;
      const std::string student = a.value("student", "");
      if (o.json) {
        Json j{{"step", step}, {"type", quiz_type_name(q->type)}, {"right", g.right}, {"expected", q->answer}};
        if (!student.empty()) j["student"] = student;
        out.push_back(j.dump());
      } else {
        out.push_back((student.empty() ? "" : student + "  ") + "step " + std::to_string(step) + " " + std::string(quiz_type_name(q->type)) + ": " +
                      (g.right ? "right: " + g.expected : "wrong: answered " + answer_text(*q, normal_answer(*q, a["answer"])) + ", the exact run gives " + g.expected));
      }
    } catch (const InputError& e) {
      throw InputError(at + ": " + e.what());
    }
  }
  for (const std::string& l : out) std::cout << l << '\n';
  if (o.json) std::cout << Json{{"score", right}, {"answered", graded}, {"questions", questions.size()}}.dump() << '\n';
  else std::cout << "score: " << right << " of " << graded << " answered right (" << questions.size() << (questions.size() == 1 ? " question" : " questions") << " in the lesson)\n";
  return 0;
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
