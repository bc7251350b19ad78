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
#include "budget.hpp"
#include "data_root.hpp"
#include "headless/gl_texture.hpp"
#include "headless/image_io.hpp"

using namespace sw;
using namespace sw::vis;
using Clock = std::chrono::steady_clock;

namespace {

struct Options {
  std::string lesson, algorithm, input, numeric, compare, screenshot, size = "1280x800", answers_dir, student;
  std::optional<std::size_t> step;
  int frames = 0, bench_scrub = 0;
  double scale = 1;
  bool present = false, quiz = false;
  Budget budget;
};

// Opens what the options ask for; failures show in the app (and are returned for the exit code).
bool open(Session& session, const Options& o) {
  if (o.bench_scrub) {
    // 499 997 pixels: 1 000 001 steps of the DDA line.
    return session.open_algorithm(find_algorithm("dda-line"), parse_json_text(R"({"p0":[0.5,0.25],"p1":[499997.5,123456.25]})", "bench"), Numeric::f64);
  }
  if (o.algorithm.empty()) {
    if (!(o.lesson.empty() ? session.open_first_lesson() : session.open_lesson(o.lesson))) return false;
  }
  if (!o.algorithm.empty() || !o.numeric.empty() || !o.compare.empty()) {
    try {
      // --algorithm with its --input (or example); or the lesson's run in other number types.
      const TraceModel* m = session.model(0);
      const Algorithm& alg = !o.algorithm.empty() || !m ? find_algorithm(o.algorithm.empty() ? "dda-line" : o.algorithm) : m->algorithm();
      const Json input = !o.input.empty() ? read_input_arg(o.input) : m && &m->algorithm() == &alg ? m->input() : parse_json_text(alg.example, "example");
      const Numeric n = !o.numeric.empty() ? parse_numeric_for(alg, o.numeric) : m && &m->algorithm() == &alg ? m->numeric() : parse_numeric_for(alg, "double");
      Comparison cmp;
      if (!o.compare.empty()) cmp = parse_comparison(alg, o.compare, n);
      if (!session.open_algorithm(alg, input, n, cmp)) return false;
    } catch (const InputError& e) {
      session.show_error(e.what());
      return false;
    }
  }
  if (!o.answers_dir.empty()) {
    const char* user = std::getenv("USER");
    session.save_answers_in(o.answers_dir, !o.student.empty() ? o.student : user && *user ? user : "student");
  }
  if (o.quiz && !session.set_quiz(true)) return false;
  if (o.step) session.set_step(*o.step);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const auto t_start = Clock::now();
  CLI::App cli{"stepwise-gui: step through classic graphics algorithms"};
  cli.set_version_flag("--version", "stepwise-gui " SW_VERSION "\ndata: " + data_root().string());
  Options o;
  auto* lesson = cli.add_option("--lesson", o.lesson, "Lesson file (default: the first lesson)");
  auto* alg = cli.add_option("--algorithm", o.algorithm, "Algorithm id");
  cli.add_option("--input", o.input, "Input as JSON text or a file holding it");
  lesson->excludes(alg);
  cli.add_option("--numeric", o.numeric, "Number type");
  cli.add_option("--compare", o.compare, "A second number type, or another algorithm of the same compare group (a reflection model), side by side");
  cli.add_option("--step", o.step, "Start at this step")->check(CLI::Validator(budget_count_error, "STEP"));
  cli.add_option("--max-steps", o.budget.max_steps, "Refuse inputs that imply more steps (default 4000000)")->check(CLI::Validator(budget_count_error, "COUNT"));
  cli.add_option("--size", o.size, "Window size WxH");
  cli.add_option("--scale", o.scale, "UI scale for fonts and spacing, 0.75 to 3 (a projector: 1.5 to 2)");
  cli.add_flag("--present", o.present, "Start in presentation mode (P toggles it)");
  cli.add_flag("--quiz", o.quiz, "Start the lesson in quiz mode (Q toggles it)")->excludes(alg);
  cli.add_option("--answers-dir", o.answers_dir, "Save quiz answers as they are given, in DIR/<lesson>.jsonl (stepwise quiz grades them)");
  cli.add_option("--student", o.student, "The name saved with the answers (default: $USER)");
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
