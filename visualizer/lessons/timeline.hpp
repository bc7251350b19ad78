// The timeline's state: the step shown, playback (playing, speed, the fraction of a step carried
// between frames) and the kind the "next of kind" buttons seek. No ImGui: the Session moves it
// (clamped to the trace and held at the quiz's questions), the timeline panel draws it.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include "core/step.hpp"

namespace sw::vis {

// Playback speeds in steps per second, chosen with +/-.
inline constexpr std::array<double, 14> kSpeeds = {1, 2, 4, 8, 15, 30, 60, 120, 250, 500, 1000, 5000, 25000, 100000};

class Timeline {
 public:
  std::size_t step() const { return step_; }
  bool playing() const { return playing_; }
  int speed_index() const { return speed_; }
  double speed() const { return kSpeeds[std::size_t(speed_)]; }  // steps per second
  StepKind seek_kind() const { return seek_kind_; }

  // Unchecked: the Session clamps the step to its trace and to the quiz's gate first.
  void set_step(std::size_t step) { step_ = step; }
  void set_playing(bool on) { playing_ = on; }
  // Play or pause, from a whole step.
  void toggle() { playing_ = !playing_, carry_ = 0; }
  void faster() { speed_ = std::min(speed_ + 1, int(kSpeeds.size()) - 1); }
  void slower() { speed_ = std::max(speed_ - 1, 0); }
  void set_seek_kind(StepKind k) { seek_kind_ = k; }

  // The whole steps that `dt` seconds of playback add (the fraction carries to the next frame).
  // The window host sleeps while idle, so the first frame after a wake-up may report a long dt:
  // at most 0.1 s counts.
  std::size_t due(float dt) {
    if (!playing_) return 0;
    carry_ += double(std::min(dt, 0.1f)) * speed();
    const double whole = std::floor(carry_);
    carry_ -= whole;
    return static_cast<std::size_t>(whole);
  }

 private:
  std::size_t step_ = 0;
  bool playing_ = false;
  int speed_ = 3;     // index into kSpeeds
  double carry_ = 0;  // fractional steps of playback
  StepKind seek_kind_ = StepKind::plot;
};

}  // namespace sw::vis
