// shade in GL's convention against Mesa's fixed-function lighting (OSMesa feedback mode) on seeded
// random scenes: the largest colour differences in units of 1/255, and which of Mesa and shade in
// float is nearer the 300-bit reference. Plain main, a Markdown table. Usage:
//   peer_gl_lighting [scenes = 20000] [seed = 1] [interp]   (interp: DRAW_USE_LLVM=0)
#include <cstdio>
#include <cstdlib>
#include <string>
#include "gl_lighting_peer.hpp"

int main(int argc, char** argv) {
  const std::size_t count = argc > 1 ? std::size_t(std::atol(argv[1])) : 20000;
  const std::uint64_t seed = argc > 2 ? std::uint64_t(std::atoll(argv[2])) : 1;
  const bool interp = argc > 3 && std::string(argv[3]) == "interp";
  sw::peer::GlLighting gl(!interp);
  std::printf("Mesa: %s, %s (%s); vertex colour clamping %s\n\n", gl.renderer().c_str(), gl.version().c_str(), interp ? "draw module interpreted" : "draw module LLVM",
              gl.unclamped() ? "off (colours compared before clamping)" : "ON (colours compared clamped)");
  const auto scenes = sw::lighting::shade_random_scenes(count, seed);
  const auto c = sw::peer::compare_gl(gl, scenes);
  std::printf("| scenes | cases | max Mesa - double | max Mesa - ref | max float - ref | max oracle - ref | Mesa nearer | float nearer | tied | > 4/255 | of which shininess 0 | no vertex |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& r : c.rows)
    std::printf("| %s | %zu | %.4f | %.4f | %.6f | %.2e | %zu | %zu | %zu | %zu | %zu | %zu |\n", r.what.c_str(), r.cases, r.mesa_vs_double, r.mesa_vs_ref,
                r.float_vs_ref, r.oracle_vs_ref, r.mesa_closer, r.float_closer, r.tied, r.decision_flips, r.flips_shininess0, r.no_vertex);
  const auto& z = c.rows[5];
  std::printf("\nShininess 0: %zu of %zu scenes differ from GL's formula ((n.h)^0 = 1, the reference) by more than 1/255;\n"
              "%zu of them are within 1/255 of Mesa's own code path (factor (n.l)^(n.l) for a spot or attenuated light,\n"
              "mesa_shininess0). Largest |Mesa - that path| over all %zu: %.4f/255.\n",
              z.s0_differ, z.cases, z.s0_explained, z.cases, z.s0_mesa_vs_model);
  std::printf("\nDifferences in units of 1/255 (the largest over r, g, b); the oracle column is the independent MPFR\n"
              "oracle against shade's reference mode.\n");
  for (const auto& e : c.examples) std::printf("%s\n", e.c_str());
  return 0;
}
