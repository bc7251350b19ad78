// Lesson files: the front matter and the section headings (docs/lessons.md). Choosing and filling
// a section is lesson_text.cpp; the lint is lesson_lint.cpp.
#include "lessons/lesson.hpp"
#include "data_root.hpp"
#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace sw::vis {
namespace {

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

std::vector<std::string> split_lines(std::string_view text) {
  std::vector<std::string> lines;
  std::istringstream in{std::string(text)};
  for (std::string l; std::getline(in, l);) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    lines.push_back(std::move(l));
  }
  return lines;
}

std::vector<std::string> words(std::string_view s) {
  std::istringstream in{std::string(s)};
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::size_t parse_count(const std::string& s, const std::string& what) {
  std::size_t v = 0;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || p != s.data() + s.size()) throw InputError("'" + what + " " + s + "' is not a step number");
  return v;
}

// "e < 0 and q.x >= 1/2": conditions split on "and", each at its comparison operator.
std::vector<Condition> parse_conditions(const std::string& text) {
  std::vector<Condition> out;
  std::string rest = " " + text + " ";
  while (true) {
    const auto cut = rest.find(" and ");
    const std::string part = trim(rest.substr(0, cut));
    std::size_t at = std::string::npos, len = 0;
    for (const char* op : {"<=", ">=", "==", "!=", "<", ">"}) {
      const auto k = part.find(op);
      if (k != std::string::npos && k < at) at = k, len = std::char_traits<char>::length(op);
    }
    if (at == std::string::npos) throw InputError("condition '" + part + "' has no comparison (<, <=, >, >=, ==, !=)");
    Condition c{trim(part.substr(0, at)), part.substr(at, len), trim(part.substr(at + len))};
    if (c.lhs.empty() || c.rhs.empty()) throw InputError("condition '" + part + "' needs a value on both sides");
    out.push_back(std::move(c));
    if (cut == std::string::npos) return out;
    rest = rest.substr(cut + 4);
  }
}

std::string listing_names(const Listing& listing) {
  std::string names;
  for (const ListingLine& l : listing.lines) names += (names.empty() ? "" : ", ") + std::string(l.name);
  return names;
}

// "on line NAME [for RUN] [if ...]", "quiz sign e on kind decide: prompt", "intro" -> a Narration.
Narration parse_heading(const std::string& heading, const Lesson& lesson) {
  Narration n;
  n.heading = heading;
  std::string key = heading;
  if (heading.rfind("quiz", 0) == 0) {
    const auto colon = heading.find(':');
    if (colon == std::string::npos) throw InputError("a quiz heading ends with ': the question'");
    n.prompt = trim(heading.substr(colon + 1));
    if (n.prompt.empty()) throw InputError("the quiz has no question after ':'");
    key = trim(heading.substr(0, colon));
  }
  std::string conditions;
  if (const auto k = key.find(" if "); k != std::string::npos) {
    conditions = key.substr(k + 4);
    key = key.substr(0, k);
    n.conditions = parse_conditions(conditions);
  }
  auto w = words(key);
  if (w.empty()) throw InputError("an empty section heading: expected '## intro', '## on ...' or '## quiz ...'");
  if (w.size() == 1 && w[0] == "intro" && conditions.empty()) return n;
  std::size_t i = 0;
  if (w[0] == "quiz") {
    i = 1;
    const std::string type = i < w.size() ? w[i] : "";
    if (type == "pixel") n.quiz = QuizType::pixel;
    else if (type == "branch") n.quiz = QuizType::branch;
    else if (type == "hit") n.quiz = QuizType::hit;
    else if (type == "same") n.quiz = QuizType::same;
    else if (type == "diverge") n.quiz = QuizType::diverge;
    else if (type == "sign" && i + 1 < w.size()) {
      n.quiz = QuizType::sign, n.quiz_var = w[++i];
      if (i + 2 < w.size() && w[i + 1] == "vs") {
        n.quiz_than = w[i + 2], i += 2;
        parse_rational(Json(n.quiz_than), "the number after 'vs'");  // throws InputError if it is not one
      }
    }
    else if (type == "flag" && i + 1 < w.size()) n.quiz = QuizType::flag, n.quiz_var = w[++i];
    else throw InputError("quiz type '" + type + "': expected pixel, branch, sign VAR, hit, flag VAR, same or diverge");
    ++i;
  }
  if (i + 2 > w.size() || w[i] != "on")
    throw InputError("section '## " + heading + "' is not '## intro', '## on line|kind|step X [for RUN] [if COND]' or '## quiz TYPE on ...: question'");
  const std::string what = w[i + 1], value = i + 2 < w.size() ? w[i + 2] : "";
  std::size_t next = i + 3;
  if (next + 1 < w.size() && w[next] == "for") n.run = w[next + 1], next += 2;
  if (next != w.size() || value.empty()) throw InputError("section '## " + heading + "': expected 'on line|kind|step X [for RUN]'");
  const Algorithm* alg = lesson.algorithm;
  if (!n.run.empty()) {
    const Algorithm* other = lesson.compare.other;
    if (other && n.run == other->id) alg = other;
    else if (!parse_numeric(n.run)) throw InputError("'for " + n.run + "': expected a number type or the compared algorithm's id");
  }
  if (what == "line" && value.find('/') != std::string::npos) {
    // A line of a nested listing, named by the callee's id: "ray-triangle-mt/u", "refract/tir".
    const std::string id = value.substr(0, value.find('/')), name = value.substr(value.find('/') + 1);
    const Listing* callee = find_listing(id);
    if (!callee) {
      std::string known;
      for (std::string_view k : listing_ids()) known += (known.empty() ? "" : ", ") + std::string(k);
      throw InputError("unknown algorithm or callee '" + id + "' (known: " + known + ")");
    }
    n.key = Narration::Key::line, n.callee = id;
    n.line = callee->find(name);
    if (n.line == 0) throw InputError("'" + name + "' is not a listing line name of " + id + " (" + listing_names(*callee) + ")");
  } else if (what == "line") {
    n.key = Narration::Key::line;
    n.line = alg->listing.find(value);  // by name, so that inserting a listing line never shifts a lesson
    if (n.line == 0) throw InputError("'" + value + "' is not a listing line name of " + std::string(alg->id) + " (" + listing_names(alg->listing) + ")");
  } else if (what == "kind") {
    auto k = parse_kind(value);
    if (!k) throw InputError("unknown step kind '" + value + "' (init, decide, advance, plot, visit, hit, miss, done)");
    n.key = Narration::Key::kind, n.kind = *k;
  } else if (what == "step") {
    n.key = Narration::Key::step, n.step = parse_count(value, "on step");
  } else {
    throw InputError("section '## " + heading + "': expected line, kind or step after 'on'");
  }
  return n;
}

// A heading that is probably meant as a section: "### on line x", "##on line x", "# intro".
bool looks_like_section(const std::string& line) {
  const auto hashes = line.find_first_not_of('#');
  if (hashes == 0 || hashes == std::string::npos) return false;
  const auto w = words(line.substr(hashes));
  if (w.empty()) return false;
  std::string first = w[0];
  std::transform(first.begin(), first.end(), first.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return first == "on" || first == "intro" || first == "quiz";
}

// The keys that are set here; the others are read after the block (parse_lesson).
void add_front_matter(Lesson& lesson, const std::string& key, const std::string& value) {
  if (key == "title") lesson.title = value;
  else if (key == "view" && (value == "fit" || value == "step")) lesson.focus = value == "step";
  else if (key == "view") throw InputError("'view: " + value + "': expected fit or step");
  else if (key != "algorithm" && key != "input" && key != "numeric" && key != "compare" && key != "step" && key != "show" && key != "screenshot" &&
           key != "include")
    throw InputError("unknown front-matter key '" + key + "' (title, algorithm, input, numeric, compare, step, view, show, screenshot, include)");
}

// The '## ' sections of lines[from..] into lesson.sections; text before the first goes to *intro,
// which an included file (intro == nullptr: only '## on ...' sections) must not have.
template <class Fail>
void parse_sections(const std::vector<std::string>& lines, std::size_t from, Lesson& lesson, std::string* intro, std::set<std::string>& headings,
                    const std::filesystem::path& source, const Fail& fail) {
  std::string spill;  // an included file's text outside any section
  std::string* body = intro ? intro : &spill;
  bool in_code = false;
  for (std::size_t i = from; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (trim(l).rfind("```", 0) == 0) in_code = !in_code;
    if (!in_code && l.rfind("## ", 0) == 0) {
      Narration n;
      try {
        n = parse_heading(trim(std::string_view(l).substr(3)), lesson);
      } catch (const InputError& e) {
        throw fail(i, e.what());
      }
      if (!intro && (n.quiz || n.key == Narration::Key::intro)) throw fail(i, "an included file holds only '## on ...' sections");
      if (!headings.insert(n.heading).second) throw fail(i, "section '## " + n.heading + "' appears twice");
      n.source_line = i + 1, n.source = source;
      if (n.key == Narration::Key::intro) {
        body = intro;
        continue;
      }
      lesson.sections.push_back(std::move(n));
      body = &lesson.sections.back().text;
      continue;
    }
    if (!in_code && intro && l.rfind("# ", 0) == 0 && lesson.sections.empty() && trim(*intro).empty() && !looks_like_section(l)) continue;  // a top title
    if (!in_code && looks_like_section(l)) throw fail(i, "'" + trim(l) + "' looks like a section heading; sections are '## on ...', '## quiz ...' or '## intro'");
    if (body == &spill && !trim(l).empty() && l.rfind("# ", 0) != 0) throw fail(i, "an included file holds only '## on ...' sections, with no text before the first");
    *body += l + '\n';
  }
}

}  // namespace

Lesson parse_lesson(const std::string& raw, const std::string& where) {
  std::string_view text = raw;
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.remove_prefix(3);  // a UTF-8 byte-order mark
  const auto lines = split_lines(text);
  std::size_t i = 0;
  auto fail = [&](std::size_t line, const std::string& msg) { return InputError(where + ":" + std::to_string(line + 1) + ": " + msg); };
  if (lines.empty() || trim(lines[0]) != "---") throw fail(0, "a lesson starts with a '---' front-matter line");
  Lesson lesson;
  lesson.path = where;
  std::map<std::string, std::pair<std::string, std::size_t>> fm;  // key -> value, line
  for (i = 1; i < lines.size() && trim(lines[i]) != "---"; ++i) {
    const std::string l = trim(lines[i]);
    if (l.empty() || l[0] == '#') continue;
    const auto colon = l.find(':');
    if (colon == std::string::npos) throw fail(i, "expected 'key: value' in the front matter");
    const std::string key = trim(std::string_view(l).substr(0, colon)), value = trim(std::string_view(l).substr(colon + 1));
    try {
      if (fm.count(key)) throw InputError("front-matter key '" + key + "' appears twice");
      add_front_matter(lesson, key, value);
    } catch (const InputError& e) {
      throw fail(i, e.what());
    }
    fm[key] = {value, i};
  }
  if (i >= lines.size()) throw fail(0, "the front matter has no closing '---' line");
  if (!fm.count("algorithm")) throw fail(0, "the front matter needs 'algorithm: <id>'");
  if (!fm.count("input")) throw fail(0, "the front matter needs 'input: {json}'");
  auto value_at = [&](const char* k) -> std::pair<std::string, std::size_t> { return fm.count(k) ? fm[k] : std::pair<std::string, std::size_t>{}; };
  std::size_t at = 0;
  try {
    at = fm["algorithm"].second;
    lesson.algorithm = &find_algorithm(fm["algorithm"].first);
    at = value_at("numeric").second;
    lesson.numeric = parse_numeric_for(*lesson.algorithm, fm.count("numeric") ? fm["numeric"].first : "exact");
    at = value_at("compare").second;
    if (fm.count("compare")) lesson.compare = parse_comparison(*lesson.algorithm, fm["compare"].first, lesson.numeric);
    at = fm["input"].second;
    lesson.input = parse_json_text(fm["input"].first, "input");
    // A relative mesh file is relative to the lesson's own directory, not to the working directory.
    if (lesson.input.is_object() && lesson.input.contains("mesh") && lesson.input["mesh"].is_string()) {
      const std::filesystem::path mesh = lesson.input["mesh"].get<std::string>();
      if (mesh.is_relative()) lesson.input["mesh"] = (std::filesystem::path(where).parent_path() / mesh).lexically_normal().string();
    }
    lesson.run.emplace(lesson.algorithm->open(lesson.input, lesson.numeric));
    if (lesson.compare.other)
      lesson.compare_run.emplace(lesson.compare.other->open(carried_input(lesson.input, parse_json_text(lesson.compare.other->example, "example")), lesson.numeric));
    else if (lesson.compare)
      lesson.compare_run.emplace(lesson.run->in(*lesson.compare.numeric));
    if (fm.count("show")) {
      at = fm["show"].second;
      lesson.show = parse_view(fm["show"].first);
      const auto& views = lesson.algorithm->views;
      if (!lesson.show || std::find(views.begin(), views.end(), *lesson.show) == views.end()) {
        std::string declared;
        for (View v : views) declared += (declared.empty() ? "" : ", ") + std::string(view_name(v));
        throw InputError("'show: " + fm["show"].first + "': " + std::string(lesson.algorithm->id) + " declares " + declared);
      }
    }
    if (fm.count("step")) {
      at = lesson.start_step_line = fm["step"].second;
      lesson.start_step = parse_count(fm["step"].first, "step:");
    }
    if (fm.count("screenshot")) {
      at = lesson.screenshot_line = fm["screenshot"].second;
      lesson.screenshot_step = parse_count(fm["screenshot"].first, "screenshot:");
    }
  } catch (const InputError& e) {
    throw fail(at, e.what());
  }
  if (lesson.title.empty()) lesson.title = std::string(lesson.algorithm->listing.title);
  std::set<std::string> headings;
  parse_sections(lines, i + 1, lesson, &lesson.intro, headings, {}, fail);
  // The included files' sections come after the lesson's own, which therefore win a tie.
  if (fm.count("include")) {
    std::stringstream list(fm["include"].first);
    for (std::string name; std::getline(list, name, ',');) {
      const std::filesystem::path file = std::filesystem::path(where).parent_path() / trim(name);
      std::string text;
      try {
        text = read_file_bounded(file.string(), "included narration", kMaxLessonBytes);
      } catch (const InputError& e) {
        throw fail(fm["include"].second, e.what());
      }
      const auto included = split_lines(text);
      auto fail_in = [&](std::size_t line, const std::string& msg) { return InputError(file.string() + ":" + std::to_string(line + 1) + ": " + msg); };
      parse_sections(included, 0, lesson, nullptr, headings, file, fail_in);
      lesson.includes.push_back(file);
    }
  }
  lesson.intro = trim(lesson.intro);
  for (Narration& n : lesson.sections) n.text = trim(n.text);
  return lesson;
}

Lesson load_lesson(const std::filesystem::path& path) {
  Lesson l = parse_lesson(read_file_bounded(path.string(), "lesson file", kMaxLessonBytes), path.string());
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
  return data_root() / "lessons";
}

}  // namespace sw::vis
