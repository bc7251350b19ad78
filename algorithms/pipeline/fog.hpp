// Fog per fragment, GL's fixed-function formulas (glFog): a factor f from the fragment's distance
// c to the eye, linear (end - c)/(end - start), exponential e^(-density c) or squared exponential
// e^(-(density c)^2), clamped to [0, 1]; the colour moves toward the fog colour by 1 - f.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/functions.hpp"
#include "core/probe.hpp"

namespace sw::pipe {

enum class FogMode : std::uint8_t { linear, exp, exp2 };

template <class Num> struct FogParams {
  FogMode mode = FogMode::linear;
  Num start{}, end{1}, density{1};
  Vec3<Num> rgb;  // the fog's colour
};

template <class Num> struct Fragment {
  Num c{};         // distance to the eye (GL's fog coordinate)
  Vec3<Num> rgb;   // the colour before fog
};

template <class Num> struct Fogged {
  Num f{};
  Vec3<Num> rgb;
};

struct FogAlgo {
  static constexpr std::string_view id = "fog";
  static constexpr std::string_view summary = "Fog per fragment: GL's linear, exp and exp2 factors, toward the fog colour";
#define SW_LINES_FOG(X) \
  X(fragment, "for each fragment (c: its distance to the eye, C: its colour):") \
  X(linear, "    GL_LINEAR: f <- (end - c) / (end - start)") \
  X(exp, "    GL_EXP:    f <- e^(-density c)") \
  X(exp2, "    GL_EXP2:   f <- e^(-(density c)^2)") \
  X(clamp, "    f <- f clamped to [0, 1]                 -- 1: no fog; 0: only fog") \
  X(colour, "    C' <- f C + (1 - f) C_fog")
  SW_LISTING("Fog", SW_LINES_FOG)
#undef SW_LINES_FOG
};

template <NumberType Num, StepProbe Probe = NoProbe>
std::vector<Fogged<Num>> fog(const FogParams<Num>& p, const std::vector<Fragment<Num>>& frags, Probe& probe) {
  using L = FogAlgo;
  std::vector<Fogged<Num>> out(frags.size());
  for (std::size_t i = 0; i < frags.size(); ++i) {
    const Fragment<Num>& q = frags[i];
    if constexpr (Probe::on) probe.step(L::fragment, StepKind::advance).idx("i", std::int64_t(i)).num("c", q.c).colour("C", q.rgb);
    Num f;
    if (p.mode == FogMode::linear) {
      f = (p.end - q.c) / (p.end - p.start);
      if constexpr (Probe::on) probe.step(L::linear, StepKind::advance).num("f", f);
    } else if (p.mode == FogMode::exp) {
      f = num::exp(Num(-(p.density * q.c)));
      if constexpr (Probe::on) probe.step(L::exp, StepKind::advance).num("f", f);
    } else {
      const Num dc = p.density * q.c;
      f = num::exp(Num(-(dc * dc)));
      if constexpr (Probe::on) probe.step(L::exp2, StepKind::advance).num("f", f);
    }
    f = std::clamp(f, Num(0), Num(1));
    if constexpr (Probe::on) probe.step(L::clamp, StepKind::decide).num("f", f);
    out[i] = {f, Vec3<Num>(Vec3<Num>(f * q.rgb) + Vec3<Num>(Num(Num(1) - f) * p.rgb))};
    if constexpr (Probe::on) probe.step(L::colour, StepKind::plot).colour("C'", out[i].rgb);
  }
  return out;
}

}  // namespace sw::pipe
