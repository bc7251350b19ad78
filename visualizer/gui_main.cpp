// stepwise-gui: the window host (GLFW + ImGui's GL3 backend).
//   stepwise-gui [--lesson FILE | --algorithm ALG --input JSON] [--numeric M] [--compare M2]
//                [--step N] [--size WxH] [--scale S] [--present] [--frames N --screenshot FILE]
// With no arguments it opens the first lesson of lessons/manifest.txt. --frames N renders N frames
// and exits (0 if the lesson or algorithm loaded, 2 if not: the app then shows why).
// Hidden: --bench-scrub K renders K frames of a 10^6-step trace, jumping to random steps.
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <GLFW/glfw3.h>
#include <CLI/CLI.hpp>
#include <cfloat>
#include <cstdlib>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include "panels/app.hpp"
#include "data_root.hpp"
#include "host_options.hpp"
#include "headless/gl_texture.hpp"
#include "headless/image_io.hpp"

using namespace sw;
using namespace sw::vis;
using Clock = std::chrono::steady_clock;

namespace {

struct Options : HostOptions {
  std::string screenshot, size = "1280x800";
  int frames = 0, bench_scrub = 0;
};

bool open(Session& session, const Options& o) {
  if (o.bench_scrub) {
    // 499 997 pixels: 1 000 001 steps of the DDA line.
    return session.open_algorithm(find_algorithm("dda-line"), parse_json_text(R"({"p0":[0.5,0.25],"p1":[499997.5,123456.25]})", "bench"), Numeric::f64);
  }
  return open_session(session, o);
}

}  // namespace

int main(int argc, char** argv) {
  const auto t_start = Clock::now();
  CLI::App cli{"stepwise-gui: step through classic graphics algorithms"};
  cli.set_version_flag("--version", "stepwise-gui " SW_VERSION "\ndata: " + data_root().string());
  Options o;
  add_host_options(cli, o);
  cli.add_option("--size", o.size, "Window size WxH");
  cli.add_option("--frames", o.frames, "Render this many frames, then exit")->check(CLI::Range(1, 100000));
  cli.add_option("--screenshot", o.screenshot, "With --frames: write the last frame to this PNG");
  cli.add_option("--bench-scrub", o.bench_scrub, "")->group("");  // hidden benchmark
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "stepwise-gui: error: " << e.what() << '\n';
    return 2;
  }
  int w = 1280, h = 800;
  if (std::sscanf(o.size.c_str(), "%dx%d", &w, &h) != 2 || w < 320 || h < 240) {
    std::cerr << "stepwise-gui: error: --size '" << o.size << "': expected WxH\n";
    return 2;
  }
  try {
    check_scale(o.scale);
  } catch (const InputError& e) {
    std::cerr << "stepwise-gui: error: " << e.what() << '\n';
    return 2;
  }
  if (!glfwInit()) {
    std::cerr << "stepwise-gui: error: no display (GLFW could not start); try `stepwise render` or xvfb-run\n";
    return 2;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 2);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(w, h, "stepwise", nullptr, nullptr);
  if (!window) {
    std::cerr << "stepwise-gui: error: could not open an OpenGL 3.2 window\n";
    glfwTerminate();
    return 2;
  }
  glfwMakeContextCurrent(window);
  const auto t_window = Clock::now();
  const bool timed = o.frames > 0 || o.bench_scrub > 0;
  glfwSwapInterval(timed ? 0 : 1);
  ImGui::CreateContext();
  const theme::Fonts fonts = theme::setup_style(float(o.scale));
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 150");
  int status = 0;
  {
    GlTextureHost textures;
    App app(textures, fonts);
    Session& session = app.session();
    session.set_budget(o.budget);
    app.set_presenting(o.present);
    const bool loaded = open(session, o);
    if (!loaded) std::cerr << "stepwise-gui: could not load: " << session.error() << '\n', status = 2;
    std::mt19937_64 rng(7);
    const int total = o.bench_scrub ? o.bench_scrub + 1 : o.frames;
    Clock::time_point t_bench;
    std::vector<std::uint8_t> shot;
    // Idle, the loop sleeps until an event: it redraws at full rate only while something moves
    // (playback, a held mouse button: drags) and for a few frames after each event, in which
    // ImGui settles (hover, rows measured a frame late). A wake-up every 0.5 s without events
    // still draws one frame: tooltips and the text caret have timers. docs/visualizer.md.
    constexpr double kIdleWait = 0.5;
    int settle = 3;
    for (int frame = 0; !glfwWindowShouldClose(window) && (total == 0 || frame < total); ++frame) {
      if (o.bench_scrub && frame == 1) t_bench = Clock::now();
      if (o.bench_scrub && session.steps()) session.set_step(rng() % session.steps());
      if (timed || app.animating() || ImGui::IsAnyMouseDown() || settle > 0) {
        glfwPollEvents();
        --settle;
      } else {
        const auto t0 = Clock::now();
        glfwWaitEventsTimeout(kIdleWait);
        if (Clock::now() - t0 < std::chrono::duration<double>(0.9 * kIdleWait)) settle = 3;  // woken by an event
      }
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      if (timed) ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);  // scripted frames: no hover
      ImGui::NewFrame();
      app.frame(ImGui::GetIO().DeltaTime);
      ImGui::Render();
      int fw = 0, fh = 0;
      glfwGetFramebufferSize(window, &fw, &fh);
      glViewport(0, 0, fw, fh);
      glClearColor(0.1f, 0.1f, 0.12f, 1.f);
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (!o.screenshot.empty() && frame == total - 1) {
        shot.resize(std::size_t(fw) * fh * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, fw, fh, GL_RGBA, GL_UNSIGNED_BYTE, shot.data());
        std::vector<std::uint8_t> flipped(shot.size());
        for (int y = 0; y < fh; ++y) std::copy_n(&shot[std::size_t(fh - 1 - y) * fw * 4], std::size_t(fw) * 4, &flipped[std::size_t(y) * fw * 4]);
        for (std::size_t i = 3; i < flipped.size(); i += 4) flipped[i] = 255;
        try {
          write_png(o.screenshot, flipped.data(), fw, fh);
          std::cerr << "stepwise-gui: wrote " << o.screenshot << '\n';
        } catch (const InputError& e) {
          std::cerr << "stepwise-gui: error: " << e.what() << '\n';
          status = 2;
        }
      }
      glfwSwapBuffers(window);
      if (frame == 0 && timed) {
        glFinish();
        const auto ms = [](auto d) { return std::chrono::duration<double, std::milli>(d).count(); };
        std::cerr << "stepwise-gui: first frame " << ms(Clock::now() - t_start) << " ms after start, " << ms(Clock::now() - t_window)
                  << " ms after the window opened (" << ms(t_window - t_start) << " ms for GLFW and the GL context); " << session.steps()
                  << " steps\n";
      }
    }
    if (o.bench_scrub) {
      glFinish();
      const double s = std::chrono::duration<double>(Clock::now() - t_bench).count();
      std::printf("bench-scrub: %d frames jumping to random steps of a %zu-step trace: %.1f fps (%.2f ms/frame)\n", o.bench_scrub,
                  session.steps(), o.bench_scrub / s, 1000 * s / o.bench_scrub);
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
