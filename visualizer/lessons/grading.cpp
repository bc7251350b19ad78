#include "lessons/grading.hpp"
#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include "input.hpp"

namespace sw::vis {

namespace fs = std::filesystem;

std::vector<fs::path> answer_files(const std::string& path) {
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) return {path};
  if (!fs::is_directory(path, ec))
    throw InputError("--answers " + one_line(path, 200) + (fs::exists(path, ec) ? ": neither a regular file nor a directory" : ": no such file or directory"));
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(path, ec))
    if (e.path().extension() == ".jsonl" && e.is_regular_file(ec)) out.push_back(e.path());
  if (ec) throw InputError("--answers " + one_line(path, 200) + ": cannot list the directory (" + ec.message() + ")");
  if (out.empty()) throw InputError("--answers " + one_line(path, 200) + ": the directory holds no .jsonl answers");
  std::sort(out.begin(), out.end());
  return out;
}

ClassGrades grade_class(const std::vector<Question>& questions, const std::vector<fs::path>& files) {
  ClassGrades g;
  std::map<std::string, std::size_t> index;         // student -> students[]
  std::set<std::pair<std::size_t, std::size_t>> seen;  // (student, step) answered
  auto student_of = [&](const std::string& name) {
    const auto [it, fresh] = index.try_emplace(name, g.students.size());
    if (fresh) g.students.push_back(name);
    return it->second;
  };
  for (const fs::path& file : files) {
    std::ifstream in = open_input_file(file.string(), "answers file");
    const std::string stem = file.stem().string();
    std::string line;
    for (std::size_t n = 1;; ++n) {
      const std::string at = file.string() + ":" + std::to_string(n) + ": ";
      try {
        if (!read_line(in, line, 1 << 16, "answers line " + std::to_string(n))) break;
      } catch (const InputError& e) {  // an overlong line: the rest of the file cannot be read in step
        g.skipped.push_back(at + e.what() + "; the rest of the file is not read");
        break;
      }
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      try {
        const Json a = parse_json_text(line, "answer");
        if (!a.is_object()) throw InputError("expected {\"step\": N, \"answer\": ...}");
        only_keys_optional(a, {"step", "answer"}, {"student"}, "answer");
        if (a.contains("student") && (!a["student"].is_string() || a["student"].get<std::string>().empty()))
          throw InputError("\"student\" must be a non-empty string");
        const auto step = static_cast<std::size_t>(parse_integer(a["step"], "step", 0, std::int64_t{1} << 40));
        const auto q = std::find_if(questions.begin(), questions.end(), [&](const Question& x) { return x.step == step; });
        if (q == questions.end()) throw InputError("no question at step " + std::to_string(step) + " (see --list)");
        const Grade verdict = grade(*q, a["answer"]);
        const std::size_t s = student_of(a.contains("student") ? a["student"].get<std::string>() : stem);
        if (!seen.insert({s, step}).second)
          throw InputError("step " + std::to_string(step) + " was already answered by " + printable_name(g.students[s]) +
                           " (the first answer counts)");
        g.answers.push_back({s, &*q, verdict.right, answer_text(*q, normal_answer(*q, a["answer"])), verdict.expected});
      } catch (const InputError& e) {
        g.skipped.push_back(at + one_line(e.what(), 300));
      }
    }
  }
  return g;
}

std::string answers_jsonl(const QuizSession& quiz, const std::string& student) {
  std::string out;
  for (const QuizSession::Answered& a : quiz.answers())
    out += Json{{"student", student}, {"step", a.step}, {"answer", a.given}}.dump() + "\n";
  return out;
}

std::string printable_name(const std::string& name) {
  const bool plain = !name.empty() && name.front() != ' ' && name.back() != ' ' && name.front() != '"' &&
                     std::none_of(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
  return plain ? name : Json(name).dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string csv_field(const std::string& s) {
  std::string v = !s.empty() && std::string_view("=+-@").find(s.front()) != std::string_view::npos ? "'" + s : s;
  if (v.find_first_of(",\"\r\n") == std::string::npos) return v;
  std::string q = "\"";
  for (char c : v) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace sw::vis
