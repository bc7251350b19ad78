// PNG files through stb: writing to a temporary file renamed into place on success (so a failure
// leaves no partial file), and reading RGB texels for the ray tracer's image textures.
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

namespace sw {

// rgba: top-down rows of w*4 bytes (channels = 4), or rgb rows of w*3 bytes (channels = 3).
// Throws InputError when the file cannot be written.
void write_png(const std::filesystem::path& path, const std::uint8_t* pixels, int w, int h, int channels = 4);

struct PngImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // top-down rows of width*3 bytes
};
// Throws InputError naming the file when it cannot be read or decoded.
PngImage read_png_rgb(const std::filesystem::path& path);

}  // namespace sw
