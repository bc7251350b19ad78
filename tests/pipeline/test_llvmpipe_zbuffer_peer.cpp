// Mesa's llvmpipe (OSMesa, 16- and 24-bit depth) as the z-buffer's peer on 10^4 triangles of fixed
// seeds (docs/pipeline/llvmpipe.md): the same coverage, and a triangle other than the exact
// oracle's only where the competing exact depths tie or lie within one step plus llvmpipe's float
// error (or, with glPolygonOffset, where its unit of two steps decides). The full run:
// bench/peer_llvmpipe_zbuffer.
#ifdef SW_HAVE_VISUALIZER  // the visualizer's build requires OSMesa: configure fails without it
#include <memory>
#include "../../bench/zbuffer_peer.hpp"
#include "peers.hpp"

using namespace sw;
using namespace sw::zpeer;

namespace {

bool open_llvmpipe(std::unique_ptr<ZLlvmpipe>& gl, int bits) {
  try {
    gl = std::make_unique<ZLlvmpipe>(bits);
    return gl->renderer().find("llvmpipe") != std::string::npos;
  } catch (const std::exception&) {
    return false;
  }
}

std::size_t count(const std::map<std::string, std::size_t>& m, const char* k) { return m.count(k) ? m.at(k) : 0; }

std::string describe(const std::string& set, int bits, const Tally& t) {
  std::string s = set + ", " + std::to_string(bits) + " bits: " + std::to_string(t.triangles) + " triangles, " +
                  std::to_string(t.differing) + " differing pixels";
  for (const auto& [why, n] : t.classes) s += "\n  " + why + ": " + std::to_string(n);
  s += "\n  coverage pass " + std::to_string(t.coverage_pass) + ", emulation " + std::to_string(t.emulation) +
       ", beyond the bound " + std::to_string(t.bound_violations) + ", exact mode != oracle " + std::to_string(t.exact_vs_oracle);
  for (const auto& [why, e] : t.examples) s += "\n  " + why + ", e.g. " + e;
  return s;
}

}  // namespace

TEST_CASE("llvmpipe's z-buffer shows the exact triangle except where exact depths tie or lie within its float error",
          "[pipeline][zbuffer][llvmpipe]") {
  std::unique_ptr<ZLlvmpipe> gl16, gl24;
  SW_REQUIRE_PEER(open_llvmpipe(gl16, 16) && open_llvmpipe(gl24, 24), "OSMesa's llvmpipe with a 16- and a 24-bit depth buffer");
  const auto tallies = compare_all(*gl16, *gl24, z_cases(2000, 33), false, 8);
  Tally all;
  for (const auto& [set, by_bits] : tallies)
    for (const auto& [bits, t] : by_bits) {
      INFO(describe(set, bits, t));
      CHECK(t.coverage_pass == 0);  // the rasterizer: the same samples
      CHECK(count(t.classes, kCoverage) == 0);
      CHECK(count(t.classes, kOther) == 0);  // ids equal wherever the exact depths differ by more
      CHECK(t.emulation == 0);               // llvmpipe's float arithmetic, as written out
      CHECK(t.bound_violations == 0);        // and the margin bounds its error
      CHECK(t.exact_vs_oracle == 0);
      if (set != "polygon offset") CHECK(count(t.classes, kOffsetUnits) == 0);
      all.add(t);
    }
  REQUIRE(all.triangles >= 10000);
  REQUIRE(all.fragments > 500000);
  // The differences the semantics predict are there: exact ties in one plane, and llvmpipe's unit.
  CHECK(count(tallies.at("coplanar").at(16).classes, kTie) > 0);
  CHECK(count(tallies.at("coplanar").at(24).classes, kTie) > 0);
  CHECK(count(tallies.at("polygon offset").at(16).classes, kOffsetUnits) > 0);
  // 24 bits tell the near-coplanar pairs 2^-20 apart by the exact order, beyond the margin, nearly everywhere.
  const Tally& near24 = tallies.at("near-coplanar 2^-20").at(24);
  CHECK(near24.differing * 100 < near24.fragments);
}

TEST_CASE("llvmpipe rounds a depth to 16 or 24 bits through float, and a unit of glPolygonOffset is two steps",
          "[pipeline][zbuffer][llvmpipe]") {
  for (const int bits : {16, 24}) {
    std::unique_ptr<ZLlvmpipe> gl;
    SW_REQUIRE_PEER(open_llvmpipe(gl, bits), "OSMesa's llvmpipe with a depth buffer");
    std::mt19937_64 rng(51);
    std::vector<std::int64_t> zs{0, kZ / 4, kZ / 2, kZ};
    while (zs.size() < 1024) zs.push_back(std::uniform_int_distribution<std::int64_t>(0, kZ)(rng));
    const auto got = flat_depths(*gl, zs, 0);
    std::size_t not_ours = 0;
    for (std::size_t k = 0; k < zs.size(); ++k) {
      INFO(bits << " bits, z = " << zs[k] << "/2^24");
      CHECK(got[k] == lp_convert(float(double(zs[k]) / kZ), bits));
      CHECK(std::abs(std::int64_t(got[k]) - std::int64_t(our_rounding(zs[k], bits))) <= 1);  // GL: one of the two nearest
      not_ours += got[k] != our_rounding(zs[k], bits);
    }
    // At 24 bits, z (2^24 - 1) is rounded to a half before the integer: k / 2^24 in (1/4, 1/2), k odd, is one low.
    if (bits == 24) CHECK(not_ours > zs.size() / 16);
    // Depths whose z M lies at least 0.3 from a half step: glPolygonOffset(0, u) moves them by 2u steps.
    const double M = double((std::int64_t(1) << bits) - 1);
    std::vector<std::int64_t> far;
    for (std::int64_t z : zs)
      if (const double zm = double(z) / kZ * M; std::fabs(zm - std::floor(zm) - 0.5) > 0.3 && z > kZ / 8 && z < 7 * kZ / 8)
        far.push_back(z);
    REQUIRE(far.size() > 100);
    for (const std::int64_t units : {-1, 2}) {
      const auto moved = flat_depths(*gl, far, units);
      for (std::size_t k = 0; k < far.size(); ++k)
        CHECK(std::int64_t(moved[k]) - std::int64_t(our_rounding(far[k], bits)) == 2 * units);
    }
  }
}

#endif
