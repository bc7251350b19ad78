#include "headless/image_io.hpp"
#include <gif_lib.h>
#include <string>
#include <vector>
#include "output.hpp"

namespace sw::vis {

struct GifWriter::Impl {
  explicit Impl(const std::filesystem::path& p) : file(p), target(p) {}
  OutputFile file;
  std::filesystem::path target;
  GifFileType* gif = nullptr;
  void fail(const char* what, int err) const {
    throw InputError(std::string("cannot write GIF ") + target.string() + ": " + what + " (" + (GifErrorString(err) ? GifErrorString(err) : "?") + ")");
  }
};

GifWriter::GifWriter(const std::filesystem::path& path, int w, int h, int delay_ms)
    : impl_(std::make_unique<Impl>(path)), w_(w), h_(h), delay_ms_(delay_ms) {
  int err = 0;
  impl_->gif = EGifOpen(&impl_->file.stream(), [](GifFileType* g, const GifByteType* data, int n) {
    auto* out = static_cast<std::ostream*>(g->UserData);
    out->write(reinterpret_cast<const char*>(data), n);
    return out->good() ? n : 0;
  }, &err);
  if (!impl_->gif) impl_->fail("open", err);
  EGifSetGifVersion(impl_->gif, true);
  if (EGifPutScreenDesc(impl_->gif, w, h, 8, 0, nullptr) == GIF_ERROR) impl_->fail("screen", impl_->gif->Error);
  // Loop forever (the NETSCAPE2.0 application extension), as slides expect.
  unsigned char app[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
  unsigned char loop[] = {1, 0, 0};
  if (EGifPutExtensionLeader(impl_->gif, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(impl_->gif, sizeof app, app) == GIF_ERROR ||
      EGifPutExtensionBlock(impl_->gif, sizeof loop, loop) == GIF_ERROR || EGifPutExtensionTrailer(impl_->gif) == GIF_ERROR)
    impl_->fail("loop extension", impl_->gif->Error);
}

GifWriter::~GifWriter() {
  if (impl_->gif) {
    int err = 0;
    EGifCloseFile(impl_->gif, &err);  // the OutputFile then removes the unfinished temporary
  }
}

void GifWriter::add_frame(const std::uint8_t* rgba) {
  const std::size_t n = std::size_t(w_) * h_;
  std::vector<GifByteType> r(n), g(n), b(n), index(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = rgba[4 * i], g[i] = rgba[4 * i + 1], b[i] = rgba[4 * i + 2];
  int colours = 256;
  GifColorType palette[256];
  if (GifQuantizeBuffer(unsigned(w_), unsigned(h_), &colours, r.data(), g.data(), b.data(), index.data(), palette) == GIF_ERROR)
    impl_->fail("quantize", 0);
  ColorMapObject* map = GifMakeMapObject(256, palette);
  GraphicsControlBlock gcb{DISPOSE_DO_NOT, false, (delay_ms_ + 5) / 10, NO_TRANSPARENT_COLOR};
  GifByteType ext[4];
  const std::size_t len = EGifGCBToExtension(&gcb, ext);
  const bool ok = EGifPutExtension(impl_->gif, GRAPHICS_EXT_FUNC_CODE, int(len), ext) != GIF_ERROR &&
                  EGifPutImageDesc(impl_->gif, 0, 0, w_, h_, false, map) != GIF_ERROR &&
                  EGifPutLine(impl_->gif, index.data(), int(n)) != GIF_ERROR;
  GifFreeMapObject(map);
  if (!ok) impl_->fail("frame", impl_->gif->Error);
  ++frames_;
}

void GifWriter::commit() {
  int err = 0;
  GifFileType* gif = impl_->gif;
  impl_->gif = nullptr;
  if (EGifCloseFile(gif, &err) == GIF_ERROR) impl_->fail("close", err);
  impl_->file.commit();
}

}  // namespace sw::vis
