// shadow-map in the catalog: one light's shadow map over a rasterized scene, every visible point
// looked up, against exact visibility (acne and peter-panning counted). The oracle is the exact ray
// cast from the light through each texel's centre with GL's rules (raster_truth.hpp), then the
// same lookup. Semantics: docs/shadows/semantics.md#shadow-map.
#include "register.hpp"
#include "shadows/shadow_map.hpp"
#include "shadows/shadow_map_input.hpp"

namespace sw {
namespace {

using namespace shadowspec;

template <class Num> struct SMPrepared {
  std::shared_ptr<const MapInput> in;
  std::vector<pipe::RasterCamera<Num>> views;
  std::vector<pipe::RasterTriangle<Num>> tris;
  std::vector<shadow::MapPoint<Num>> points;
  Vec3<Num> light;
  shadow::MapParams<Num> params;
};

struct SMOutput {
  MapPixels px;
  friend bool operator==(const SMOutput& a, const SMOutput& b) { return a.px.lit == b.px.lit; }
};

struct ShadowMapSpec {
  static constexpr std::array hooks{Hook::error, Hook::estimate_steps};
  using Algo = shadow::ShadowMap;
  using Input = MapInputRef;
  using Output = SMOutput;
  static constexpr std::array views{View::plane2d, View::table};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  // The spot-lit scene's first spot (a 30-degree cone) at 24 x 18, a 24 x 24 map of 24 bits and
  // no bias: acne where the floor's own depth rounds against itself.
  static inline const std::string example =
      R"({"scene":"scenes/spot-lit.json","size":[24,18],"stacks":3,"light":0,"map":{"size":24,"depth_bits":24}})";
  static Input parse(const Json& j) { return parse_map_input(j); }
  template <class Num> static SMPrepared<Num> prepare(const Input& in) {
    SMPrepared<Num> p{in.p, {}, pipespec::triangles_in<Num>(in.p->scene->tris), map_points<Num>(*in.p), to_num<Num>(in.p->views.position),
                      map_params<Num>(in.p->options)};
    for (const auto& v : in.p->views.views) p.views.push_back(pipespec::camera_in<Num>(v));
    return p;
  }
  template <class Num, class Probe> static Output compute(const SMPrepared<Num>& p, Probe& probe) {
    return {map_pixels(*p.in, shadow::shadow_map(p.views, p.in->views.cube, p.light, p.tris, p.points, p.params, probe))};
  }
  static Json to_json(const Output& o) { return map_json(o.px); }
  static std::size_t ops(const Output& o) { return std::max<std::size_t>(1, o.px.lit.size()); }
  static constexpr std::string_view error_unit = "points";
  static double error(const Output& got, const Output& exact) {
    double wrong = 0;
    for (std::size_t i = 0; i < got.px.lit.size() && i < exact.px.lit.size(); ++i) wrong += got.px.lit[i] != exact.px.lit[i];
    return wrong;
  }
  static std::size_t estimate_steps(const Input& in) { return map_steps(*in.p); }
  static Output oracle(const Input& in) { return {oracle_pixels(*in.p)}; }
  static std::vector<BenchSet<Input>> bench_sets() { return map_sets(); }
};

SW_REGISTER(ShadowMapSpec);

}  // namespace
}  // namespace sw
