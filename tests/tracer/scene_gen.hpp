// Random ray-tracer scenes for the planner's proof and its benchmark: a seeded mix of spheres,
// boxes, triangles and planes, mirrors and glass, point, directional and spot lights. Half are
// sparse (small objects far apart, no floor), where shadow proofs can succeed; half stand on a floor.
#pragma once
#include <random>
#include <string>
#include "input.hpp"

namespace sw::testing {

inline Json random_scene(std::uint32_t seed, int width, int height) {
  std::mt19937 rng(seed);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  auto half = [&](int lo, int hi) { return Json(uni(2 * lo, 2 * hi) / 2.0); };  // exact in binary
  auto point = [&](int r) { return Json::array({half(-r, r), half(-r, r), half(-r, r)}); };
  auto colour = [&] { return Json::array({uni(1, 8) / 8.0, uni(1, 8) / 8.0, uni(1, 8) / 8.0}); };
  const bool sparse = seed % 2 == 0;
  Json s;
  const int er = 14;
  s["camera"] = {{"eye", {uni(-er, er), uni(2, er), er}}, {"vpn", {0, 1, 2}}, {"vup", {0, 1, 0}}, {"d", 1}, {"fov", 60},
                 {"resolution", {width, height}}};
  Json mats = Json::object();
  const int nm = uni(1, 4);
  static const char* spec[] = {"none", "phong", "blinn-phong", "cook-torrance"};
  for (int k = 0; k < nm; ++k) {
    Json m = {{"diffuse", colour()}};
    const int kr = uni(0, 3) == 0 ? uni(1, 2) : 0, kt = uni(0, 3) == 0 ? uni(1, 2) : 0;  // quarters, kr + kt <= 1
    if (kr) m["kr"] = std::to_string(kr) + "/4";
    if (kt) m["kt"] = std::to_string(kt) + "/4";
    if (kt) m["ior"] = uni(0, 1) ? Json(1.5) : Json("4/3");
    const int sp = uni(0, 3);
    if (sp) m["specular_model"] = spec[sp], m["specular"] = colour(), m["shininess"] = 20;
    if (uni(0, 5) == 0) m["fresnel"] = "schlick";
    mats["m" + std::to_string(k)] = m;
  }
  s["materials"] = mats;
  auto mat = [&] { return "m" + std::to_string(uni(0, nm - 1)); };
  Json objs = Json::array();
  if (!sparse) objs.push_back({{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", mat()}});
  const int no = uni(1, 6);
  const int spread = sparse ? 12 : 4;
  for (int k = 0; k < no; ++k) {
    const Json c = sparse ? point(spread) : Json::array({half(-spread, spread), uni(1, 3), half(-spread, spread)});
    switch (uni(0, 2)) {
      case 0: objs.push_back({{"type", "sphere"}, {"center", c}, {"radius", uni(1, 4) / 4.0}, {"material", mat()}}); break;
      case 1: {
        const double x = c[0], y = c[1], z = c[2], h = uni(1, 4) / 4.0;
        objs.push_back({{"type", "box"}, {"min", {x - h, y - h, z - h}}, {"max", {x + h, y + h, z + h}}, {"material", mat()}});
        break;
      }
      default: {
        const double x = c[0], y = c[1], z = c[2];
        objs.push_back({{"type", "triangle"}, {"vertices", {{x - 1, y, z}, {x + 1, y, z + 0.5}, {x, y + 1, z - 0.5}}}, {"material", mat()}});
      }
    }
  }
  s["objects"] = objs;
  Json lights = Json::array();
  const int nl = uni(1, 3);
  for (int k = 0; k < nl; ++k) {
    switch (uni(0, 2)) {
      case 0: lights.push_back({{"type", "point"}, {"position", {half(-10, 10), uni(4, 12), half(-10, 10)}}}); break;
      case 1: lights.push_back({{"type", "directional"}, {"direction", {half(-2, 2), uni(1, 3), half(-2, 2)}}}); break;
      default:
        lights.push_back({{"type", "spot"}, {"position", {half(-6, 6), uni(5, 10), half(-6, 6)}}, {"spot_direction", {0, -1, 0}}, {"cutoff", uni(20, 70)}});
    }
  }
  s["lights"] = lights;
  s["max_depth"] = uni(1, 5);
  return s;
}

}  // namespace sw::testing
