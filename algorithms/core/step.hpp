// The step model: what one instrumented step of an algorithm says about itself. Trace vocabulary
// v2: one table describes every geometry kind, and everything else (names, arity checks, which
// items are decisions for `check --decisions-only` and the compare view) derives from it.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace sw {

// What a step does. Lessons and the timeline's "next step of kind" key on these names.
enum class StepKind : std::uint8_t { init, decide, advance, plot, visit, hit, miss, done };
inline constexpr std::array<std::string_view, 8> kStepKindNames = {"init",  "decide", "advance", "plot",
                                                                   "visit", "hit",    "miss",    "done"};

constexpr std::string_view kind_name(StepKind k) { return kStepKindNames[static_cast<std::size_t>(k)]; }
inline std::optional<StepKind> parse_kind(std::string_view s) {
  for (std::size_t i = 0; i < kStepKindNames.size(); ++i)
    if (kStepKindNames[i] == s) return static_cast<StepKind>(i);
  return std::nullopt;
}

// The geometry vocabulary: X(enumerator, JSON name, arity, integer, dimension, decision).
//  - arity: how many values, in the order written to JSON; 0 = a variable-length list of
//    `dimension`-sized points (polyline, polygon).
//  - integer: the values are integer indices (pixels, spans), not numbers of the mode.
//  - decision: the item is an outcome of the algorithm's decisions (which pixel), compared even
//    when only decisions are checked; the other items are rounded values.
#define SW_GEO_KINDS(X) \
  X(pixel, "pixel", 2, true, 2, true)          /* i j */ \
  X(point2, "point", 2, false, 2, false)       /* x y */ \
  X(segment2, "segment", 4, false, 2, false)   /* x0 y0 x1 y1 */ \
  X(point3, "point3", 3, false, 3, false)      /* x y z */ \
  X(segment3, "segment3", 6, false, 3, false)  /* x0 y0 z0 x1 y1 z1 */ \
  X(ray3, "ray", 6, false, 3, false)           /* ox oy oz dx dy dz */ \
  X(box3, "box", 6, false, 3, false)           /* min, max */ \
  X(sphere, "sphere", 4, false, 3, false)      /* cx cy cz r */ \
  X(triangle3, "triangle", 9, false, 3, false) /* three vertices */ \
  X(plane, "plane", 6, false, 3, false)        /* p, n */ \
  X(polyline, "polyline", 0, false, 2, false)  /* x y, x y, ... */ \
  X(polygon, "polygon", 0, false, 2, false)    /* closed: x y, x y, ... */ \
  X(span, "span", 3, true, 2, true)            /* row j, first i, last i*/ \
  X(rect, "rect", 4, false, 2, false)          /* min x y, max x y */ \
  X(circle, "circle", 3, false, 2, false)      /* cx cy r */ \
  X(arrow, "arrow", 4, false, 2, false)        /* from x y, to x y */ \
  X(node2, "node", 6, false, 2, false)         /* id, parent, min, max */ \
  X(node3, "node3", 8, false, 3, false)        /* id, parent, min, max */

enum class GeoKind : std::uint8_t {
#define SW_GEO_ENUM(id, name, arity, integer, dim, decision) id,
  SW_GEO_KINDS(SW_GEO_ENUM)
#undef SW_GEO_ENUM
};

struct GeoDesc {
  std::string_view name;
  std::uint8_t arity;  // 0: variable (a list of points)
  bool integer;
  std::uint8_t dim;
  bool decision;
};
inline constexpr GeoDesc kGeoDescs[] = {
#define SW_GEO_DESC(id, name, arity, integer, dim, decision) {name, arity, integer, dim, decision},
    SW_GEO_KINDS(SW_GEO_DESC)
#undef SW_GEO_DESC
};
inline constexpr std::size_t kGeoKindCount = std::size(kGeoDescs);

constexpr const GeoDesc& geo_desc(GeoKind k) { return kGeoDescs[static_cast<std::size_t>(k)]; }
constexpr std::string_view geo_name(GeoKind k) { return geo_desc(k).name; }
// The fixed number of values of k, or 0 for a variable-length kind.
constexpr int geo_arity(GeoKind k) { return geo_desc(k).arity; }
inline std::optional<GeoKind> parse_geo(std::string_view s) {
  for (std::size_t i = 0; i < kGeoKindCount; ++i)
    if (kGeoDescs[i].name == s) return static_cast<GeoKind>(i);
  return std::nullopt;
}
// Does a list of n values fit kind k?
constexpr bool geo_count_ok(GeoKind k, std::size_t n) {
  const GeoDesc& d = geo_desc(k);
  return d.arity ? n == d.arity : n >= d.dim && n % d.dim == 0;
}

// A list variable (an edge-table row, a traversal stack) holds at most this many entries.
inline constexpr std::size_t kMaxListLength = 64;

// How long a geometry item stays on a view: this step only, from its step on, or from its step on
// replacing the earlier item with the same label (a running interval, the current estimate).
enum class Life : std::uint8_t { step, keep, replace };
inline constexpr std::array<std::string_view, 3> kLifeNames = {"step", "keep", "replace"};
constexpr std::string_view life_name(Life l) { return kLifeNames[static_cast<std::size_t>(l)]; }
inline std::optional<Life> parse_life(std::string_view s) {
  for (std::size_t i = 0; i < kLifeNames.size(); ++i)
    if (kLifeNames[i] == s) return static_cast<Life>(i);
  return std::nullopt;
}

// A line of a pseudocode listing written by us: a stable name (lessons and tests address lines by
// it) and the text shown.
struct ListingLine {
  std::string_view name, text;
};
// Step line ids are 1-based indices into `lines`.
struct Listing {
  std::string_view title;
  std::span<const ListingLine> lines;
  // The 1-based id of the line called `name`, or 0.
  constexpr std::uint32_t find(std::string_view name) const {
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (lines[i].name == name) return static_cast<std::uint32_t>(i + 1);
    return 0;
  }
};

// Declares an algorithm's listing from X(name, "text") entries: `enum Line` (the names, numbered
// from 1 in listing order), `lines` and `listing()`. The names are the lines' stable ids.
#define SW_LISTING_ENUM(name, text) name,
#define SW_LISTING_LINE(name, text) ::sw::ListingLine{#name, text},
#define SW_LISTING(TITLE, LINES) \
  enum Line : std::uint32_t { kNoLine_ = 0, LINES(SW_LISTING_ENUM) }; \
  static constexpr ::sw::ListingLine lines[] = {LINES(SW_LISTING_LINE)}; \
  static constexpr ::sw::Listing listing() { return {TITLE, lines}; }

}  // namespace sw
