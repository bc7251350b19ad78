// Grading a class's answers to one lesson's quiz (`stepwise quiz LESSON --answers PATH...`,
// docs/cli.md#grading-a-class). Answers are JSONL lines {"step": N, "answer": A} with an optional
// "student": a file is one student's (named by its stem) unless its lines name theirs. A student's
// first answer to a step counts; a bad line or a later answer to the same step is skipped and
// reported as "file:line: problem". No ImGui: the CLI prints the result, the app writes answers.
#pragma once
#include <filesystem>
#include <string>
#include <vector>
#include "lessons/quiz.hpp"
#include "lessons/quiz_session.hpp"

namespace sw::vis {

struct GradedAnswer {
  std::size_t student = 0;  // index into ClassGrades::students
  const Question* question = nullptr;
  bool right = false;
  std::string given, expected;  // as text
};

struct ClassGrades {
  std::vector<std::string> students;  // in the order they first appear
  std::vector<GradedAnswer> answers;  // in the order read
  std::vector<std::string> skipped;   // "file:line: problem", in the order read
};

// The files a PATH names: itself, or a directory's *.jsonl files in name order. Throws InputError
// for a path that is neither, or a directory without answers.
std::vector<std::filesystem::path> answer_files(const std::string& path);

// Grades every line of the files against the questions. Throws InputError only for a file that
// cannot be read; everything wrong inside one is skipped and reported.
ClassGrades grade_class(const std::vector<Question>& questions, const std::vector<std::filesystem::path>& files);

// A quiz's answers as the JSONL lines grade_class reads, each with the student's name.
std::string answers_jsonl(const QuizSession& quiz, const std::string& student);

// A name as it is safe to print on one line of text: itself when it is printable ASCII or UTF-8
// without control characters, else its JSON string form (quoted, escaped).
std::string printable_name(const std::string& name);
// A CSV field (RFC 4180), with a leading = + - @ defused by a quote so no spreadsheet runs it.
std::string csv_field(const std::string& s);

}  // namespace sw::vis
