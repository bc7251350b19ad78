// The z-buffer's real peer, Mesa's llvmpipe through OSMesa (docs/pipeline/llvmpipe.md):
//  1. how llvmpipe turns a depth into 16 or 24 bits, and what one unit of glPolygonOffset is, on
//     flat triangles (whose float depth is exact);
//  2. >= 10^5 triangles in five case sets at 16 and 24 bits, GL_LESS and GL_LEQUAL: every pixel
//     where llvmpipe's triangle is not the exact oracle's, classified; our float mode likewise;
//  3. the fill rate with the depth test (LP_NUM_THREADS=1) against our z-buffer in double.
// Usage: peer_llvmpipe_zbuffer [triangles (default 100000)]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include "zbuffer_peer.hpp"

using namespace sw;
using namespace sw::zpeer;

namespace {

void conversion_experiment(ZLlvmpipe& gl) {
  const int bits = gl.bits();
  std::mt19937_64 rng(41 + std::uint64_t(bits));
  std::vector<std::int64_t> zs{0, 1, kZ / 4, kZ / 4 + 1, kZ / 2 - 1, kZ / 2, kZ / 2 + 1, kZ - 1, kZ};
  while (zs.size() < 4096) zs.push_back(std::uniform_int_distribution<std::int64_t>(0, kZ)(rng));
  const auto got = flat_depths(gl, zs, 0);
  std::size_t ours = 0, emulated = 0, quarter = 0;
  for (std::size_t k = 0; k < zs.size(); ++k) {
    ours += got[k] != our_rounding(zs[k], bits);
    quarter += got[k] != our_rounding(zs[k], bits) && zs[k] > kZ / 4 && zs[k] < kZ / 2;
    emulated += got[k] != lp_convert(float(double(zs[k]) / kZ), bits);
  }
  std::printf(
      "%d bits, %zu flat triangles at z = k / 2^24: stored != round(z (2^n - 1)) at %zu (%zu of them with z in (1/4, 1/2)); "
      "!= llvmpipe's conversion written out at %zu\n",
      bits, zs.size(), ours, quarter, emulated);
  // One unit of glPolygonOffset, on depths whose z M lies at least 0.3 from a half step.
  std::vector<std::int64_t> far;
  const double M = double((std::int64_t(1) << bits) - 1);
  for (std::int64_t z : zs) {
    const double zm = double(z) / kZ * M;
    if (std::fabs(zm - std::floor(zm) - 0.5) > 0.3 && z > kZ / 8 && z < 7 * kZ / 8) far.push_back(z);
  }
  for (const std::int64_t units : {-2, -1, 1, 2}) {
    const auto moved = flat_depths(gl, far, units);
    std::map<std::int64_t, std::size_t> shifts;
    for (std::size_t k = 0; k < far.size(); ++k) ++shifts[std::int64_t(moved[k]) - std::int64_t(our_rounding(far[k], bits))];
    std::printf("  glPolygonOffset(0, %+lld) moves the stored depth by:", (long long)units);
    for (const auto& [d, n] : shifts) std::printf(" %+lld steps (%zu)", (long long)d, n);
    std::printf("\n");
  }
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

void print_tally(const std::string& title, const Tally& t) {
  std::printf("%-22s %6zu %7zu %9zu %9zu", title.c_str(), t.cases, t.triangles, t.fragments, t.differing);
  for (const char* k : {kTie, kWithin, kOffsetUnits, kCoverage, kOther})
    std::printf(" %9zu", t.classes.count(k) ? t.classes.at(k) : 0);
  std::printf(" %8.1f %8zu", median(t.margins), t.float_differing);
  for (const char* k : {kTie, kWithin, kCoverage, kOther})
    std::printf(" %8zu", t.float_classes.count(k) ? t.float_classes.at(k) : 0);
  std::printf("\n");
}

// ---- fill rate ----

struct RateSet {
  std::vector<ZTri> tris;  // on the 1/256 grid in a kFb^2 window, depths uniform on the 2^-24 grid
  std::vector<float> ndc;
};

RateSet rate_set(double area, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const double radius = std::sqrt(4 * area / (3 * std::sqrt(3.0))), margin = radius + 2, span = kFb - 2 * margin - 1;
  RateSet s;
  for (std::size_t k = 0; k < n; ++k) {
    const double cx = margin + span * unit(rng), cy = margin + span * unit(rng), turn = 2 * M_PI * unit(rng);
    ZTri t;
    for (int v = 0; v < 3; ++v) {
      const double a = turn + 2 * M_PI * v / 3 + 0.3 * (unit(rng) - 0.5);
      t.v[std::size_t(v)] = {std::llround((cx + radius * std::cos(a)) * kXY), std::llround((cy + radius * std::sin(a)) * kXY),
                             std::int64_t(unit(rng) * kZ)};
      for (int c = 0; c < 2; ++c) s.ndc.push_back(ndc_xy(double(t.v[std::size_t(v)][std::size_t(c)]) / kXY + 0.5));
      s.ndc.push_back(ndc_z(t.v[std::size_t(v)][2]));
    }
    s.tris.push_back(t);
  }
  return s;
}

void fill_rate(ZLlvmpipe& gl24) {
  std::printf("\nfill rate with the depth test (24 bits, GL_LESS), LP_NUM_THREADS=%s, best of 5 interleaved passes\n",
              std::getenv("LP_NUM_THREADS"));
  std::printf("  ours: untraced z-buffer in double into a %d^2 window (its depth and id buffers made anew each pass)\n", kFb);
  std::printf("  %-6s %-7s %-10s %-11s %-11s %s\n", "px^2", "tris", "fragments", "llvmpipe/s", "double/s", "double / llvmpipe");
  for (const auto& [area, n] : std::vector<std::pair<double, std::size_t>>{{8, 200000}, {128, 20000}, {2048, 2000}}) {
    const RateSet set = rate_set(area, n, 77 + std::uint64_t(area));
    ZCase c{set.tris, ZConfig{24, false, kZ}, "rate"};
    const auto tris = our_tris<double>(c);
    gl24.time_draw(set.ndc, 1);  // warm up: shader compilation
    double lp = 1e30, ours = 1e30;
    std::int64_t fragments = 0;
    for (int pass = 0; pass < 5; ++pass) {
      lp = std::min(lp, gl24.time_draw(set.ndc, 1));
      NoProbe none;
      const auto t0 = std::chrono::steady_clock::now();
      const auto buf = pipe::z_buffer<double>(kFb, kFb, tris, 24, pipe::DepthFunc::less, 1.0, none);
      ours = std::min(ours, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      fragments = buf.fragments;
    }
    std::printf("  %-6.0f %-7zu %-10lld %-11.3e %-11.3e %.2f\n", area, n, (long long)fragments, double(fragments) / lp,
                double(fragments) / ours, lp / ours);
  }
}

}  // namespace

int main(int argc, char** argv) {
  setenv("LP_NUM_THREADS", "1", 1);  // before the first context: llvmpipe reads it once
  const std::size_t triangles = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 100000;
  ZLlvmpipe gl16(16), gl24(24);
  std::printf("renderer: %s; FMA in llvmpipe's interpolation: %s\n\n", gl24.renderer().c_str(), lp_fused() ? "yes" : "no");

  // 1. Conversion and offset units.
  conversion_experiment(gl16);
  conversion_experiment(gl24);

  // 2. The case sets.
  const auto t0 = std::chrono::steady_clock::now();
  const auto cases = z_cases(triangles / 5, 2032);
  const auto tallies = compare_all(gl16, gl24, cases, true, 4);
  std::printf("\nllvmpipe against our exact mode, per set and depth bits (GL_LESS and GL_LEQUAL together); %.1f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  std::printf("%-22s %6s %7s %9s %9s %9s %9s %9s %9s %9s %8s %8s %8s %8s %8s %8s\n", "set", "cases", "tris", "fragments",
              "differ", "tie", "within", "units", "coverage", "other", "margin", "float", "tie", "within", "coverage", "other");
  Tally all;
  for (const auto& [set, by_bits] : tallies)
    for (const auto& [bits, t] : by_bits) {
      print_tally(set + ", " + std::to_string(bits), t);
      all.add(t);
    }
  print_tally("all", all);
  std::printf(
      "(differ: pixels where llvmpipe shows another triangle, classified by the exact oracle; margin: the median margin in "
      "steps\n"
      " there; float: our float mode against our exact mode, likewise)\n");
  std::printf(
      "checks: coverage pass (depth test off) differing samples %zu; float emulation != llvmpipe at %zu samples; "
      "float depth beyond its error bound at %zu of %zu fragments (worst |error| / bound %.3f); "
      "our exact mode != the oracle at %zu samples of the %zu cases it checked\n",
      all.coverage_pass, all.emulation, all.bound_violations, all.fragments, all.worst_bound_use, all.exact_vs_oracle,
      all.oracle_cases);
  for (const auto& [why, e] : all.examples) std::printf("  %s, e.g. %s\n", why.c_str(), e.c_str());

  // 3. Speed.
  fill_rate(gl24);
  const bool ok = all.coverage_pass == 0 && all.emulation == 0 && all.bound_violations == 0 && all.exact_vs_oracle == 0 &&
                  !all.classes.count(kOther) && !all.classes.count(kCoverage);
  return ok ? 0 : 1;
}
