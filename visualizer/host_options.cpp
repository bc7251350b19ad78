#include "host_options.hpp"
#include <cstdlib>
#include "input.hpp"

namespace sw::vis {

void add_host_options(CLI::App& cli, HostOptions& o) {
  auto* lesson = cli.add_option("--lesson", o.lesson, "Lesson file, or its number in the manifest (default: the first lesson)");
  auto* alg = cli.add_option("--algorithm", o.algorithm, "Algorithm id");
  cli.add_option("--input", o.input, "Input as JSON text or a file holding it");
  lesson->excludes(alg);
  cli.add_option("--numeric", o.numeric, "Number type");
  cli.add_option("--compare", o.compare, "A second number type, or another algorithm of the same compare group (a reflection model), side by side");
  cli.add_option("--step", o.step, "Start at this step")->check(CLI::Validator(budget_count_error, "STEP"));
  cli.add_option("--max-steps", o.budget.max_steps, "Refuse inputs that imply more steps (default 4000000)")->check(CLI::Validator(budget_count_error, "COUNT"));
  cli.add_option("--scale", o.scale, "UI scale for fonts and spacing, 0.75 to 3 (a projector: 1.5 to 2)");
  cli.add_flag("--present", o.present, "Start in presentation mode (P toggles it)");
  cli.add_flag("--quiz", o.quiz, "Start the lesson in quiz mode (Q toggles it)")->excludes(alg);
  cli.add_option("--answers-dir", o.answers_dir, "Save quiz answers as they are given, in DIR/<lesson>.jsonl (stepwise quiz grades them)");
  cli.add_option("--student", o.student, "The name saved with the answers (default: $USER)");
}

namespace {

// The manifest entry whose file name starts with `number` and a dash ("05-..."), if `number` is one.
std::optional<std::size_t> lesson_numbered(const Session& session, const std::string& number) {
  if (number.empty() || number.size() > 3 || number.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  for (std::size_t k = 0; k < session.lessons().size(); ++k)
    if (session.lessons()[k].filename().string().starts_with(number + "-")) return k;
  return std::nullopt;
}

}  // namespace

bool open_session(Session& session, const HostOptions& o) {
  if (o.algorithm.empty()) {
    const std::optional<std::size_t> numbered = lesson_numbered(session, o.lesson);
    const bool opened = numbered ? session.open_manifest_lesson(*numbered) : o.lesson.empty() ? session.open_first_lesson() : session.open_lesson(o.lesson);
    if (!opened) return false;
  }
  try {
    if (!o.algorithm.empty()) {  // --algorithm with its --input, or its example
      const Algorithm& alg = find_algorithm(o.algorithm);
      const Json input = !o.input.empty() ? read_input_arg(o.input) : parse_json_text(alg.example, "example");
      const Numeric n = parse_numeric_for(alg, !o.numeric.empty() ? o.numeric : "double");
      Comparison cmp;
      if (!o.compare.empty()) cmp = parse_comparison(alg, o.compare, n);
      if (!session.open_algorithm(alg, input, n, cmp)) return false;
    } else {
      // The lesson stays open, its narration with it: its run with another --input, or in other
      // number types (with its own comparison unless --compare names one).
      if (!o.input.empty())
        if (const std::string err = session.apply_input(read_input_arg(o.input)); !err.empty()) {
          session.show_error(err);
          return false;
        }
      if (const TraceModel* m = session.model(0); m && (!o.numeric.empty() || !o.compare.empty())) {
        const Numeric n = !o.numeric.empty() ? parse_numeric_for(m->algorithm(), o.numeric) : m->numeric();
        const Comparison cmp = !o.compare.empty() ? parse_comparison(m->algorithm(), o.compare, n) : session.comparison();
        if (!session.set_numerics(n, cmp)) return false;
      }
    }
  } catch (const InputError& e) {
    session.show_error(e.what());
    return false;
  }
  if (!o.answers_dir.empty()) {
    const char* user = std::getenv("USER");
    session.save_answers_in(o.answers_dir, !o.student.empty() ? o.student : user && *user ? user : "student");
  }
  if (o.quiz && !session.set_quiz(true)) return false;
  if (o.step) session.set_step(*o.step);
  return true;
}

}  // namespace sw::vis
