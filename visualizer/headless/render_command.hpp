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

struct RenderOptions {
  std::string lesson, algorithm, input, numeric, compare, out, gif, size = "1280x800", view;
  std::optional<std::size_t> step, from, to;
  int delay_ms = 250;
  bool focus = false, present = false;
  double scale = 1;  // the UI scale, theme::kMinScale to theme::kMaxScale
  std::uint64_t max_steps = Budget{}.max_steps;  // the work budget (trace_io.hpp)
  std::uint64_t max_pixels = std::uint64_t{1} << 31;  // a GIF's frames x width x height
};

// "WxH" with 320 <= W, 240 <= H, both <= 4096; throws InputError naming --size otherwise.
std::pair<int, int> parse_frame_size(const std::string& size, std::string_view option = "--size");

// Adds the subcommand; main calls run_render when it was given.
CLI::App* add_render_command(CLI::App& app, RenderOptions& opts);
// Returns 0; throws InputError (one line, exit 2 in main) on bad input, writing no partial file.
int run_render(const RenderOptions& opts);

}  // namespace sw::vis
