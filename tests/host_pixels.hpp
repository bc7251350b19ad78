#pragma once
// Helpers for tests that read a headless host's pixels (0xAABBGGRR, as ImGui packs them).
#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace sw::testing {

// The largest difference over the red, green and blue channels of two packed colours.
inline int channel_distance(std::uint32_t a, std::uint32_t b) {
  int d = 0;
  for (int ch = 0; ch < 3; ++ch) d = std::max(d, std::abs(int((a >> (8 * ch)) & 255) - int((b >> (8 * ch)) & 255)));
  return d;
}

// The headless host's size in the view tests: the app's default window.
constexpr int kHostW = 960, kHostH = 600;

}  // namespace sw::testing
