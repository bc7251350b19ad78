#include "panels/image_view.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include "panels/theme.hpp"

namespace sw::vis {
namespace {

constexpr std::size_t kRingedAtMost = 400;               // disagreements ringed so single ones show
constexpr float kShadeTolerance = 1.f / 255;             // a shaded sample differs when it would show

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::uint32_t rgba(ImU32 c) { return c; }  // IM_COL32 is RGBA in memory order already

}  // namespace

int SweepImage::disagreement(std::size_t k) const {
  const bool a = !std::isnan(mode[k]), e = !std::isnan(exact[k]);
  if (a != e) return a ? 1 : -1;
  if (!a || !shaded || std::fabs(mode[k] - exact[k]) <= kShadeTolerance) return 0;
  return mode[k] > exact[k] ? 1 : -1;
}

SweepImage sweep_image(const TraceModel& m, SweepGrid grid, bool lobe) {
  SweepImage img;
  const Algorithm& alg = m.algorithm();
  const SweepInfo& sweep = lobe ? alg.lobe : alg.sweep;
  auto run = [&](const Run& r, std::vector<float>& out) { lobe ? r.lobe(grid, out) : r.sweep(grid, out); };
  grid.inputs = m.numeric() == Numeric::f32 ? Numeric::f32 : Numeric::f64;
  img.grid = grid;
  img.shaded = sweep.shaded;
  const auto& ns = alg.numerics;
  img.reference = std::find(ns.begin(), ns.end(), Numeric::exact) == ns.end() && std::find(ns.begin(), ns.end(), Numeric::reference) != ns.end()
                      ? Numeric::reference : Numeric::exact;
  if (!sweep) return img;
  auto t0 = std::chrono::steady_clock::now();
  run(m.run(), img.mode);
  img.mode_ms = ms_since(t0);
  if (m.numeric() == img.reference) {
    img.exact = img.mode;
  } else {
    t0 = std::chrono::steady_clock::now();
    run(m.run().in(img.reference), img.exact);
    img.exact_ms = ms_since(t0);
  }
  for (std::size_t k = 0; k < img.mode.size(); ++k) {
    img.hits += !std::isnan(img.exact[k]);
    const int d = img.disagreement(k);
    img.false_hits += d > 0;
    img.missed += d < 0;
  }
  return img;
}

ImageCanvas::~ImageCanvas() {
  if (tex_) host_->destroy(tex_);
}

void ImageCanvas::focus(const TraceModel& m, std::size_t, double) {
  const auto at = m.run().sweep_marker();
  if (!at) return;
  cx_ = (*at)[0], cy_ = (*at)[1];
  half_ = std::min(half_, kFocusHalf);
}

void ImageCanvas::follow(const Canvas& other) {
  if (const auto* o = dynamic_cast<const ImageCanvas*>(&other)) cx_ = o->cx_, cy_ = o->cy_, half_ = o->half_;
}

std::array<float, 4> ImageCanvas::sample_rect(int i, int j) const {
  const float sx = size_.x / float(std::max(image_.grid.w, 1)), sy = size_.y / float(std::max(image_.grid.h, 1));
  return {origin_.x + sx * float(i), origin_.y + sy * float(j), origin_.x + sx * float(i + 1), origin_.y + sy * float(j + 1)};
}

void ImageCanvas::handle_input(bool hovered) {
  const ImGuiIO& io = ImGui::GetIO();
  const double aspect = size_.x / std::max(size_.y, 1.f);
  auto to_frame = [&](ImVec2 p) {
    return std::array<double, 2>{cx_ + ((p.x - origin_.x) / size_.x * 2 - 1) * half_ * aspect, cy_ - ((p.y - origin_.y) / size_.y * 2 - 1) * half_};
  };
  if (hovered && io.MouseWheel != 0) {
    const auto before = to_frame(io.MousePos);
    half_ = std::clamp(half_ * std::pow(1.25, -io.MouseWheel), 1e-12, 1e3);
    const auto after = to_frame(io.MousePos);
    cx_ += before[0] - after[0], cy_ += before[1] - after[1];
  }
  if (ImGui::IsItemActivated()) moved_ = false;
  if (ImGui::IsItemActive() && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
    cx_ -= io.MouseDelta.x / size_.x * 2 * half_ * aspect;
    cy_ += io.MouseDelta.y / size_.y * 2 * half_;
    moved_ = true;
  }
  if (hovered && !io.WantTextInput)
    for (ImWchar ch : io.InputQueueCharacters) {
      if (ch == 'f' || ch == 'F') fit();
      if ((ch == 'z' || ch == 'Z') && keep_) {  // onto the input, 8x closer each time
        const double half = half_;
        focus(*keep_, 0, 0);
        half_ = std::max(half / 8, 1e-12);
      }
    }
}

void ImageCanvas::upload() {
  const SweepGrid& g = image_.grid;
  if (g.w <= 0 || g.h <= 0) return;
  if (!tex_ || tex_w_ != g.w || tex_h_ != g.h) {
    if (tex_) host_->destroy(tex_);
    tex_ = host_->create(g.w, g.h);
    tex_w_ = g.w, tex_h_ = g.h;
  }
  float lo = INFINITY, hi = -INFINITY;
  for (float v : image_.exact)
    if (!std::isnan(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  std::vector<std::uint32_t> px(image_.samples());
  for (std::size_t k = 0; k < px.size(); ++k) {
    const bool a = !std::isnan(image_.mode[k]);
    if (const int d = image_.disagreement(k)) {
      px[k] = rgba(d > 0 ? kSweepFalseHit : kSweepMissed);
    } else if (!a) {
      px[k] = rgba(kSweepMissBoth);
    } else if (image_.shaded) {  // the intensity itself, grey
      const int s = static_cast<int>(std::lround(255 * std::clamp(image_.exact[k], 0.f, 1.f)));
      px[k] = rgba(IM_COL32(s, s, s, 255));
    } else {  // nearer is brighter
      const float u = hi > lo ? (image_.exact[k] - lo) / (hi - lo) : 0.f;
      const int s = static_cast<int>(225 - 120 * std::clamp(u, 0.f, 1.f));
      px[k] = rgba(IM_COL32(s * 6 / 10, s * 8 / 10, s, 255));
    }
  }
  host_->update(tex_, 0, 0, g.w, g.h, px.data(), g.w);
}

CanvasEvents ImageCanvas::draw(const CanvasInput& in, ImVec2 size) {
  CanvasEvents ev;
  size.x = std::max(size.x, 16.f), size.y = std::max(size.y, 16.f);
  origin_ = ImGui::GetCursorScreenPos();
  size_ = size;
  ImGui::InvisibleButton("##image", size, ImGuiButtonFlags_MouseButtonLeft);
  const bool hovered = ImGui::IsItemHovered();
  if (in.model) keep_ = in.model;
  handle_input(hovered);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 end(origin_.x + size.x, origin_.y + size.y);
  dl->PushClipRect(origin_, end, true);
  dl->AddRectFilled(origin_, end, theme::kCanvasBg);
  if (!in.model || !in.model->algorithm().sweep || in.hide_sweep) {
    if (in.hide_sweep) sweep_hidden_note(dl, origin_);
    else dl->AddText(ImVec2(origin_.x + 10, origin_.y + 10), theme::kLabel, "This algorithm declares no sweep.");
    dl->PopClipRect();
    return ev;
  }
  // The grid: kSide samples along the longer side, the window's aspect the canvas's.
  const double aspect = size.x / size.y;
  SweepGrid g;
  auto odd = [](double n) { return std::max(1, int(std::lround((n - 1) / 2)) * 2 + 1); };  // a middle sample
  g.w = aspect >= 1 ? kSide : odd(kSide * aspect);
  g.h = aspect >= 1 ? odd(kSide / aspect) : kSide;
  g.cx = cx_, g.cy = cy_, g.dx = 2 * half_ * aspect / g.w, g.dy = 2 * half_ / g.h;
  g.inputs = in.model->numeric() == Numeric::f32 ? Numeric::f32 : Numeric::f64;
  if (swept_ != in.model.get() || !(image_.grid == g)) {
    swept_ = in.model.get();
    try {
      image_ = sweep_image(*in.model, g);
      error_.clear();
    } catch (const std::exception& e) {
      image_ = SweepImage{g, {}, {}};
      error_ = e.what();
    }
    upload();
  }
  if (tex_ && image_.samples()) dl->AddImage(tex_, origin_, end);
  const SweepGrid& grid = image_.grid;
  // Rings around the disagreements, so that a single texel shows.
  if (image_.disagreements() <= kRingedAtMost)
    for (int j = 0; j < grid.h && image_.disagreements(); ++j)
      for (int i = 0; i < grid.w; ++i) {
        const std::size_t k = std::size_t(j) * grid.w + i;
        const int d = image_.disagreement(k);
        if (!d) continue;
        const auto r = sample_rect(i, j);
        const float rad = std::max(6.f, (r[2] - r[0]) * 1.5f);
        dl->AddCircle(ImVec2((r[0] + r[2]) / 2, (r[1] + r[3]) / 2), rad, d < 0 ? kSweepMissed : kSweepFalseHit, 16, 1.5f);
      }
  // The input itself.
  {
    if (const auto at = in.model->run().sweep_marker()) {
      const float x = origin_.x + float(((*at)[0] - grid.cx) / (grid.dx * grid.w) + 0.5) * size.x;
      const float y = origin_.y + float((grid.cy - (*at)[1]) / (grid.dy * grid.h) + 0.5) * size.y;
      dl->AddLine(ImVec2(x - 8, y), ImVec2(x + 8, y), theme::kHandleP0, 2.f);
      dl->AddLine(ImVec2(x, y - 8), ImVec2(x, y + 8), theme::kHandleP0, 2.f);
      dl->AddText(ImVec2(x + 6, y + 4), theme::kHandleP0, "input");
    }
  }
  // The count, and the legend.
  const std::string mode(numeric_name(in.model->numeric())), ref(numeric_name(image_.reference));
  const std::string caption(in.model->algorithm().sweep.caption);
  const bool self = in.model->numeric() == image_.reference, shaded = image_.shaded;
  char lines[3][200];
  if (!error_.empty()) {
    std::snprintf(lines[0], sizeof lines[0], "sweep failed: %s", error_.c_str());
  } else if (self) {
    std::snprintf(lines[0], sizeof lines[0], "%s: %zu of %zu %s", ref.c_str(), image_.hits, image_.samples(), shaded ? "shaded" : "hit");
  } else {
    std::snprintf(lines[0], sizeof lines[0], "%s: %zu of %zu %s %s", mode.c_str(), image_.disagreements(), image_.samples(),
                  shaded ? "differ by more than 1/255 from" : "disagree with", ref.c_str());
  }
  std::snprintf(lines[1], sizeof lines[1], "%dx%d %s", grid.w, grid.h, caption.c_str());
  if (self) std::snprintf(lines[2], sizeof lines[2], "swept in %.1f ms", image_.mode_ms);
  else if (shaded) std::snprintf(lines[2], sizeof lines[2], "%zu brighter, %zu darker in %s; %.1f + %.1f ms", image_.false_hits, image_.missed, mode.c_str(), image_.mode_ms, image_.exact_ms);
  else std::snprintf(lines[2], sizeof lines[2], "%zu only %s hit, %zu only %s; %.1f + %.1f ms", image_.false_hits, mode.c_str(), image_.missed, ref.c_str(), image_.mode_ms, image_.exact_ms);
  status_plate(dl, ImVec2(origin_.x + 4, origin_.y + 4), lines, image_.disagreements() || !error_.empty());
  const float ly = end.y - 24;
  dl->AddRectFilled(ImVec2(origin_.x, ly - 4), end, IM_COL32(16, 18, 24, 210));
  float lx = origin_.x + 8;
  auto key = [&](ImU32 col, const char* text) {
    dl->AddRectFilled(ImVec2(lx, ly + 2), ImVec2(lx + 12, ly + 14), col);
    dl->AddText(ImVec2(lx + 17, ly), theme::kLabel, text);
    lx += 17 + ImGui::CalcTextSize(text).x + 16;
  };
  if (shaded) {
    key(IM_COL32(200, 200, 200, 255), "agree: the value, grey");
    key(kSweepMissBoth, "no value");
    if (!self) key(kSweepFalseHit, ("brighter in " + mode).c_str()), key(kSweepMissed, ("darker in " + mode).c_str());
  } else {
    key(IM_COL32(135, 180, 225, 255), "both hit");
    key(kSweepMissBoth, "both miss");
    if (!self) key(kSweepFalseHit, ("only " + mode).c_str()), key(kSweepMissed, ("only " + ref).c_str());
  }
  if ((hovered || ImGui::IsItemDeactivated()) && image_.samples()) {
    const ImGuiIO& io = ImGui::GetIO();
    const int i = std::clamp(int((io.MousePos.x - origin_.x) / size.x * grid.w), 0, grid.w - 1);
    const int j = std::clamp(int((io.MousePos.y - origin_.y) / size.y * grid.h), 0, grid.h - 1);
    const std::size_t k = std::size_t(j) * grid.w + i;
    if (ImGui::IsItemDeactivated() && !moved_ && in.editable && in.model->algorithm().sweep.sample) {  // a click: trace this sample
      try {
        ev.edit = in.model->run().sweep_sample(grid, i, j);
      } catch (const std::exception& e) {
        error_ = e.what();
      }
    }
    auto say = [](float v) { return std::isnan(v) ? std::string("miss") : "hit, t = " + std::to_string(v); };
    if (hovered)
      ImGui::SetTooltip("sample (%d, %d) at (%.6g, %.6g)\n%s: %s\nexact: %s%s", i, j, grid.x(i), grid.y(j), mode.c_str(), say(image_.mode[k]).c_str(),
                        say(image_.exact[k]).c_str(), in.model->algorithm().sweep.sample && in.editable ? "\nclick: trace this sample" : "");
  }
  corner_label(dl, origin_, size, in.label);
  dl->PopClipRect();
  return ev;
}

}  // namespace sw::vis
