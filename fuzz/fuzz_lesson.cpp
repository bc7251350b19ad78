// libFuzzer harness for lessons: the parser (front matter, the input it names, section headings
// with their conditions), then, for a lesson whose run is small, every step's choice of section,
// its conditions and its templates, and the quiz's questions and a grade of each.
#include <cstddef>
#include <cstdint>
#include <string>
#include "input.hpp"
#include "lessons/lesson.hpp"
#include "lessons/quiz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const sw::vis::Lesson l = sw::vis::parse_lesson(std::string(reinterpret_cast<const char*>(data), size), "fuzz.md");
    sw::Budget small;
    small.max_steps = 2000;  // a fuzz run stays fast; larger lessons are refused by the budget
    const sw::vis::QuizRuns runs = sw::vis::record_quiz_runs(l, small);
    for (std::size_t s = 0; s < runs.run->size(); ++s) (void)sw::vis::narrate(l, *runs.run, s);
    for (const sw::vis::Question& q : sw::vis::quiz_questions(l, *runs.run, runs.compared.get())) (void)sw::vis::grade(q, q.answer);
  } catch (const sw::InputError&) {
  }
  return 0;
}
