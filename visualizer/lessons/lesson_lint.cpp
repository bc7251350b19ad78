// The lesson lint: parses a lesson, records its runs and walks every step of each, so that every
// section is shown somewhere and every template and condition resolves wherever it is evaluated.
#include <map>
#include <set>
#include "lessons/lesson.hpp"
#include "lessons/quiz.hpp"
#include "lessons/trace_model.hpp"

namespace sw::vis {
namespace {

bool has_template(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\') ++i;
    else if (text[i] == '{' && text.find('}', i) != std::string::npos) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string> lint_lesson(const std::filesystem::path& path, const Budget& budget) {
  Lesson lesson;
  try {
    lesson = load_lesson(path);
  } catch (const InputError& e) {
    return {e.what()};
  }
  std::vector<std::string> out;
  // A broken template or condition is reported once, at its first step, with how many more steps
  // it fails at: "template '{x}': ..." is keyed on its line and "template '{x}'".
  std::map<std::string, std::pair<std::size_t, std::size_t>> said;  // key -> (index in out, repeats)
  auto at = [&](std::size_t line, const std::string& msg, const std::filesystem::path& file = {}) {
    const std::string where = (file.empty() ? path : file).string() + ":" + std::to_string(line);
    const auto quote = msg.find("': ");
    const std::string key = where + ":" + (quote == std::string::npos ? msg : msg.substr(0, quote));
    if (auto it = said.find(key); it != said.end()) {
      ++it->second.second;
      return;
    }
    said.emplace(key, std::pair{out.size(), std::size_t{0}});
    out.push_back(where + ": " + msg);
  };
  if (has_template(lesson.intro)) at(1, "the intro is shown at every step, so it cannot hold {templates}");

  std::vector<std::shared_ptr<const TraceModel>> runs;
  try {
    runs.push_back(record_model(*lesson.run, budget));
    if (lesson.compare_run) runs.push_back(record_model(*lesson.compare_run, budget));
    if (const Numeric q = quiz_numeric(lesson); q != lesson.numeric && !(lesson.compare.numeric == q && !lesson.compare.other))
      runs.push_back(record_model(lesson.run->in(q), budget));  // the quiz's truth
  } catch (const InputError& e) {
    at(1, e.what());
    return out;
  }
  if (lesson.start_step > runs[0]->last())
    at(lesson.start_step_line + 1, "step " + std::to_string(lesson.start_step) + " is past the last step (" + std::to_string(runs[0]->last()) + ")");
  if (lesson.screenshot_step && *lesson.screenshot_step > runs[0]->last())
    at(lesson.screenshot_line + 1, "screenshot " + std::to_string(*lesson.screenshot_step) + " is past the last step (" + std::to_string(runs[0]->last()) + ")");

  const auto& secs = lesson.sections;
  std::vector<bool> shown(secs.size()), matched(secs.size());
  const Numeric quiz_mode = quiz_numeric(lesson);
  const TraceModel* compared = nullptr;  // the float questions' other run
  if (const auto c = quiz_compared_numeric(lesson))
    for (const auto& r : runs)
      if (&r->algorithm() == lesson.algorithm && r->numeric() == *c) compared = r.get();
  std::map<const Narration*, std::string> unasked;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const TraceModel& run = *runs[r];
    const bool quiz_run = &run.algorithm() == lesson.algorithm && run.numeric() == quiz_mode;
    // The extra quiz run is checked for its questions only: the app never narrates it.
    const bool narrated = r == 0 || (r == 1 && lesson.compare);
    for (std::size_t s = 0; s < run.size(); ++s) {
      for (std::size_t k = 0; k < secs.size(); ++k) {
        std::vector<std::string> problems;
        if (section_matches(secs[k], lesson, run, s, &problems)) matched[k] = true;
        for (const std::string& p : problems) at(secs[k].source_line, p, secs[k].source);
      }
      if (narrated)
        if (const Narration* n = lesson.section_for(run, s)) {
          shown[n - secs.data()] = true;
          for (const std::string& p : fill_templates(n->text, run, s).problems) at(n->source_line, p, n->source);
        }
      if (const Narration* n = quiz_run ? lesson.quiz_for(run, s) : nullptr) {
        std::string why;
        if (question_at(lesson, run, s, &why, compared)) {
          shown[n - secs.data()] = true;
          for (const std::string& p : fill_templates(n->prompt, run, s).problems) at(n->source_line, p);
        } else {
          unasked.emplace(n, "step " + std::to_string(s) + ": " + why);
        }
      }
    }
  }
  for (std::size_t k = 0; k < secs.size(); ++k) {
    if (shown[k] || !secs[k].source.empty()) continue;  // a shared file's section need not fit every lesson
    const std::string what = "section '## " + secs[k].heading + "' is shown at no step: ";
    if (secs[k].quiz && unasked.count(&secs[k])) at(secs[k].source_line, what + "nothing follows to predict (" + unasked[&secs[k]] + ")");
    else if (matched[k]) at(secs[k].source_line, what + "a more specific section wins wherever it applies");
    else at(secs[k].source_line, what + "no step of " + (secs[k].quiz ? "the quiz run" : "any run") + " has its key" + (secs[k].conditions.empty() ? "" : " with its conditions true"));
  }
  for (const auto& [key, where] : said)
    if (where.second) out[where.first] += " (and at " + std::to_string(where.second) + " more step" + (where.second == 1 ? ")" : "s)");
  return out;
}

}  // namespace sw::vis
