#include "png.hpp"
#include <stb_image.h>
#include <stb_image_write.h>
#include <memory>
#include "input.hpp"
#include "output.hpp"

namespace sw {

void write_png(const std::filesystem::path& path, const std::uint8_t* pixels, int w, int h, int channels) {
  OutputFile file(path);
  struct Sink {
    std::ostream* out;
  } sink{&file.stream()};
  const int ok = stbi_write_png_to_func(
      [](void* ctx, void* data, int size) { static_cast<Sink*>(ctx)->out->write(static_cast<const char*>(data), size); }, &sink,
      w, h, channels, pixels, w * channels);
  if (!ok) throw InputError("cannot encode PNG for " + path.string());
  file.commit();
}

PngImage read_png_rgb(const std::filesystem::path& path) {
  int w = 0, h = 0, n = 0;
  std::unique_ptr<std::uint8_t, void (*)(void*)> data(stbi_load(path.string().c_str(), &w, &h, &n, 3), stbi_image_free);
  if (!data) throw InputError(path.string() + ": cannot decode the PNG (" + (stbi_failure_reason() ? stbi_failure_reason() : "?") + ")");
  PngImage out;
  out.width = w, out.height = h;
  out.rgb.assign(data.get(), data.get() + std::size_t(w) * std::size_t(h) * 3);
  return out;
}

}  // namespace sw
