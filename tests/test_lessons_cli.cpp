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

namespace fs = std::filesystem;

namespace {

struct Out {
  int status = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream f(p);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

Out run(const std::string& args) {
  const fs::path dir = fs::temp_directory_path() / ("sw-lessons-cli-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const int rc = std::system((std::string("'") + SW_STEPWISE_EXE + "' " + args + " >" + (dir / "o").string() + " 2>" + (dir / "e").string()).c_str());
  Out o{WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, slurp(dir / "o"), slurp(dir / "e")};
  fs::remove_all(dir);
  return o;
}

const std::string kSource = SW_SOURCE_DIR;

}  // namespace

TEST_CASE("lessons cli: lint exits 0 on the lessons, 1 with file and line on a broken one", "[lesson][cli]") {
  Out o = run("lesson lint " + kSource + "/lessons/01-dda-line.md " + kSource + "/lessons/05-triangle-crack.md");
  CHECK(o.status == 0);
  CHECK(o.out.empty());
  o = run("lesson lint " + kSource + "/tests/cases/lessons-broken/shadowed.md");
  CHECK(o.status == 1);
  CHECK(o.out.find("shadowed.md:8: section '## on line plot' is shown at no step") != std::string::npos);
  o = run("lesson lint /nonexistent/lesson.md");
  CHECK(o.status == 2);
  CHECK(o.err.find("cannot read lesson file") != std::string::npos);
}

TEST_CASE("lessons cli: quiz grades answers, and a bad line prints only its error", "[lesson][cli][quiz]") {
  const fs::path answers = fs::temp_directory_path() / ("sw-quiz-" + std::to_string(::getpid()) + ".jsonl");
  // Bresenham (1, 2)-(13, 7): e = 2B - A = 2 * 5 - 12 = -2 is the first decision (by hand).
  std::ofstream(answers) << "{\"step\":2,\"answer\":\"negative\",\"student\":\"ann\"}\n{\"step\":2,\"answer\":1}\n";
  Out o = run("quiz " + kSource + "/lessons/03-bresenham.md --answers " + answers.string());
  CHECK(o.status == 0);
  CHECK(o.out.find("ann  step 2 sign: right: negative") != std::string::npos);
  CHECK(o.out.find("step 2 sign: wrong: answered positive, the exact run gives negative") != std::string::npos);
  CHECK(o.out.find("score: 1 of 2") != std::string::npos);
  std::ofstream(answers) << "{\"step\":2,\"answer\":\"negative\"}\n{\"step\":2,\"answer\":[1,2]}\n";
  o = run("quiz " + kSource + "/lessons/03-bresenham.md --answers " + answers.string());
  CHECK(o.status == 2);
  CHECK(o.out.empty());  // nothing graded is printed when a line is bad
  CHECK(o.err.find(answers.string() + ":2:") != std::string::npos);
  CHECK(std::count(o.err.begin(), o.err.end(), '\n') == 1);
  fs::remove(answers);
}
#endif
