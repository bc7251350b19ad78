// Output that never destroys or truncates silently (docs/cli.md#output-files): --out naming an open
// descriptor is written through it, a replaced file keeps its inode, mode, owner and links, a file
// the user may not write is refused, and a failed write to standard output is one line and exit 2.
#include <catch2/catch.hpp>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <csignal>
#include <filesystem>
#include <fstream>
#include "cli_harness.hpp"

using namespace sw::testing;

namespace {

const std::string kTrace = "trace dda-line --input '{\"p0\":[0,0],\"p1\":[4,2]}'";

// Runs a whole shell command line (the test's own redirections); the exit status.
int shell(const std::string& line) {
  const int raw = std::system(line.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string exe() { return sh_quote(SW_STEPWISE_EXE); }

std::size_t count_lines(const std::string& s) { return std::size_t(std::count(s.begin(), s.end(), '\n')); }

struct stat stat_of(const std::filesystem::path& p) {
  struct stat st {};
  REQUIRE(::stat(p.c_str(), &st) == 0);
  return st;
}

}  // namespace

TEST_CASE("output: --out /dev/stdout appends through a redirection and writes into a pipe", "[cli][out]") {
  const auto dir = scratch("out-descriptor");
  const auto log = dir / "log";
  std::ofstream(log) << "MARKER\n";
  REQUIRE(shell(exe() + " " + kTrace + " --out /dev/stdout >>" + sh_quote(log.string()) + " 2>/dev/null") == 0);
  const std::string text = slurp(log);
  CHECK(text.rfind("MARKER\n{\"format\":\"stepwise-trace\"", 0) == 0);  // appended, not replaced
  CHECK(count_lines(text) == 1 + 16);
  // A pipe: written through (it used to fail with "cannot write /proc/self/fd/pipe:[N]").
  const auto piped = dir / "piped";
  REQUIRE(shell(exe() + " " + kTrace + " --out /dev/stdout 2>/dev/null | cat >" + sh_quote(piped.string())) == 0);
  CHECK(count_lines(slurp(piped)) == 16);
  // /dev/fd/N and /proc/self/fd/N name the command's own descriptors.
  for (const char* name : {"/dev/fd/7", "/proc/self/fd/7"}) {
    const auto f = dir / "fd7";
    std::filesystem::remove(f);
    REQUIRE(shell(exe() + " " + kTrace + " --out " + name + " 7>" + sh_quote(f.string()) + " 2>/dev/null") == 0);
    CHECK(count_lines(slurp(f)) == 16);
  }
  const auto r = run_stepwise(kTrace + " --out /dev/fd/9");
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("descriptor 9 is not open"));
}

TEST_CASE("output: a write that fails on standard output is one line and exit 2", "[cli][out]") {
  const auto dir = scratch("out-stdout");
  const auto err = dir / "err";
  for (const std::string& cmd : {kTrace, std::string("list"), std::string("schema"), std::string("list --json"),
                                 std::string("scene plan scenes/cornell-box.json")}) {
    INFO(cmd);
    for (const char* redirect : {">/dev/full", ">&-"}) {
      INFO(redirect);
      const int status = shell("cd " + sh_quote(SW_SOURCE_DIR) + " && " + exe() + " " + cmd + " " + redirect + " 2>" + sh_quote(err.string()));
      CHECK(status == 2);
      const std::string e = slurp(err);
      CHECK_THAT(e, Catch::Contains("cannot write to standard output"));
      CHECK(count_lines(e) == 1);
    }
  }
}

TEST_CASE("output: replacing a file keeps its mode, owner, inode and hard links", "[cli][out]") {
  const auto dir = scratch("out-replace");
  const auto priv = dir / "private.jsonl";
  std::ofstream(priv) << "old\n";
  REQUIRE(::chmod(priv.c_str(), 0600) == 0);
  REQUIRE(run_stepwise(kTrace + " --out " + sh_quote(priv.string())).status == 0);
  CHECK((stat_of(priv).st_mode & 07777) == 0600);  // it used to come back 0644
  CHECK(count_lines(slurp(priv)) == 16);
  // A file with a second hard link: both names see the new trace, one inode.
  const auto a = dir / "a.jsonl", b = dir / "b.jsonl";
  std::ofstream(a) << "old\n";
  REQUIRE(::link(a.c_str(), b.c_str()) == 0);
  const ino_t inode = stat_of(a).st_ino;
  REQUIRE(run_stepwise(kTrace + " --out " + sh_quote(a.string())).status == 0);
  CHECK(stat_of(a).st_ino == inode);
  CHECK(stat_of(b).st_nlink == 2);
  CHECK(slurp(b) == slurp(a));
  CHECK(count_lines(slurp(b)) == 16);
  // No temporaries left.
  std::size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) n += e.path().string().find(".tmp-") != std::string::npos;
  CHECK(n == 0);
}

TEST_CASE("output: a file the user may not write is refused and stays as it was", "[cli][out]") {
  // As root the test writes as nobody (65534) into a directory anyone may write: a 0444 file of
  // root's there is the case "a read-only file of another owner in a writable directory".
  const auto dir = scratch("out-readonly");
  REQUIRE(::chmod(dir.c_str(), 0777) == 0);
  const auto ro = dir / "readonly.jsonl";
  std::ofstream(ro) << "keep me\n";
  REQUIRE(::chmod(ro.c_str(), 0444) == 0);
  const std::string as_user = ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
  const auto err = dir / "err";
  const int status = shell(as_user + exe() + " " + kTrace + " --out " + sh_quote(ro.string()) + " 2>" + sh_quote(err.string()));
  CHECK(status == 2);
  CHECK_THAT(slurp(err), Catch::Contains("Permission denied"));
  CHECK(slurp(ro) == "keep me\n");
  CHECK((stat_of(ro).st_mode & 07777) == 0444);
}

TEST_CASE("output: SIGHUP during a long write leaves no temporary file", "[cli][out]") {
  const auto dir = scratch("out-sighup");
  const auto out = dir / "long.jsonl";
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    ::execl(SW_STEPWISE_EXE, SW_STEPWISE_EXE, "trace", "dda-grid-walk", "--input", "{\"p0\":[0,0],\"p1\":[16000000,7000001]}", "--max-steps",
            "100000000", "--out", out.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  bool seen = false;
  for (int k = 0; k < 400 && !seen; ++k) {
    for (const auto& e : std::filesystem::directory_iterator(dir)) seen = seen || e.path().string().find(".tmp-") != std::string::npos;
    if (!seen) ::usleep(10000);
  }
  CHECK(seen);
  ::kill(pid, SIGHUP);
  int status = 0;
  ::waitpid(pid, &status, 0);
  CHECK(WIFSIGNALED(status));
  CHECK(std::filesystem::is_empty(dir));
}
