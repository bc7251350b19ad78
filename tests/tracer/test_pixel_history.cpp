// The catalog's `whitted`: one pixel's recorded history. The expected rays come from the scene's
// geometry worked out by hand (scenes/glass-spheres.json at 80x60, camera at (0, 2, 8) looking
// along -(0, 0.3, 1), fov 45): pixel (44, 18) looks at the chrome sphere (centre (0.5, 1.2, -2.5),
// r 1.2, kr 0.85); pixel (62, 27) at the floor point near (2.44, 0, 0.39), from which the segment
// to the point light (-3, 6, 4) passes through the water sphere (centre (1.3, 0.7, 1), r 0.7) while
// the directional light (1, 2, 1) is in the clear.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include "catalog.hpp"
#include "tracer/history.hpp"
#include "tracer/ray_tree.hpp"

using namespace sw;
using tracer::RayNode;

namespace {

Json input(int i, int j) { return {{"scene", "scenes/glass-spheres.json"}, {"size", {80, 60}}, {"pixel", {i, j}}}; }

std::vector<RayNode> tree_of(const Json& in, const Recorded& rec) {
  return tracer::ray_tree(*rec.trace, tracer::parse_history_input(in).scene->lights);
}

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

}  // namespace

TEST_CASE("pixel history: a pixel on the chrome sphere has a depth-2 mirror ray of weight kr", "[tracer][history]") {
  const Algorithm& alg = find_algorithm("whitted");
  const Recorded rec = alg.open(input(44, 18), Numeric::f64).record();
  const auto tree = tree_of(input(44, 18), rec);
  REQUIRE(!tree.empty());
  CHECK(tree[0].kind == RayNode::Kind::primary);
  CHECK(tree[0].depth == 1);
  CHECK(distance(tree[0].at, {0.5, 1.2, -2.5}) == Approx(1.2).epsilon(1e-12));  // on the chrome sphere
  CHECK(tree[0].weight == 1);
  const auto mirror = std::find_if(tree.begin(), tree.end(), [](const RayNode& n) { return n.kind == RayNode::Kind::mirror; });
  REQUIRE(mirror != tree.end());
  CHECK(mirror->depth == 2);
  CHECK(mirror->parent == 0);
  CHECK(mirror->weight == Approx(0.85).epsilon(1e-15));  // kr = 0.85, kt = 0
  CHECK(mirror->step > tree[0].step);
  // The shares sum to the pixel's colour, and that colour is the renderer's pixel.
  const auto sum = tracer::ray_tree_sum(tree);
  const Json& c = rec.result["colour"];
  for (std::size_t k = 0; k < 3; ++k) CHECK(sum[k] == Approx(c[k].get<double>()).margin(1e-12));
  tracer::HistoryInput in = tracer::parse_history_input(input(44, 18));
  tracer::Scene centres = *in.scene;
  centres.sampling = tracer::Sampling{};
  tracer::RenderOptions opt;
  opt.width = 80, opt.height = 60;
  const tracer::RenderResult r = tracer::render(centres, opt);
  const Vec3<double> px = r.rgb[18 * 80 + 44];
  CHECK(px.x == c[0].get<double>());
  CHECK(px.y == c[1].get<double>());
  CHECK(px.z == c[2].get<double>());
}

TEST_CASE("pixel history: a floor pixel under the water sphere has a blocked shadow ray to the point light", "[tracer][history]") {
  const Recorded rec = find_algorithm("whitted").open(input(62, 27), Numeric::f64).record();
  const auto tree = tree_of(input(62, 27), rec);
  REQUIRE(!tree.empty());
  CHECK(tree[0].at[1] == Approx(0).margin(1e-12));  // on the floor
  std::vector<const RayNode*> shadows;
  for (const RayNode& n : tree)
    if (n.kind == RayNode::Kind::shadow && n.parent == 0) shadows.push_back(&n);
  REQUIRE(shadows.size() == 2);
  CHECK(shadows[0]->light == 0);
  CHECK(shadows[0]->hit);  // blocked by the water sphere
  CHECK(shadows[1]->light == 1);
  CHECK(!shadows[1]->hit);
  CHECK(rec.result["rays"]["shadow_blocked"] == 1);
  // The blocking hit, in the nested scene-hit listing, is object 2 (the water sphere).
  bool water = false;
  const TraceView& t = *rec.trace;
  for (std::size_t s = 0; s < shadows[0]->step; ++s) {
    const StepRecord& st = t.at(s);
    if (st.scope && t.scope_id(st.scope) == "scene-hit" && t.scope_listing(st.scope).lines[st.line - 1].name == "any")
      for (std::uint32_t v = st.var_begin; v < st.var_end; ++v)
        if (std::string_view(t.var_at(v).name) == "k") water = t.value_double(t.var_at(v)) == 2;
  }
  CHECK(water);
  // No mirror ray: the floor's kr and kt are 0, and the planner turned reflection off for it.
  for (const RayNode& n : tree) CHECK(n.kind != RayNode::Kind::mirror);
}

TEST_CASE("pixel history: bad input is one line naming the JSON path", "[tracer][history]") {
  const Algorithm& alg = find_algorithm("whitted");
  auto message = [&](const std::string& text) {
    try {
      (void)alg.open(Json::parse(text), Numeric::f64);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK_THAT(message(R"({"scene":"scenes/glass-spheres.json","pixel":[320,0]})"), Catch::StartsWith("input.pixel[0]"));
  CHECK_THAT(message(R"({"scene":"scenes/glass-spheres.json","pixel":[0,0],"size":[0,5]})"), Catch::StartsWith("input.size[0]"));
  CHECK_THAT(message(R"({"scene":"scenes/glass-spheres.json","pixel":[0,0],"offset":"tiny"})"), Catch::StartsWith("input.offset"));
  CHECK_THAT(message(R"({"scene":{"camera":{}},"pixel":[0,0]})"), Catch::StartsWith("input.scene"));
  CHECK_THAT(message(R"({"scene":"scenes/glass-spheres.json"})"), Catch::Contains("pixel"));
  CHECK_THAT(message(R"({"scene":"scenes/glass-spheres.json","pixel":[0,0],"all_effects":1})"), Catch::StartsWith("input.all_effects"));
  CHECK(message(R"({"scene":"scenes/glass-spheres.json","pixel":[0,0]})") == "accepted");
  for (const std::string& m : {message(R"({"scene":3,"pixel":[0,0]})"), message(R"({"scene":"scenes/none.json","pixel":[0,0]})")})
    CHECK(m.find('\n') == std::string::npos);
}

// The tree reads no variable's name (ray_tree.hpp): were the colours recorded under another name,
// or the weights no longer on the mirror and transmitted rays, the shares would no longer sum to
// the pixel's colour. Every case of the tracer corpus, and the chrome sphere's mirror ray.
TEST_CASE("pixel history: the ray tree's colours and weights are there, and its shares sum to the pixel", "[tracer][history]") {
  const Algorithm& alg = find_algorithm("whitted");
  std::vector<Json> inputs{input(44, 18)};
  std::ifstream corpus(std::string(SW_SOURCE_DIR) + "/tests/cases/tracer/corpus.jsonl");
  for (std::string line; std::getline(corpus, line);)
    if (!line.empty()) inputs.push_back(Json::parse(line)["input"]);
  REQUIRE(inputs.size() >= 5);
  std::size_t lit = 0, transmitted = 0;
  for (const Json& in : inputs) {
    INFO(in.dump());
    const Recorded rec = alg.open(in, Numeric::f64).record();
    const auto tree = tree_of(in, rec);
    REQUIRE(!tree.empty());
    const Json& c = rec.result["colour"];
    const auto sum = tracer::ray_tree_sum(tree);
    for (std::size_t k = 0; k < 3; ++k) CHECK(sum[k] == Approx(c[k].get<double>()).margin(1e-12));
    lit += sum[0] + sum[1] + sum[2] > 0;
    for (const RayNode& n : tree) {
      if (n.kind == RayNode::Kind::shadow) {
        CHECK(n.light >= 0);
        continue;
      }
      CHECK(n.returned);
      CHECK(n.weight >= 0);
      transmitted += n.kind == RayNode::Kind::transmitted;
    }
  }
  CHECK(lit >= inputs.size() - 1);  // the shares are not empty: the colours are there
  CHECK(transmitted >= 1);          // the glass pixel's
}
