// The classroom app through the headless host: at 1024x640 the panels tile the window without
// overlapping and the toolbar's and timeline's rows fit (they wrap); presentation mode hides the
// edit rows and the state panel; the Lesson menu's titles and Next/Previous; the canvas follows a
// step taken off-screen and keeps its zoom; the 3D view's label boxes are pairwise disjoint.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <imgui_internal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include "cli_harness.hpp"
#include "headless/headless.hpp"
#include "panels/orbit_canvas.hpp"
#include "source_paths.hpp"

using namespace sw;
using namespace sw::vis;

namespace {

bool disjoint(const PanelRect& a, const PanelRect& b) {
  return a.right() <= b.pos.x || b.right() <= a.pos.x || a.bottom() <= b.pos.y || b.bottom() <= a.pos.y;
}

// The window's content (as ImGui's cursor reached it last frame) stays inside its padded rect.
void check_fits(const char* name, ImVec2 display) {
  const ImGuiWindow* w = ImGui::FindWindowByName(name);
  REQUIRE(w);
  INFO(name << " at " << w->Pos.x << "," << w->Pos.y << " size " << w->Size.x << "x" << w->Size.y << ", content reaches "
            << w->DC.CursorMaxPos.x << "," << w->DC.CursorMaxPos.y);
  CHECK(w->Pos.x >= 0);
  CHECK(w->Pos.y >= 0);
  CHECK(w->Pos.x + w->Size.x <= display.x);
  CHECK(w->Pos.y + w->Size.y <= display.y);
  CHECK(w->DC.CursorMaxPos.x <= w->Pos.x + w->Size.x - w->WindowPadding.x + 0.5f);
  CHECK(w->DC.CursorMaxPos.y <= w->Pos.y + w->Size.y - w->WindowPadding.y + 0.5f);
}

// Every panel of the last frame: inside the display, none overlapping another; the toolbar's and
// the timeline's rows inside them.
void check_layout(HeadlessHost& host, bool presenting) {
  const PanelLayout& l = host.app().layout();
  std::vector<PanelRect> rects = {l.toolbar, l.canvas, l.narration, l.listing, l.timeline};
  if (!presenting) rects.push_back(l.state);
  const ImVec2 d(float(host.width()), float(host.height()));
  for (std::size_t i = 0; i < rects.size(); ++i) {
    INFO("panel " << i);
    CHECK(rects[i].size.x >= 200);
    CHECK(rects[i].size.y >= 40);
    CHECK(rects[i].right() <= d.x);
    CHECK(rects[i].bottom() <= d.y);
    for (std::size_t j = 0; j < i; ++j) CHECK(disjoint(rects[i], rects[j]));
  }
  CHECK(l.canvas.size.x * l.canvas.size.y >= 0.25f * d.x * d.y);  // the canvas dominates
  check_fits("Toolbar", d);
  check_fits("Timeline", d);
  const ImGuiWindow* state = ImGui::FindWindowByName("State");
  CHECK((state && state->Active) == !presenting);
}

}  // namespace

TEST_CASE("visualizer classroom: at 1024x640 the panels tile the window and the toolbar fits", "[visualizer][classroom]") {
  HeadlessHost host(1024, 640);
  App& app = host.app();
  Session& session = app.session();
  const auto lessons = lesson_manifest(default_lessons_dir());
  // Two segments (four exact fields), sliders of two compared models, and the first lesson.
  for (const char* name : {"01-dda-line.md", "22-phong-blinn.md", "19-gouraud-phong.md"}) {
    INFO(name);
    REQUIRE(session.open_lesson(default_lessons_dir() / name));
    host.render(3);
    check_layout(host, false);
    app.set_presenting(true);
    host.render(3);
    check_layout(host, true);
    app.set_presenting(false);
  }
  // An algorithm with a JSON input field and the compare toggle on.
  REQUIRE(session.open_algorithm(find_algorithm("ray-triangle-mt"),
                             parse_json_text(find_algorithm("ray-triangle-mt").example, "example"), Numeric::f64,
                             Comparison(Numeric::f32)));
  host.render(3);
  check_layout(host, false);
}

TEST_CASE("visualizer classroom: at 2560x1440 and scale 2 the panels tile the window", "[visualizer][classroom]") {
  HeadlessHost host(2560, 1440, default_lessons_dir(), 2.f);
  REQUIRE(host.app().session().open_first_lesson());
  host.render(3);
  CHECK(host.app().layout().em == Approx(30));  // the body font at scale 2
  check_layout(host, false);
}

TEST_CASE("visualizer classroom: presentation mode by key, with bigger fonts", "[visualizer][classroom]") {
  HeadlessHost host(1024, 640);
  App& app = host.app();
  REQUIRE(app.session().open_first_lesson());
  host.render(3);
  const float toolbar_h = app.layout().toolbar.size.y;
  host.type('p');
  host.render(3);
  CHECK(app.presenting());
  CHECK(app.layout().em == Approx(15 * theme::kPresentScale));
  CHECK(app.layout().toolbar.size.y < toolbar_h);  // the input row is gone
  host.press(ImGuiKey_Escape);
  host.render(3);
  CHECK_FALSE(app.presenting());
}

TEST_CASE("visualizer classroom: every lesson's key step text is in view on open, and in presentation mode", "[visualizer][classroom][lesson]") {
  for (const bool presenting : {false, true}) {
    HeadlessHost host(1024, 640);
    App& app = host.app();
    app.set_presenting(presenting);
    for (const auto& file : lesson_manifest(default_lessons_dir())) {
      INFO(file.filename().string() << (presenting ? ", presenting" : ""));
      REQUIRE(app.session().open_lesson(file));
      REQUIRE_FALSE(narrate(*app.session().lesson(), *app.session().model(0), app.session().step()).empty());
      host.render(3);
      // Its first two lines at least, below the title row and inside the panel.
      const PanelRect& r = app.layout().narration;
      CHECK(app.narration_marks().text_y > r.pos.y);
      CHECK(app.narration_marks().text_y + 2 * ImGui::GetFontSize() <= r.bottom());
    }
  }
}

TEST_CASE("visualizer classroom: a step scrolls the State panel to the first variable it sets", "[visualizer][classroom]") {
  HeadlessHost host(1024, 640);
  App& app = host.app();
  Session& s = app.session();
  REQUIRE(s.open_lesson(sw::testing::kLessons / "16-kd-sah.md"));
  // The State table scrolls inside a child of the State window; its scroll, and whether the step's
  // first set variable (below the fold at step 65, the fifth of a long list) lies inside it.
  auto table = []() -> const ImGuiWindow* {
    const ImGuiWindow* state = ImGui::FindWindowByName("State");
    for (const ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
      if (w->ParentWindow == state && w != state) return w;
    return nullptr;
  };
  s.go(65);
  host.render(3);
  const ImGuiWindow* w = table();
  REQUIRE(w);
  CHECK(w->Scroll.y > 0);
  const auto vars = s.model(0)->state_at(65);
  const auto first = std::find_if(vars.begin(), vars.end(), [](const VarState& v) { return v.set_here; });
  REQUIRE(first != vars.end());
  CHECK(first - vars.begin() >= 4);  // it would be hidden without the scroll
  // A step that sets the first rows scrolls back to the top.
  s.go(0);
  host.render(3);
  REQUIRE(table());
  CHECK(table()->Scroll.y == 0);
}

TEST_CASE("visualizer classroom: the Lesson menu lists titles in manifest order, Ctrl+Right and Ctrl+Left move along it",
          "[visualizer][classroom]") {
  HeadlessHost host(1024, 640);
  App& app = host.app();
  Session& session = app.session();
  const auto lessons = lesson_manifest(default_lessons_dir());
  const auto& titles = session.lesson_titles();
  REQUIRE(titles.size() == lessons.size());
  for (std::size_t k : {std::size_t(0), std::size_t(1), lessons.size() - 1}) CHECK(titles[k] == load_lesson(lessons[k]).title);
  CHECK(titles[0] != titles[1]);
  REQUIRE(session.open_first_lesson());
  host.render(2);
  ImGui::GetIO().KeyCtrl = true;
  host.press(ImGuiKey_RightArrow);
  host.render(2);
  REQUIRE(session.model(0));
  CHECK(&session.model(0)->algorithm() == load_lesson(lessons[1]).algorithm);
  host.press(ImGuiKey_RightArrow);
  host.render(2);
  CHECK(&session.model(0)->algorithm() == load_lesson(lessons[2]).algorithm);
  host.press(ImGuiKey_LeftArrow);
  host.render(2);
  ImGui::GetIO().KeyCtrl = false;
  CHECK(&session.model(0)->algorithm() == load_lesson(lessons[1]).algorithm);
  CHECK(session.step() == load_lesson(lessons[1]).start_step);  // Ctrl+arrows do not step
  CHECK(session.open_adjacent_lesson(-1));
  CHECK_FALSE(session.open_adjacent_lesson(-1));  // before the first: nothing
  CHECK(&session.model(0)->algorithm() == load_lesson(lessons[0]).algorithm);
}

TEST_CASE("visualizer classroom: stepping off-screen pans the canvas to the step and keeps the zoom", "[visualizer][classroom]") {
  HeadlessHost host(1024, 640);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_algorithm(find_algorithm("dda-line"), parse_json_text(R"({"p0":[0,0],"p1":[300,70]})", "t"), Numeric::exact));
  const TraceModel& m = *session.model(0);
  REQUIRE(m.plots().size() > 200);
  const PlotEvent start = m.plots().front(), end_plot = m.plots().back();
  app.jump_and_focus(start.step);
  host.render(2);
  const auto first = app.canvas(0)->cell_rect(start.cell);
  REQUIRE(first);
  const float cell = (*first)[2] - (*first)[0];
  CHECK(cell >= 23.5f);
  const Pixel end = end_plot.cell;
  REQUIRE_FALSE(app.canvas(0)->cell_rect(end));  // 300 cells away: off the canvas
  host.press(ImGuiKey_End);
  host.render(2);
  REQUIRE(session.step() == m.last());
  const auto now = app.canvas(0)->cell_rect(end);
  REQUIRE(now);
  CHECK((*now)[2] - (*now)[0] == Approx(cell));
  // A pan away is kept while the step stays: drag the view 400 px left.
  const ImVec2 c(app.layout().canvas.pos.x + 300, app.layout().canvas.pos.y + 200);
  host.set_mouse(c, true);
  host.render(1);
  for (int k = 1; k <= 4; ++k) host.set_mouse(ImVec2(c.x - 100.f * float(k), c.y), true), host.render(1);
  host.set_mouse(std::nullopt, false);
  host.render(2);
  const auto after_pan = app.canvas(0)->cell_rect(end);
  CHECK((!after_pan || (*after_pan)[0] < (*now)[0] - 300));
  // A step taken brings it back.
  host.press(ImGuiKey_Home);
  host.render(2);
  host.press(ImGuiKey_End);
  host.render(2);
  CHECK(app.canvas(0)->cell_rect(end));
}

TEST_CASE("visualizer classroom: stepping to a hit off the 3D canvas looks at it at the same distance",
          "[visualizer][classroom][rays]") {
  HeadlessHost host(1024, 640);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_algorithm(find_algorithm("ray-sphere-geometric"),
                             parse_json_text(find_algorithm("ray-sphere-geometric").example, "example"), Numeric::f64));
  REQUIRE(session.set_view(View::orbit3d));
  const TraceModel& m = *session.model(0);
  std::optional<std::pair<std::size_t, V3>> hit;  // the first step that records a point
  for (std::size_t s = 0; s < m.size() && !hit; ++s)
    for (std::uint32_t g = m.trace().at(s).geo_begin; g < m.trace().at(s).geo_end && !hit; ++g)
      if (m.trace().geo_at(g).kind == GeoKind::point3 && s > 0) hit = {s, item_of(m.trace(), g).at(0)};
  REQUIRE(hit);
  session.set_step(0);
  host.render(2);
  const auto* c = dynamic_cast<const OrbitCanvas*>(app.canvas(0));
  REQUIRE(c);
  for (int k = 0; k < 40 && c->screen_of(hit->second); ++k) host.press(ImGuiKey_PageUp), host.render(1);  // zoom in
  REQUIRE_FALSE(c->screen_of(hit->second));
  const double dist = c->camera().dist;
  session.set_step(hit->first);
  host.render(2);
  CHECK(c->screen_of(hit->second));
  CHECK(c->camera().dist == dist);
}

TEST_CASE("visualizer classroom: the 3D view's labels never overlap", "[visualizer][classroom][rays]") {
  HeadlessHost host(1024, 640);
  App& app = host.app();
  Session& session = app.session();
  std::size_t labels = 0, steps = 0;
  for (const char* name : {"05-triangle-crack.md", "06-far-sphere.md", "18-kd-ray-mesh.md"}) {
    REQUIRE(session.open_lesson(default_lessons_dir() / name));
    REQUIRE(session.set_view(View::orbit3d));
    const std::size_t first = name[1] == '8' ? 70185 : 0;  // lesson 18: the traversal after its build
    const std::size_t last = session.steps() - 1, stride = std::max<std::size_t>(1, (last - first) / 40);
    for (std::size_t s = first; s <= last; s += stride) {
      session.set_step(s);
      host.render(2);
      const auto* c = dynamic_cast<const OrbitCanvas*>(app.canvas(0));
      REQUIRE(c);
      const auto& r = c->label_rects();
      INFO(name << " step " << s);
      for (std::size_t i = 0; i < r.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
          CHECK((r[i][2] <= r[j][0] || r[j][2] <= r[i][0] || r[i][3] <= r[j][1] || r[j][3] <= r[i][1]));
      labels += r.size(), ++steps;
    }
  }
  CHECK(steps > 50);
  CHECK(labels > 3 * steps);  // they are there: several labels a step (273 at 57 steps)
}

TEST_CASE("visualizer classroom: --scale out of range exits 2 with one line and writes nothing", "[visualizer][classroom][cli]") {
  namespace fs = std::filesystem;
  const fs::path dir = sw::testing::scratch("scale");
  const std::string lesson = (fs::path(SW_SOURCE_DIR) / "lessons" / "01-dda-line.md").string();
  auto run = [&](const std::string& exe, const std::string& args) {
    const int rc = std::system((exe + " " + args + " 2>" + (dir / "err.txt").string() + " >/dev/null").c_str());
    std::ifstream f(dir / "err.txt");
    std::ostringstream err;
    err << f.rdbuf();
    return std::pair(WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, err.str());
  };
  const std::string render =
      std::string(SW_STEPWISE_EXE) + " render --lesson " + lesson + " --size 400x260 --out " + (dir / "x.png").string();
  for (const char* bad : {"0.5", "3.5", "0"}) {
    INFO("--scale " << bad);
    const auto [status, err] = run(render, std::string("--scale ") + bad);
    CHECK(status == 2);
    CHECK_THAT(err, Catch::Contains("--scale") && Catch::Contains("0.75 to 3"));
    CHECK(std::count(err.begin(), err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(dir / "x.png"));
  }
  const auto gui = run(SW_GUI_EXE, "--scale 9 --frames 1");  // refused before any window opens
  CHECK(gui.first == 2);
  CHECK_THAT(gui.second, Catch::Contains("--scale 9"));
  CHECK(run(render, "--scale 2 --present").first == 0);
  CHECK(fs::exists(dir / "x.png"));
}

#endif
