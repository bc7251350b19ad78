// `stepwise lesson lint` and `stepwise quiz`: exit codes, one-line errors, and grades on stdout.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include "cli_harness.hpp"
#include "input.hpp"

namespace fs = std::filesystem;
using sw::testing::Ran;
using sw::testing::run_stepwise;
using sw::testing::scratch;

namespace {

const std::string kSource = SW_SOURCE_DIR;

}  // namespace

TEST_CASE("lessons cli: lint exits 0 on the lessons, 1 with file and line on a broken one", "[lesson][cli]") {
  Ran o = run_stepwise("lesson lint " + kSource + "/lessons/01-dda-line.md " + kSource + "/lessons/05-triangle-crack.md");
  CHECK(o.status == 0);
  CHECK(o.out.empty());
  o = run_stepwise("lesson lint " + kSource + "/tests/cases/lessons-broken/shadowed.md");
  CHECK(o.status == 1);
  CHECK(o.out.find("shadowed.md:8: section '## on line plot' is shown at no step") != std::string::npos);
  o = run_stepwise("lesson lint /nonexistent/lesson.md");
  CHECK(o.status == 2);
  CHECK(o.err.find("cannot read lesson file") != std::string::npos);
}

TEST_CASE("lessons cli: quiz grades a class: a file per student, first answers count, bad lines skipped and named", "[lesson][cli][quiz]") {
  const fs::path dir = scratch("quiz");
  fs::create_directories(dir / "class");
  // Bresenham (1, 2)-(13, 7): e = 2B - A = 2 * 5 - 12 = -2 is the first decision (by hand), asked at step 2.
  std::ofstream(dir / "class" / "ann.jsonl") << "{\"step\":2,\"answer\":\"negative\"}\n{\"step\":2,\"answer\":1}\nnot json\n";
  std::ofstream(dir / "class" / "bob.jsonl") << "{\"step\":2,\"answer\":1}\n";
  // A name that tries to forge a grade line, and one a spreadsheet would run.
  std::ofstream(dir / "class" / "x.jsonl") << "{\"step\":2,\"answer\":-1,\"student\":\"eve\\nann: 9 of 9 answered right\"}\n"
                                           << "{\"step\":2,\"answer\":0,\"student\":\"=cmd()\"}\n";
  std::ofstream(dir / "class" / "notes.txt") << "not answers\n";  // a directory's *.jsonl only
  const std::string lesson = kSource + "/lessons/03-bresenham.md";
  Ran o = run_stepwise("quiz " + lesson + " --answers " + (dir / "class").string());
  INFO(o.out << o.err);
  CHECK(o.status == 1);  // graded, but lines were skipped
  CHECK(o.out.find("ann: 1 of 1 answered right\n  step 2 sign: right: negative") != std::string::npos);  // the first answer
  CHECK(o.out.find("bob: 0 of 1 answered right\n  step 2 sign: wrong: answered positive, the truth is negative") != std::string::npos);
  CHECK(o.out.find("\nann: 9 of 9") == std::string::npos);  // the forged line is escaped into its name
  CHECK(o.out.find("\"eve\\nann: 9 of 9 answered right\": 1 of 1 answered right") != std::string::npos);
  CHECK(o.out.find("step 2 sign: 2 of 4 right") != std::string::npos);
  CHECK(o.out.find("class: 2 of 4 answers right; 4 students") != std::string::npos);
  CHECK(o.err.find("ann.jsonl:2: step 2 was already answered by ann (the first answer counts)") != std::string::npos);
  CHECK(o.err.find("ann.jsonl:3: answer: malformed JSON") != std::string::npos);
  CHECK(std::count(o.err.begin(), o.err.end(), '\n') == 2);

  o = run_stepwise("quiz " + lesson + " --answers " + (dir / "class" / "bob.jsonl").string() + " --answers " + (dir / "class" / "x.jsonl").string() + " --csv");
  CHECK(o.status == 0);
  std::istringstream csv(o.out);
  std::string header, row;
  std::getline(csv, header);
  CHECK(header.rfind("student,right,answered,step 2 sign,", 0) == 0);
  std::getline(csv, row);
  CHECK(row.rfind("bob,0,1,wrong,", 0) == 0);
  CHECK(o.out.find("\"eve\nann: 9 of 9 answered right\",1,1,right,") != std::string::npos);  // quoted per RFC 4180
  CHECK(o.out.find("'=cmd(),0,1,wrong,") != std::string::npos);                          // no formula

  o = run_stepwise("quiz " + lesson + " --answers " + (dir / "class" / "ann.jsonl").string() + " --json");
  CHECK(o.status == 1);
  std::istringstream lines(o.out);
  std::size_t n = 0;
  for (std::string l; std::getline(lines, l); ++n) CHECK_NOTHROW(sw::Json::parse(l));
  CHECK(o.out.find("\"class\":{\"answered\":1,\"questions\":17,\"right\":1,\"skipped\":2,\"students\":1}") != std::string::npos);
  CHECK(n == 1 + 17 + 1);  // the student, each question, the class

  // An answers path that does not exist: nothing printed, exit 2.
  o = run_stepwise("quiz " + lesson + " --answers " + (dir / "none.jsonl").string());
  CHECK(o.status == 2);
  CHECK(o.out.empty());
  CHECK(std::count(o.err.begin(), o.err.end(), '\n') == 1);
}
#endif
