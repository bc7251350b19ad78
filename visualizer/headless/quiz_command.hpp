// `stepwise quiz` and `stepwise lesson lint` (docs/lessons.md, docs/cli.md):
//   stepwise quiz LESSON --answers FILE.jsonl [--json]   grade a student's answers
//   stepwise quiz LESSON --list [--json]                 the questions, by step
//   stepwise lesson lint FILE...                         exit 0 clean, 1 problems, 2 unreadable
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>
#include "trace_io.hpp"

namespace sw::vis {

struct QuizOptions {
  std::string lesson, answers;
  bool list = false, json = false;
  std::uint64_t max_steps = Budget{}.max_steps;
};
CLI::App* add_quiz_command(CLI::App& app, QuizOptions& opts);
// Prints the grades, or the questions; throws InputError on a bad lesson or answers file, before
// printing anything.
int run_quiz(const QuizOptions& opts);

struct LintOptions {
  std::vector<std::string> files;
  std::uint64_t max_steps = Budget{}.max_steps;
};
CLI::App* add_lint_command(CLI::App& lesson_group, LintOptions& opts);
int run_lint(const LintOptions& opts);

}  // namespace sw::vis
