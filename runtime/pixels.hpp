// The output of every algorithm that plots pixels: the pixels in plotting order, written to JSON
// as [[i, j], ...] under a family-chosen key ("pixels", "cells").
#pragma once
#include <ostream>
#include <vector>
#include "core/vec.hpp"
#include "input.hpp"

namespace sw {

struct PixelsOutput {
  std::vector<Pixel> pixels;
  bool finished = true;  // false: the loop bound stopped the walk
  friend bool operator==(const PixelsOutput&, const PixelsOutput&) = default;
};

// The result's members, written straight to the stream without braces: a long line's result is
// held once, as pixels.
inline void pixels_members(const char* key, const PixelsOutput& o, std::ostream& os) {
  os << '"' << key << "\":[";
  for (std::size_t i = 0; i < o.pixels.size(); ++i) os << (i ? ",[" : "[") << o.pixels[i].x << ',' << o.pixels[i].y << ']';
  os << ']';
  if (!o.finished) os << ",\"bound_hit\":true";
}

inline Json pixels_json(const char* key, const PixelsOutput& o) {
  Json a = Json::array();
  for (Pixel p : o.pixels) a.push_back({p.x, p.y});
  Json r{{key, std::move(a)}};
  if (!o.finished) r["bound_hit"] = true;
  return r;
}

}  // namespace sw
