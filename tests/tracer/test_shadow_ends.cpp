// Where a shadow ray ends: a directional light's at infinity (an occluder however far along the
// light's direction blocks it), a point light's at the light (an occluder beyond it does not), and
// neither looks backwards. One pixel of `whitted` on a receiver at z = 0, seen head-on.
#include <catch2/catch.hpp>
#include "catalog.hpp"

using namespace sw;

namespace {

// The shadow rays cast and blocked for the centre pixel, with `light` and a unit sphere at `occluder`.
std::pair<std::int64_t, std::int64_t> shadows(const Json& light, const Json& occluder) {
  Json scene = Json::parse(R"({"camera":{"eye":[0,0,5],"vpn":[0,0,1],"vup":[0,1,0],"d":1,"fov":40,"resolution":[9,9]},
    "materials":{"m":{"diffuse":[0.5,0.5,0.5]}},"max_depth":1,
    "objects":[{"type":"triangle","vertices":[[-10,-10,0],[10,-10,0],[0,10,0]],"material":"m"}]})");
  scene["lights"] = Json::array({light});
  scene["objects"].push_back({{"type", "sphere"}, {"center", occluder}, {"radius", 1}, {"material", "m"}});
  const Json r = find_algorithm("whitted").open({{"pixel", {4, 4}}, {"scene", scene}}, Numeric::f64).run();
  return {r["rays"]["shadow"].get<std::int64_t>(), r["rays"]["shadow_blocked"].get<std::int64_t>()};
}

}  // namespace

TEST_CASE("shadow rays: a directional light's reach infinity, a point light's end at the light", "[tracer][shadow]") {
  const Json sun = {{"type", "directional"}, {"direction", {1, 0, 1}}};
  // Along (1, 0, 1) from the hit point (0, 0, 0): near (t ~ 0.3 of the direction) and far (t ~ 29).
  CHECK(shadows(sun, {1, 0, 1}) == std::pair<std::int64_t, std::int64_t>{1, 1});
  CHECK(shadows(sun, {30, 0, 30}) == std::pair<std::int64_t, std::int64_t>{1, 1});
  CHECK(shadows(sun, {-30, 0, 30}).second == 0);  // off the ray (the planner may skip the ray altogether)
  const Json bulb = {{"type", "point"}, {"position", {4, 0, 4}}};
  CHECK(shadows(bulb, {2, 0, 2}) == std::pair<std::int64_t, std::int64_t>{1, 1});    // between: blocks
  CHECK(shadows(bulb, {8, 0, 8}).second == 0);                                        // beyond the light: does not
}
