// stepwise-web: the browser host, the same App as stepwise-gui (gui_main.cpp) compiled with
// emscripten: GLFW is emscripten's JavaScript one on the page's canvas, GL is WebGL 2 through
// ImGui's OpenGL 3 backend, and the browser calls frame() once per display refresh. The data
// (lessons, scenes, meshes, fonts) is embedded in the page's file system (visualizer/web/web.cmake).
//
// The page (shell.html, pre.js) turns its URL fragment into the command line: #lesson=05&step=10
// is --lesson 05 --step 10, and any other key=value is --key value (algorithm, input, numeric,
// compare, quiz, student). Quiz answers are saved in /answers and offered as a download.
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

}  // namespace

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
  CLI::App cli{"stepwise-web: step through classic graphics algorithms"};
  HostOptions o;
  add_host_options(cli, o);
  o.answers_dir = "/answers", o.student = "student";
  std::string bad_arguments;
  try {
    cli.parse(argc, argv);
    check_scale(o.scale);
  } catch (const CLI::ParseError& e) {
    bad_arguments = std::string("the page's address: ") + e.what();
  } catch (const InputError& e) {
    bad_arguments = std::string("the page's address: ") + e.what();
  }
  if (!glfwInit()) {
    std::cerr << "stepwise-web: error: GLFW could not start\n";
    return 2;
  }
  const int width = EM_ASM_INT(return window.innerWidth), height = EM_ASM_INT(return window.innerHeight);
  host = new Host;  // lives as long as the page
  host->window = glfwCreateWindow(width, height, "stepwise", nullptr, nullptr);
  if (!host->window) {
    std::cerr << "stepwise-web: error: no WebGL 2 context\n";
    return 2;
  }
  glfwMakeContextCurrent(host->window);
  emscripten_set_resize_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, EM_FALSE, on_resize);
  ImGui::CreateContext();
  const theme::Fonts fonts = theme::setup_style(float(o.scale));
  ImGui_ImplGlfw_InitForOpenGL(host->window, true);
  ImGui_ImplOpenGL3_Init("#version 300 es");
  host->app = std::make_unique<App>(host->textures, fonts);
  App& app = *host->app;
  app.set_presenting(o.present);
  app.set_file_offer([](const std::filesystem::path& file) { offer_download(file.c_str(), file.filename().c_str()); });
  Session& session = app.session();
  session.set_budget(o.budget);
  if (!bad_arguments.empty()) {
    session.open_first_lesson();
    session.show_error(bad_arguments);
  } else if (!open_session(session, o)) {
    std::cerr << "stepwise-web: could not load: " << session.error() << '\n';
  }
  emscripten_set_main_loop(frame, 0, false);  // main returns; the page calls frame() from now on
  return 0;
}
