// shadow-volume's real peer, Mesa's llvmpipe through OSMesa (docs/shadows/llvmpipe.md): every example
// scene (but the bunny, whose exact run is long) and every light, by z-fail and z-pass, llvmpipe's
// stencil verdict against our exact counts at every pixel a point is seen at, each difference
// classified by the exact oracle; and our float mode against exact visibility.
// Usage: peer_llvmpipe_volume [width height (default 96 72)]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include "data_root.hpp"
#include "volume_llvmpipe.hpp"

using namespace sw;

int main(int argc, char** argv) {
  setenv("LP_NUM_THREADS", "1", 1);
  const int w = argc > 2 ? std::atoi(argv[1]) : 96, h = argc > 2 ? std::atoi(argv[2]) : 72;
  volpeer::VolumeLlvmpipe gl(w, h);
  std::printf("renderer: %s; %d x %d, spheres of 8 stacks\n", gl.renderer().c_str(), w, h);
  std::printf("%-22s %5s %-6s %7s %7s %5s %5s %9s %6s %7s %7s %7s\n", "scene", "light", "method", "pixels", "differ", "eye", "away", "llvmpipe", "ours",
              "counts", "lp:ex", "float");
  std::vector<std::filesystem::path> scenes;
  for (const auto& e : std::filesystem::directory_iterator(data_root() / "scenes"))
    if (e.path().extension() == ".json" && e.path().stem() != "bunny") scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  volpeer::Comparison all[2];
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& path : scenes) {
    for (int light = 0; light < 3; ++light)
      for (const bool zfail : {true, false}) {
        shadowspec::VolumeInputRef in;
        try {
          in = shadowspec::parse_volume_input(Json{{"scene", path.string()}, {"size", {w, h}}, {"stacks", 8}, {"light", light}, {"method", zfail ? "zfail" : "zpass"}});
        } catch (const InputError&) {
          continue;  // no such light, or a camera the rasterizer cannot take
        }
        const volpeer::Comparison c = volpeer::compare(gl, *in.p);
        all[zfail].add(c);
        std::printf("%-22s %5d %-6s %7lld %7lld %5lld %5lld %9lld %6lld %7lld %7lld %7lld\n", path.stem().string().c_str(), light, zfail ? "zfail" : "zpass",
                    (long long)c.pixels, (long long)c.differ, (long long)c.eye, (long long)c.away, (long long)c.llvmpipe_wrong, (long long)c.ours_wrong,
                    (long long)c.counts_differ, (long long)c.llvmpipe_exact, (long long)c.float_wrong);
      }
  }
  for (const bool zfail : {true, false}) {
    const auto& c = all[zfail];
    std::printf("%-22s %5s %-6s %7lld %7lld %5lld %5lld %9lld %6lld %7lld %7lld %7lld\n", "all", "", zfail ? "zfail" : "zpass", (long long)c.pixels, (long long)c.differ,
                (long long)c.eye, (long long)c.away, (long long)c.llvmpipe_wrong, (long long)c.ours_wrong, (long long)c.counts_differ, (long long)c.llvmpipe_exact, (long long)c.float_wrong);
  }
  std::printf(
      "(differ: pixels where llvmpipe's stencil verdict is not our exact count's; eye: of those, llvmpipe's eye pass shows another object; away: "
      "the point faces away from the light; llvmpipe: llvmpipe wrong against exact visibility; ours: our exact count wrong; counts: stencil "
      "values != our count mod 256; lp:ex: llvmpipe wrong against exact visibility at points facing the light; float: our float mode wrong against exact visibility at points facing the light)  %.1f s\n",
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return all[1].ours_wrong == 0 ? 0 : 1;
}
