// The step model: what one instrumented step of an algorithm says about itself.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace sw {

// What a step does. Lessons and the timeline's "next step of kind" key on these names.
enum class StepKind : std::uint8_t { init, decide, advance, plot, visit, split, hit, miss, done };
inline constexpr std::array<std::string_view, 9> kStepKindNames = {
    "init", "decide", "advance", "plot", "visit", "split", "hit", "miss", "done"};

constexpr std::string_view kind_name(StepKind k) { return kStepKindNames[static_cast<std::size_t>(k)]; }
inline std::optional<StepKind> parse_kind(std::string_view s) {
  for (std::size_t i = 0; i < kStepKindNames.size(); ++i)
    if (kStepKindNames[i] == s) return static_cast<StepKind>(i);
  return std::nullopt;
}

// Geometry a step carries for the canvas. Pixels hold integer indices; the others hold numbers.
enum class GeoKind : std::uint8_t { pixel, point2, segment2, point3, segment3, ray3, box3, sphere, triangle3, plane };
inline constexpr std::array<std::string_view, 10> kGeoKindNames = {
    "pixel", "point", "segment", "point3", "segment3", "ray", "box", "sphere", "triangle", "plane"};
// How many numbers (or indices, for pixels) each geometry kind holds, in the order written to JSON.
inline constexpr std::array<std::uint8_t, 10> kGeoArity = {2, 2, 4, 3, 6, 6, 6, 4, 9, 6};

constexpr std::string_view geo_name(GeoKind k) { return kGeoKindNames[static_cast<std::size_t>(k)]; }
constexpr int geo_arity(GeoKind k) { return kGeoArity[static_cast<std::size_t>(k)]; }
inline std::optional<GeoKind> parse_geo(std::string_view s) {
  for (std::size_t i = 0; i < kGeoKindNames.size(); ++i)
    if (kGeoKindNames[i] == s) return static_cast<GeoKind>(i);
  return std::nullopt;
}

// A pseudocode listing written by us. Step line ids are 1-based indices into `lines`.
struct Listing {
  std::string_view title;
  std::span<const std::string_view> lines;
};

}  // namespace sw
