// `stepwise lesson export LESSON --html DIR`: a self-contained page that steps through a lesson
// (DIR/index.html and one PNG per step in DIR/frames/), each frame rendered as `stepwise render
// --lesson LESSON --step N --size WxH` renders it (docs/lesson-export.md).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include "trace_io.hpp"

namespace sw::vis {

// The work budget of a page in frames x width x height, measured as the GIF's (render_command.hpp):
// a frame's pixel costs about 120 ns here, rendered and then compressed to PNG.
inline constexpr std::uint64_t kDefaultPagePixels = std::uint64_t{1} << 26;

struct ExportOptions {
  std::string lesson, html_dir, size = "1280x800";
  std::optional<std::size_t> from, to;
  std::uint64_t max_steps = Budget{}.max_steps;  // the work budget (trace_io.hpp)
  std::uint64_t max_pixels = kDefaultPagePixels;
};

// A page holds at most this many frames; a longer lesson needs --from/--to.
inline constexpr std::size_t kMaxPageFrames = 600;

// Returns 0. Throws InputError (one line; exit 2 in main) on a missing or bad lesson, a bad size or
// range, too many frames, or a DIR that cannot be written or is something other than an earlier
// export. The page is built in a temporary sibling directory and renamed to DIR when complete, so
// DIR is never left half-written.
int run_lesson_export(const ExportOptions& opts);

}  // namespace sw::vis
