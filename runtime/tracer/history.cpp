#include "tracer/history.hpp"
#include "platform.hpp"
#include "data_root.hpp"
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <thread>
#include "tracer/photons.hpp"

namespace sw::tracer {

namespace {

// A scene file as an input names it: relative to the data root.
std::filesystem::path scene_path(const Json& v) {
  std::filesystem::path p = v.get<std::string>();
  if (p.is_relative()) p = data_root() / p;
  return p.lexically_normal();
}

}  // namespace

std::shared_ptr<const Scene> scene_input(const Json& v, std::string* name) {
  if (v.is_string()) {
    *name = v.get<std::string>();
    const std::filesystem::path p = scene_path(v);
    require_regular_file(p.string(), "input.scene");
    return std::make_shared<const Scene>(read_scene_file(p.string()));
  }
  if (!v.is_object()) throw InputError("input.scene: expected a scene file (relative to the source tree) or a scene object");
  *name = "inline";
  SceneOptions opt;
  opt.base_dir = data_root().string();
  try {
    return std::make_shared<const Scene>(parse_scene(v, opt));
  } catch (const InputError& e) {
    throw InputError("input." + std::string(e.what()));  // "input.scene.objects[1]...": the input's path
  }
}

namespace {

std::array<std::int64_t, 2> pair(const Json& j, const char* key, std::int64_t lo, std::int64_t hi0, std::int64_t hi1) {
  const Json& v = j[key];
  const std::string what = std::string("input.") + key;
  if (!v.is_array() || v.size() != 2) throw InputError(what + ": expected [" + (key[0] == 'p' ? "i, j" : "width, height") + "]");
  return {parse_integer(v[0], what + "[0]", lo, hi0), parse_integer(v[1], what + "[1]", lo, hi1)};
}

}  // namespace

HistoryInput parse_history_input(const Json& j) {
  if (!j.is_object()) throw InputError("input: expected an object");
  only_keys_optional(j, {"scene", "pixel"}, {"size", "offset", "all_effects"}, "input");
  HistoryInput in;
  in.scene = scene_input(j["scene"], &in.scene_name);
  in.width = in.scene->camera.width, in.height = in.scene->camera.height;
  if (j.contains("size")) {
    const auto s = pair(j, "size", 1, kMaxResolution, kMaxResolution);
    in.width = s[0], in.height = s[1];
  }
  // What the prepared scene is built from: the file as it is now (its path, size and time), or the
  // inline scene; then the image size, offset and plan below.
  if (j["scene"].is_string()) {
    const std::filesystem::path f = scene_path(j["scene"]);
    std::error_code e;
    in.scene_key = "file " + f.string() + " " + std::to_string(std::filesystem::file_size(f, e)) + " " +
                   std::to_string(static_cast<long long>(std::filesystem::last_write_time(f, e).time_since_epoch().count()));
  } else {
    in.scene_key = j["scene"].dump();
  }
  const auto p = pair(j, "pixel", 0, in.width - 1, in.height - 1);
  in.i = p[0], in.j = p[1];
  if (j.contains("offset")) {
    const Json& o = j["offset"];
    if (o == "robust") in.offset = Offset::robust;
    else if (o == "none") in.offset = Offset::none;
    else if (o == "epsilon") in.offset = Offset::epsilon;
    else throw InputError("input.offset: expected \"robust\", \"none\" or \"epsilon\"");
  }
  if (j.contains("all_effects")) {
    if (!j["all_effects"].is_boolean()) throw InputError("input.all_effects: expected true or false");
    in.all_effects = j["all_effects"].get<bool>();
  }
  return in;
}

std::shared_ptr<const HistoryScene> history_scene(const HistoryInput& in) {
  // The last one prepared is kept: the app traces a pixel at each click, and the photon map
  // costs more than the pixel's trace. An input without a key (made in code) is never shared.
  static std::mutex guard;
  static std::string last_key;
  static std::shared_ptr<const HistoryScene> last;
  const std::string key = in.scene_key.empty() ? std::string() : in.scene_key + " | " + std::to_string(in.width) + "x" + std::to_string(in.height) + " " +
                                                                     std::to_string(int(in.offset)) + " " + std::to_string(in.all_effects);
  if (!key.empty()) {
    const std::lock_guard lock(guard);
    if (last && key == last_key) return last;
  }
  auto h = std::make_shared<HistoryScene>();
  h->scene = trace_scene(*in.scene, in.width, in.height);
  h->scene.offset = in.offset;
  h->plan = in.all_effects ? all_effects_plan(*in.scene) : plan_scene(*in.scene);
  if (h->plan.effects.caustics) {  // the same photon map as render() builds
    std::uint64_t rays = 0;
    build_photon_map(*in.scene, h->scene, worker_threads(), h->photons, rays);
    h->scene.caustics = &h->photons;
  }
  if (!key.empty()) {
    const std::lock_guard lock(guard);
    last_key = key, last = h;
  }
  return h;
}

PixelColour pixel_colour(const HistoryScene& s, std::int64_t i, std::int64_t j) {
  PixelColour out;
  NoProbe none;
  WhittedTracer<double> tracer(s.scene, s.plan.effects, out.counts, none);
  out.rgb = tracer.sample(i, j, 0.0, 0.0);
  out.budget_spent = out.counts.budget_stops > 0;
  return out;
}

Preview render_preview(const HistoryInput& in, std::int64_t max_side) {
  Preview p;
  p.scale = std::max<std::int64_t>(1, (std::max(in.width, in.height) + max_side - 1) / std::max<std::int64_t>(max_side, 1));
  Scene centres = *in.scene;
  centres.sampling = Sampling{};  // one sample through each pixel's centre, as the history traces
  RenderOptions opt;
  opt.width = std::max<std::int64_t>(1, in.width / p.scale), opt.height = std::max<std::int64_t>(1, in.height / p.scale);
  opt.all_effects = in.all_effects, opt.offset = in.offset;
  const RenderResult r = render(centres, opt);
  p.width = r.width, p.height = r.height, p.rgb = to_rgb8(r), p.plan = r.plan, p.seconds = r.seconds;
  return p;
}

Json with_pixel(Json input, std::int64_t i, std::int64_t j) {
  input["pixel"] = Json::array({i, j});
  return input;
}

}  // namespace sw::tracer
