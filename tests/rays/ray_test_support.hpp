// Shared by the ray family's tests: the corpus reader, exact result comparison, and small exact
// vector helpers for the closed-form expectations.
#pragma once
#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <string>
#include <vector>
#include "catalog.hpp"

namespace sw::testing::rays {

using V3 = Vec3<Rational>;

inline const std::map<std::string, std::vector<std::string>> kAlgs = {
    {"triangle", {"ray-triangle-barycentric", "ray-triangle-mt", "ray-triangle-watertight"}},
    {"sphere", {"ray-sphere-geometric", "ray-sphere-quadratic", "ray-sphere-stable"}},
    {"box", {"ray-box"}},
    {"plane", {"ray-plane"}}};

inline std::vector<Json> read_jsonl(const std::string& name) {
  std::ifstream f(std::string(SW_SOURCE_DIR) + "/tests/cases/rays/" + name);
  REQUIRE(f.good());
  std::vector<Json> out;
  for (std::string line; std::getline(f, line);)
    if (!line.empty()) out.push_back(Json::parse(line));
  return out;
}

inline Rational q(const Json& v) { return parse_rational(v, "value"); }

// Results agree: hit, and every reported number as an exact rational.
inline bool same_result(const Json& got, const Json& want) {
  if (got.at("hit") != want.at("hit")) return false;
  for (const char* k : {"t", "t_near", "t_far"})
    if (want.contains(k) && (!got.contains(k) || q(got[k]) != q(want[k]))) return false;
  if (want.contains("b"))
    for (int i = 0; i < 3; ++i)
      if (q(got["b"][i]) != q(want["b"][i])) return false;
  if (want.contains("attr") != got.contains("attr")) return false;
  if (want.contains("attr"))
    for (std::size_t k = 0; k < want["attr"].size(); ++k)
      if (q(got["attr"][k]) != q(want["attr"][k])) return false;
  return true;
}

inline V3 sub(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Rational dotq(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 crossq(const V3& a, const V3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline const V3 kAxis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

struct Parsed {
  V3 o, d;
  std::array<V3, 3> v;
  Rational r;
};
inline Parsed parse(const Json& in, const std::string& prim) {
  Parsed p;
  p.o = parse_point3(in["ray"], "o");
  p.d = parse_point3(in["ray"], "d");
  const Json& g = in[prim];
  if (prim == "triangle")
    for (int i = 0; i < 3; ++i) p.v[i] = {q(g[i][0]), q(g[i][1]), q(g[i][2])};
  if (prim == "sphere") p.v[0] = parse_point3(g, "c"), p.r = q(g["r"]);
  if (prim == "box") p.v[0] = parse_point3(g, "min"), p.v[1] = parse_point3(g, "max");
  if (prim == "plane") p.v[0] = parse_point3(g, "p"), p.v[1] = parse_point3(g, "n");
  return p;
}

// |x - y| <= 2^-200 max(|y|, 1): for values that went through a 300-bit square root.
inline bool close(const Rational& x, const Rational& y) {
  Rational scale = abs(y) > 1 ? Rational(abs(y)) : Rational(1);
  Rational tol = scale;
  mpq_div_2exp(tol.get_mpq_t(), tol.get_mpq_t(), 200);
  return abs(Rational(x - y)) <= tol;
}


}  // namespace sw::testing::rays
