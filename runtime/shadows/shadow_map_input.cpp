#include "shadows/shadow_map_input.hpp"
#include "platform.hpp"
#include <filesystem>
#include "bench_harness.hpp"
#include "data_root.hpp"
#include "pipeline/depth_plane.hpp"
#include <thread>
#include "tracer/history.hpp"
#include "tracer/parallel.hpp"

namespace sw::shadowspec {

namespace {

using V3 = Vec3<Rational>;

// A number in [lo, hi] (exact).
Rational bounded(const Json& v, const std::string& what, const Rational& lo, const Rational& hi) {
  const Rational x = parse_rational(v, what);
  if (x < lo || x > hi) throw InputError(what + ": " + x.get_str() + " is outside [" + lo.get_str() + ", " + hi.get_str() + "]");
  return x;
}

// Two directions along a raster triangle's plane: from its first corner to the others (a corner at
// infinity is itself a direction).
std::array<V3, 2> along_of(const pipe::RasterTriangle<Rational>& t) {
  auto dir = [&](int k) {
    const pipe::Vec4<Rational>& a = t.x[0];
    const pipe::Vec4<Rational>& b = t.x[k];
    return b.w == 0 ? V3{b.x, b.y, b.z} : V3{b.x - a.x, b.y - a.y, b.z - a.z};
  };
  return {dir(1), dir(2)};
}

}  // namespace

MapOptions parse_map_options(const Json& map, const std::string& what, std::int64_t max_size) {
  MapOptions o;
  if (map.is_null()) return o;
  if (!map.is_object()) throw InputError(what + ": expected an object (size, depth_bits, bias, slope, pcf)");
  only_keys_optional(map, {}, {"size", "depth_bits", "bias", "slope", "pcf"}, what);
  if (map.contains("size")) o.size = parse_integer(map["size"], what + ".size", 1, max_size);
  if (map.contains("depth_bits")) {
    o.bits = static_cast<int>(parse_integer(map["depth_bits"], what + ".depth_bits", 0, 24));
    if (o.bits != 0 && o.bits != 16 && o.bits != 24) throw InputError(what + ".depth_bits: expected 16 or 24 (or 0: depth in the number type)");
  }
  if (map.contains("bias")) o.bias = bounded(map["bias"], what + ".bias", -1, 1);
  if (map.contains("slope")) o.slope = bounded(map["slope"], what + ".slope", -1000, 1000);
  if (map.contains("pcf")) {
    o.pcf = static_cast<int>(parse_integer(map["pcf"], what + ".pcf", 1, kMaxPcf));
    if (o.pcf % 2 == 0) throw InputError(what + ".pcf: the k of k x k taps is odd (1, 3, 5, ...), got " + std::to_string(o.pcf));
  }
  return o;
}

namespace {

// The seen points and their exact visibility; a map's views only with options.
std::shared_ptr<const MapInput> light_input(std::shared_ptr<const RasterScene> scene, std::size_t light, const MapOptions* o,
                                            const pipespec::RasterTruth& truth, unsigned threads) {
  auto in = std::make_shared<MapInput>();
  in->scene = std::move(scene), in->light = light;
  if (o) in->options = *o, in->views = light_views(*in->scene, light, o->size);
  in->points = seen_points(*in->scene, truth);
  for (const SeenPoint& p : in->points) {
    const RasterScene& s = *in->scene;
    in->along.push_back(along_of(s.tris[std::size_t(s.objects[std::size_t(p.object)].first + std::max(p.prim, 0))]));
  }
  in->reaches.assign(in->points.size(), 0);
  // The surface's normal on the eye's side (perspective: toward the eye), against the light's way.
  const RasterScene& sc = *in->scene;
  const lighting::Light<Rational>& li = sc.scene->lights.at(light);
  for (std::size_t k = 0; k < in->points.size(); ++k) {
    const V3 N = cross(in->along[k][0], in->along[k][1]);
    const V3 toward = li.type == lighting::LightType::directional ? li.where : V3(li.where - in->points[k].p);
    const Rational side = dot(N, V3(sc.camera.eye - in->points[k].p)), lit_side = dot(N, toward);
    in->faces.push_back((side > 0 && lit_side > 0) || (side < 0 && lit_side < 0));
  }
  if (threads == 0) threads = worker_threads();
  constexpr std::int64_t kChunk = 256;  // points a task
  tracer::parallel_rows((std::int64_t(in->points.size()) + kChunk - 1) / kChunk, threads, {}, [&](std::int64_t c) {
    for (std::size_t k = std::size_t(c * kChunk); k < std::min(in->points.size(), std::size_t((c + 1) * kChunk)); ++k)
      in->reaches[k] = reaches(*in->scene, light, in->points[k]);
  });
  return in;
}

}  // namespace

std::shared_ptr<const MapInput> map_input(std::shared_ptr<const RasterScene> scene, std::size_t light, const MapOptions& o,
                                          const pipespec::RasterTruth& truth, unsigned threads) {
  return light_input(std::move(scene), light, &o, truth, threads);
}
std::shared_ptr<const MapInput> map_input(std::shared_ptr<const RasterScene> scene, std::size_t light, const MapOptions& o, unsigned threads) {
  const pipespec::RasterTruth truth = pipespec::raster_truth(*scene, threads);
  return light_input(std::move(scene), light, &o, truth, threads);
}
std::shared_ptr<const MapInput> seen_input(std::shared_ptr<const RasterScene> scene, std::size_t light, const pipespec::RasterTruth& truth,
                                           unsigned threads) {
  return light_input(std::move(scene), light, nullptr, truth, threads);
}
std::shared_ptr<const MapInput> seen_input(std::shared_ptr<const RasterScene> scene, std::size_t light, unsigned threads) {
  const pipespec::RasterTruth truth = pipespec::raster_truth(*scene, threads);
  return light_input(std::move(scene), light, nullptr, truth, threads);
}

MapPixels looked_up(const MapInput& in, Numeric n) {
  return pipespec::in_mode(n, "shadow-map", nullptr, [&]<class Num>(std::type_identity<Num>) {
    std::vector<pipe::RasterCamera<Num>> views;
    for (const auto& v : in.views.views) views.push_back(pipespec::camera_in<Num>(v));
    const std::vector<shadow::MapPoint<Num>> points = map_points<Num>(in);
    const shadow::MapParams<Num> p = map_params<Num>(in.options);
    NoProbe none;
    return map_pixels(in, shadow::shadow_map(views, in.views.cube, to_num<Num>(in.views.position), pipespec::triangles_in<Num>(in.scene->tris), points, p, none));
  });
}

LightScene parse_light_scene(const Json& j) {
  std::string name;
  std::shared_ptr<const tracer::Scene> scene = tracer::scene_input(j["scene"], &name);
  pipespec::RasterOptions ro;
  if (j.contains("size")) {
    const Json& s = j["size"];
    if (!s.is_array() || s.size() != 2) throw InputError("input.size: expected [width, height]");
    ro.width = parse_integer(s[0], "input.size[0]", 1, kMaxSpecMapSize), ro.height = parse_integer(s[1], "input.size[1]", 1, kMaxSpecMapSize);
  } else if (scene->camera.width > kMaxSpecMapSize || scene->camera.height > kMaxSpecMapSize) {
    throw InputError("input.size: the scene's resolution exceeds " + std::to_string(kMaxSpecMapSize) + " on a side; give a size");
  }
  if (j.contains("stacks")) ro.stacks = static_cast<int>(parse_integer(j["stacks"], "input.stacks", pipespec::kMinStacks, pipespec::kMaxStacks));
  if (scene->lights.empty()) throw InputError("input.scene: the scene has no light to cast a shadow");
  const std::size_t light = j.contains("light") ? std::size_t(parse_integer(j["light"], "input.light", 0, std::int64_t(scene->lights.size()) - 1)) : 0;
  try {
    return {pipespec::raster_scene(std::move(scene), ro), light};
  } catch (const InputError& e) {
    throw InputError("input." + std::string(e.what()));
  }
}

MapInputRef parse_map_input(const Json& j) {
  if (!j.is_object()) throw InputError("input: expected an object with a scene and a light");
  only_keys_optional(j, {"scene"}, {"size", "stacks", "light", "map"}, "input");
  LightScene ls = parse_light_scene(j);
  const MapOptions o = parse_map_options(j.contains("map") ? j["map"] : Json(), "input.map", kMaxSpecMapSize);
  return {map_input(std::move(ls.scene), ls.light, o)};
}

Json map_json(const MapPixels& p) {
  return Json{{"width", p.width}, {"height", p.height}, {"lit", p.lit}, {"fraction", p.fraction}, {"visible", p.visible},
              {"acne", p.acne}, {"peter_panning", p.peter_panning}, {"outside", p.outside}, {"outside_shadowed", p.outside_shadowed}, {"away", p.away},
              {"pcf_error", p.pcf_error}};
}

MapPixels oracle_pixels(const MapInput& in) {
  const RasterScene& s = *in.scene;
  const MapOptions& o = in.options;
  const Rational M_scale = o.bits == 0 ? Rational(1) : Rational((mpz_class(1) << o.bits) - 1);
  // Each view's map: the exact depth of GL's answer at every texel centre, quantized as the
  // z-buffer stores it, over the stored scale. Rows bottom up, as GL's.
  struct Map {
    pipe::RasterCamera<Rational> cam;
    pipe::Mat4<Rational> M;
    std::vector<Rational> D;
  };
  std::vector<Map> maps;
  for (const auto& cam : in.views.views) {
    pipespec::RasterScene from = s;
    from.camera = cam, from.width = cam.width, from.height = cam.height;
    const pipespec::RasterTruth t = pipespec::raster_truth(from);
    Map m{cam, pipe::raster_matrix(cam), std::vector<Rational>(std::size_t(cam.width * cam.height), Rational(1))};
    for (std::int64_t jt = 0; jt < cam.height; ++jt)
      for (std::int64_t i = 0; i < cam.width; ++i) {
        const pipespec::PixelTruth& p = t.px[std::size_t(jt * cam.width + i)];
        if (p.object < 0) continue;
        Rational z = std::clamp(window_depth(cam, p.t), Rational(0), Rational(1));
        if (o.bits) z = Rational(num::floor_int(Rational(z * M_scale + Rational(1, 2)))) / M_scale;
        m.D[std::size_t((cam.height - 1 - jt) * cam.width + i)] = z;
      }
    maps.push_back(std::move(m));
  }
  std::vector<shadow::MapLookup<Rational>> looks(in.points.size());
  for (std::size_t k = 0; k < in.points.size(); ++k) {
    const V3& P = in.points[k].p;
    const int v = in.views.cube ? shadow::cube_face(V3(P - in.views.position)) : 0;
    const Map& m = maps[std::size_t(v)];
    const pipe::Vec4<Rational> c = pipe::apply(m.M, pipe::Vec4<Rational>{P.x, P.y, P.z, Rational(1)});
    if (c.w <= 0) continue;
    const Rational x = Rational(-1, 2) + (c.x / c.w + 1) * m.cam.width / 2, y = Rational(-1, 2) + (c.y / c.w + 1) * m.cam.height / 2;
    const Rational slope = o.slope == 0 ? Rational(0) : window_slope(m.M, m.cam, P, in.along[k][0], in.along[k][1]);
    const Rational ref = (c.z / c.w + 1) / 2 - o.bias - o.slope * slope;
    const std::int64_t i = num::floor_int(Rational(x + Rational(1, 2))), j = num::floor_int(Rational(y + Rational(1, 2)));
    if (i < 0 || j < 0 || i >= m.cam.width || j >= m.cam.height) continue;
    auto passes = [&](std::int64_t a, std::int64_t b) { return ref <= m.D[std::size_t(b * m.cam.width + a)]; };
    shadow::MapLookup<Rational>& l = looks[k];
    l.outside = false, l.view = v, l.i = i, l.j = j, l.lit = passes(i, j);
    l.stored = m.D[std::size_t(j * m.cam.width + i)], l.ref = ref;
    std::int64_t taps = 0, pass = 0;
    for (std::int64_t b = std::max<std::int64_t>(0, j - o.pcf / 2); b <= std::min<std::int64_t>(m.cam.height - 1, j + o.pcf / 2); ++b)
      for (std::int64_t a = std::max<std::int64_t>(0, i - o.pcf / 2); a <= std::min<std::int64_t>(m.cam.width - 1, i + o.pcf / 2); ++a)
        ++taps, pass += passes(a, b);
    l.fraction = Rational(pass) / Rational(taps);
  }
  return map_pixels(in, looks);
}

std::size_t map_steps(const MapInput& in) {
  const RasterScene& s = *in.scene;
  double steps = 4 + 8.0 * double(in.points.size()) + double(in.points.size()) * in.options.pcf * in.options.pcf;
  for (const auto& cam : in.views.views) {
    NoProbe none;
    const auto img = pipe::scene_raster<double>(pipespec::camera_in<double>(cam), pipespec::triangles_in<double>(s.tris), none);
    const double n = double(s.tris.size()), w = double(img.drawn.size() + s.tris.size());
    steps += 4 + n * 126 + 3 * w + 3 * (2 * double(img.buffer.fragments) + double(cam.width * cam.height));
  }
  return static_cast<std::size_t>(steps);
}

std::vector<BenchSet<MapInputRef>> map_sets() {
  BenchSet<MapInputRef> set{"lights", {}};
  // A spot's cone, a point light's cube and a directional light's box; no bias, then a bias.
  for (const char* scene : {"scenes/spot-lit.json", "scenes/glass-spheres.json", "scenes/cornell-box.json"})
    for (int light = 0; light < 2; ++light)
      for (const Json& map : {Json{{"size", 64}}, Json{{"size", 64}, {"slope", 2}, {"bias", "1/4096"}, {"pcf", 3}}}) {
        try {
          set.inputs.push_back(parse_map_input(Json{{"scene", scene}, {"size", {32, 24}}, {"stacks", 6}, {"light", light}, {"map", map}}));
        } catch (const InputError&) {  // the scene has one light only
        }
      }
  return {set};
}

}  // namespace sw::shadowspec
