// `stepwise render`: frames of the visualizer without a window, through the OSMesa host.
//   stepwise render (--lesson FILE | --algorithm ALG --input JSON) [--numeric M] [--compare M2]
//                   [--step N] [--view V] [--focus] --out frame.png [--size WxH] [--scale S] [--present]
//   stepwise render ... --gif out.gif [--from N --to M] [--delay ms]
#pragma once
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <string_view>
#include "trace_io.hpp"

namespace sw::vis {

// The work budget of a GIF in frames x width x height, measured so that the largest the default
// accepts takes about 10 s here (docs/visualizer.md): a GIF frame's pixel costs about 45 ns.
inline constexpr std::uint64_t kDefaultGifPixels = std::uint64_t{1} << 27;
// Throws InputError naming --max-pixels when frames x w x h exceeds max_pixels.
void check_frame_pixels(std::size_t frames, int w, int h, std::uint64_t max_pixels, std::string_view what);

struct RenderOptions {
  std::string lesson, algorithm, input, numeric, compare, out, gif, size = "1280x800", view;
  std::optional<std::size_t> step, from, to;
  int delay_ms = 250;
  bool focus = false, present = false, shot = false;  // shot: the lesson's screenshot step
  double scale = 1;  // the UI scale, theme::kMinScale to theme::kMaxScale
  std::uint64_t max_steps = Budget{}.max_steps;  // the work budget (trace_io.hpp)
  std::uint64_t max_pixels = kDefaultGifPixels;  // a GIF's frames x width x height
};

// "WxH" with 320 <= W, 240 <= H, both <= 4096; throws InputError naming --size otherwise.
std::pair<int, int> parse_frame_size(const std::string& size, std::string_view option = "--size");

// Adds the subcommand; main calls run_render when it was given.
CLI::App* add_render_command(CLI::App& app, RenderOptions& opts);
// Returns 0; throws InputError (one line, exit 2 in main) on bad input, writing no partial file.
int run_render(const RenderOptions& opts);

}  // namespace sw::vis
