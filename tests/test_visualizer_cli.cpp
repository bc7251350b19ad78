// The two executables: `stepwise render` (PNG and GIF through OSMesa, bad input -> exit 2 and no
// file) and `stepwise-gui` under xvfb-run (frames, screenshot, exit 0).
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include "cli_harness.hpp"
#include "peers.hpp"
#include <gif_lib.h>
#include <stb_image.h>
#include <sys/wait.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

using sw::testing::scratch;
using sw::testing::sh_quote;

struct Result {
  int status = -1;
  std::string err;
};

// Runs a shell command line; returns the exit status and what it wrote to stderr.
Result run(const std::string& cmd, const fs::path& dir) {
  const fs::path err = dir / "stderr.txt";
  const int rc = std::system((cmd + " 2>" + sh_quote(err.string()) + " >/dev/null").c_str());
  std::ifstream f(err);
  std::ostringstream s;
  s << f.rdbuf();
  return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, s.str()};
}

// Under xvfb-run: retried (at most 3 runs) when xvfb-run itself fails ("xvfb-run: error: Xvfb
// failed to start", or "problem while cleaning up temporary directory", exit 5, seen once under
// load in CI), since then the app's own exit status is lost. The app never prints that line.
Result run_gui(const std::string& cmd, const fs::path& dir) {
  Result r = run(cmd, dir);
  for (int k = 1; k < 3 && r.err.find("xvfb-run: error") != std::string::npos; ++k) r = run(cmd, dir);
  return r;
}

std::string stepwise() { return sh_quote(SW_STEPWISE_EXE); }
std::string lesson(const char* name) { return sh_quote((fs::path(SW_SOURCE_DIR) / "lessons" / name).string()); }

// Only the scratch files the test made itself: nothing partial left behind.
bool only_files(const fs::path& dir, std::initializer_list<const char*> names) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    ++n;
    bool known = false;
    for (const char* k : names) known |= e.path().filename() == k;
    if (!known) return false;
  }
  return n == names.size();
}

}  // namespace

TEST_CASE("visualizer cli: stepwise render: a PNG of a lesson step", "[visualizer][cli]") {
  const fs::path dir = scratch("png");
  const fs::path out = dir / "frame.png";
  const Result r = run(stepwise() + " render --lesson " + lesson("01-dda-line.md") + " --step 9 --size 480x300 --out " + sh_quote(out.string()), dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  int w = 0, h = 0, n = 0;
  unsigned char* img = stbi_load(out.c_str(), &w, &h, &n, 4);
  REQUIRE(img);
  CHECK(w == 480);
  CHECK(h == 300);
  stbi_image_free(img);
}

TEST_CASE("visualizer cli: stepwise render: a GIF has one frame per step of the inclusive range", "[visualizer][cli]") {
  const fs::path dir = scratch("gif");
  const fs::path out = dir / "anim.gif";
  const Result r = run(stepwise() + " render --algorithm bresenham-line --input '{\"p0\":[0,0],\"p1\":[6,2]}' --numeric int" +
                           " --gif " + sh_quote(out.string()) + " --from 3 --to 9 --delay 100 --size 400x260",
                       dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  int err = 0;
  GifFileType* gif = DGifOpenFileName(out.c_str(), &err);
  REQUIRE(gif);
  REQUIRE(DGifSlurp(gif) == GIF_OK);
  CHECK(gif->ImageCount == 7);
  CHECK(gif->SWidth == 400);
  CHECK(gif->SHeight == 260);
  GraphicsControlBlock gcb;
  REQUIRE(DGifSavedExtensionToGCB(gif, 0, &gcb) == GIF_OK);
  CHECK(gcb.DelayTime == 10);
  DGifCloseFile(gif, &err);
}

TEST_CASE("visualizer cli: stepwise render: malformed lessons and bad arguments exit 2 with one line and no file", "[visualizer][cli]") {
  const fs::path dir = scratch("bad");
  const fs::path out = dir / "frame.png", gif = dir / "anim.gif";
  struct Case {
    const char* name;
    std::string lesson_text, args, message;
  };
  const std::string good_head = "---\nalgorithm: dda-line\ninput: {\"p0\":[0,0],\"p1\":[5,2]}\n";
  // Within the budget in double; in exact, its 4000-character numbers weigh each step 11 times.
  const std::string den = "1" + std::string(1999, '0') + "7", big = std::string(2000, '0') + "/" + den;
  const std::string long_head = "---\nalgorithm: dda-line\ninput: {\"p0\":[\"1" + big + "\",0],\"p1\":[\"900000" + big + "\",1]}\n";
  const std::vector<Case> cases = {
      {"no front matter", "# A lesson\nno dashes\n", "", "front-matter"},
      {"unclosed front matter", good_head, "", "no closing"},
      {"unknown algorithm", "---\nalgorithm: dda-circle\ninput: {}\n---\n", "", "unknown algorithm 'dda-circle'"},
      {"bad input", "---\nalgorithm: dda-line\ninput: {\"p0\":[0,0],\"p1\":[\"1/0\",2]}\n---\n", "", "zero denominator"},
      {"bad JSON", "---\nalgorithm: dda-line\ninput: {\"p0\":[0,0\n---\n", "", "malformed JSON"},
      {"bad heading", good_head + "---\n## on line 42\n", "", "not a listing line"},
      {"step past the end", good_head + "---\n", " --step 999", "past the last step"},
      {"gif range reversed", good_head + "---\n", " --from 5 --to 2", "is after --to"},
      {"over the work budget", "---\nalgorithm: dda-line\ninput: {\"p0\":[0,0],\"p1\":[4000000,1]}\n---\n", "", "more than the budget of 4000000"},
      {"compared run over the budget", long_head + "---\n", " --numeric double --compare exact", "x 11 for exact numbers"},
      // 10 frames of 400 x 260 are 1,040,000 pixels.
      {"gif over its pixel budget", good_head + "---\n", " --from 0 --to 9 --max-pixels 1000000", "more than --max-pixels 1000000"},
      {"negative step budget", good_head + "---\n", " --from 0 --to 2 --max-steps -1", "expected a whole number"},
      {"overflowing step budget", good_head + "---\n", " --max-steps 18446744073709551616", "expected a whole number"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    std::ofstream(dir / "lesson.md") << c.lesson_text;
    const bool as_gif = c.args.find("--from") != std::string::npos;
    const std::string target = as_gif ? " --gif " + sh_quote(gif.string()) : " --out " + sh_quote(out.string());
    const Result r = run(stepwise() + " render --lesson " + sh_quote((dir / "lesson.md").string()) + c.args + target + " --size 400x260", dir);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains(c.message));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(only_files(dir, {"lesson.md", "stderr.txt"}));
  }
  const Result unknown = run(stepwise() + " render --algorithm nope --input '{}' --out " + sh_quote(out.string()), dir);
  CHECK(unknown.status == 2);
  CHECK_THAT(unknown.err, Catch::Contains("unknown algorithm 'nope'"));
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("visualizer gui: stepwise-gui starts under xvfb-run, renders frames, takes a screenshot and exits 0", "[visualizer][gui]") {
  SW_REQUIRE_PEER(std::system("command -v xvfb-run >/dev/null 2>&1") == 0, "xvfb-run");
  const fs::path dir = scratch("gui");
  const std::string xvfb = "xvfb-run -a -s '-screen 0 800x500x24' ";
  const fs::path shot = dir / "shot.png";
  Result r = run_gui(xvfb + sh_quote(SW_GUI_EXE) + " --size 800x500 --frames 4 --screenshot " + sh_quote(shot.string()), dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  int w = 0, h = 0, n = 0;
  unsigned char* img = stbi_load(shot.c_str(), &w, &h, &n, 4);
  REQUIRE(img);
  CHECK(w == 800);
  CHECK(h == 500);
  // Not a blank frame: the panels drew something other than the clear colour.
  std::size_t differing = 0;
  for (int i = 0; i < w * h; ++i) differing += img[4 * i] != img[0] || img[4 * i + 1] != img[1] || img[4 * i + 2] != img[2];
  CHECK(differing > std::size_t(w * h / 20));
  stbi_image_free(img);

  // A lesson that fails to load: the window shows the message, still writes its screenshot, exits 2.
  std::ofstream(dir / "bad.md") << "---\nalgorithm: dda-circle\ninput: {}\n---\n";
  const fs::path bad_shot = dir / "bad.png";
  r = run_gui(xvfb + sh_quote(SW_GUI_EXE) + " --size 800x500 --frames 2 --lesson " + sh_quote((dir / "bad.md").string()) + " --screenshot " +
              sh_quote(bad_shot.string()),
              dir);
  INFO(r.err);
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("unknown algorithm 'dda-circle'"));
  CHECK(fs::exists(bad_shot));
}
#endif  // SW_HAVE_VISUALIZER
