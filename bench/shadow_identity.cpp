// The shadow family's identities at full size (docs/shadows/semantics.md): every example scene at
// its own resolution, by shadow map, stencil volumes (z-fail) and projective shadows, drawn in
// double with the planner and with --all-effects. Per scene and method: the lights, the passes the
// planner skipped, the pixels whose colour differs between the two pictures and of those the
// unexplained ones (a point that faces a skipped light, where the all-effects verdict is exact
// visibility: the planner's proof would be wrong), and each method's verdicts against exact
// visibility at the points that face a light. Exit 1 on an unexplained difference.
// Usage: shadow_identity [scene.json ...] (default: scenes/*.json)
#include <chrono>
#include <cstdio>
#include <filesystem>
#include "data_root.hpp"
#include "pipeline/raster_shade.hpp"
#include "shadows/scene_shadows.hpp"
#include "tracer/history.hpp"
#include "tracer/render.hpp"

using namespace sw;
using namespace sw::shadowspec;

namespace {

// Light l's verdict at pixel p: 1 lit, 0 shadowed, by the method's own pixels.
bool lit_at(const LightShadows& l, ShadowMethod m, std::size_t p) {
  switch (m) {
    case ShadowMethod::map: return l.map.lit[p] == 1;
    case ShadowMethod::projective: return l.projective.shadowed[p] != 1;
    default: return l.volume.lit[p] == 1;
  }
}
const char* method_name(ShadowMethod m) { return m == ShadowMethod::map ? "map" : m == ShadowMethod::projective ? "projective" : "volume"; }

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::filesystem::path> scenes;
  for (int i = 1; i < argc; ++i) scenes.emplace_back(argv[i]);
  if (scenes.empty()) {
    for (const auto& e : std::filesystem::directory_iterator(data_root() / "scenes"))
      if (e.path().extension() == ".json") scenes.push_back(e.path());
    std::sort(scenes.begin(), scenes.end());
  }
  std::printf("%-20s %9s %-10s %6s %7s %8s %6s %11s %8s %8s %7s\n", "scene", "size", "method", "lights", "skipped", "differ", "unexpl",
              "facing pts", "wrong", "wrong:sk", "s");
  std::int64_t unexplained = 0, skipped_all = 0, passes_all = 0, differ_all = 0;
  const auto t_all = std::chrono::steady_clock::now();
  for (const auto& path : scenes) {
    std::string name;
    std::shared_ptr<const RasterScene> s;
    try {
      s = pipespec::raster_scene(tracer::scene_input(Json(path.string()), &name), {});
    } catch (const InputError& e) {
      std::printf("%-20s not drawn: %s\n", path.stem().string().c_str(), e.what());
      continue;
    }
    const pipespec::RasterPixels px = pipespec::draw(*s, Numeric::f64);
    for (const ShadowMethod m : {ShadowMethod::map, ShadowMethod::volume_zfail, ShadowMethod::projective}) {
      const auto t0 = std::chrono::steady_clock::now();
      const MapOptions o{512, 24, Rational(1, 65536), Rational(2), 1};  // scene raster's defaults
      SceneShadows planned, all;
      try {
        planned = scene_shadows(s, m, o, Numeric::f64, false);
        all = scene_shadows(s, m, o, Numeric::f64, true);
      } catch (const InputError& e) {
        std::printf("%-20s %9s %-10s not drawn: %s\n", path.stem().string().c_str(), "", method_name(m), e.what());
        continue;
      }
      std::int64_t skipped = 0, facing = 0, wrong = 0, wrong_skipped = 0, differ = 0, unexpl = 0;
      std::vector<char> excused(px.objects.size(), 0);
      for (std::size_t i = 0; i < all.lights.size(); ++i) {
        const LightShadows& l = all.lights[i];
        skipped += !planned.lights[i].pass;
        for (std::size_t k = 0; k < l.in->points.size(); ++k) {
          const std::size_t p = l.in->points[k].pixel;
          const bool right = lit_at(l, m, p) == bool(l.in->reaches[k]);
          if (l.in->faces[k]) ++facing, wrong += !right;
          if (planned.lights[i].pass) continue;
          if (l.in->faces[k]) wrong_skipped += !right;
          if (!l.in->faces[k] || !right) excused[p] = 1;
          else if (!lit_at(l, m, p)) ++unexpl;  // a shadow exact visibility confirms on a light the planner skipped
        }
      }
      const auto a = tracer::to_rgb8(pipespec::shade_pixels(*s, px, pipespec::Shading::phong, &planned.blocked));
      const auto b = tracer::to_rgb8(pipespec::shade_pixels(*s, px, pipespec::Shading::phong, &all.blocked));
      for (std::size_t k = 0; k < px.objects.size(); ++k)
        if (a[3 * k] != b[3 * k] || a[3 * k + 1] != b[3 * k + 1] || a[3 * k + 2] != b[3 * k + 2]) ++differ, unexpl += !excused[k];
      unexplained += unexpl, skipped_all += skipped, passes_all += std::int64_t(all.lights.size()), differ_all += differ;
      const std::string size = std::to_string(s->width) + "x" + std::to_string(s->height);
      std::printf("%-20s %9s %-10s %6zu %7lld %8lld %6lld %11lld %8lld %8lld %7.1f\n", path.stem().string().c_str(), size.c_str(), method_name(m),
                  all.lights.size(), (long long)skipped, (long long)differ, (long long)unexpl, (long long)facing, (long long)wrong, (long long)wrong_skipped,
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  std::printf("all: %lld of %lld passes skipped, %lld pixels differ, %lld unexplained  (%.0f s)\n", (long long)skipped_all, (long long)passes_all,
              (long long)differ_all, (long long)unexplained, std::chrono::duration<double>(std::chrono::steady_clock::now() - t_all).count());
  std::printf(
      "(differ: pixels whose colour the planned and the all-effects pictures give differently; unexpl: of those, or at a point facing a skipped "
      "light, a shadow exact visibility confirms; facing pts: points facing a light, summed over lights; wrong: the all-effects verdict against "
      "exact visibility there; wrong:sk: of those, on lights the planner skipped)\n");
  return unexplained == 0 ? 0 : 1;
}
