// What the fill family's Specs share: the bounds, the pixels-and-values output, and the parsing of
// vertices, attributes and the sample budget. Semantics and bounds: docs/fill/semantics.md.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>
#include "core/number.hpp"
#include "fill/vary.hpp"
#include "input.hpp"

namespace sw::fillspec {

inline constexpr double kCoordBound = 1073741824.0;    // 2^30: |x|, |y| of every vertex
inline constexpr double kFixedCoordBound = 2097152.0;  // 2^21 in int mode: every edge function fits 62 bits
inline constexpr std::int64_t kFixedUnit = 256;        // int mode: vertices in 1/256 pixel, llvmpipe's grid
inline constexpr double kMaxSamples = 1048576.0;       // 2^20 samples in a fill's bounding box
inline constexpr std::size_t kMaxRingVertices = 4096;  // all rings together

// Pixels in scanline order and, when the input has attributes, n values per pixel: the mode's
// values widened to double, and exact mode's rationals.
struct FillOutput {
  std::vector<Pixel> pixels;
  std::size_t n = 0;
  std::vector<double> values;
  std::vector<Rational> exact_values;  // exact mode only
  // Modes are compared by their pixels: rounded modes round the values by design.
  friend bool operator==(const FillOutput& a, const FillOutput& b) { return a.pixels == b.pixels; }
};

template <class Num> FillOutput fill_output(std::vector<Pixel> pixels, std::size_t n, const std::vector<Num>& values) {
  FillOutput o{std::move(pixels), n, {}, {}};
  for (const Num& v : values) o.values.push_back(num::to_double(v));
  if constexpr (std::is_same_v<Num, Rational>) o.exact_values = values;
  return o;
}

Json fill_json(const FillOutput& o);
// Wrong pixels against exact: those in one set and not the other.
double wrong_pixels(const FillOutput& got, const FillOutput& exact);
// A vertex [x, y] as an exact point within the bound (what names it in errors, e.g. "input.triangle[1]").
Vec2<Rational> parse_vertex(const Json& v, const std::string& what, double bound);
// The samples (i, j) in the points' bounding box, and a refusal of more than kMaxSamples of them.
double box_samples(const std::vector<Vec2<Rational>>& pts);
void check_budget(const std::vector<Vec2<Rational>>& pts, const std::string& what);
// input.attrs: one list of 1 to 8 numbers per vertex, all of one length.
std::vector<std::vector<Rational>> parse_attrs(const Json& a, std::size_t vertices);
// The oracle's output for a triangle's covered pixels: at each, the plane through the vertices'
// attributes (none when attrs is empty).
FillOutput plane_values(std::vector<Pixel> pixels, const std::array<Vec2<Rational>, 3>& v, const std::vector<std::vector<Rational>>& attrs);

}  // namespace sw::fillspec
