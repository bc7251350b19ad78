// Lessons: Markdown files with a front-matter block that names the algorithm, the input and the
// number types, and narration sections tied to step kinds or listing lines (docs/lessons.md).
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>
#include "catalog.hpp"
#include "compare.hpp"

namespace sw::vis {

struct Narration {
  enum class Key { intro, line, kind } key = Key::intro;
  std::uint32_t line = 0;          // for Key::line
  StepKind kind = StepKind::init;  // for Key::kind
  std::string text;                // Markdown body of the section
};

struct Lesson {
  std::filesystem::path path;
  std::string title;
  const Algorithm* algorithm = nullptr;
  Json input;
  Numeric numeric = Numeric::exact;
  Comparison compare;              // a second number type, or another model, shown side by side
  std::size_t start_step = 0;      // where the timeline starts
  bool focus = false;              // "view: step": zoom in on the start step, not the whole trace
  std::optional<View> show;        // "show: tree": the declared view to open on (default: the first)
  std::vector<Narration> sections;

  // The narration for a step: its listing line wins over its kind; nullptr if none.
  const Narration* narration_for(std::uint32_t line, StepKind kind) const;
  const Narration* intro() const;
};

class TraceModel;

// The narration `run` shows at `step`: the Markdown of the section that applies, with its {templates}
// filled from the run's recorded values; empty if no section applies (docs/lessons.md).
std::string narrate(const Lesson& lesson, const TraceModel& run, std::size_t step);

// Parses lesson text; `where` names the file in errors. Throws InputError ("lesson.md:3: ...").
// Validates the algorithm, the numerics and the input against the catalog. A relative "mesh" file
// in the input is taken relative to where's directory.
Lesson parse_lesson(const std::string& text, const std::string& where);
Lesson load_lesson(const std::filesystem::path& path);

// The lesson files in manifest order (lessons/manifest.txt: one file name a line, '#' comments).
// Throws InputError if the manifest is missing or names a missing file.
std::vector<std::filesystem::path> lesson_manifest(const std::filesystem::path& lessons_dir);

// The lessons directory: $STEPWISE_LESSONS, else the source tree's lessons/ (compiled in).
std::filesystem::path default_lessons_dir();

}  // namespace sw::vis
