// `stepwise lesson ...`: the commands that work on one lesson file. `export` writes it as a web page
// (html_export.hpp); `lint` checks it (quiz_command.hpp). A sibling subcommand adds its options struct and CLI::App* here, one block in
// add_lesson_commands and one line in run_lesson_commands.
#pragma once
#include <CLI/CLI.hpp>
#include "headless/html_export.hpp"
#include "headless/quiz_command.hpp"

namespace sw::vis {

// main keeps this alive while parsing: the subcommands write their options into it.
struct LessonCommands {
  CLI::App* group = nullptr;
  CLI::App* export_cmd = nullptr;
  ExportOptions export_opts;
  CLI::App* lint_cmd = nullptr;
  LintOptions lint_opts;
};

// Adds the `lesson` group and its subcommands; main calls run_lesson_commands when *c.group.
void add_lesson_commands(CLI::App& app, LessonCommands& c);
// Runs the subcommand that was given; returns its exit code. Throws InputError on bad input.
int run_lesson_commands(const LessonCommands& c);

}  // namespace sw::vis
