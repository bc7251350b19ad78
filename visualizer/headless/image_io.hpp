// Writing frames: PNG (runtime/png.hpp), animated GIF through giflib. Both write to a
// temporary file renamed into place on success, so a failure leaves no partial file.
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include "png.hpp"

namespace sw::vis {

// PNG: sw::write_png (runtime/png.hpp).

class GifWriter {
 public:
  // delay_ms: display time of each frame (GIF counts in hundredths of a second).
  GifWriter(const std::filesystem::path& path, int w, int h, int delay_ms);
  ~GifWriter();
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;
  // Quantizes to 256 colours (giflib's median cut) with a palette local to the frame.
  void add_frame(const std::uint8_t* rgba);
  void commit();  // finishes the file and moves it into place
  std::size_t frames() const { return frames_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int w_, h_, delay_ms_;
  std::size_t frames_ = 0;
};

}  // namespace sw::vis
