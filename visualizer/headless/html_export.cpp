#include "headless/html_export.hpp"
#include <stdlib.h>
#include <sys/stat.h>
#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include "headless/headless.hpp"
#include "headless/html_page.hpp"
#include "headless/image_io.hpp"
#include "headless/render_command.hpp"
#include "data_root.hpp"

namespace sw::vis {
namespace {

namespace fs = std::filesystem;

// Where the page goes. DIR may be new, an empty directory, or an earlier export (index.html, and
// frames/ for a flip-book), which is replaced; anything else is refused, so no one's files are lost.
// `option` and `arg` name the flag and its value in messages (--html DIR, --frames DIR).
struct Target {
  std::string option, arg;
  fs::path dir, parent;
  bool exists = false, empty = false;
  // The one-line error "OPTION ARG<what>".
  InputError fail(const std::string& what) const { return InputError(option + " " + arg + what); }
};

Target check_target(const std::string& arg, const std::string& option) {
  if (arg.empty()) throw InputError(option + ": give the directory to write the page to");
  Target t;
  t.option = option, t.arg = arg;
  t.dir = fs::absolute(fs::path(arg)).lexically_normal();
  if (!t.dir.has_filename()) t.dir = t.dir.parent_path();  // "pages/" and "pages/." name "pages"
  if (t.dir == t.dir.root_path()) throw t.fail(": refusing to write to the root directory");
  t.parent = t.dir.parent_path();
  std::error_code ec;
  if (!fs::is_directory(t.parent, ec))
    throw t.fail(": the directory " + t.parent.string() + " does not exist");
  const fs::file_status st = fs::symlink_status(t.dir, ec);
  if (st.type() == fs::file_type::not_found) return t;
  if (st.type() == fs::file_type::symlink) throw t.fail(" is a symbolic link; give the directory itself");
  if (st.type() != fs::file_type::directory) throw t.fail(" exists and is not a directory");
  t.exists = true;
  std::size_t entries = 0;
  bool ours = true, index = false;
  for (fs::directory_iterator it(t.dir, ec), end; !ec && it != end && entries <= 2; it.increment(ec)) {
    ++entries;
    const std::string name = it->path().filename().string();
    index |= name == "index.html" && it->is_regular_file();
    ours &= (name == "index.html" && it->is_regular_file()) || (name == "frames" && it->is_directory());
  }
  if (ec) throw t.fail(": cannot read the directory (" + ec.message() + ")");
  t.empty = entries == 0;
  if (!t.empty && (!ours || !index || entries > 2))
    throw t.fail(" holds files other than an earlier export (index.html, and frames/); refusing to replace it");
  return t;
}

// A temporary sibling of DIR, removed unless committed.
class TempDir {
 public:
  explicit TempDir(const Target& t) {
    std::string pattern = (t.parent / ("." + t.dir.filename().string() + ".tmp-XXXXXX")).string();
    if (!::mkdtemp(pattern.data()))
      throw t.fail(": cannot write in " + t.parent.string() + " (" + std::strerror(errno) + ")");
    path_ = pattern;
    // mkdtemp makes it 0700; the page is made to be served, so it takes the mode mkdir would give it.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::chmod(path_.c_str(), 0777 & ~mask);
  }
  ~TempDir() {
    std::error_code ec;
    if (!path_.empty()) fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }
  // Moves the finished page to DIR: rename(2) replaces an empty directory; an earlier export is
  // moved aside first and removed once the new page is in place.
  void commit(const Target& t) {
    std::error_code ec;
    if (t.exists && !t.empty) {
      const fs::path old = path_.string() + ".old";
      fs::rename(t.dir, old, ec);
      if (ec) throw t.fail(": cannot move the earlier export aside (" + ec.message() + ")");
      fs::rename(path_, t.dir, ec);
      if (ec) {
        std::error_code back;
        fs::rename(old, t.dir, back);
        throw t.fail(": cannot move the page into place (" + ec.message() + ")");
      }
      fs::remove_all(old, ec);
    } else {
      fs::rename(path_, t.dir, ec);
      if (ec) throw t.fail(": cannot move the page into place (" + ec.message() + ")");
    }
    path_.clear();
  }

 private:
  fs::path path_;
};

std::string frame_name(std::size_t step) {
  std::array<char, 32> buf{};
  std::snprintf(buf.data(), buf.size(), "frames/%04zu.png", step);
  return buf.data();
}

Json listing_json(const Listing& listing, std::string title) {
  Json lines = Json::array();
  for (const ListingLine& l : listing.lines) lines.push_back({{"name", std::string(l.name)}, {"text", std::string(l.text)}});
  return {{"title", std::move(title)}, {"lines", std::move(lines)}};
}

// The page data (docs/lesson-export.md): per step its frame, listing and line, kind and narration
// (an index into the distinct narrations, each HTML from narrate's Markdown).
Json page_data(const Lesson& lesson, const TraceModel& run, std::size_t from, std::size_t to, int w, int h) {
  const Algorithm& alg = run.algorithm();
  Json listings = Json::array({listing_json(alg.listing, std::string(alg.listing.title))});
  std::array<int, 256> listing_of_scope;
  listing_of_scope.fill(-1);
  listing_of_scope[0] = 0;
  std::map<std::string, std::size_t> narration_index;
  Json narrations = Json::array(), steps = Json::array();
  for (std::size_t s = from; s <= to; ++s) {
    const StepRecord& st = run.trace().at(s);
    int& listing = listing_of_scope[st.scope];
    if (listing < 0) {
      const Listing& callee = run.trace().scope_listing(st.scope);
      listing = int(listings.size());
      listings.push_back(listing_json(callee, std::string(callee.title) + " (called by " + std::string(alg.listing.title) + ")"));
    }
    const std::string html = markdown_html(narrate(lesson, run, s));
    auto [it, added] = narration_index.emplace(html, narrations.size());
    if (added) narrations.push_back(html);
    steps.push_back({{"step", s},
                     {"frame", frame_name(s)},
                     {"listing", listing},
                     {"line", st.line},
                     {"kind", std::string(kind_name(st.kind))},
                     {"narration", it->second}});
  }
  const std::size_t start = lesson.start_step >= from && lesson.start_step <= to ? lesson.start_step - from : 0;
  return {{"title", lesson.title},
          {"algorithm", std::string(alg.id)},
          {"numeric", std::string(numeric_name(run.numeric()))},
          {"size", {w, h}},
          {"start", start},
          {"listings", std::move(listings)},
          {"narrations", std::move(narrations)},
          {"steps", std::move(steps)}};
}

// The flip-book (--frames).
int export_frames(const ExportOptions& o) {
  const auto [w, h] = parse_frame_size(o.size);
  const Lesson lesson = load_lesson(o.lesson);
  const Target target = check_target(o.frames_dir, "--frames");

  Budget budget;
  budget.max_steps = o.max_steps;
  HeadlessHost host(w, h);
  App& app = host.app();
  Session& session = app.session();
  session.set_budget(budget);
  if (!session.open_lesson(o.lesson)) throw InputError(session.error());
  const std::size_t last = session.steps() - 1;
  const std::size_t from = o.from.value_or(0), to = o.to.value_or(last);
  for (auto [value, flag] : {std::pair{from, "--from"}, std::pair{to, "--to"}})
    if (value > last)
      throw InputError(std::string(flag) + " " + std::to_string(value) + " is past the last step (" + std::to_string(last) + ")");
  if (from > to) throw InputError("--from " + std::to_string(from) + " is after --to " + std::to_string(to));
  if (const std::size_t frames = to - from + 1; frames > kMaxPageFrames) {
    const std::string limit = "a page holds at most " + std::to_string(kMaxPageFrames) + " frames";
    if (o.from || o.to)
      throw InputError("steps " + std::to_string(from) + ".." + std::to_string(to) + " are " + std::to_string(frames) +
                       " frames; " + limit);
    throw InputError(o.lesson + " has " + std::to_string(frames) + " steps; " + limit + " (choose a range with --from and --to)");
  }
  check_frame_pixels(to - from + 1, w, h, o.max_pixels, "the page");

  const Json data = page_data(lesson, *session.model(0), from, to, w, h);
  const std::string page = lesson_page(lesson.title, lesson.intro.empty() ? std::string() : markdown_html(lesson.intro), data);

  TempDir temp(target);
  if (std::error_code ec; !fs::create_directory(temp.path() / "frames", ec)) throw target.fail(": cannot create frames/ (" + ec.message() + ")");
  for (std::size_t s = from; s <= to; ++s) {
    app.restart_view();  // each frame as `stepwise render --lesson --step s` draws it, from the opening view
    session.set_step(s);
    write_png(temp.path() / frame_name(s), host.render(3).data(), w, h);
  }
  {
    std::ofstream f(temp.path() / "index.html", std::ios::binary);
    f << page;
    f.close();
    if (!f) throw target.fail(": cannot write index.html");
  }
  temp.commit(target);
  std::cerr << "stepwise: wrote " << (to - from + 1) << " frames (steps " << from << ".." << to << ") and index.html to "
            << target.dir.string() << '\n';
  return 0;
}

// A file's whole text; InputError naming it if it cannot be read.
std::string read_text(const fs::path& file, const std::string& what) {
  std::ifstream in(file, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw InputError(what + " " + file.string() + " cannot be read");
  return text;
}

// The app's page opened on the lesson (--html): the built page with the lesson's own files (the
// lesson and what it includes, at their paths relative to it) in its stepwiseLesson (shell.html).
int export_app_page(const ExportOptions& o) {
  const Lesson lesson = load_lesson(o.lesson);  // a bad lesson is refused before anything is written
  if (o.from) {
    Session session;
    Budget budget;
    budget.max_steps = o.max_steps;
    session.set_budget(budget);
    if (!session.open_lesson(o.lesson)) throw InputError(session.error());
    if (*o.from >= session.steps())
      throw InputError("--from " + std::to_string(*o.from) + " is past the last step (" + std::to_string(session.steps() - 1) + ")");
  }
  const Target target = check_target(o.html_dir, "--html");
  const fs::path page_file = web_page_file();
  if (!fs::is_regular_file(page_file))
    throw InputError("the browser page " + page_file.string() + " is not built: run scripts/web.sh (or use --frames DIR)");
  std::string page = read_text(page_file, "the browser page");
  const std::string marker = "var stepwiseLesson = null;";
  const std::size_t at = page.find(marker);
  if (at == std::string::npos) throw InputError(page_file.string() + " is not stepwise's browser page (no stepwiseLesson)");
  // In the page the lesson sits in /stepwise/lessons and each include where its path relative to the
  // lesson leads from there (written normalised: ../shared/x.md is /stepwise/shared/x.md).
  const fs::path lesson_dir = fs::absolute(o.lesson).parent_path();
  const fs::path root = "/stepwise/lessons";
  Json files = Json::array({{{"path", (root / fs::path(o.lesson).filename()).generic_string()}, {"text", read_text(o.lesson, "the lesson")}}});
  for (const fs::path& inc : lesson.includes)
    files.push_back({{"path", (root / fs::relative(fs::absolute(inc), lesson_dir)).lexically_normal().generic_string()},
                     {"text", read_text(inc, "the included file")}});
  const Json carried = {{"files", files}, {"lesson", files[0]["path"]}, {"step", o.from ? Json(*o.from) : Json()}};
  page.replace(at, marker.size(), "var stepwiseLesson = " + script_safe_json(carried) + ";");

  TempDir temp(target);
  {
    std::ofstream f(temp.path() / "index.html", std::ios::binary);
    f << page;
    f.close();
    if (!f) throw target.fail(": cannot write index.html");
  }
  temp.commit(target);
  std::cerr << "stepwise: wrote " << (target.dir / "index.html").string() << " (" << page.size() / 1024
            << " KiB): the app, opened on " << lesson.title << '\n';
  return 0;
}

}  // namespace

fs::path web_page_file() { return data_root() / "out" / "web" / "stepwise.html"; }

int run_lesson_export(const ExportOptions& o) {
  if (!o.frames_dir.empty()) return export_frames(o);
  if (o.html_dir.empty()) throw InputError("lesson export: give --html DIR (the app's page) or --frames DIR (the flip-book)");
  return export_app_page(o);
}

}  // namespace sw::vis
