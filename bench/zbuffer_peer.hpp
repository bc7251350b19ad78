// The z-buffer's llvmpipe peer (docs/pipeline/llvmpipe.md), shared by bench/peer_llvmpipe_zbuffer.cpp
// and tests/pipeline/test_llvmpipe_zbuffer_peer.cpp: each case drawn by llvmpipe, by its float
// arithmetic written out, by our z-buffer (exact and float), and every pixel where llvmpipe (or our
// float mode) shows another triangle than our exact mode classified by the exact oracle.
#pragma once
#include <algorithm>
#include <map>
#include <string>
#include <vector>
#include "fill_oracle.hpp"
#include "zbuffer_llvmpipe_float.hpp"

namespace sw::zpeer {

inline constexpr const char* kCoverage = "coverage differs";
inline constexpr const char* kTie = "exact depth tie (order decides)";
inline constexpr const char* kWithin = "depths within one step + float error";
inline constexpr const char* kOffsetUnits = "offset units (llvmpipe's r is 2/(2^n - 1))";
inline constexpr const char* kOther = "other";

struct Tally {
  std::size_t cases = 0, triangles = 0, fragments = 0, differing = 0;
  std::size_t coverage_pass = 0;                      // samples whose count of covering triangles differs (depth test off)
  std::size_t emulation = 0;                          // samples where the float emulation's id or depth is not llvmpipe's
  std::size_t bound_violations = 0;                   // fragments whose float depth lies farther than the bound from the plane
  double worst_bound_use = 0;                         // the largest |float depth - exact| / bound
  std::size_t oracle_cases = 0, exact_vs_oracle = 0;  // samples where our exact mode's id is not the oracle's
  std::size_t float_differing = 0;                    // samples where our float mode's id is not exact mode's
  std::map<std::string, std::size_t> classes, float_classes;
  std::vector<double> margins;                  // in steps, at llvmpipe's differing samples
  std::map<std::string, std::string> examples;  // the first pixel of each class
  void add(const Tally& o) {
    cases += o.cases, triangles += o.triangles, fragments += o.fragments, differing += o.differing;
    coverage_pass += o.coverage_pass, emulation += o.emulation, bound_violations += o.bound_violations;
    worst_bound_use = std::max(worst_bound_use, o.worst_bound_use);
    oracle_cases += o.oracle_cases, exact_vs_oracle += o.exact_vs_oracle, float_differing += o.float_differing;
    for (const auto& [k, n] : o.classes) classes[k] += n;
    for (const auto& [k, n] : o.float_classes) float_classes[k] += n;
    margins.insert(margins.end(), o.margins.begin(), o.margins.end());
    examples.insert(o.examples.begin(), o.examples.end());
  }
};

inline Rational steps_of(int bits) { return Rational((std::int64_t(1) << bits) - 1); }

// Triangle t's fragment at sample (i, j), from the oracle: t alone, moved so that (i, j) is the
// one sample of a 1 x 1 window, no quantization (its r is then 2^-24, so units are rescaled to r
// = per_unit / M), GL_LEQUAL against a clear depth of 1 so that any covering fragment is kept.
struct Fragment {
  bool covered = false;
  Rational z;
};
inline Fragment oracle_fragment(const ZTri& t, std::int64_t i, std::int64_t j, int bits, int per_unit) {
  ZTri moved = t;
  for (auto& p : moved.v) p[0] -= i * kXY, p[1] -= j * kXY;
  pipeline_oracle::DepthTriangle d = oracle_tri(moved, 0);
  d.units = Rational(t.units * per_unit) * Rational(kZ) / steps_of(bits);
  const auto img = pipeline_oracle::z_buffer(1, 1, {d}, 0, true, Rational(1));
  return Fragment{img.ids[0] >= 0, img.depth[0]};
}

// Why sample (i, j) shows triangle `shown` rather than our exact mode's `exact` (-1: the clear
// depth), by the oracle's fragments. bound(k): the float error of triangle k's fragment there;
// slack: the conversion's, in steps. Two fragments whose exact depths lie within one step plus
// both errors can come out in either order; farther apart, only in the exact one.
template <class Bound> std::string classify(const ZCase& c, std::int64_t shown, std::int64_t exact, std::int64_t i,
                                            std::int64_t j, Bound&& bound, double slack, bool offset_units,
                                            double& margin_steps) {
  const int bits = c.cfg.bits;
  const double M = double((std::int64_t(1) << bits) - 1);
  const auto frag = [&](std::int64_t id, int per_unit) {
    return id < 0 ? Fragment{true, clear_q(c.cfg)} : oracle_fragment(c.tris[std::size_t(id)], i, j, bits, per_unit);
  };
  const Fragment s = frag(shown, 1), e = frag(exact, 1);
  if (!s.covered || !e.covered) return kCoverage;
  const double margin = (1 + 2 * slack) / M + (shown < 0 ? 0 : bound(shown)) + (exact < 0 ? 0 : bound(exact));
  margin_steps = margin * M;
  const Rational gap = abs(s.z - e.z);
  if (gap == 0) return kTie;
  if (gap.get_d() <= margin) return kWithin;
  const auto offset = [&](std::int64_t id) { return id >= 0 && c.tris[std::size_t(id)].offset(); };
  if (offset_units && (offset(shown) || offset(exact)) && Rational(abs(frag(shown, 2).z - frag(exact, 2).z)).get_d() <= margin)
    return kOffsetUnits;
  return kOther;
}

inline std::string where(const ZCase& c, std::int64_t i, std::int64_t j, std::int64_t shown, std::int64_t exact) {
  return c.set + " (" + std::to_string(c.cfg.bits) + " bits, " + (c.cfg.lequal ? "lequal" : "less") + "), sample (" +
         std::to_string(i) + ", " + std::to_string(j) + "): shown " + std::to_string(shown) + ", exact " + std::to_string(exact);
}

// One case: llvmpipe's image (drawn in the cell at `origin`) against its emulation and our modes.
inline Tally compare_case(const ZCase& c, const LpImage& lp, std::array<int, 2> origin, bool with_float, bool with_oracle) {
  Tally t;
  t.cases = 1, t.triangles = c.tris.size();
  const int bits = c.cfg.bits;
  const std::size_t n = std::size_t(kWin * kWin);
  // Coverage, by the fill family's oracle (the same samples and tie rule as the z-buffer's).
  std::vector<std::vector<Pixel>> covered;
  std::vector<int> counts(n);
  for (const ZTri& tri : c.tris) {
    std::array<Vec2<Rational>, 3> r;
    for (int k = 0; k < 3; ++k) r[std::size_t(k)] = {xy_q(tri.v[std::size_t(k)][0]), xy_q(tri.v[std::size_t(k)][1])};
    covered.push_back(oracle::triangle_samples(r));
    for (const Pixel& p : covered.back()) ++counts[std::size_t(p.y * kWin + p.x)];
  }
  for (std::size_t s = 0; s < n; ++s) t.coverage_pass += counts[s] != lp.covers[s];
  // llvmpipe's arithmetic, written out: its ids and depths, and each fragment's float error.
  const double M = double((std::int64_t(1) << bits) - 1);
  std::vector<std::int64_t> ids(n, -1);
  std::vector<std::uint32_t> depth(
      n, c.cfg.clear >= kZ ? std::uint32_t(M) : std::uint32_t(std::lrint(double(c.cfg.clear) / kZ * M)));
  for (std::size_t k = 0; k < c.tris.size(); ++k) {
    const LpTri lt = lp_tri(c.tris[k], origin, bits);
    const LpPlane plane = lp_setup(lt);
    for (const Pixel& p : covered[k]) {
      const auto px = lp_pixel(origin, p.x, p.y);
      const float z = lp_depth(plane, px);
      const double err = std::fabs(double(z - plane_depth(c.tris[k], p.x, p.y, 2.0L / M))), bound = lp_bound(lt, px);
      t.bound_violations += err > bound;
      t.worst_bound_use = std::max(t.worst_bound_use, err / bound);
      const std::uint32_t d = lp_convert(z, bits);
      std::uint32_t& cell = depth[std::size_t(p.y * kWin + p.x)];
      ++t.fragments;
      if (c.cfg.lequal ? d <= cell : d < cell) cell = d, ids[std::size_t(p.y * kWin + p.x)] = std::int64_t(k);
    }
  }
  for (std::size_t s = 0; s < n; ++s) t.emulation += ids[s] != lp.ids[s] || depth[s] != lp.depth[s];
  // Our exact mode is the reference; the oracle checks it on the cases asked (it costs 4 times more).
  const pipe::DepthFunc func = c.cfg.lequal ? pipe::DepthFunc::lequal : pipe::DepthFunc::less;
  NoProbe none;
  const auto exact = pipe::z_buffer<Rational>(kWin, kWin, our_tris<Rational>(c), bits, func, clear_q(c.cfg), none);
  if (with_oracle) {
    std::vector<pipeline_oracle::DepthTriangle> otris;
    for (std::size_t k = 0; k < c.tris.size(); ++k) otris.push_back(oracle_tri(c.tris[k], std::int64_t(k)));
    const auto oracle = pipeline_oracle::z_buffer(kWin, kWin, otris, bits, c.cfg.lequal, clear_q(c.cfg));
    ++t.oracle_cases;
    for (std::size_t s = 0; s < n; ++s) t.exact_vs_oracle += exact.id[s] != oracle.ids[s];
  }
  const auto lp_err = [&](std::int64_t i, std::int64_t j) {
    return [&, i, j](std::int64_t k) { return lp_bound(lp_tri(c.tris[std::size_t(k)], origin, bits), lp_pixel(origin, i, j)); };
  };
  for (std::int64_t j = 0; j < kWin; ++j)
    for (std::int64_t i = 0; i < kWin; ++i) {
      const std::size_t s = std::size_t(j * kWin + i);
      if (lp.ids[s] == exact.id[s]) continue;
      ++t.differing;
      double margin = 0;
      const std::string why = classify(c, lp.ids[s], exact.id[s], i, j, lp_err(i, j), convert_slack(bits), true, margin);
      ++t.classes[why];
      t.margins.push_back(margin);
      if (!t.examples.count(why))
        t.examples[why] = where(c, i, j, lp.ids[s], exact.id[s]) + ", margin " + std::to_string(margin) + " steps";
    }
  if (!with_float) return t;
  const auto ours = pipe::z_buffer<float>(kWin, kWin, our_tris<float>(c), bits, func, float(double(c.cfg.clear) / kZ), none);
  for (std::int64_t j = 0; j < kWin; ++j)
    for (std::int64_t i = 0; i < kWin; ++i) {
      const std::size_t s = std::size_t(j * kWin + i);
      if (ours.id[s] == exact.id[s]) continue;
      ++t.float_differing;
      double margin = 0;
      const auto err = [&](std::int64_t k) { return our_float_bound(c.tris[std::size_t(k)], i, j, bits); };
      // Our float rounds z M to a float, then adds 1/2 and floors: up to one step beyond 1/2 at 24 bits.
      ++t.float_classes[classify(c, ours.id[s], exact.id[s], i, j, err, bits == 16 ? 1.0 / 256 : 1.0, false, margin)];
    }
  return t;
}

// Flat triangles, one depth z (over kZ) all over, so that llvmpipe's float depth is z itself (plus
// the offset): the integer it stores at a covered sample, for glPolygonOffset(0, units).
inline std::vector<std::uint32_t> flat_depths(ZLlvmpipe& gl, const std::vector<std::int64_t>& zs, std::int64_t units) {
  std::vector<std::uint32_t> out;
  const std::int64_t w = (kWin - 1) * kXY;
  for (std::size_t first = 0; first < zs.size(); first += kCells) {
    std::vector<ZCase> cases;
    for (std::size_t k = first; k < std::min(zs.size(), first + kCells); ++k)
      cases.push_back(
          ZCase{{ZTri{{{{0, 0, zs[k]}, {w, 0, zs[k]}, {0, w, zs[k]}}}, 0, units}}, ZConfig{gl.bits(), true, kZ}, "flat"});
    for (const LpImage& img : gl.render(cases)) out.push_back(img.depth[std::size_t(10 * kWin + 10)]);
  }
  return out;
}

// Our rule: round(z M) = floor(z M + 1/2), z over kZ, exactly.
inline std::uint32_t our_rounding(std::int64_t z, int bits) {
  const __int128 M = (std::int64_t(1) << bits) - 1;
  return std::uint32_t((2 * __int128(z) * M + kZ) / (2 * __int128(kZ)));
}

// Every case on the llvmpipe of its depth bits, in draws of one configuration (up to kCells cases);
// the oracle checks our exact mode on every oracle_every-th case. Tallies by set and bits.
inline std::map<std::string, std::map<int, Tally>> compare_all(ZLlvmpipe& gl16, ZLlvmpipe& gl24, const std::vector<ZCase>& cases,
                                                               bool with_float, std::size_t oracle_every) {
  std::map<ZConfig, std::vector<std::size_t>> by_config;
  for (std::size_t k = 0; k < cases.size(); ++k) by_config[cases[k].cfg].push_back(k);
  std::map<std::string, std::map<int, Tally>> out;
  for (const auto& [cfg, idx] : by_config)
    for (std::size_t first = 0; first < idx.size(); first += kCells) {
      std::vector<ZCase> draw;
      for (std::size_t k = first; k < std::min(idx.size(), first + kCells); ++k) draw.push_back(cases[idx[k]]);
      const auto images = (cfg.bits == 16 ? gl16 : gl24).render(draw);
      for (std::size_t c = 0; c < draw.size(); ++c) {
        const bool oracle = idx[first + c] % oracle_every == 0;
        out[draw[c].set][cfg.bits].add(compare_case(draw[c], images[c], cell_origin(c), with_float, oracle));
      }
    }
  return out;
}

}  // namespace sw::zpeer
