// The ray tracer in the catalog: `whitted`, one pixel's whole history (the primary ray's
// traversal and tests, the shading, every shadow, mirror and transmitted ray with its depth) as
// nested listings. Double only: the tracer's colours go through sqrt, pow and noise, and exact
// rationals would grow without bound over the recursion. Semantics: docs/tracer/renderer.md.
#include <memory>
#include "register.hpp"
#include "tracer/history.hpp"

namespace sw {
namespace {

using tracer::HistoryInput;

struct WhittedPrepared {
  std::shared_ptr<const tracer::HistoryScene> scene;
  std::int64_t i = 0, j = 0;
};

struct WhittedOutput {
  tracer::PixelColour pixel;
  friend bool operator==(const WhittedOutput&, const WhittedOutput&) = default;
};

// The pixel's history in the recorder may nest a callee per recursion level under the scene's
// tests: room for the deepest recursion (16) and its callees, so that no ray is summarised.
constexpr int kHistoryNesting = 24;

// An upper estimate of a history's steps: at most 2^max_depth - 1 rays (each casts at most a
// mirror and a transmitted ray); per ray its scene-hit and one per light, each a visit, a nested
// test of at most 13 steps and a keep per object (a mesh: bvh-traverse's 51 per triangle), shade's
// steps per light and Whitted's own lines.
std::size_t history_steps(const HistoryInput& in) {
  const tracer::Scene& s = *in.scene;
  std::size_t per_hit = 4;
  for (const tracer::Object& o : s.objects)
    per_hit += o.kind == tracer::ObjectKind::mesh && s.meshes[std::size_t(o.mesh)].mesh ? 51 * s.meshes[std::size_t(o.mesh)].mesh->size() + 8 : 16;
  const std::size_t lights = s.lights.size();
  const std::size_t per_ray = (1 + lights) * per_hit + 40 * lights + 40;
  const std::size_t rays = (std::size_t{1} << std::min<std::int64_t>(s.max_depth, 20)) - 1;
  return 16 + rays * per_ray;
}

struct WhittedSpec {
  static constexpr std::array hooks{Hook::estimate_steps, Hook::result_keys};
  using Algo = tracer::Whitted;
  using Input = HistoryInput;
  using Output = WhittedOutput;
  static constexpr std::array views{View::scene, View::orbit3d};
  static constexpr std::array numerics{Numeric::f64};
  // A pixel of the glass-spheres scene at 80x60 that sees the chrome sphere: a mirror ray, then
  // the floor and its shadow rays.
  static inline const std::string example = R"({"scene":"scenes/glass-spheres.json","size":[80,60],"pixel":[44,18]})";
  static Input parse(const Json& j) { return tracer::parse_history_input(j); }
  // Every number type runs in double (only f64 is declared; the bench's exact column is double too).
  template <class Num> static WhittedPrepared prepare(const Input& in) { return {tracer::history_scene(in), in.i, in.j}; }
  template <class Num, class Probe> static Output compute(const WhittedPrepared& p, Probe& probe) {
    if constexpr (requires { probe.set_max_depth(1); }) probe.set_max_depth(kHistoryNesting);
    Output o;
    tracer::WhittedTracer<double, Probe> t(p.scene->scene, p.scene->plan.effects, o.pixel.counts, probe);
    o.pixel.rgb = t.sample(p.i, p.j, 0.0, 0.0);
    o.pixel.budget_spent = o.pixel.counts.budget_stops > 0;
    return o;
  }
  static Json to_json(const Output& o) {
    const tracer::RayCounts& c = o.pixel.counts;
    return {{"colour", {o.pixel.rgb.x, o.pixel.rgb.y, o.pixel.rgb.z}},
            {"rays", {{"primary", c.primary}, {"shadow", c.shadow}, {"shadow_blocked", c.shadow_blocked}, {"reflection", c.reflection}, {"refraction", c.refraction}}},
            {"budget_spent", o.pixel.budget_spent}};
  }
  static std::size_t ops(const Output&) { return 1; }
  static std::size_t estimate_steps(const Input& in) { return history_steps(in); }
  static constexpr std::array result_keys{std::string_view("colour")};  // the scene view shows the pixel's colour
  // The renderer's own pixel, untraced (tests/tracer/test_pixel_history.cpp holds it to render()).
  static Output oracle(const Input& in) { return {tracer::pixel_colour(*tracer::history_scene(in), in.i, in.j)}; }
  static std::vector<BenchSet<Input>> bench_sets() {
    BenchSet<Input> row{"glass-row", {}};
    const Json base = Json::parse(example);
    for (int i = 0; i < 80; i += 5) row.inputs.push_back(tracer::parse_history_input(tracer::with_pixel(base, i, 30)));
    return {row};
  }
};

SW_REGISTER(WhittedSpec);

}  // namespace

}  // namespace sw
