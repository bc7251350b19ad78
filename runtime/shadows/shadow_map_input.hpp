// shadow-map's input, parsed once: the rasterized scene, one light and the map's settings, the
// light's views, the points the eye sees (the exact ray cast of every pixel) and whether the light
// reaches each one exactly. The result per pixel, and the oracle: the exact ray cast from the light
// through every texel's centre with GL's rules, quantized and offset as the map is, then the lookup.
// JSON: {"scene": ..., "size": [w, h], "stacks": n, "light": i,
//        "map": {"size": n, "depth_bits": 0|16|24, "bias": b, "slope": s, "pcf": k}}
// Semantics: docs/shadows/semantics.md#shadow-map.
#pragma once
#include <memory>
#include <vector>
#include "bench_harness.hpp"
#include "catalog.hpp"
#include "shadows/shadow_map.hpp"
#include "shadows/shadow_views.hpp"

namespace sw::shadowspec {

inline constexpr std::int64_t kMaxMapSize = 2048, kMaxSpecMapSize = 256, kMaxPcf = 15;

struct MapOptions {
  std::int64_t size = 256;  // texels a side, per view
  int bits = 24;            // 0: depth in the number type
  Rational bias;            // subtracted from each point's reference depth
  Rational slope;           // times the point's own depth slope in the light's window, subtracted too
  int pcf = 1;              // k x k taps, odd
};
// Reads "map" (absent: the defaults); throws InputError naming what.<key>.
MapOptions parse_map_options(const Json& map, const std::string& what, std::int64_t max_size);

struct MapInput {
  std::shared_ptr<const RasterScene> scene;
  std::size_t light = 0;
  MapOptions options;
  LightViews views;
  std::vector<SeenPoint> points;
  std::vector<std::array<Vec3<Rational>, 2>> along;  // per point, two directions along its surface
  std::vector<char> reaches;  // per point, exact
  std::vector<char> faces;    // per point: its surface, seen from the eye's side, faces the light
};
struct MapInputRef {
  std::shared_ptr<const MapInput> p;
};
// The views, the seen points and their exact visibility for one light of a rasterized scene.
std::shared_ptr<const MapInput> map_input(std::shared_ptr<const RasterScene> scene, std::size_t light, const MapOptions& o,
                                          unsigned threads = 1);
// The same from the eye's ray cast, already made (`scene raster` shares one among its lights).
std::shared_ptr<const MapInput> map_input(std::shared_ptr<const RasterScene> scene, std::size_t light, const MapOptions& o,
                                          const pipespec::RasterTruth& truth, unsigned threads = 1);
// The seen points and their exact visibility alone, no views (stencil volumes, projective shadows).
std::shared_ptr<const MapInput> seen_input(std::shared_ptr<const RasterScene> scene, std::size_t light, unsigned threads = 1);
std::shared_ptr<const MapInput> seen_input(std::shared_ptr<const RasterScene> scene, std::size_t light, const pipespec::RasterTruth& truth,
                                           unsigned threads = 1);

MapInputRef parse_map_input(const Json& j);
// The common keys of the family's inputs (scene, size, stacks, light), the other keys checked by
// the caller: the rasterized scene and the light's index.
struct LightScene {
  std::shared_ptr<const RasterScene> scene;
  std::size_t light = 0;
};
LightScene parse_light_scene(const Json& j);

// Per pixel, row 0 at the top: the map's test at the point's own texel (-1: no surface, 0
// shadowed, 1 lit), its PCF fraction (-1: none) and the exact visibility (-1, 0, 1). Over the
// points whose surface faces the light (a shadow there changes the picture) that a view holds: acne
// counts those the light reaches that the map calls shadowed, peter_panning the reverse, pcf_error
// the summed |fraction - exact|. outside counts the facing points no view holds (called lit:
// outside a spot's cone, beyond a directional light's box), of which outside_shadowed are
// shadowed exactly; away, the points facing away from the light.
struct MapPixels {
  std::int64_t width = 0, height = 0;
  std::vector<int> lit, visible;
  std::vector<double> fraction;
  std::int64_t acne = 0, peter_panning = 0, outside = 0, outside_shadowed = 0, away = 0;
  double pcf_error = 0;
};
template <class Num> MapPixels map_pixels(const MapInput& in, const std::vector<shadow::MapLookup<Num>>& r) {
  const RasterScene& s = *in.scene;
  MapPixels o{s.width, s.height, std::vector<int>(std::size_t(s.width * s.height), -1), std::vector<int>(std::size_t(s.width * s.height), -1),
              std::vector<double>(std::size_t(s.width * s.height), -1.0)};
  for (std::size_t k = 0; k < in.points.size(); ++k) {
    const std::size_t px = in.points[k].pixel;
    const bool reach = in.reaches[k];
    o.lit[px] = r[k].lit, o.visible[px] = reach, o.fraction[px] = num::to_double(r[k].fraction);
    if (!in.faces[k]) {
      ++o.away;
      continue;
    }
    if (r[k].outside) {
      ++o.outside, o.outside_shadowed += !reach;
      continue;
    }
    o.acne += reach && !r[k].lit, o.peter_panning += !reach && r[k].lit;
    o.pcf_error += std::abs(o.fraction[px] - (reach ? 1.0 : 0.0));
  }
  return o;
}
// The input's points and settings in Num.
template <class Num> std::vector<shadow::MapPoint<Num>> map_points(const MapInput& in) {
  std::vector<shadow::MapPoint<Num>> out;
  for (std::size_t k = 0; k < in.points.size(); ++k) out.push_back({to_num<Num>(in.points[k].p), to_num<Num>(in.along[k][0]), to_num<Num>(in.along[k][1])});
  return out;
}
template <class Num> shadow::MapParams<Num> map_params(const MapOptions& o) {
  return {o.bits, num::from_rational<Num>(o.bias), num::from_rational<Num>(o.slope), o.pcf};
}
// The map drawn and looked up untraced in mode n (filtered: intervals, else exact rationals).
MapPixels looked_up(const MapInput& in, Numeric n);
Json map_json(const MapPixels& p);

MapPixels oracle_pixels(const MapInput& in);
std::size_t map_steps(const MapInput& in);
std::vector<BenchSet<MapInputRef>> map_sets();

}  // namespace sw::shadowspec
