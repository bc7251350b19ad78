// shadow-map's real peer, Mesa's llvmpipe through OSMesa (docs/shadows/llvmpipe.md): every example
// scene (but the bunny, whose exact run is long) and every light, without a bias, with the default
// bias (1/65536 and slope 2) and with 3 x 3 PCF, llvmpipe's depth-texture compare against our exact
// lookup at every pixel a view holds, each difference classified by the exact oracle; and both
// against exact visibility (acne, peter-panning).
// Usage: peer_llvmpipe_map [width height map (default 96 72 128)]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include "data_root.hpp"
#include "map_llvmpipe.hpp"

using namespace sw;

int main(int argc, char** argv) {
  setenv("LP_NUM_THREADS", "1", 1);
  const bool sized = argc > 3;
  const int w = sized ? std::atoi(argv[1]) : 96, h = sized ? std::atoi(argv[2]) : 72, size = sized ? std::atoi(argv[3]) : 128;
  mappeer::MapLlvmpipe gl(w, h, size);
  std::printf("renderer: %s; %d x %d, maps of %d texels a side, 24 bits, spheres of 8 stacks\n", gl.renderer().c_str(), w, h, size);
  std::printf("%-20s %5s %-8s %6s %6s %4s %4s %4s %5s %5s %5s %6s %6s %6s %6s %6s\n", "scene", "light", "map", "pixels", "differ", "eye", "map",
              "tie", "texel", "other", "right", "acne", "panning", "ours:a", "ours:p", "pcf");
  std::vector<std::filesystem::path> scenes;
  for (const auto& e : std::filesystem::directory_iterator(data_root() / "scenes"))
    if (e.path().extension() == ".json" && e.path().stem() != "bunny") scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  const std::pair<const char*, Json> settings[] = {{"no bias", Json{{"size", size}}},
                                                   {"bias", Json{{"size", size}, {"bias", "1/65536"}, {"slope", 2}}},
                                                   {"pcf 3", Json{{"size", size}, {"bias", "1/65536"}, {"slope", 2}, {"pcf", 3}}}};
  mappeer::Comparison all, pcf;  // pcf: the settings with k > 1
  const auto t0 = std::chrono::steady_clock::now();
  auto row = [](const char* scene, const std::string& light, const char* map, const mappeer::Comparison& c) {
    std::printf("%-20s %5s %-8s %6lld %6lld %4lld %4lld %4lld %5lld %5lld %5lld %6lld %6lld %6lld %6lld %3lld/%lld\n", scene, light.c_str(), map,
                (long long)c.pixels, (long long)c.differ, (long long)c.eye, (long long)c.map, (long long)c.tie, (long long)c.texel, (long long)c.other,
                (long long)c.llvmpipe_right, (long long)c.acne, (long long)c.peter_panning, (long long)c.our_acne, (long long)c.our_peter_panning,
                (long long)c.pcf_differ, (long long)c.pcf_pixels);
  };
  for (const auto& path : scenes)
    for (int light = 0; light < 3; ++light)
      for (const auto& [name, map] : settings) {
        shadowspec::MapInputRef in;
        try {
          in = shadowspec::parse_map_input(Json{{"scene", path.string()}, {"size", {w, h}}, {"stacks", 8}, {"light", light}, {"map", map}});
        } catch (const InputError&) {
          continue;  // no such light, or a camera the rasterizer cannot take
        }
        const mappeer::Comparison c = mappeer::compare(gl, *in.p);
        all.add(c);
        if (map.value("pcf", 1) > 1) pcf.add(c);
        row(path.stem().string().c_str(), std::to_string(light), name, c);
      }
  row("all", "", "", all);
  std::printf(
      "(pixels: seen points a view holds; differ: llvmpipe's verdict at the point's own texel is not our exact one; of those, eye: llvmpipe's eye "
      "pass shows another object; map: its light pass stored another depth at the texel; tie: the reference within 2^-20 of the stored depth; "
      "texel: the point within 2^-8 of a texel's edge; other: none of these; right: llvmpipe's verdict is exact visibility. acne, panning: "
      "llvmpipe's against exact visibility at points facing the light; ours:a, ours:p: our exact lookup's; pcf: fractions that differ / "
      "compared)  %.1f s\n",
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  std::printf("3 x 3 PCF fractions differing: %lld of %lld; eye %lld, map %lld, tie %lld, other %lld\n", (long long)pcf.pcf_differ, (long long)pcf.pcf_pixels,
              (long long)pcf.pcf_eye, (long long)pcf.pcf_map, (long long)pcf.pcf_tie, (long long)pcf.pcf_other);
  return all.other == 0 && pcf.pcf_other == 0 ? 0 : 1;
}
