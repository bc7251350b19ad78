// The headless host: an OSMesa context (software GL2) driving the same App as the window, for
// `stepwise render` and the tests. Never link this with libGL: both export gl* (docs/visualizer.md).
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>
#include "panels/app.hpp"

namespace sw::vis {

class HeadlessHost {
 public:
  // Throws std::runtime_error if OSMesa cannot make a context. `scale` is the UI scale
  // (theme::setup_style; in [theme::kMinScale, theme::kMaxScale]).
  HeadlessHost(int width, int height, std::filesystem::path lessons_dir = default_lessons_dir(), float scale = 1.f);
  ~HeadlessHost();
  HeadlessHost(const HeadlessHost&) = delete;
  HeadlessHost& operator=(const HeadlessHost&) = delete;

  App& app() { return *app_; }
  // Builds and draws `frames` frames (layout settles over two); returns top-down RGBA rows.
  const std::vector<std::uint8_t>& render(int frames = 2);
  // The same, drawing `paint` (e.g. into the background draw list) instead of the app: a chart.
  const std::vector<std::uint8_t>& render_with(const std::function<void()>& paint, int frames = 2);
  int width() const { return w_; }
  int height() const { return h_; }
  // RGBA of one pixel of the last render.
  std::uint32_t pixel(int x, int y) const;
  // Scripted mouse for tests: position (none: outside the window) and left button state.
  void set_mouse(std::optional<ImVec2> pos, bool left_down) { mouse_ = pos, mouse_down_ = left_down; }
  // Scripted keys for tests: held during the first frame of the next render, then released.
  void press(ImGuiKey key) { keys_.push_back(key); }
  void type(char c) { chars_ += c; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::unique_ptr<App> app_;
  int w_, h_;
  std::vector<std::uint8_t> pixels_;
  std::optional<ImVec2> mouse_;
  bool mouse_down_ = false;
  std::vector<ImGuiKey> keys_;
  std::string chars_;
  std::function<void()> paint_;  // set during render_with
};

}  // namespace sw::vis
