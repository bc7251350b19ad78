// The ray tracer in the catalog: `whitted`, one pixel's whole history (the primary ray's
// traversal and tests, the shading, every shadow, mirror and transmitted ray with its depth) as
// nested listings. Double only: the tracer's colours go through sqrt, pow and noise, and exact
// rationals would grow without bound over the recursion. Semantics: docs/tracer/renderer.md.
#include <cstdio>
#include <memory>
#include "register.hpp"
#include "tracer/history.hpp"
#include "tracer/ray_tree.hpp"

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

// The scene view's picture: the scene through each pixel's centre, with the planner's decisions.
Picture scene_picture(const HistoryInput& in, std::int64_t max_side) {
  const tracer::Preview p = tracer::render_preview(in, max_side);
  Picture pic{p.width, p.height, p.scale, p.rgb, p.seconds, "Planner", {}, {}, {}};
  if (p.plan.all_effects) pic.notes.push_back({"All effects on (all_effects): nothing planned away.", "", std::nullopt});
  for (const tracer::Decision& d : p.plan.decisions)
    pic.notes.push_back({d.effect + " for " + d.subject + ": " + (d.on ? "on" : "off"), d.reason, d.on});
  return pic;
}

// The ray tree (ray_tree.hpp) as the scene view's table: per ray its depth, kind, path weight,
// the colour found there and its share of the pixel; the shares' sum, the pixel's colour.
SummaryTable ray_tree_table(const HistoryInput& in, const TraceView& t) {
  using Node = tracer::RayNode;
  const std::vector<Node> tree = tracer::ray_tree(t, in.scene->lights);
  SummaryTable table{"Ray tree", {"ray", "depth", "kind", "weight", "found", "share"}, {}, std::nullopt};
  char buf[96];
  auto share = [&](const std::array<double, 3>& c) {
    std::snprintf(buf, sizeof buf, "%.3f %.3f %.3f", c[0], c[1], c[2]);
    return SummaryTable::Cell{buf, c};
  };
  for (std::size_t k = 0; k < tree.size(); ++k) {
    const Node& n = tree[k];
    SummaryTable::Row row{n.step, n.end, {}};
    row.cells.push_back({std::to_string(k), std::nullopt});
    row.cells.push_back({std::to_string(n.depth), std::nullopt});
    const bool shadow = n.kind == Node::Kind::shadow;
    if (shadow) std::snprintf(buf, sizeof buf, "shadow %lld: %s", (long long)n.light, n.hit ? "blocked" : "lit");
    else std::snprintf(buf, sizeof buf, "%s%s", std::string(tracer::kind_name(n.kind)).c_str(), n.hit ? "" : " (miss)");
    row.cells.push_back({buf, std::nullopt});
    std::snprintf(buf, sizeof buf, "%.4g", n.weight);
    row.cells.push_back({buf, std::nullopt});
    const bool found = !shadow && n.returned;
    row.cells.push_back(found ? SummaryTable::Cell{"", n.local} : SummaryTable::Cell{});
    row.cells.push_back(found ? share(n.added) : SummaryTable::Cell{});
    table.rows.push_back(std::move(row));
  }
  table.total = SummaryTable::Row{0, 0, {{"sum", std::nullopt}, {}, {}, {}, {}, share(tracer::ray_tree_sum(tree))}};
  return table;
}

struct WhittedSpec {
  static constexpr std::array hooks{Hook::estimate_steps, Hook::result_keys, Hook::picture, Hook::pick, Hook::summary_table, Hook::contract_inputs};
  using Algo = tracer::Whitted;
  using Input = HistoryInput;
  using Output = WhittedOutput;
  static constexpr std::array views{View::scene, View::orbit3d};
  static constexpr std::array numerics{Numeric::f64};
  // A pixel of the glass-spheres scene at 80x60 that sees the chrome sphere: a mirror ray, then
  // the floor and its shadow rays.
  static inline const std::string example = R"({"scene":"scenes/glass-spheres.json","size":[80,60],"pixel":[44,18]})";
  // The seeded row (y = 30) sees no glass and no sky: a pixel through the glass sphere (refract's
  // steps) and one of the background.
  static constexpr std::array contract_inputs{std::string_view(R"({"scene":"scenes/glass-spheres.json","size":[80,60],"pixel":[28,15]})"),
                                              std::string_view(R"({"scene":"scenes/glass-spheres.json","size":[80,60],"pixel":[40,2]})")};
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
  // The scene view: the picture, where a click traces the pixel clicked, and the ray tree.
  static Picture picture(const Input& in, std::int64_t max_side) { return scene_picture(in, max_side); }
  static constexpr std::string_view pick = "/pixel";
  static SummaryTable summary_table(const Input& in, const TraceView& t) { return ray_tree_table(in, t); }
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
// Whitted's callees that are no algorithm of their own: `list --listing refract`, and lessons' "refract/split".
SW_REGISTER_CALLEE(tracer::Refract);
SW_REGISTER_CALLEE(tracer::SceneHit);

}  // namespace

}  // namespace sw
