// Lessons: Markdown files with a front-matter block that names the algorithm, the input and the
// number types, an intro, and narration sections keyed on listing lines, kinds or steps, with
// conditions on recorded values and {templates} that quote them (docs/lessons.md).
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>
#include "catalog.hpp"
#include "lessons/compare.hpp"

namespace sw::vis {

class TraceModel;

// "e < 0", "q.x >= 3/2", "e != d": operands are variable references or exact numbers.
struct Condition {
  std::string lhs, op, rhs;
};

// What a quiz point asks about the steps after the one it is on (docs/lessons.md, Quizzes): the
// next pixel, line, sign of a variable, hit or miss, whether a flag variable is set; and, against
// the compared number type's run, whether it does the same next and where it first leaves.
enum class QuizType { pixel, branch, sign, hit, flag, same, diverge };

struct Narration {
  enum class Key { intro, line, kind, step } key = Key::intro;
  std::uint32_t line = 0;          // Key::line: in the listing of the run it is for
  std::string callee;              // Key::line of a nested listing ("ray-triangle-mt/u"): its id
  StepKind kind = StepKind::init;  // Key::kind
  std::size_t step = 0;            // Key::step
  std::string run;                 // "for X": only the run of number type or algorithm X
  std::vector<Condition> conditions;
  std::string heading;             // as written, for messages
  std::size_t source_line = 0;     // 1-based line of the heading in its file
  std::filesystem::path source;    // an included file's path; empty: the lesson itself
  std::string text;                // Markdown body, {templates} unfilled
  std::optional<QuizType> quiz;    // "## quiz ...": a question, its body the explanation
  std::string quiz_var;            // QuizType::sign and flag: the variable ("e", "c.r", "l[2]")
  std::string quiz_than;           // QuizType::sign: "sign F vs 1/2" compares F with 1/2 ("" = 0)
  std::string prompt;              // the question
};

struct Lesson {
  std::filesystem::path path;
  std::string title;
  const Algorithm* algorithm = nullptr;
  Json input;
  Numeric numeric = Numeric::exact;
  Comparison compare;              // a second number type, or another model, shown side by side
  // The input opened (parsed once) for the lesson's run, and for the compared run if any.
  std::optional<Run> run, compare_run;
  std::size_t start_step = 0;      // where the timeline starts
  std::size_t start_step_line = 0;
  std::optional<std::size_t> screenshot_step;  // "screenshot: N": the step lessons/screenshots.sh shows (else start_step)
  std::size_t screenshot_line = 0;
  bool focus = false;              // "view: step": zoom in on the start step, not the whole trace
  std::optional<View> show;        // "show: tree": the declared view to open on (default: the first)
  std::string intro;               // Markdown, always shown above the step's narration
  std::vector<Narration> sections; // narration and quiz sections in file order, then the included ones
  // "include: calls/ray-tracer.md": shared narration of the nested calls, relative to the lesson's
  // directory; a lesson's own section wins over an included one with the same key.
  std::vector<std::filesystem::path> includes;

  // The narration section `run` shows at `step` (the most specific that matches); nullptr if none.
  const Narration* section_for(const TraceModel& run, std::size_t step) const;
  // The quiz section at `step` of `run`, or nullptr.
  const Narration* quiz_for(const TraceModel& run, std::size_t step) const;
};

// A variable reference: "q.x" -> ("q", 0), "c.g" -> ("c", 1), "l[2]" -> ("l", 2), "e" -> ("e", none).
std::pair<std::string, std::optional<std::uint32_t>> split_ref(const std::string& ref);

// A section's text at one step: templates filled; problems name what did not resolve.
struct Filled {
  std::string text;
  std::vector<std::string> problems;
};
// Component k of a recorded variable as the exact rational it stands for (an exact run's own
// value, a float run's value exactly); nullopt for NaN or infinity.
std::optional<Rational> exact_value(const TraceModel& run, const VarRecord& v, std::uint32_t k);
Filled fill_templates(const std::string& text, const TraceModel& run, std::size_t step);
// Whether a section's key, run and conditions match the step; problems as in Filled.
bool section_matches(const Narration& n, const Lesson& lesson, const TraceModel& run, std::size_t step,
                     std::vector<std::string>* problems = nullptr);

// The narration `run` shows at `step`: the Markdown of the section that applies, with its {templates}
// filled from the run's recorded values; empty if no section applies (docs/lessons.md).
std::string narrate(const Lesson& lesson, const TraceModel& run, std::size_t step);

// Parses lesson text; `where` names the file in errors. Throws InputError ("lesson.md:3: ...").
// Validates the algorithm, the numerics and the input against the catalog. A relative "mesh" file
// in the input is taken relative to where's directory.
Lesson parse_lesson(const std::string& text, const std::string& where);
// A lesson file is at most this long (the longest is 5 KB): a device or a huge file is refused.
inline constexpr std::size_t kMaxLessonBytes = std::size_t{1} << 20;
Lesson load_lesson(const std::filesystem::path& path);

// Everything wrong with a lesson, one "file:line: message" each; empty if none. Parses it, records
// its runs (held to `budget`) and walks every step: a section no step shows, a template or condition
// that does not resolve, a start step past the end, a quiz point with no question to ask.
std::vector<std::string> lint_lesson(const std::filesystem::path& path, const Budget& budget = {});

// The lesson files in manifest order (lessons/manifest.txt: one file name a line, '#' comments).
// Throws InputError if the manifest is missing or names a missing file.
std::vector<std::filesystem::path> lesson_manifest(const std::filesystem::path& lessons_dir);

// The lessons directory: $STEPWISE_LESSONS, else the data root's lessons/ (data_root.hpp).
std::filesystem::path default_lessons_dir();

}  // namespace sw::vis
