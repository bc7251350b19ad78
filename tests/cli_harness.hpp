// Runs the `stepwise` binary for the CLI tests: exit code, stdout and stderr.
#pragma once
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace sw::testing {

struct Ran {
  int status = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// This test process's scratch root, removed when the process exits normally (ctest runs each
// case as its own process: without this every run left hundreds of directories in $TMPDIR). A
// crash leaves it behind to look at.
inline const std::filesystem::path& scratch_root() {
  struct Root {
    std::filesystem::path path = std::filesystem::temp_directory_path() / ("stepwise-test-" + std::to_string(::getpid()));
    ~Root() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Root root;
  return root.path;
}

// A fresh scratch directory under the process's root.
inline std::filesystem::path scratch(const std::string& name) {
  auto dir = scratch_root() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Single-quotes an argument for /bin/sh.
inline std::string sh_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline Ran run_stepwise(const std::string& args, const std::string& exe = SW_STEPWISE_EXE) {
  static int counter = 0;
  const auto dir = scratch("run-" + std::to_string(counter++));
  const std::string cmd = sh_quote(exe) + " " + args + " >" + sh_quote((dir / "out").string()) + " 2>" + sh_quote((dir / "err").string()) + " </dev/null";
  const int raw = std::system(cmd.c_str());
  Ran r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  std::filesystem::remove_all(dir);
  return r;
}

// `stepwise trace ALG --numeric N --input INPUT --out FILE` must refuse the input: exit 2, one line
// on stderr containing `expect`, and no output file. Catch2 checks; call inside a TEST_CASE.
#define SW_CHECK_BAD_TRACE(alg, numeric, input, expect)                                                                       \
  do {                                                                                                                        \
    const auto sw_dir_ = ::sw::testing::scratch("bad-trace");                                                                 \
    const auto sw_out_ = sw_dir_ / "t.jsonl";                                                                                 \
    const auto sw_ran_ = ::sw::testing::run_stepwise(std::string("trace ") + (alg) + " --numeric " + (numeric) + " --input " + \
                                                     ::sw::testing::sh_quote(input) + " --out " + ::sw::testing::sh_quote(sw_out_.string())); \
    CHECK(sw_ran_.status == 2);                                                                                               \
    CHECK_THAT(sw_ran_.err, Catch::Contains(expect));                                                                         \
    CHECK(std::count(sw_ran_.err.begin(), sw_ran_.err.end(), '\n') == 1);                                                    \
    CHECK(!std::filesystem::exists(sw_out_));                                                                                 \
  } while (false)

}  // namespace sw::testing
