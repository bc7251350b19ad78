// stepwise-web: the browser host, the same App as stepwise-gui (gui_main.cpp) compiled with
// emscripten: GLFW is emscripten's JavaScript one on the page's canvas, GL is WebGL 2 through
// ImGui's OpenGL 3 backend, and the browser calls frame() once per display refresh. The data
// (lessons, scenes, meshes, fonts) is embedded in the page's file system (visualizer/web/web.cmake).
//
// The page (shell.html, pre.js) turns its URL fragment into the command line: #lesson=05&step=10
// is --lesson 05 --step 10, and any other key=value is --key value (algorithm, input, numeric,
// compare, quiz, student). A new fragment opens what it names in the running page (sw_open): no
// reload, and the name the student typed stays. Quiz answers are saved in /answers and offered as
// a download.
// For tests, the page's JavaScript can ask sw_state() for what is shown, as JSON.
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <emscripten.h>
#include <emscripten/html5.h>
#include <GLFW/glfw3.h>
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <string>
#include <vector>
#include "headless/gl_texture.hpp"
#include "host_options.hpp"
#include "panels/app.hpp"

using namespace sw;
using namespace sw::vis;

namespace {

struct Host {
  GLFWwindow* window = nullptr;
  GlTextureHost textures;
  std::unique_ptr<App> app;
  double scale = 1;   // the fonts' scale, fixed at the start
  std::string state;  // sw_state()'s last answer, alive until the next call
};
Host* host = nullptr;

// Hands a file of the page's file system to the person as a download.
EM_JS(void, offer_download, (const char* path, const char* name), {
  const data = FS.readFile(UTF8ToString(path));
  const link = document.createElement("a");
  link.href = URL.createObjectURL(new Blob([data], {type: "application/x-ndjson"}));
  link.download = UTF8ToString(name);
  document.body.appendChild(link);
  link.click();
  link.remove();
});

// The canvas follows the browser window (CSS pixels; shell.html sizes it to the whole page).
EM_BOOL on_resize(int, const EmscriptenUiEvent* e, void*) {
  if (host && host->window) glfwSetWindowSize(host->window, e->windowInnerWidth, e->windowInnerHeight);
  return EM_FALSE;
}

void frame() {
  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  host->app->frame(ImGui::GetIO().DeltaTime);
  ImGui::Render();
  int w = 0, h = 0;
  glfwGetFramebufferSize(host->window, &w, &h);
  glViewport(0, 0, w, h);
  glClearColor(0.1f, 0.1f, 0.12f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  EM_ASM(Module.swFrames = (Module.swFrames | 0) + 1);  // frames drawn: the page's test waits for the first
}

// The page's arguments (pre.js) as the host's options, with the browser's own answers directory,
// and on an error the one line the app shows.
struct PageOptions {
  HostOptions options;
  std::string error;
};
PageOptions parse_page_arguments(const std::vector<std::string>& args) {
  CLI::App cli{"stepwise-web: step through classic graphics algorithms"};
  PageOptions p;
  add_host_options(cli, p.options);
  p.options.answers_dir = "/answers";
  std::vector<const char*> argv{"stepwise-web"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    cli.parse(int(argv.size()), argv.data());
    check_scale(p.options.scale);
  } catch (const CLI::ParseError& e) {
    p.error = std::string("the page's address: ") + e.what();
  } catch (const InputError& e) {
    p.error = std::string("the page's address: ") + e.what();
  }
  return p;
}

// Opens what the options name, or the first lesson with the error shown.
void open_page(Session& session, const PageOptions& p) {
  if (!p.error.empty()) {
    session.open_first_lesson();
    session.show_error(p.error);
  } else if (!open_session(session, p.options)) {
    std::cerr << "stepwise-web: could not load: " << session.error() << '\n';
  }
}

}  // namespace

// A new fragment in the running page (pre.js): args_json is pre.js's arguments as a JSON
// array of strings. Returns 1 where only a fresh page can honour them (another --scale: the fonts
// are built at the start), else 0.
extern "C" EMSCRIPTEN_KEEPALIVE int sw_open(const char* args_json) {
  if (!host || !host->app) return 1;  // main() has not opened the app
  std::vector<std::string> args;
  const Json parsed = Json::parse(args_json, nullptr, false);
  if (parsed.is_array())
    for (const Json& a : parsed)
      if (a.is_string()) args.push_back(a.get<std::string>());
  PageOptions p = parse_page_arguments(args);
  if (p.error.empty() && p.options.scale != host->scale) return 1;
  if (p.options.student.empty()) p.options.student = host->app->session().student();  // the name typed stays
  host->app->set_presenting(p.options.present);
  host->app->session().set_budget(p.options.budget);
  open_page(host->app->session(), p);
  return 0;
}

// What the app shows, as one JSON object: the lesson file (or ""), the algorithm, the number type,
// the step shown and the trace's length, and each variable's latest value at that step as its
// lossless text (the state panel's). For the browser test (tests/web_browser.py).
extern "C" EMSCRIPTEN_KEEPALIVE const char* sw_state() {
  const Session& s = host->app->session();
  Json out = Json::object();
  out["lesson"] = s.lesson() ? s.lesson()->path.filename().string() : "";
  out["algorithm"] = s.algorithm() ? std::string(s.algorithm()->id) : "";
  out["numeric"] = std::string(numeric_name(s.numeric()));
  out["quiz"] = s.quiz();
  out["step"] = s.shown_step();
  out["steps"] = s.steps();
  out["error"] = s.error().empty() ? s.edit_error() : s.error();
  out["input"] = s.input();
  Json vars = Json::object();
  if (const TraceModel* m = s.model(0); m && s.steps())
    for (const VarState& v : m->state_at(s.shown_step())) vars[std::string(v.name)] = v.text;
  out["vars"] = std::move(vars);
  const auto [right, asked] = s.quiz_score();
  out["answered"] = asked, out["right"] = right, out["student"] = s.student();
  const Question* q = s.quiz_pending();
  out["question"] = q ? Json(std::string(quiz_type_name(q->type))) : Json();
  // Where a test can press: the quiz panel's buttons and name field, and each declared 2D handle's point on the
  // screen (from the canvas's test hook: the cell that holds it, whose square spans the cell
  // centre +- 1/2), in CSS pixels.
  Json widgets = Json::array();
  for (const WidgetMark& w : host->app->narration_marks().quiz_widgets) widgets.push_back({{"label", w.label}, {"rect", w.rect}});
  out["widgets"] = std::move(widgets);
  Json handles = Json::array();
  if (const TraceModel* m = s.model(0); m && host->app->canvas(0))
    for (const auto& p : m->handle_points()) {
      if (!p) continue;
      const Pixel c{num::floor_int((*p)[0] + 0.5), num::floor_int((*p)[1] + 0.5)};
      if (const auto r = host->app->canvas(0)->cell_rect(c))
        handles.push_back({(*r)[0] + ((*p)[0] - (double(c.x) - 0.5)) * ((*r)[2] - (*r)[0]), (*r)[1] + ((double(c.y) + 0.5) - (*p)[1]) * ((*r)[3] - (*r)[1])});
    }
  out["handles"] = std::move(handles);
  const PanelRect& c = host->app->layout().canvas;
  out["canvas"] = {c.pos.x, c.pos.y, c.right(), c.bottom()};
  host->state = out.dump();
  return host->state.c_str();
}

int main(int argc, char** argv) {
  PageOptions page = parse_page_arguments(std::vector<std::string>(argv + 1, argv + argc));
  if (page.options.student.empty()) page.options.student = "student";
  const HostOptions& o = page.options;
  if (!glfwInit()) {
    std::cerr << "stepwise-web: error: GLFW could not start\n";
    return 2;
  }
  const int width = EM_ASM_INT(return window.innerWidth), height = EM_ASM_INT(return window.innerHeight);
  host = new Host;  // lives as long as the page
  host->scale = page.error.empty() ? o.scale : 1;  // a bad --scale is reported, not used
  host->window = glfwCreateWindow(width, height, "stepwise", nullptr, nullptr);
  if (!host->window) {
    std::cerr << "stepwise-web: error: no WebGL 2 context\n";
    return 2;
  }
  glfwMakeContextCurrent(host->window);
  emscripten_set_resize_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, EM_FALSE, on_resize);
  ImGui::CreateContext();
  const theme::Fonts fonts = theme::setup_style(float(host->scale));
  ImGui_ImplGlfw_InitForOpenGL(host->window, true);
  ImGui_ImplOpenGL3_Init("#version 300 es");
  host->app = std::make_unique<App>(host->textures, fonts);
  App& app = *host->app;
  app.set_presenting(o.present);
  app.set_file_offer([](const std::filesystem::path& file) { offer_download(file.c_str(), file.filename().c_str()); });
  app.session().set_budget(o.budget);
  open_page(app.session(), page);
  emscripten_set_main_loop(frame, 0, false);  // main returns; the page calls frame() from now on
  return 0;
}
