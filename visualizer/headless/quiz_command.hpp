// `stepwise quiz` and `stepwise lesson lint` (docs/lessons.md, docs/cli.md):
//   stepwise quiz LESSON --answers PATH... [--json|--csv] grade a class's answers (grading.hpp)
//   stepwise quiz LESSON --list [--json]                 the questions, by step
//   stepwise lesson lint FILE...                         exit 0 clean, 1 problems, 2 unreadable
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>
#include "trace_io.hpp"

namespace sw::vis {

struct QuizOptions {
  std::string lesson;
  std::vector<std::string> answers;  // files, or directories of *.jsonl files
  bool list = false, json = false, csv = false;
  std::uint64_t max_steps = Budget{}.max_steps;
};
CLI::App* add_quiz_command(CLI::App& app, QuizOptions& opts);
// Prints the questions, or the grades: 0 when every answer line was graded, 1 when some were
// skipped (each named on stderr as file:line: problem). Throws InputError on a bad lesson or an
// unreadable answers path, before printing anything.
int run_quiz(const QuizOptions& opts);

struct LintOptions {
  std::vector<std::string> files;
  std::uint64_t max_steps = Budget{}.max_steps;
};
CLI::App* add_lint_command(CLI::App& lesson_group, LintOptions& opts);
int run_lint(const LintOptions& opts);

}  // namespace sw::vis
