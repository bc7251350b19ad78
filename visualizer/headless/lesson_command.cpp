#include "headless/lesson_command.hpp"
#include "budget.hpp"

namespace sw::vis {

void add_lesson_commands(CLI::App& app, LessonCommands& c) {
  c.group = app.add_subcommand("lesson", "Work on lesson files: export one as a web page, lint them");
  c.group->require_subcommand(1);

  ExportOptions& e = c.export_opts;
  c.export_cmd = c.group->add_subcommand(
      "export", "Write a lesson as a web page: the whole app opened on it (--html DIR: DIR/index.html, one file), or a "
                "flip-book of its frames (--frames DIR: DIR/index.html and DIR/frames/*.png)");
  c.export_cmd->add_option("lesson", e.lesson, "Lesson file (lessons/*.md)")->required();
  auto* html = c.export_cmd->add_option("--html", e.html_dir, "Directory to write the app's page to (new, empty, or an earlier export, which is replaced)");
  auto* frames = c.export_cmd->add_option("--frames", e.frames_dir, "Directory to write the flip-book to (new, empty, or an earlier export)");
  html->excludes(frames);
  c.export_cmd->add_option("--size", e.size, "--frames: frame size WxH (default 1280x800)")->excludes(html);
  c.export_cmd->add_option("--from", e.from, "--frames: first step of the page (default 0); --html: the step it opens at")->check(CLI::Validator(budget_count_error, "STEP"));
  c.export_cmd->add_option("--to", e.to, "--frames: last step of the page, inclusive (default: the last step)")->check(CLI::Validator(budget_count_error, "STEP"))->excludes(html);
  c.export_cmd->add_option("--max-pixels", e.max_pixels, "--frames: refuse a page of more frames x width x height (default " + std::to_string(kDefaultPagePixels) + ")")->check(CLI::Validator(budget_count_error, "COUNT"))->excludes(html);
  c.export_cmd->add_option("--max-steps", e.max_steps, "Refuse inputs that imply more steps (default 4000000)")->check(CLI::Validator(budget_count_error, "COUNT"));
  c.lint_cmd = add_lint_command(*c.group, c.lint_opts);
}

int run_lesson_commands(const LessonCommands& c) {
  if (*c.export_cmd) return run_lesson_export(c.export_opts);
  if (*c.lint_cmd) return run_lint(c.lint_opts);
  throw InputError("lesson: give a subcommand (export, lint)");
}

}  // namespace sw::vis
