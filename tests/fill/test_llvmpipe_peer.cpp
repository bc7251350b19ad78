// Mesa's llvmpipe (through OSMesa) against the exact oracle on about 10^4 random and hard triangles
// on its 1/256 sub-pixel grid: no differing pixel after the documented mapping, sample (i, j) ->
// GL window (i, j) + (1/2, 1/2) + a whole-pixel offset, no y flip (docs/fill/llvmpipe.md).
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include "../../bench/llvmpipe_peer.hpp"

using namespace sw;
using sw::peer::CatalogComparison;
using sw::peer::Comparison;
using sw::peer::compare;
using sw::peer::compare_catalog;
using sw::peer::large_cases;
using sw::peer::Layout;
using sw::peer::Llvmpipe;
using sw::peer::off_grid_cases;
using sw::peer::on_grid_cases;

namespace {

std::string describe(const Comparison& c) {
  std::string s = std::to_string(c.triangles) + " triangles, " + std::to_string(c.differing) + " differing pixels";
  for (const auto& [why, n] : c.classes) s += "\n  " + why + ": " + std::to_string(n);
  for (const auto& d : c.examples)
    s += "\n  group " + std::to_string(d.group) + " sample (" + std::to_string(d.sample.x) + ", " + std::to_string(d.sample.y) +
         "): llvmpipe " + std::to_string(d.llvmpipe) + ", exact " + std::to_string(d.exact) + " (" + d.why + ")";
  return s;
}

}  // namespace

TEST_CASE("llvmpipe covers exactly the oracle's samples on its sub-pixel grid", "[fill][llvmpipe]") {
  Llvmpipe gl;
  const auto cases = on_grid_cases(10000, 31);
  const Comparison within_tiles = compare(gl, cases, false);
  INFO(describe(within_tiles));
  REQUIRE(within_tiles.triangles >= 10000);
  REQUIRE(within_tiles.exact_pixels > 100000);
  CHECK(within_tiles.differing == 0);
  // The same cases straddling llvmpipe's 64-pixel tiles, and large ones over several tiles.
  const Comparison straddling = compare(gl, cases, false, 8, false, Layout{64, 32});
  INFO(describe(straddling));
  CHECK(straddling.differing == 0);
  const Comparison large = compare(gl, large_cases(200, 35), false, 8, false, Layout{256, 0});
  INFO(describe(large));
  CHECK(large.differing == 0);
}

TEST_CASE("llvmpipe drawn mirrored in y differs only by the tie rule on horizontal edges and vertices", "[fill][llvmpipe]") {
  // The experiment behind the mapping: mirrored, llvmpipe's bottom edges become our top edges.
  Llvmpipe gl;
  const Comparison c = compare(gl, on_grid_cases(2000, 32), true);
  INFO(describe(c));
  CHECK(c.differing > 0);
  for (const auto& [why, n] : c.classes)
    CHECK((why == "tie rule differs on a horizontal edge" || why == "tie rule differs at a vertex"));
}

TEST_CASE("llvmpipe off its grid differs only where the snapped triangle's exact answer does", "[fill][llvmpipe]") {
  Llvmpipe gl;
  const Comparison c = compare(gl, off_grid_cases(2000, 33), false);
  INFO(describe(c));
  for (const auto& [why, n] : c.classes) CHECK(why == "llvmpipe snapped a vertex");
}

TEST_CASE("the catalog's triangle fills equal llvmpipe on its sub-pixel grid", "[fill][llvmpipe]") {
  Llvmpipe gl;
  const auto cases = on_grid_cases(2000, 34);
  for (const char* id : {"triangle-edge", "triangle-dda"}) {
    const CatalogComparison c = compare_catalog(gl, cases, id, false);
    REQUIRE(c.found);  // a renamed algorithm fails here, it is not skipped
    INFO(std::string(id) + " (" + c.numeric + "): " + std::to_string(c.triangles) + " triangles, first error: " + c.first_error);
    CHECK(c.errors == 0);
    CHECK(c.differing == 0);
  }
}

#endif
