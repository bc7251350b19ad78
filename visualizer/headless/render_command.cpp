#include "headless/render_command.hpp"
#include "budget.hpp"
#include <algorithm>
#include <charconv>
#include <fstream>
#include <iostream>
#include <sstream>
#include "headless/headless.hpp"
#include "headless/image_io.hpp"

namespace sw::vis {

std::pair<int, int> parse_frame_size(const std::string& s, std::string_view option) {
  const auto x = s.find('x');
  int w = 0, h = 0;
  const bool ok = x != std::string::npos && std::from_chars(s.data(), s.data() + x, w).ptr == s.data() + x &&
                  std::from_chars(s.data() + x + 1, s.data() + s.size(), h).ptr == s.data() + s.size();
  if (!ok || w < 320 || h < 240 || w > 4096 || h > 4096)
    throw InputError(std::string(option) + " '" + s + "': expected WxH with 320 <= W, 240 <= H and both <= 4096");
  return {w, h};
}

void check_frame_pixels(std::size_t frames, int w, int h, std::uint64_t max_pixels, std::string_view what) {
  // Every frame is rendered whole (frames <= 2000, pixels <= 2^24: no overflow).
  const std::uint64_t pixels = std::uint64_t(frames) * std::uint64_t(w) * std::uint64_t(h);
  if (pixels > max_pixels)
    throw InputError(std::string(what) + " would render " + std::to_string(pixels) + " pixels (" + std::to_string(frames) + " frames of " +
                     std::to_string(w) + "x" + std::to_string(h) + "), more than --max-pixels " + std::to_string(max_pixels));
}

CLI::App* add_render_command(CLI::App& app, RenderOptions& o) {
  auto* r = app.add_subcommand("render", "Render visualizer frames headless (OSMesa): a PNG, or a GIF of a step range");
  auto* lesson = r->add_option("--lesson", o.lesson, "Lesson file (lessons/*.md)");
  auto* alg = r->add_option("--algorithm", o.algorithm, "Algorithm id (see `stepwise list`)");
  auto* input = r->add_option("--input", o.input, "Input as JSON text or a file holding it");
  lesson->excludes(alg)->excludes(input);
  alg->needs(input);
  r->add_option("--numeric", o.numeric, "Number type (default: the lesson's, else double)");
  r->add_option("--compare", o.compare, "A second number type, or another algorithm of the same compare group (a reflection model), side by side");
  auto* step = r->add_option("--step", o.step, "The step to show (default: the lesson's step, else the last)")->check(CLI::Validator(budget_count_error, "STEP"));
  auto* shot = r->add_flag("--shot", o.shot, "The lesson's screenshot step (its front matter's screenshot:, else its step)")->needs(lesson)->excludes(step);
  auto* out = r->add_option("--out", o.out, "PNG file to write");
  auto* gif = r->add_option("--gif", o.gif, "Animated GIF to write: one frame per step");
  out->excludes(gif);
  shot->excludes(gif);
  r->add_option("--from", o.from, "First step of the GIF (default 0)")->needs(gif)->check(CLI::Validator(budget_count_error, "STEP"));
  r->add_option("--to", o.to, "Last step of the GIF, inclusive (default: the last step)")->needs(gif)->check(CLI::Validator(budget_count_error, "STEP"));
  r->add_option("--delay", o.delay_ms, "Milliseconds per GIF frame")->check(CLI::Range(10, 10000))->needs(gif);
  r->add_option("--size", o.size, "Frame size WxH (default 1280x800)");
  r->add_option("--scale", o.scale, "UI scale for fonts and spacing, 0.75 to 3 (default 1)");
  r->add_flag("--present", o.present, "Presentation mode: big fonts, no edit rows or state panel");
  r->add_flag("--focus", o.focus, "Zoom the view onto the step (the image view: onto the input itself)");
  r->add_option("--max-steps", o.max_steps, "Refuse inputs that imply more steps (default 4000000)")->check(CLI::Validator(budget_count_error, "COUNT"));
  r->add_option("--max-pixels", o.max_pixels, "Refuse a GIF of more frames x width x height (default " + std::to_string(kDefaultGifPixels) + ")")->check(CLI::Validator(budget_count_error, "COUNT"));
  r->add_option("--view", o.view, "The view to show: one the algorithm declares (plane2d, orbit3d, table, image, plot, tree, lobe; default the lesson's, else the first)");
  return r;
}

int run_render(const RenderOptions& o) {
  if (o.lesson.empty() == o.algorithm.empty()) throw InputError("render: give --lesson FILE or --algorithm ALG --input JSON");
  if (o.out.empty() == o.gif.empty()) throw InputError("render: give --out frame.png or --gif anim.gif");
  const auto [w, h] = parse_frame_size(o.size);
  check_scale(o.scale);
  // Check everything that can be checked before starting GL.
  std::optional<Lesson> lesson;
  const Algorithm* alg = nullptr;
  Json input;
  if (!o.lesson.empty()) {
    lesson = load_lesson(o.lesson);
    alg = lesson->algorithm;
    input = lesson->input;
  } else {
    alg = &find_algorithm(o.algorithm);
    input = read_input_arg(o.input);
  }
  const Numeric numeric = !o.numeric.empty() ? parse_numeric_for(*alg, o.numeric) : lesson ? lesson->numeric : parse_numeric_for(*alg, "double");
  Comparison compare = lesson ? lesson->compare : Comparison{};
  if (!o.compare.empty()) compare = parse_comparison(*alg, o.compare, numeric);

  std::optional<View> view;
  if (!o.view.empty()) {
    view = parse_view(o.view);
    if (!view || std::find(alg->views.begin(), alg->views.end(), *view) == alg->views.end()) {
      std::string declared;
      for (View d : alg->views) declared += (declared.empty() ? "" : ", ") + std::string(view_name(d));
      throw InputError("--view '" + o.view + "': " + std::string(alg->id) + " declares " + declared);
    }
  }

  Budget budget;
  budget.max_steps = o.max_steps;
  HeadlessHost host(w, h, default_lessons_dir(), float(o.scale));
  App& app = host.app();
  Session& session = app.session();
  session.set_budget(budget);
  app.set_presenting(o.present);
  const bool ok = lesson ? session.open_lesson(o.lesson) : session.open_algorithm(*alg, input, numeric, compare);
  if (!ok) throw InputError(session.error());
  // A lesson with other number types keeps its narration: each run narrates its own steps.
  if (lesson && (!o.numeric.empty() || !o.compare.empty()) && !session.set_numerics(numeric, compare)) throw InputError(session.error());
  if (view) session.set_view(*view);
  const std::size_t last = session.steps() - 1;
  auto check_step = [&](std::size_t s, const char* what) {
    if (s > last) throw InputError(std::string(what) + " " + std::to_string(s) + " is past the last step (" + std::to_string(last) + ")");
  };

  if (!o.out.empty()) {
    const std::size_t step = o.step                                    ? *o.step
                             : lesson && o.shot && lesson->screenshot_step ? *lesson->screenshot_step
                             : lesson && lesson->start_step              ? lesson->start_step
                                                                         : last;
    check_step(step, "--step");
    session.set_step(step);
    if (o.focus) app.jump_and_focus(step);
    write_png(o.out, host.render(3).data(), w, h);
    std::cerr << "stepwise: wrote step " << step << " to " << o.out << '\n';
    return 0;
  }
  const std::size_t from = o.from.value_or(0), to = o.to.value_or(last);
  check_step(from, "--from");
  check_step(to, "--to");
  if (from > to) throw InputError("--from " + std::to_string(from) + " is after --to " + std::to_string(to));
  constexpr std::size_t kMaxFrames = 2000;
  if (to - from + 1 > kMaxFrames) throw InputError("the GIF would have " + std::to_string(to - from + 1) + " frames; at most " + std::to_string(kMaxFrames));
  check_frame_pixels(to - from + 1, w, h, o.max_pixels, "the GIF");
  GifWriter gif(o.gif, w, h, o.delay_ms);
  for (std::size_t s = from; s <= to; ++s) {
    session.set_step(s);
    gif.add_frame(host.render(s == from ? 3 : 2).data());
  }
  gif.commit();
  std::cerr << "stepwise: wrote " << gif.frames() << " frames (steps " << from << ".." << to << ") to " << o.gif << '\n';
  return 0;
}

}  // namespace sw::vis
