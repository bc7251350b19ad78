#include "panels/pixel_layer.hpp"
#include <algorithm>
#include <cmath>

namespace sw::vis {

bool CellWindow::contains(const CellWindow& o) const {
  return k == o.k && o.x0 >= x0 && o.y0 >= y0 && o.x0 + std::int64_t(o.w) * k <= x0 + std::int64_t(w) * k &&
         o.y0 + std::int64_t(o.h) * k <= y0 + std::int64_t(h) * k;
}

WorldRect CellWindow::world() const {
  return {double(x0) - 0.5, double(y0) - 0.5, double(x0 + std::int64_t(w) * k) - 0.5, double(y0 + std::int64_t(h) * k) - 0.5};
}

std::uint32_t plot_colour(std::size_t step, std::size_t last) {
  // Early pixels are blue, late ones amber, through violet: all bright against the dark canvas.
  const float t = last ? float(step) / float(last) : 0.f;
  const float stops[3][3] = {{66, 135, 245}, {176, 102, 235}, {250, 170, 50}};
  const int seg = t < 0.5f ? 0 : 1;
  const float f = t < 0.5f ? t * 2 : (t - 0.5f) * 2;
  std::uint32_t c = 0xff000000u;
  for (int ch = 0; ch < 3; ++ch) {
    const float v = stops[seg][ch] + (stops[seg + 1][ch] - stops[seg][ch]) * f;
    c |= std::uint32_t(std::lround(v)) << (8 * ch);
  }
  return c;
}

PixelLayer::~PixelLayer() {
  if (tex_) host_->destroy(tex_);
}

bool PixelLayer::prepare(const std::shared_ptr<const TraceModel>& model, const WorldRect& visible, double scale, std::size_t step) {
  last_texels_ = 0;
  if (!model || model->plots().empty()) return false;
  // Power-of-two blocks of cells per texel, so that the texture never exceeds the screen; when
  // zoomed out, a texel covers at least two screen pixels so that a line of pixels stays visible.
  int k = 1;
  while (k < (1 << 24) && scale < 1.0 && double(k) * scale < 2.0) k *= 2;
  auto cell_lo = [&](double v) { return static_cast<std::int64_t>(std::floor((v + 0.5) / k)) * k; };
  CellWindow need;
  need.k = k;
  need.x0 = cell_lo(visible.x0), need.y0 = cell_lo(visible.y0);
  need.w = int(std::min<std::int64_t>(4096, (cell_lo(visible.x1) - need.x0) / k + 1));
  need.h = int(std::min<std::int64_t>(4096, (cell_lo(visible.y1) - need.y0) / k + 1));
  if (model != model_ || !win_.contains(need)) {
    model_ = model;
    // A margin of half the view on each side, so small pans do not rebuild.
    CellWindow win = need;
    const int mx = need.w / 2 + 1, my = need.h / 2 + 1;
    win.x0 -= std::int64_t(mx) * k, win.y0 -= std::int64_t(my) * k;
    win.w = std::min(4096, need.w + 2 * mx), win.h = std::min(4096, need.h + 2 * my);
    rebuild(win);
  }
  recolour(std::min(step, model_->last()));
  upload_dirty();
  return true;
}

void PixelLayer::rebuild(const CellWindow& win) {
  win_ = win;
  first_step_.assign(std::size_t(win.w) * win.h, kNoStep);
  rgba_.assign(first_step_.size(), 0);
  for (const PlotEvent& e : model_->plots()) {
    const std::int64_t u = e.cell.x - win.x0, r = e.cell.y - win.y0;
    if (u < 0 || r < 0 || u >= std::int64_t(win.w) * win.k || r >= std::int64_t(win.h) * win.k) continue;
    const std::size_t t = std::size_t(win.h - 1 - r / win.k) * win.w + std::size_t(u / win.k);
    first_step_[t] = std::min(first_step_[t], e.step);
  }
  if (!tex_ || tex_w_ != win.w || tex_h_ != win.h) {
    if (tex_) host_->destroy(tex_);
    tex_ = host_->create(win.w, win.h);
    tex_w_ = win.w, tex_h_ = win.h;
  }
  shown_ = false;
}

void PixelLayer::recolour(std::size_t step) {
  const std::size_t last = model_->last();
  auto colour_of = [&](std::uint32_t first) {
    if (first > step) return 0u;
    const std::uint32_t own = model_->step_rgba(first);  // a colour the step records, else the plot order's
    return own ? own : plot_colour(first, last);
  };
  const std::size_t lo = shown_ ? model_->plots_through(std::min(step, shown_step_)) : 0;
  const std::size_t hi = shown_ ? model_->plots_through(std::max(step, shown_step_)) : model_->plots().size();
  if (shown_ && lo == hi) {
    shown_step_ = step;
    return;
  }
  if (!shown_ || hi - lo >= rgba_.size()) {  // cheaper to recolour every texel
    for (std::size_t t = 0; t < rgba_.size(); ++t) rgba_[t] = colour_of(first_step_[t]);
    dirty_x0_ = 0, dirty_y0_ = 0, dirty_x1_ = win_.w - 1, dirty_y1_ = win_.h - 1;
    last_texels_ = rgba_.size();
  } else {
    const auto events = model_->plots().subspan(lo, hi - lo);
    for (const PlotEvent& e : events) {
      const std::int64_t u = e.cell.x - win_.x0, r = e.cell.y - win_.y0;
      if (u < 0 || r < 0 || u >= std::int64_t(win_.w) * win_.k || r >= std::int64_t(win_.h) * win_.k) continue;
      const int tx = int(u / win_.k), ty = win_.h - 1 - int(r / win_.k);
      const std::size_t t = std::size_t(ty) * win_.w + tx;
      rgba_[t] = colour_of(first_step_[t]);
      if (dirty_x1_ < dirty_x0_) dirty_x0_ = dirty_x1_ = tx, dirty_y0_ = dirty_y1_ = ty;
      dirty_x0_ = std::min(dirty_x0_, tx), dirty_x1_ = std::max(dirty_x1_, tx);
      dirty_y0_ = std::min(dirty_y0_, ty), dirty_y1_ = std::max(dirty_y1_, ty);
    }
    last_texels_ = events.size();
  }
  shown_step_ = step;
  shown_ = true;
}

void PixelLayer::upload_dirty() {
  if (dirty_x1_ < dirty_x0_) return;
  host_->update(tex_, dirty_x0_, dirty_y0_, dirty_x1_ - dirty_x0_ + 1, dirty_y1_ - dirty_y0_ + 1,
                rgba_.data() + std::size_t(dirty_y0_) * win_.w + dirty_x0_, win_.w);
  dirty_x0_ = 0, dirty_y0_ = 0, dirty_x1_ = -1, dirty_y1_ = -1;
}

}  // namespace sw::vis
