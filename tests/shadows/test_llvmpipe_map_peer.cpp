// Mesa's llvmpipe (OSMesa, 24-bit depth texture, GL_COMPARE_REF_TO_TEXTURE with GL_LEQUAL) as
// shadow-map's peer: with a bias its verdict is our exact lookup's at every pixel a view holds,
// PCF's 3 x 3 fractions too, on a spot's cone, a point light's cube and a directional light's box;
// without one, where the reference meets its own surface's stored depth (acne), the two differ
// only where llvmpipe's float depths differ from the exact ones. The full run over every example
// scene: bench/peer_llvmpipe_map.
#ifdef SW_HAVE_VISUALIZER  // the visualizer's build requires OSMesa: configure fails without it
#include "../../bench/map_llvmpipe.hpp"
#include "peers.hpp"

using namespace sw;

TEST_CASE("llvmpipe's depth-texture compare is our exact lookup, with a bias and with PCF", "[shadows][map][llvmpipe]") {
  const std::unique_ptr<mappeer::MapLlvmpipe> gl = peer::llvmpipe_peer<mappeer::MapLlvmpipe>(40, 30, 48);
  SW_REQUIRE_PEER(gl != nullptr, "OSMesa's llvmpipe with a depth buffer");
  mappeer::Comparison biased, unbiased;
  // spot-lit's light 0 is a spot (one cone), glass-spheres' a point light (six faces), eye-in-shadow's directional (a box).
  for (const char* scene : {"scenes/spot-lit.json", "scenes/glass-spheres.json", "scenes/eye-in-shadow.json", "scenes/textured.json"}) {
    INFO(scene);
    const auto at = [&](const Json& map) {
      return shadowspec::parse_map_input(Json{{"scene", scene}, {"size", {40, 30}}, {"stacks", 6}, {"light", 0}, {"map", map}});
    };
    for (const int pcf : {1, 3}) {
      const mappeer::Comparison c = mappeer::compare(*gl, *at(Json{{"size", 48}, {"bias", "1/65536"}, {"slope", 2}, {"pcf", pcf}}).p);
      CHECK(c.differ == 0);
      CHECK(c.pcf_differ == 0);
      CHECK(c.acne == c.our_acne);
      CHECK(c.peter_panning == c.our_peter_panning);
      biased.add(c);
    }
    const mappeer::Comparison c = mappeer::compare(*gl, *at(Json{{"size", 48}}).p);
    CHECK(c.eye == 0);
    CHECK(c.other + c.texel == 0);  // every difference is llvmpipe's float depth: another stored depth, or a reference within 2^-20
    unbiased.add(c);
  }
  CHECK(biased.pixels > 5000);
  CHECK(biased.pcf_pixels > 4000);
  CHECK(unbiased.our_acne > 300);  // acne without a bias, in both
  CHECK(unbiased.acne > 300);
  CHECK(unbiased.differ > 0);       // where the float depths decide it
}
#endif
