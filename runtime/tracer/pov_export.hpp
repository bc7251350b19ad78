// A scene written as POV-Ray 3.7 SDL, for the subset that maps one to one, in three modes: the
// image (materials mapped, approximations listed), object ids (each object one flat colour) and a
// shadow mask (white lambert objects, one light, no ambient). What maps, what is approximated and
// what is refused: docs/tracer/povray.md. POV-Ray must be run with povray_args (File_Gamma=1.0,
// no antialiasing), or the colours are not the ones written.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>
#include "tracer/scene.hpp"

namespace sw::tracer {

enum class PovMode : std::uint8_t { image, ids, shadow };

struct PovOptions {
  PovMode mode = PovMode::image;
  std::size_t light = 0;               // shadow: the light whose mask is drawn
  std::int64_t width = 0, height = 0;  // 0: the scene's resolution (the camera's aspect depends on it)
};

struct PovScene {
  std::string text;                         // the SDL
  std::vector<std::string> approximations;  // image mode: one line per approximated mapping (empty: exact)
};

// Throws InputError naming the JSON path of the first thing that does not map (any mode: fisheye and
// cylindrical cameras; image mode: non-lambert diffuse models, specular models other than phong and
// blinn-phong, toon, bump maps, image, marble and wood textures, a checker on anything but an
// axis-aligned plane; ids mode: more than kMaxPovIds objects; shadow mode: a light index out of range).
// Meshes must have been loaded (read_scene_file does).
PovScene export_pov(const Scene& s, const PovOptions& o);

// Object ids as colours: id + 1 in base 16, one digit a channel, each digit d written as 17 d / 255,
// so a channel read back within 8 levels of 17 d decodes to d. Background black decodes to -1.
inline constexpr int kMaxPovIds = 4094;
std::array<std::uint8_t, 3> pov_id_colour(int id);
// -1: the background; -2: a colour no id is written as (more than 4 levels off).
int pov_id_of(std::uint8_t r, std::uint8_t g, std::uint8_t b);

// The povray arguments for one render at width x height, one thread, no antialiasing, no display,
// PNG output with file gamma 1 (linear, as stepwise writes), the Debian include path.
std::vector<std::string> povray_args(const std::string& pov, const std::string& png, std::int64_t width, std::int64_t height);

}  // namespace sw::tracer
