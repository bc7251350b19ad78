#include "lesson.hpp"
#include "trace_model.hpp"
#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sw::vis {
namespace {

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    lines.push_back(std::move(l));
  }
  return lines;
}

// "## on line plot", "## on kind plot", "## intro" -> a Narration key.
Narration parse_heading(const std::string& heading, const Algorithm& alg, const std::string& at) {
  Narration n;
  std::istringstream in(heading);
  std::string word, what, value;
  in >> word;
  if (word == "intro") return n;
  in >> what >> value;
  if (word != "on" || value.empty())
    throw InputError(at + ": section '## " + heading + "' is not '## intro', '## on line NAME' or '## on kind K'");
  if (what == "line") {
    // Lines are addressed by name, so that inserting a listing line never shifts a lesson.
    n.line = alg.listing.find(value);
    if (n.line == 0) {
      std::string names;
      for (const ListingLine& l : alg.listing.lines) names += (names.empty() ? "" : ", ") + std::string(l.name);
      throw InputError(at + ": '" + value + "' is not a listing line name of " + std::string(alg.id) + " (" + names + ")");
    }
    n.key = Narration::Key::line;
    return n;
  }
  if (what == "kind") {
    auto k = parse_kind(value);
    if (!k) throw InputError(at + ": unknown step kind '" + value + "'");
    n.key = Narration::Key::kind;
    n.kind = *k;
    return n;
  }
  throw InputError(at + ": section '## " + heading + "': expected 'line' or 'kind' after 'on'");
}

}  // namespace

const Narration* Lesson::narration_for(std::uint32_t line, StepKind kind) const {
  for (const Narration& n : sections)
    if (n.key == Narration::Key::line && n.line == line) return &n;
  for (const Narration& n : sections)
    if (n.key == Narration::Key::kind && n.kind == kind) return &n;
  return nullptr;
}

const Narration* Lesson::intro() const {
  for (const Narration& n : sections)
    if (n.key == Narration::Key::intro) return &n;
  return nullptr;
}

std::string narrate(const Lesson& lesson, const TraceModel& run, std::size_t step) {
  const StepRecord& st = run.trace().at(step);
  const Narration* n = lesson.narration_for(st.scope ? 0 : st.line, st.kind);
  return n ? n->text : std::string();
}

Lesson parse_lesson(const std::string& text, const std::string& where) {
  const auto lines = split_lines(text);
  auto at = [&](std::size_t i) { return where + ":" + std::to_string(i + 1); };
  if (lines.empty() || trim(lines[0]) != "---") throw InputError(at(0) + ": a lesson starts with a '---' front-matter line");
  Lesson lesson;
  lesson.path = where;
  std::string alg_id, numeric = "exact", compare, input_text, start_step, show;
  std::size_t show_line = 0;
  std::size_t i = 1, input_line = 0;
  for (; i < lines.size() && trim(lines[i]) != "---"; ++i) {
    const std::string l = trim(lines[i]);
    if (l.empty() || l[0] == '#') continue;
    const auto colon = l.find(':');
    if (colon == std::string::npos) throw InputError(at(i) + ": expected 'key: value' in the front matter");
    const std::string key = trim(std::string_view(l).substr(0, colon)), value = trim(std::string_view(l).substr(colon + 1));
    if (key == "title") lesson.title = value;
    else if (key == "algorithm") alg_id = value;
    else if (key == "input") input_text = value, input_line = i;
    else if (key == "numeric") numeric = value;
    else if (key == "compare") compare = value;
    else if (key == "step") start_step = value;
    else if (key == "view" && (value == "fit" || value == "step")) lesson.focus = value == "step";
    else if (key == "view") throw InputError(at(i) + ": 'view: " + value + "': expected fit or step");
    else if (key == "show") show = value, show_line = i;
    else throw InputError(at(i) + ": unknown front-matter key '" + key + "' (title, algorithm, input, numeric, compare, step, view, show)");
  }
  if (i >= lines.size()) throw InputError(at(0) + ": the front matter has no closing '---' line");
  if (alg_id.empty()) throw InputError(at(0) + ": the front matter needs 'algorithm: <id>'");
  if (input_text.empty()) throw InputError(at(0) + ": the front matter needs 'input: {json}'");
  try {
    lesson.algorithm = &find_algorithm(alg_id);
    lesson.numeric = parse_numeric_for(*lesson.algorithm, numeric);
    if (!compare.empty()) lesson.compare = parse_comparison(*lesson.algorithm, compare, lesson.numeric);
    lesson.input = parse_json_text(input_text, "input");
    // A relative mesh file is relative to the lesson's own directory, not to the working directory.
    if (lesson.input.is_object() && lesson.input.contains("mesh") && lesson.input["mesh"].is_string()) {
      const std::filesystem::path mesh = lesson.input["mesh"].get<std::string>();
      if (mesh.is_relative()) lesson.input["mesh"] = (std::filesystem::path(where).parent_path() / mesh).lexically_normal().string();
    }
    lesson.algorithm->validate(lesson.input, lesson.numeric);
    if (lesson.compare.other) lesson.compare.other->validate(carried_input(lesson.input, parse_json_text(lesson.compare.other->example, "example")), lesson.numeric);
    else if (lesson.compare) lesson.algorithm->validate(lesson.input, *lesson.compare.numeric);
  } catch (const InputError& e) {
    throw InputError(at(input_line ? input_line : 0) + ": " + e.what());
  }
  if (!show.empty()) {
    lesson.show = parse_view(show);
    const auto& views = lesson.algorithm->views;
    if (!lesson.show || std::find(views.begin(), views.end(), *lesson.show) == views.end()) {
      std::string declared;
      for (View v : views) declared += (declared.empty() ? "" : ", ") + std::string(view_name(v));
      throw InputError(at(show_line) + ": 'show: " + show + "': " + std::string(lesson.algorithm->id) + " declares " + declared);
    }
  }
  if (!start_step.empty()) {
    auto [p, ec] = std::from_chars(start_step.data(), start_step.data() + start_step.size(), lesson.start_step);
    if (ec != std::errc() || p != start_step.data() + start_step.size())
      throw InputError(where + ": 'step: " + start_step + "' is not a step number");
  }
  if (lesson.title.empty()) lesson.title = std::string(lesson.algorithm->listing.title);
  // Narration: '## ' headings open sections; text before the first heading is the intro.
  Narration current;
  auto flush = [&] {
    const std::string body = trim(current.text);
    if (!body.empty() || current.key != Narration::Key::intro) lesson.sections.push_back({current.key, current.line, current.kind, body});
  };
  for (++i; i < lines.size(); ++i) {
    if (lines[i].rfind("## ", 0) == 0) {
      flush();
      current = parse_heading(trim(std::string_view(lines[i]).substr(3)), *lesson.algorithm, at(i));
      continue;
    }
    if (lines[i].rfind("# ", 0) == 0 && lesson.sections.empty() && trim(current.text).empty()) continue;  // a top title
    current.text += lines[i] + '\n';
  }
  flush();
  return lesson;
}

Lesson load_lesson(const std::filesystem::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError("cannot read lesson file '" + path.string() + "'");
  std::ostringstream s;
  s << f.rdbuf();
  Lesson l = parse_lesson(s.str(), path.string());
  l.path = path;
  return l;
}

std::vector<std::filesystem::path> lesson_manifest(const std::filesystem::path& dir) {
  const auto manifest = dir / "manifest.txt";
  std::ifstream f(manifest);
  if (!f) throw InputError("cannot read lesson manifest '" + manifest.string() + "'");
  std::vector<std::filesystem::path> out;
  for (std::string l; std::getline(f, l);) {
    l = trim(l);
    if (l.empty() || l[0] == '#') continue;
    if (!std::filesystem::exists(dir / l)) throw InputError(manifest.string() + ": lists '" + l + "', which does not exist");
    out.push_back(dir / l);
  }
  return out;
}

std::filesystem::path default_lessons_dir() {
  if (const char* env = std::getenv("STEPWISE_LESSONS"); env && *env) return env;
#ifdef SW_LESSONS_DIR
  return SW_LESSONS_DIR;
#else
  return "lessons";
#endif
}

}  // namespace sw::vis
