// `stepwise lesson export LESSON --html DIR`: the browser page (the whole app, scripts/web.sh) opened
// on the lesson, carrying the lesson's own files: DIR/index.html, one file to hand to a class.
// `--frames DIR`: a flip-book that steps through a lesson (DIR/index.html and one PNG per step in
// DIR/frames/), each frame rendered as `stepwise render --lesson LESSON --step N --size WxH`
// renders it (docs/lesson-export.md).
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include "trace_io.hpp"

namespace sw::vis {

// The work budget of a page in frames x width x height, measured as the GIF's (render_command.hpp):
// a frame's pixel costs about 120 ns here, rendered and then compressed to PNG.
inline constexpr std::uint64_t kDefaultPagePixels = std::uint64_t{1} << 26;

struct ExportOptions {
  std::string lesson, html_dir, frames_dir, size = "1280x800";
  std::optional<std::size_t> from, to;
  std::uint64_t max_steps = Budget{}.max_steps;  // the work budget (trace_io.hpp)
  std::uint64_t max_pixels = kDefaultPagePixels;
};

// A page holds at most this many frames; a longer lesson needs --from/--to.
inline constexpr std::size_t kMaxPageFrames = 600;

// Returns 0. Throws InputError (one line; exit 2 in main) on a missing or bad lesson, a bad size or
// range, too many frames, a browser page not built, or a DIR that cannot be written or is something
// other than an earlier export. The page is built in a temporary sibling directory and renamed to DIR
// when complete, so DIR is never left half-written.
int run_lesson_export(const ExportOptions& opts);

// Where `--html` finds the browser page that scripts/web.sh builds: out/web/stepwise.html under the
// data root (an install keeps the source tree's layout).
std::filesystem::path web_page_file();

}  // namespace sw::vis
