// Comparing our passes with POV-Ray's (docs/tracer/povray.md): running povray, decoding its id and
// shadow images, and classifying each differing pixel by an exact oracle (oracle/rays_oracle: the
// rays family's independent exact tests on rationals) on the pixel-centre ray. The ray is camera-ray
// in reference mode (its sqrt and tan to 300 bits); every intersection after it is exact (a
// sphere's irrational t rounded to 128 bits).
#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include "tracer/scene.hpp"

namespace sw::tracer {

struct IdCounts {
  std::size_t pixels = 0, differ = 0;
  std::size_t ours_right = 0, pov_right = 0, both_right = 0, both_wrong = 0;  // both right: an exact tie
  std::size_t silhouette = 0;        // differing pixels with an 8-neighbour of another id (ours or POV's)
  std::size_t pov_wrong_inside = 0;  // differing, not silhouette, and POV-Ray wrong by the oracle
  std::size_t unexplained = 0;       // differing, not silhouette, and POV-Ray right by the oracle
  std::size_t unknown_colour = 0;    // POV pixels that decode to no id
};

struct ShadowCounts {
  std::size_t compared = 0;  // pixels where both hit the same object
  std::size_t differ = 0;
  std::size_t grazing = 0;                                   // of which |cos(N, L)| < 2/255: POV's 8-bit value rounds to 0 or 1
  std::size_t silhouette = 0;                                // of which (not grazing) a neighbour's mask differs in ours
  std::size_t ours_right = 0, pov_right = 0, undecided = 0;  // the ones not grazing, by the exact oracle
  std::size_t unexplained = 0;                               // POV-Ray right, and not on the mask's edge
};

// The first-hit objects of pixel (i, j)'s centre ray at width x height, exactly: every object at
// the least t (more than one on an exact tie); empty when the ray hits nothing.
std::vector<int> exact_first_hits(const Scene& s, std::int64_t w, std::int64_t h, std::int64_t i, std::int64_t j);
// 1 lit, 0 not (facing away, or an occluder with 0 < t < 1 to a positional light, any t > 0 to a
// directional one), -1 undecided (no hit, or a tie); from the exact first hit of the pixel's ray.
int exact_lit(const Scene& s, std::int64_t w, std::int64_t h, std::int64_t i, std::int64_t j, std::size_t light);

IdCounts compare_ids(const Scene& s, std::int64_t w, std::int64_t h, const std::vector<int>& ours, const std::vector<int>& pov);
ShadowCounts compare_shadows(const Scene& s, std::int64_t w, std::int64_t h, std::size_t light, const std::vector<int>& ours_ids,
                             const std::vector<int>& pov_ids, const std::vector<char>& ours_lit,
                             const std::vector<double>& cosine, const std::vector<char>& pov_lit);

// Runs povray (povray_args) and returns its wall time in seconds; throws InputError with the tail of
// its output when it fails or writes no PNG.
double run_povray(const std::string& pov, const std::string& png, std::int64_t w, std::int64_t h);
bool povray_available();
// The ids of a POV-Ray ids-mode PNG (pov_id_of), and the lit pixels of a shadow-mode PNG (not black).
std::vector<int> read_pov_ids(const std::string& png);
std::vector<char> read_pov_lit(const std::string& png);
// PSNR in dB of two RGB8 images of one size (infinity when equal).
double psnr(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b);

}  // namespace sw::tracer
