// The llvmpipe peer for the triangle fills (docs/fill/llvmpipe.md), shared by bench/peer_llvmpipe.cpp
// and tests/fill/test_llvmpipe_peer.cpp: the cases (random and hard) and the comparison of
// llvmpipe's pixels (llvmpipe_harness.hpp) with the exact oracle and the catalog's fills.
#pragma once
#include <map>
#include <random>
#include <string>
#include <string_view>
#include <vector>
#include "llvmpipe_harness.hpp"

namespace sw::peer {

// ---- cases ----

// Random numerators on a grid of 1/step_den px (step_den divides kDen) in [0, size].
class CaseMaker {
 public:
  explicit CaseMaker(std::uint64_t seed) : rng_(seed) {}

  std::int64_t coord(std::int64_t size_px, std::int64_t grid_den) {
    const std::int64_t step = kDen / grid_den;
    return std::uniform_int_distribution<std::int64_t>(0, size_px * grid_den)(rng_) * step;
  }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  Tri shuffled(Tri t) {
    std::shuffle(t.v.begin(), t.v.end(), rng_);  // both orientations
    return t;
  }
  std::int64_t grid_den() {
    static constexpr std::array<std::int64_t, 5> dens{1, 2, 16, 256, 256};
    return dens[std::size_t(pick(5))];
  }
  std::int64_t size_px() {
    static constexpr std::array<std::int64_t, 5> sizes{1, 3, 8, 24, 56};
    return sizes[std::size_t(pick(5))];
  }

  Tri random_tri(std::int64_t den, std::int64_t size) {
    Tri t;
    for (auto& p : t.v) p = {coord(size, den), coord(size, den)};
    return t;
  }
  // Right triangle: one horizontal and one vertical edge.
  Tri axis_aligned(std::int64_t den, std::int64_t size) {
    const std::int64_t x0 = coord(size, den), y0 = coord(size, den), x1 = coord(size, den), y1 = coord(size, den);
    return shuffled(Tri{{{{x0, y0}, {x1, y0}, {x0, y1}}}});
  }
  // An edge through a sample point that is not a vertex: a = s - k d, b = s + m d.
  Tri edge_through_sample(std::int64_t den) {
    const std::int64_t step = kDen / den;
    const std::int64_t sx = (20 + pick(9)) * kDen, sy = (20 + pick(9)) * kDen;
    std::int64_t dx = (pick(9) - 4) * step * (1 + pick(2)), dy = (pick(9) - 4) * step * (1 + pick(2));
    if (dx == 0 && dy == 0) dx = kDen;
    const std::int64_t k = 1 + pick(2), m = 1 + pick(2);  // |k d|, |m d| <= 16 px
    const std::array<std::int64_t, 2> a{sx - k * dx, sy - k * dy}, b{sx + m * dx, sy + m * dy};
    return shuffled(Tri{{{a, b, {coord(30, den), coord(30, den)}}}});
  }
  // Thinner than a pixel: the third vertex within 1/2 px of the long edge's midpoint.
  Tri sliver() {
    const std::array<std::int64_t, 2> a{coord(50, 256), coord(50, 256)}, b{coord(50, 256), coord(50, 256)};
    const std::int64_t off = (pick(128) + 1) * kSnap * (pick(2) ? 1 : -1);
    const std::int64_t mx = snap_numerator((a[0] + b[0]) / 2), my = snap_numerator((a[1] + b[1]) / 2);
    const bool steep = std::abs(b[1] - a[1]) > std::abs(b[0] - a[0]);
    return shuffled(Tri{{{a, b, {steep ? mx + off : mx, steep ? my : my + off}}}});
  }
  // Collinear or repeated vertices: covers nothing.
  Tri zero_area(std::int64_t den) {
    const std::int64_t step = kDen / den;
    const std::array<std::int64_t, 2> a{10 * kDen + coord(20, den), 10 * kDen + coord(20, den)};
    const std::int64_t dx = (pick(9) - 4) * step * (1 + pick(2)), dy = (pick(9) - 4) * step * (1 + pick(2));
    const std::int64_t k = pick(4) - 1, m = pick(4) + 2;  // c may repeat a (k = 0)
    return shuffled(Tri{{{a, {a[0] + m * dx, a[1] + m * dy}, {a[0] + k * dx, a[1] + k * dy}}}});
  }
  // 64 triangles around one vertex, rim points rounded to 1/den. The rim spacing (2 pi r / 64) stays
  // above twice the rounding shift (sqrt(2) / (2 den)), so the angles keep increasing.
  std::vector<Tri> fan64(std::int64_t den) {
    const std::int64_t cx = 28 * kDen + (den == 1 ? 0 : coord(1, den)), cy = 28 * kDen + (den == 1 ? 0 : coord(1, den));
    const double radius = den == 1 ? 20 + pick(6) : 12 + pick(14);
    const double phase = pick(1000) * 1e-3;
    std::vector<std::array<std::int64_t, 2>> rim;
    for (int k = 0; k < 64; ++k) {
      const double angle = phase + 2 * M_PI * k / 64;
      const auto on_grid = [&](double px) { return std::int64_t(std::llround(px * double(den))) * (kDen / den); };
      rim.push_back({cx + on_grid(radius * std::cos(angle)), cy + on_grid(radius * std::sin(angle))});
    }
    std::vector<Tri> fan;
    for (int k = 0; k < 64; ++k) fan.push_back(Tri{{{{cx, cy}, rim[std::size_t(k)], rim[std::size_t((k + 1) % 64)]}}});
    return fan;
  }
  // A jittered 4 x 4 grid of quads, each split along a diagonal: 32 triangles with shared edges.
  std::vector<Tri> mesh(std::int64_t den) {
    std::array<std::array<std::array<std::int64_t, 2>, 5>, 5> p{};
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) {
        const std::int64_t jitter = den == 1 ? 0 : 3 * kDen;
        const auto jit = [&] { return jitter ? coord(6, den) - jitter : 0; };
        p[j][i] = {(4 + 12 * i) * kDen + jit(), (4 + 12 * j) * kDen + jit()};
      }
    std::vector<Tri> out;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        const auto a = p[j][i], b = p[j][i + 1], c = p[j + 1][i + 1], d = p[j + 1][i];
        if (pick(2)) out.push_back(Tri{{{a, b, c}}}), out.push_back(Tri{{{a, c, d}}});
        else out.push_back(Tri{{{a, b, d}}}), out.push_back(Tri{{{b, c, d}}});
      }
    return out;
  }
  // Off llvmpipe's grid: numerators over 4096 that are not all multiples of 16.
  Tri off_grid(std::int64_t size) {
    Tri t = random_tri(kDen, size);
    if (on_llvmpipe_grid(t)) t.v[0][0] += 1;
    return t;
  }

 private:
  std::mt19937_64 rng_;
};

// On-grid random and hard cases: about `triangles` triangles. Fans and meshes come twice: as one
// group (counts: no double hit, no gap) and as singletons (each triangle's own set).
inline std::vector<Group> on_grid_cases(std::size_t triangles, std::uint64_t seed) {
  CaseMaker make(seed);
  std::vector<Group> groups;
  std::size_t count = 0;
  const auto add = [&](Tri t, const char* kind) {
    groups.push_back(Group{{t}, kind});
    ++count;
  };
  for (std::size_t round = 0; count < triangles && round < triangles; ++round) {
    const std::int64_t den = make.grid_den();
    switch (round % 16) {
      case 0:
      case 1:
      case 2:
      case 3:
      case 4:
      case 5: add(make.random_tri(den, make.size_px()), "random"); break;
      case 6: add(make.random_tri(1, make.size_px()), "vertices on samples"); break;
      case 7: add(make.edge_through_sample(den), "edge through a sample"); break;
      case 8: add(make.edge_through_sample(1), "edge through a sample"); break;
      case 9:
      case 10: add(make.axis_aligned(den, make.size_px()), "horizontal and vertical edges"); break;
      case 11: add(make.sliver(), "sliver"); break;
      case 12: add(make.zero_area(den), "zero area"); break;
      case 13: add(make.random_tri(2, make.size_px()), "half-integer vertices"); break;
      case 14:
      case 15: {
        if (round % 64 != 14 && round % 64 != 15) {
          add(make.random_tri(den, make.size_px()), "random");
          break;
        }
        const bool fan = round % 64 == 14;
        const std::int64_t group_den = std::array<std::int64_t, 3>{1, 16, 256}[std::size_t(make.pick(3))];
        std::vector<Tri> tris = fan ? make.fan64(group_den) : make.mesh(group_den);
        const char* kind = fan ? "fan of 64" : "mesh of 32 (shared edges)";
        groups.push_back(Group{tris, kind});
        for (const Tri& t : tris) add(t, kind);
        break;
      }
    }
  }
  return groups;
}

// Up to 240 px (cells of 256): several tiles each, whole tiles covered; random, axis-aligned, fans.
inline std::vector<Group> large_cases(std::size_t triangles, std::uint64_t seed) {
  CaseMaker make(seed);
  std::vector<Group> groups;
  for (std::size_t k = 0; k < triangles; ++k) {
    const std::int64_t den = make.grid_den(), size = 64 + make.pick(177);
    if (k % 4 == 3) groups.push_back(Group{{make.axis_aligned(den, size)}, "large, horizontal and vertical edges"});
    else groups.push_back(Group{{make.random_tri(den, size)}, "large, random"});
  }
  return groups;
}

inline std::vector<Group> off_grid_cases(std::size_t triangles, std::uint64_t seed) {
  CaseMaker make(seed);
  std::vector<Group> groups;
  for (std::size_t k = 0; k < triangles; ++k) groups.push_back(Group{{make.off_grid(make.size_px())}, "off grid (1/4096)"});
  return groups;
}

// ---- comparison ----

struct Difference {
  std::size_t group = 0;
  Pixel sample;
  int llvmpipe = 0, exact = 0;  // counts
  std::string why;
};

inline std::map<Pixel, int> oracle_counts(const Group& g, bool snap) {
  std::map<Pixel, int> counts;
  for (const Tri& t : g.tris)
    for (const Pixel& p : oracle_samples(snap ? snapped(t) : t)) ++counts[p];
  return counts;
}

// Classifies a differing sample with the exact oracle: the snapped triangle's exact answer explains
// it, or the sample lies exactly on a vertex or an edge (a tie rule), or neither.
inline std::string classify(const Group& g, Pixel s, int llvmpipe_count) {
  bool all_on_grid = true;
  for (const Tri& t : g.tris) all_on_grid = all_on_grid && on_llvmpipe_grid(t);
  if (!all_on_grid) {
    const auto snapped_counts = oracle_counts(g, true);
    const auto it = snapped_counts.find(s);
    if ((it == snapped_counts.end() ? 0 : it->second) == llvmpipe_count) return "llvmpipe snapped a vertex";
  }
  Contact worst = Contact::none;
  for (const Tri& t : g.tris) worst = std::max(worst, contact(all_on_grid ? t : snapped(t), s));
  switch (worst) {
    case Contact::vertex: return "tie rule differs at a vertex";
    case Contact::horizontal_edge: return "tie rule differs on a horizontal edge";
    case Contact::other_edge: return "tie rule differs on a sloped or vertical edge";
    case Contact::none: break;
  }
  return "other";
}

struct Comparison {
  std::size_t triangles = 0, groups = 0, exact_pixels = 0, differing = 0;
  std::map<std::string, std::size_t> classes;  // differing samples per class
  std::map<std::string, std::size_t> kinds;    // differing samples per case kind
  std::vector<Difference> examples;            // the first few
};

// against_snapped: the exact side is the oracle on the snapped vertices (llvmpipe's own input).
inline Comparison compare(Llvmpipe& gl, const std::vector<Group>& groups, bool mirror_y, std::size_t max_examples = 8,
                          bool against_snapped = false, Layout layout = {}) {
  Comparison out;
  out.groups = groups.size();
  const auto covered = gl.cover(groups, mirror_y, layout);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    out.triangles += groups[g].tris.size();
    const auto exact = oracle_counts(groups[g], against_snapped);
    for (const auto& [p, c] : exact) out.exact_pixels += std::size_t(c);
    std::map<Pixel, std::pair<int, int>> both;  // llvmpipe, exact
    for (const auto& [p, c] : covered[g]) both[p].first = c;
    for (const auto& [p, c] : exact) both[p].second = c;
    for (const auto& [p, lc] : both) {
      if (lc.first == lc.second) continue;
      ++out.differing;
      const std::string why = classify(groups[g], p, lc.first);
      ++out.classes[why];
      ++out.kinds[groups[g].kind];
      if (out.examples.size() < max_examples) out.examples.push_back(Difference{g, p, lc.first, lc.second, why});
    }
  }
  return out;
}

// A catalog fill against llvmpipe on the groups of one triangle: run untraced in int mode (exact on
// the grid) if it has one, else filtered; input coordinates as exact "n/4096" strings.
struct CatalogComparison {
  bool found = false;
  std::string numeric, first_error;
  std::size_t triangles = 0, pixels = 0, differing = 0, errors = 0;
};

inline CatalogComparison compare_catalog(Llvmpipe& gl, const std::vector<Group>& groups, std::string_view id, bool mirror_y) {
  CatalogComparison out;
  const Algorithm* alg = nullptr;
  try {
    alg = &find_algorithm(id);
  } catch (const std::exception&) {
    return out;  // not registered (yet)
  }
  out.found = true;
  const Numeric numeric = alg->supports(Numeric::integer) ? Numeric::integer : Numeric::filtered;
  out.numeric = numeric_name(numeric);
  std::vector<Group> singles;
  for (const Group& g : groups)
    if (g.tris.size() == 1) singles.push_back(g);
  const auto covered = gl.cover(singles, mirror_y);
  const auto text = [](std::int64_t n) { return std::to_string(n) + "/" + std::to_string(kDen); };
  for (std::size_t g = 0; g < singles.size(); ++g) {
    ++out.triangles;
    Json tri = Json::array();
    for (const auto& p : singles[g].tris[0].v) tri.push_back({text(p[0]), text(p[1])});
    std::map<Pixel, std::pair<int, int>> both;  // llvmpipe, ours
    for (const auto& [p, c] : covered[g]) both[p].first = c;
    try {
      const Json result = (*alg).open(Json{{"triangle", tri}}, numeric).run();
      for (const auto& px : result.at("pixels")) ++both[Pixel{px.at(0).get<std::int64_t>(), px.at(1).get<std::int64_t>()}].second;
    } catch (const std::exception& e) {
      if (out.errors++ == 0) out.first_error = e.what();
      continue;
    }
    for (const auto& [p, lo] : both) out.pixels += std::size_t(lo.second), out.differing += lo.first != lo.second;
  }
  return out;
}

}  // namespace sw::peer
