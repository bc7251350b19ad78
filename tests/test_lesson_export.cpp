// `stepwise lesson export --frames DIR` (the flip-book): the files of a page, replacing an earlier export, bad input
// (exit 2, one line, nothing left in DIR's parent), and the page's escaping. The page in a browser:
// tests/lesson_export_browser.py.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <sys/stat.h>
#include <stb_image.h>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include "cli_harness.hpp"
#include "peers.hpp"
#include "headless/html_page.hpp"

namespace fs = std::filesystem;
using sw::testing::run_stepwise;
using sw::testing::sh_quote;

namespace {

std::string lesson(const char* name) { return sh_quote((fs::path(SW_SOURCE_DIR) / "lessons" / name).string()); }

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

// The JSON text of a page between the first `open` and the `close` after it.
sw::Json json_between(const std::string& html, const std::string& open, const std::string& close) {
  const auto a = html.find(open);
  REQUIRE(a != std::string::npos);
  const auto b = html.find(close, a);
  REQUIRE(b != std::string::npos);
  return sw::Json::parse(html.substr(a + open.size(), b - a - open.size()));
}

// The page data blob of an exported index.html.
sw::Json page_data(const fs::path& index) {
  return json_between(sw::testing::slurp(index), "<script type=\"application/json\" id=\"page-data\">", "</script>");
}

// Runs an export that must fail: exit 2, one line naming `expect`, and `dir` left as it was.
void check_refused(const std::string& args, const fs::path& dir, const std::string& expect) {
  const std::set<std::string> before = names_in(dir);
  const auto r = run_stepwise("lesson export " + args);
  INFO(args << "\n" << r.err);
  CHECK(r.status == 2);
  CHECK(r.err.find(expect) != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(names_in(dir) == before);
}

}  // namespace

TEST_CASE("visualizer lesson export: a step range writes index.html and one frame per step", "[visualizer][cli]") {
  const fs::path dir = sw::testing::scratch("export-range");
  const fs::path page = dir / "page";
  auto r = run_stepwise("lesson export " + lesson("02-grid-walk.md") + " --frames " + sh_quote(page.string()) +
                        " --size 320x240 --from 2 --to 5");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(names_in(dir) == std::set<std::string>{"page"});  // no temporary left beside it
  CHECK(names_in(page) == std::set<std::string>{"index.html", "frames"});
  CHECK(names_in(page / "frames") == std::set<std::string>{"0002.png", "0003.png", "0004.png", "0005.png"});
  // The page is made to be served: its directories take the umask's mode, as mkdir gives (not mkdtemp's 0700).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  const auto want = static_cast<fs::perms>(0777 & ~mask);
  CHECK((fs::status(page).permissions() & fs::perms::all) == want);
  CHECK((fs::status(page / "frames").permissions() & fs::perms::all) == want);
  for (const auto& e : fs::directory_iterator(page / "frames")) {
    int w = 0, h = 0, n = 0;
    REQUIRE(stbi_info(e.path().c_str(), &w, &h, &n));
    CHECK(w == 320);
    CHECK(h == 240);
  }
  const sw::Json data = page_data(page / "index.html");
  REQUIRE(data.at("steps").size() == 4);
  CHECK(data.at("algorithm") == "dda-grid-walk");
  CHECK(data.at("start") == 2);  // the lesson's step: 4
  for (std::size_t i = 0; i < 4; ++i) {
    const sw::Json& s = data.at("steps")[i];
    CHECK(s.at("step") == 2 + i);
    CHECK(s.at("frame") == "frames/000" + std::to_string(2 + i) + ".png");
    CHECK(s.at("narration").get<std::size_t>() < data.at("narrations").size());
    CHECK(s.at("line").get<std::size_t>() <= data.at("listings")[0].at("lines").size());
  }

  // A second export replaces the first: only its own frames remain.
  r = run_stepwise("lesson export " + lesson("02-grid-walk.md") + " --frames " + sh_quote(page.string()) +
                   " --size 320x240 --from 0 --to 1");
  REQUIRE(r.status == 0);
  CHECK(names_in(dir) == std::set<std::string>{"page"});
  CHECK(names_in(page / "frames") == std::set<std::string>{"0000.png", "0001.png"});
}

TEST_CASE("visualizer lesson export: bad input exits 2 with one line and writes nothing", "[visualizer][cli]") {
  const fs::path dir = sw::testing::scratch("export-bad");
  const std::string out = sh_quote((dir / "page").string());
  { std::ofstream(dir / "bad.md") << "---\nalgorithm: dda-line\ninput: {\"p0\":[0,0],\"p1\":[3,1]}\ncolour: red\n---\n"; }
  { std::ofstream(dir / "file.txt") << "not a directory\n"; }
  fs::create_directories(dir / "mine");
  { std::ofstream(dir / "mine" / "notes.txt") << "a teacher's file\n"; }

  check_refused(sh_quote((dir / "missing.md").string()) + " --frames " + out, dir, "missing.md");
  check_refused(sh_quote((dir / "bad.md").string()) + " --frames " + out, dir, "unknown front-matter key 'colour'");
  check_refused(lesson("02-grid-walk.md") + " --frames " + sh_quote((dir / "file.txt" / "page").string()), dir, "does not exist");
  check_refused(lesson("02-grid-walk.md") + " --frames " + sh_quote((dir / "nowhere" / "page").string()), dir, "does not exist");
  check_refused(lesson("02-grid-walk.md") + " --frames " + sh_quote((dir / "file.txt").string()), dir, "is not a directory");
  check_refused(lesson("02-grid-walk.md") + " --frames " + sh_quote((dir / "mine").string()), dir, "refusing to replace it");
  CHECK(names_in(dir / "mine") == std::set<std::string>{"notes.txt"});
  check_refused(lesson("02-grid-walk.md") + " --frames " + out + " --size 10x10", dir, "--size");
  check_refused(lesson("02-grid-walk.md") + " --frames " + out + " --from 5 --to 3", dir, "--from 5 is after --to 3");
  check_refused(lesson("02-grid-walk.md") + " --frames " + out + " --to 100000", dir, "past the last step");
  // The float-drift lesson walks 3000 columns: more steps than a page holds.
  check_refused(lesson("04-float-drift.md") + " --frames " + out + " --size 320x240", dir,
                "steps; a page holds at most 600 frames (choose a range with --from and --to)");
  check_refused(lesson("04-float-drift.md") + " --frames " + out + " --size 320x240 --from 0 --to 600", dir,
                "steps 0..600 are 601 frames; a page holds at most 600 frames");
  // The pixel budget: 100 frames of 1280x800 (1.02e8 pixels) is over the default 2^26; a smaller
  // --max-pixels refuses what the default takes; -1 cannot turn it off.
  check_refused(lesson("04-float-drift.md") + " --frames " + out + " --from 0 --to 99", dir,
                "the page would render 102400000 pixels (100 frames of 1280x800), more than --max-pixels 67108864");
  check_refused(lesson("02-grid-walk.md") + " --frames " + out + " --size 320x240 --from 0 --to 3 --max-pixels 300000", dir,
                "more than --max-pixels 300000");
  check_refused(lesson("02-grid-walk.md") + " --frames " + out + " --max-pixels -1", dir, "--max-pixels");
}

TEST_CASE("visualizer lesson export: lesson text cannot inject markup or script", "[visualizer]") {
  const std::string html =
      sw::vis::markdown_html("Hi <script>alert(1)</script> [x](javascript:alert(1)) [y](https://a.b/c) [z](#top)\n");
  CHECK(html.find("<script") == std::string::npos);
  CHECK(html.find("&lt;script&gt;") != std::string::npos);
  CHECK(html.find("javascript:") == std::string::npos);
  CHECK(html.find("href=\"#\"") != std::string::npos);
  CHECK(html.find("href=\"https://a.b/c\"") != std::string::npos);
  CHECK(html.find("href=\"#top\"") != std::string::npos);
  CHECK(sw::vis::html_escape("<b a=\"1\">&'") == "&lt;b a=&quot;1&quot;&gt;&amp;&#39;");
  const std::string blob = sw::vis::script_safe_json(sw::Json{{"n", "</script><b>&"}});
  CHECK(blob.find('<') == std::string::npos);
  CHECK(sw::Json::parse(blob).at("n") == "</script><b>&");
}


// `--html DIR`: the browser page (scripts/web.sh) with the lesson's own files in it.
namespace {

// The stepwiseLesson object an exported page carries (visualizer/web/shell.html).
sw::Json carried_lesson(const std::string& html) { return json_between(html, "var stepwiseLesson = ", ";\n"); }

}  // namespace

TEST_CASE("visualizer lesson export --html: the app's page, carrying the lesson and its includes, opened where asked", "[visualizer][cli]") {
  const fs::path built = fs::path(SW_SOURCE_DIR) / "out" / "web" / "stepwise.html";
  SW_REQUIRE_PEER(fs::is_regular_file(built), "the browser page out/web/stepwise.html (scripts/web.sh)");
  const std::string page = sw::testing::slurp(built);
  REQUIRE(page.find("var stepwiseLesson = null;") != std::string::npos);
  const fs::path dir = sw::testing::scratch("export-app");

  // A lesson of the tree: the page opens on it at --from.
  auto r = run_stepwise("lesson export " + lesson("24-glass-tir.md") + " --html " + sh_quote((dir / "tir").string()) + " --from 3");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(names_in(dir / "tir") == std::set<std::string>{"index.html"});
  const std::string html = sw::testing::slurp(dir / "tir" / "index.html");
  const sw::Json own = carried_lesson(html);
  CHECK(own["lesson"] == "/stepwise/lessons/24-glass-tir.md");
  CHECK(own["step"] == 3);
  REQUIRE(!own["files"].empty());
  CHECK(own["files"][0]["text"] == sw::testing::slurp(fs::path(SW_SOURCE_DIR) / "lessons" / "24-glass-tir.md"));
  // Everything else is the built page's, byte for byte.
  const auto at = page.find("var stepwiseLesson = null;");
  CHECK(html.substr(0, at) == page.substr(0, at));
  CHECK(html.substr(html.size() - (page.size() - at - 26)) == page.substr(at + 26));

  // A teacher's own lesson outside the tree, with included files: all go in, at their paths
  // relative to the lesson (one in a folder beside the lesson's); no --from: it opens where the
  // lesson says.
  const fs::path mine = dir / "mine";
  fs::create_directories(mine / "parts");
  fs::create_directories(dir / "shared");
  { std::ofstream(mine / "parts" / "extra.md") << "## on line delta\nThe walk starts </script> here.\n"; }
  { std::ofstream(dir / "shared" / "more.md") << "## on line plot\nA pixel.\n"; }
  { std::ofstream(mine / "walk.md") << "---\nalgorithm: dda-line\ninput: {\"p0\":[0,0],\"p1\":[5,2]}\ninclude: parts/extra.md, ../shared/more.md\n---\n# My walk\n"; }
  r = run_stepwise("lesson export " + sh_quote((mine / "walk.md").string()) + " --html " + sh_quote((dir / "walk").string()));
  INFO(r.err);
  REQUIRE(r.status == 0);
  const std::string walk = sw::testing::slurp(dir / "walk" / "index.html");
  CHECK(walk.find("here.</script>") == std::string::npos);  // the included text cannot end the script
  const sw::Json carried = carried_lesson(walk);
  CHECK(carried["lesson"] == "/stepwise/lessons/walk.md");
  CHECK(carried["step"].is_null());
  REQUIRE(carried["files"].size() == 3);
  CHECK(carried["files"][1]["path"] == "/stepwise/lessons/parts/extra.md");
  CHECK(carried["files"][1]["text"] == "## on line delta\nThe walk starts </script> here.\n");
  CHECK(carried["files"][2]["path"] == "/stepwise/shared/more.md");  // where ../shared/more.md leads from the lesson
  CHECK(carried["files"][2]["text"] == "## on line plot\nA pixel.\n");

  // Refused, with nothing written: the flip-book's options, a step past the end, a bad lesson, and
  // a data root without the page.
  const std::string out = sh_quote((dir / "page").string());
  check_refused(lesson("02-grid-walk.md") + " --html " + out + " --size 320x240", dir, "--size");
  check_refused(lesson("02-grid-walk.md") + " --html " + out + " --to 3", dir, "--to");
  check_refused(lesson("02-grid-walk.md") + " --html " + out + " --frames " + out, dir, "--frames");
  check_refused(lesson("02-grid-walk.md") + " --html " + out + " --from 100000", dir, "past the last step");
  { std::ofstream(dir / "bad.md") << "---\nalgorithm: dda-line\ncolour: red\n---\n"; }
  check_refused(sh_quote((dir / "bad.md").string()) + " --html " + out, dir, "unknown front-matter key 'colour'");
  check_refused(lesson("02-grid-walk.md"), dir, "give --html DIR");
  const fs::path bare = sw::testing::scratch("export-app-bare");
  fs::create_directories(bare / "lessons");
  ::setenv("STEPWISE_DATA", bare.c_str(), 1);
  check_refused(lesson("02-grid-walk.md") + " --html " + out, dir, "is not built: run scripts/web.sh");
  ::unsetenv("STEPWISE_DATA");
}

#endif
