// Rendering a scene with the Whitted tracer (algorithms/tracer/whitted.hpp): the scene converted to
// doubles (meshes placed and put in a BVH, image textures decoded), the pixels traced on all cores
// in any order, each from its own sample positions and its own budget, so the image does not
// depend on the thread count. Semantics: docs/tracer/renderer.md.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>
#include "budget.hpp"  // kDefaultMaxRays
#include "tracer/plan.hpp"
#include "tracer/scene.hpp"
#include "tracer/whitted.hpp"

namespace sw::tracer {

struct RenderOptions {
  std::int64_t width = 0, height = 0;  // 0: the scene's resolution
  std::int64_t spp = 0;                // > 0: spp samples a pixel on a sqrt(spp)^2 grid (regular, or the scene's jitter)
  bool adaptive = false;               // the scene's adaptive settings, or threshold 1/16 and max_n 4
  bool all_effects = false;            // simulate every effect (the planner's reference)
  unsigned threads = 0;                // 0: every core
  Offset offset = Offset::robust;      // naive offsets, for the lessons on acne
  std::function<void(double)> progress;  // called with the fraction done, from the calling thread
  std::uint64_t max_rays = kDefaultMaxRays;  // render() refuses a scene whose render_cost exceeds it
};

struct RenderResult {
  std::int64_t width = 0, height = 0;
  std::vector<Vec3<double>> rgb;  // row 0 at the top; not clamped
  RayCounts counts;
  std::uint64_t budget_pixels = 0;   // pixels whose budget stopped a ray
  std::uint64_t refined_pixels = 0;  // adaptive: pixels that took more than one sample
  std::uint64_t photons_stored = 0;  // caustic photons in the map
  double seconds = 0;
  Plan plan;
};

TraceScene<double> trace_scene(const Scene& s, std::int64_t width, std::int64_t height);

// An upper bound on a render's work in rays, before any is cast: per pixel its primary samples and
// the secondary rays the plan allows under each (a chain of max_depth where only mirrors or only
// glass are on, a binary tree where both are), within the pixel's rays_per_pixel (twice that for
// --all-effects, whose rays of weight 0 have an allowance of their own); at each of them a shadow
// ray per light whose shadows are on, and a photon gather counted as gather / 64 rays where
// caustics are on; and each photon's path of at most max_depth rays.
std::uint64_t render_cost(const Scene& s, const Plan& plan, const RenderOptions& opt);

// Throws InputError naming the estimate and --max-rays when render_cost exceeds opt.max_rays, or
// when the image has more than kMaxPixels pixels.
RenderResult render(const Scene& s, const RenderOptions& opt);

// Colours clamped to [0, 1] and rounded to 8 bits, RGB rows.
std::vector<std::uint8_t> to_rgb8(const std::vector<Vec3<double>>& rgb);
std::vector<std::uint8_t> to_rgb8(const RenderResult& r);
// "rays: 123 primary, ..." and the time: what `scene render` prints at the end.
std::string render_summary(const RenderResult& r);

}  // namespace sw::tracer
