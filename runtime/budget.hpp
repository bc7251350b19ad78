// The work budget of trace, run, check, render and the app (docs/cli.md): the steps an input
// implies, estimated before running (Run::check_budget), and the bytes written (BudgetedStream,
// output.hpp). The defaults keep the largest accepted input within about 10 s and 1 GB on a 2-core
// machine.
#pragma once
#include <cstdint>
#include <initializer_list>
#include "input.hpp"

namespace sw {

struct Budget {
  std::uint64_t max_steps = 4'000'000;
  std::uint64_t max_output = std::uint64_t{1} << 30;
};

namespace tracer {
// The work budget of a render (docs/tracer/renderer.md#the-work-budget), in rays: 2^26, measured
// so that the largest render the default accepts takes about 10 s on this project's 2-core machine.
inline constexpr std::uint64_t kDefaultMaxRays = std::uint64_t{1} << 26;
}  // namespace tracer

namespace pipespec {
// The work budget of `scene raster` in exact and filtered modes and with --identity (docs/cli.md),
// in units of about 5 us of exact arithmetic on this machine: a triangle carried to the screen
// costs 50 (250 us: its corners, its clip and its divide in rationals), a fragment 1 (double's
// count), a pixel's exact ray cast 3. 2^21 units keep the largest accepted draw within about 10 s.
inline constexpr std::uint64_t kDefaultMaxWork = std::uint64_t{1} << 21;
inline constexpr std::uint64_t kWorkPerTriangle = 50, kWorkPerFragment = 1, kWorkPerRay = 3;
}  // namespace pipespec

// In exact, filtered and reference modes a step costs more the longer the input's exact numbers: a step counts
// 1 + (longest string) / kDigitsPerWeight against max_steps (measured on dda-grid-walk: 1.3 us a
// step at 1 character, 5.5 us at 2000, 12 us at 4000; docs/cli.md).
inline constexpr std::size_t kDigitsPerWeight = 400;
std::uint64_t step_weight(const Json& input, Numeric n);
// The longest string in an input: exact numbers are strings ("p/q", decimals).
std::size_t longest_string(const Json& j);
// A budget option's text (--max-steps, --max-output, --max-rays): an error message unless it is a
// whole number in [0, 2^62] written in decimal digits (so -1 or 2^64 cannot turn a budget off);
// empty if it is. For CLI11's Validator.
std::string budget_count_error(std::string& text);
// The product, or UINT64_MAX where it overflows.
std::uint64_t saturating_product(std::initializer_list<std::uint64_t> factors);

}  // namespace sw
