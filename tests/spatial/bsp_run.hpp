// Shared by the BSP tests: inputs as JSON, a run's fragments and order read back exactly from the
// result, and the independent oracle's verdict on them (oracle/spatial_bsp_oracle.hpp).
#pragma once
#include <array>
#include <optional>
#include <random>
#include <string>
#include <vector>
#include "catalog.hpp"
#include "spatial_bsp_oracle.hpp"

namespace sw::testing::bsp {

using Seg = std::array<double, 4>;  // x0 y0 x1 y1

inline Json input_json(const std::vector<Seg>& segs, std::optional<std::array<double, 2>> eye = std::nullopt) {
  Json s = Json::array();
  for (const Seg& g : segs) s.push_back({{g[0], g[1]}, {g[2], g[3]}});
  Json in{{"segments", s}};
  if (eye) in["eye"] = {(*eye)[0], (*eye)[1]};
  return in;
}

inline Rational q(const Json& v) { return parse_rational(v, "value"); }

inline std::vector<oracle::Seg2Q> segments_of(const std::vector<Seg>& segs) {
  std::vector<oracle::Seg2Q> out;
  for (const Seg& g : segs) out.push_back({{num::to_rational(g[0]), num::to_rational(g[1])}, {num::to_rational(g[2]), num::to_rational(g[3])}});
  return out;
}

inline std::vector<oracle::FragmentQ> fragments_of(const Json& result) {
  std::vector<oracle::FragmentQ> out;
  for (const Json& f : result.at("fragments")) out.push_back({f.at("seg").get<std::int32_t>(), {q(f["a"][0]), q(f["a"][1])}, {q(f["b"][0]), q(f["b"][1])}});
  return out;
}

// One run judged by the oracle: "" when the fragments cover the segments exactly and (for the
// painter) the order is valid, else why not (a rounded mode may also pass its fragment budget).
struct Verdict {
  std::string cover;
  oracle::OrderCheck order;
  bool budget = false;
  bool ok() const { return cover.empty() && order.violations == 0 && !budget; }
};

inline Verdict judge(const std::string& id, const std::vector<Seg>& segs, std::optional<std::array<double, 2>> eye, Numeric n, Json* result = nullptr) {
  Verdict v;
  Json r;
  try {
    r = find_algorithm(id).open(input_json(segs, eye), n).run();
  } catch (const InputError&) {
    v.budget = true;
    return v;
  }
  const auto frags = fragments_of(r);
  v.cover = oracle::fragments_cover(segments_of(segs), frags);
  if (eye) v.order = oracle::painter_order({num::to_rational((*eye)[0]), num::to_rational((*eye)[1])}, frags, r.at("order").get<std::vector<std::int32_t>>());
  if (result) *result = r;
  return v;
}

// n random segments: long ones across [-50, 50]^2 (crossing), or one inside each cell of a grid of
// 10 x 10 cells (no two meet). Ends on a 1/den grid (den = 0: full-precision doubles).
inline std::vector<Seg> random_segments(std::mt19937_64& rng, std::size_t n, bool crossing, double den) {
  std::uniform_real_distribution<double> u(0, 1);
  auto g = [&](double x) { return den > 0 ? std::floor(x * den) / den : x; };
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  std::vector<Seg> out;
  while (out.size() < n) {
    const std::size_t i = out.size();
    Seg s;
    if (crossing) {
      for (double& x : s) x = g(-50 + 100 * u(rng));
    } else {
      const double cx = static_cast<double>(i % side) * 10, cy = static_cast<double>(i / side) * 10;
      s = {g(cx + 1 + 8 * u(rng)), g(cy + 1 + 8 * u(rng)), g(cx + 1 + 8 * u(rng)), g(cy + 1 + 8 * u(rng))};
    }
    if (s[0] != s[2] || s[1] != s[3]) out.push_back(s);
  }
  return out;
}

}  // namespace sw::testing::bsp
