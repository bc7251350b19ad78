#include "tracer/render.hpp"
#include "platform.hpp"
#include <algorithm>
#include <atomic>
#include <chrono>
#include <map>
#include <cmath>
#include <mutex>
#include <sstream>
#include <thread>
#include "budget.hpp"
#include "lighting/shade_input.hpp"
#include "png.hpp"
#include "tracer/parallel.hpp"
#include "tracer/photons.hpp"

namespace sw::tracer {

namespace {

Vec3<double> d3(const Real3& r) { return {r.d[0], r.d[1], r.d[2]}; }

// An image file is decoded once, however many textures name it.
TraceTexture convert_texture(const Texture& t, std::map<std::string, TraceTexture>& decoded) {
  TraceTexture o;
  o.kind = t.kind, o.scale = t.scale.d, o.noise = Noise(t.seed);
  o.colours = {d3(t.colours[0]), d3(t.colours[1])};
  if (t.kind == TextureKind::image) {
    auto [it, fresh] = decoded.try_emplace(t.path);
    if (fresh) {
      PngImage img = read_png_rgb(t.path);
      it->second.width = img.width, it->second.height = img.height;
      it->second.rgb = std::make_shared<const std::vector<std::uint8_t>>(std::move(img.rgb));
    }
    o.width = it->second.width, o.height = it->second.height, o.rgb = it->second.rgb;
  }
  return o;
}

}  // namespace

TraceScene<double> trace_scene(const Scene& s, std::int64_t width, std::int64_t height) {
  TraceScene<double> t;
  const Camera& c = s.camera;
  t.camera.eye = d3(c.eye), t.camera.vpn = d3(c.vpn), t.camera.vup = d3(c.vup), t.camera.dist = c.dist.d;
  t.camera.fov = c.has_window ? 0.0 : c.fov.d * (3.14159265358979323846 / 180);
  t.camera.width = width, t.camera.height = height, t.camera.projection = c.projection;
  t.camera.has_window = c.has_window;
  for (std::size_t k = 0; k < 4; ++k) t.camera.window[k] = c.window[k].d;
  for (const Object& o : s.objects) {
    Prim<double> p;
    p.shape = o.kind, p.material = o.material;
    p.a = d3(o.a), p.b = d3(o.b), p.radius = o.radius.d;
    for (std::size_t k = 0; k < 3; ++k) p.v[k] = d3(o.v[k]);
    if (o.kind == Shape::mesh) {
      const spatial::Mesh& file = *s.meshes[static_cast<std::size_t>(o.mesh)].mesh;
      MeshData<double> m;
      m.tris.resize(file.size());
      const Vec3<double> tr = d3(o.translate);
      for (std::size_t i = 0; i < file.size(); ++i)
        for (std::size_t v = 0; v < 3; ++v) {
          const auto& x = file.v[static_cast<std::size_t>(file.f[i][v])];
          m.tris[i][v] = Vec3<double>{o.scale.d * x[0], o.scale.d * x[1], o.scale.d * x[2]} + tr;
        }
      NoProbe none;
      m.bvh = spatial::bvh_build<double>(m.tris, none);
      p.mesh = static_cast<int>(t.meshes.size());
      t.meshes.push_back(std::move(m));
    }
    t.objects.push_back(p);
  }
  index_objects(t);
  std::map<std::string, TraceTexture> decoded;
  for (const Texture& x : s.textures) t.textures.push_back(convert_texture(x, decoded));
  lighting::ShadeScene<Rational> lights;  // the lighting family's conversion of lights and materials
  lights.lights = s.lights;
  for (const Material& m : s.materials) {
    lights.material = m.shading;
    const lighting::ShadeScene<double> d = lighting::convert_scene<double>(lights);
    TraceMaterial<double> tm;
    tm.shading = d.material, tm.kr = m.kr.d, tm.kt = m.kt.d, tm.ior = m.ior.d, tm.texture = m.texture;
    tm.bump.on = m.bump.on, tm.bump.amplitude = m.bump.amplitude.d, tm.bump.scale = m.bump.scale.d, tm.bump.noise = Noise(m.bump.seed);
    t.materials.push_back(tm);
    if (t.lights.empty()) t.lights = d.lights;
  }
  t.background = d3(s.background), t.ambient = d3(s.ambient);
  t.max_depth = static_cast<int>(s.max_depth);
  t.budget = s.rays_per_pixel;
  return t;
}

namespace {

// A uniform double in [0, 1) from sample (i, j, k) of a seeded jitter: a pure function, so a
// pixel's samples do not depend on which thread takes it.
double jitter(std::uint32_t seed, std::int64_t i, std::int64_t j, std::int64_t k) {
  std::uint64_t x = (std::uint64_t(seed) << 32) ^ (std::uint64_t(i) * 0x9E3779B1u) ^ (std::uint64_t(j) << 20) ^ std::uint64_t(k);
  splitmix64(x);
  return double(splitmix64(x) >> 11) * 0x1p-53;
}

struct Sampler {
  std::int64_t n = 1;  // n x n samples
  bool jittered = false;
  std::uint32_t seed = 0;
};

}  // namespace

std::uint64_t render_cost(const Scene& s, const Plan& plan, const RenderOptions& opt) {
  const EffectPlan& e = plan.effects;
  const auto any = [](const std::vector<char>& v) { return std::any_of(v.begin(), v.end(), [](char c) { return c != 0; }); };
  const bool mirrors = any(e.reflection), glass = any(e.refraction);
  const std::uint64_t depth = std::uint64_t(std::max<std::int64_t>(s.max_depth, 1));
  const std::uint64_t tree = mirrors && glass ? (depth >= 63 ? UINT64_MAX : (std::uint64_t{1} << depth) - 1) : mirrors || glass ? depth : 1;
  const bool adaptive = opt.adaptive || (opt.spp == 0 && s.sampling.kind == SamplingKind::adaptive);
  const std::uint64_t max_n = std::uint64_t(s.sampling.kind == SamplingKind::adaptive ? s.sampling.n : 4);
  const std::uint64_t samples = opt.spp > 0 ? std::uint64_t(opt.spp) : adaptive ? 1 + max_n * max_n : std::uint64_t(s.sampling.samples());
  std::uint64_t per_pixel = std::min(saturating_product({samples, tree}), std::uint64_t(s.rays_per_pixel));
  if (e.zero_weight) per_pixel *= 2;
  const std::uint64_t shadows = std::uint64_t(std::count(e.shadows.begin(), e.shadows.end(), char(1)));
  const std::uint64_t gathers = e.caustics && s.photons.count > 0 ? std::uint64_t(s.photons.gather + 63) / 64 : 0;
  const std::uint64_t w = std::uint64_t(opt.width > 0 ? opt.width : s.camera.width), h = std::uint64_t(opt.height > 0 ? opt.height : s.camera.height);
  const std::uint64_t tracing = saturating_product({w, h, per_pixel, 1 + shadows + gathers});
  const std::uint64_t photons = e.caustics ? saturating_product({std::uint64_t(s.photons.count), depth}) : 0;
  return tracing > UINT64_MAX - photons ? UINT64_MAX : tracing + photons;
}

RenderResult render(const Scene& s, const RenderOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  RenderResult out;
  out.width = opt.width > 0 ? opt.width : s.camera.width;
  out.height = opt.height > 0 ? opt.height : s.camera.height;
  if (out.width * out.height > kMaxPixels)
    throw InputError(std::to_string(out.width) + "x" + std::to_string(out.height) + " pixels, more than the bound 2^24 (4096x4096)");
  out.plan = opt.all_effects ? all_effects_plan(s) : plan_scene(s);
  if (const std::uint64_t cost = render_cost(s, out.plan, opt); cost > opt.max_rays)
    throw InputError("this render implies up to " + std::to_string(cost) + " rays, more than the budget of " + std::to_string(opt.max_rays) +
                     " (--max-rays raises it)");
  TraceScene<double> ts = trace_scene(s, out.width, out.height);
  ts.offset = opt.offset;
  const unsigned threads = opt.threads ? opt.threads : worker_threads();
  PhotonMap photons;
  if (out.plan.effects.caustics) {
    build_photon_map(s, ts, threads, photons, out.counts.photon);
    out.photons_stored = photons.at.size();
    ts.caustics = &photons;
  }
  Sampler base;
  const bool adaptive = opt.adaptive || (opt.spp == 0 && s.sampling.kind == SamplingKind::adaptive);
  if (opt.spp > 0) {
    base.n = std::llround(std::sqrt(double(opt.spp)));
    base.jittered = s.sampling.kind == SamplingKind::jittered, base.seed = s.sampling.seed;
  } else if (!adaptive) {
    base.n = s.sampling.n, base.jittered = s.sampling.kind == SamplingKind::jittered, base.seed = s.sampling.seed;
  }
  const std::int64_t max_n = s.sampling.kind == SamplingKind::adaptive ? s.sampling.n : 4;
  const double threshold = s.sampling.kind == SamplingKind::adaptive ? s.sampling.threshold.d : 1.0 / 16;
  const std::size_t w = static_cast<std::size_t>(out.width);
  out.rgb.assign(w * static_cast<std::size_t>(out.height), {});
  std::vector<RayCounts> counts(static_cast<std::size_t>(out.height));
  std::vector<std::uint64_t> budget_pixels(static_cast<std::size_t>(out.height));
  // One pixel: the mean of its n x n samples, traced with one budget.
  auto pixel = [&](std::int64_t i, std::int64_t j, const Sampler& sm) {
    RayCounts& rc = counts[static_cast<std::size_t>(j)];
    NoProbe none;
    WhittedTracer<double> tracer(ts, out.plan.effects, rc, none);
    const std::uint64_t stops = rc.budget_stops;
    Vec3<double> sum{};
    for (std::int64_t a = 0; a < sm.n; ++a)
      for (std::int64_t b = 0; b < sm.n; ++b) {
        const double ox = sm.jittered ? jitter(sm.seed, i, j, 2 * (a * sm.n + b)) : 0.5, oy = sm.jittered ? jitter(sm.seed, i, j, 2 * (a * sm.n + b) + 1) : 0.5;
        const double di = sm.n == 1 && !sm.jittered ? 0.0 : (double(b) + ox) / double(sm.n) - 0.5;
        const double dj = sm.n == 1 && !sm.jittered ? 0.0 : (double(a) + oy) / double(sm.n) - 0.5;
        sum = sum + tracer.sample(i, j, di, dj);
      }
    if (rc.budget_stops != stops) ++budget_pixels[static_cast<std::size_t>(j)];
    return sm.n == 1 ? sum : (1.0 / double(sm.n * sm.n)) * sum;
  };
  const double rows = double(out.height) * (adaptive ? 2 : 1);
  auto progress_part = [&](double offset) -> std::function<void(double)> {
    if (!opt.progress) return {};
    return [&, offset](double f) { opt.progress((offset + f * double(out.height)) / rows); };
  };
  parallel_rows(out.height, threads, progress_part(0), [&](std::int64_t j) {
    for (std::int64_t i = 0; i < out.width; ++i) out.rgb[static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i)] = pixel(i, j, base);
  });
  if (adaptive) {
    // Refine where a pixel's centre sample differs from a 4-neighbour's by more than the threshold
    // in some channel (decided on the first pass only, so the order of refinement does not matter).
    const std::vector<Vec3<double>> first = out.rgb;
    std::vector<char> refine(first.size(), 0);
    auto differs = [&](std::size_t a, std::size_t b) {
      for (int k = 0; k < 3; ++k)
        if (std::abs(std::clamp(first[a][k], 0.0, 1.0) - std::clamp(first[b][k], 0.0, 1.0)) > threshold) return true;
      return false;
    };
    for (std::size_t j = 0; j < static_cast<std::size_t>(out.height); ++j)
      for (std::size_t i = 0; i < w; ++i) {
        const std::size_t p = j * w + i;
        if ((i > 0 && differs(p, p - 1)) || (i + 1 < w && differs(p, p + 1)) || (j > 0 && differs(p, p - w)) ||
            (j + 1 < static_cast<std::size_t>(out.height) && differs(p, p + w)))
          refine[p] = 1, ++out.refined_pixels;
      }
    const Sampler fine{max_n, false, 0};
    parallel_rows(out.height, threads, progress_part(double(out.height)), [&](std::int64_t j) {
      for (std::int64_t i = 0; i < out.width; ++i) {
        const std::size_t p = static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i);
        if (refine[p]) out.rgb[p] = pixel(i, j, fine);
      }
    });
  }
  for (std::size_t j = 0; j < counts.size(); ++j) out.counts += counts[j], out.budget_pixels += budget_pixels[j];
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::vector<std::uint8_t> to_rgb8(const std::vector<Vec3<double>>& rgb) {
  std::vector<std::uint8_t> out(rgb.size() * 3);
  for (std::size_t p = 0; p < rgb.size(); ++p)
    for (int k = 0; k < 3; ++k) out[3 * p + static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(std::lround(255 * std::clamp(rgb[p][k], 0.0, 1.0)));
  return out;
}
std::vector<std::uint8_t> to_rgb8(const RenderResult& r) { return to_rgb8(r.rgb); }

std::string render_summary(const RenderResult& r) {
  std::ostringstream o;
  const RayCounts& c = r.counts;
  o << r.width << "x" << r.height << " in " << r.seconds << " s; rays: " << c.total() << " (" << c.primary << " primary, " << c.shadow << " shadow, "
    << c.reflection << " reflection, " << c.refraction << " refraction, " << c.photon << " photon); " << c.shadow_blocked << " shadow rays blocked\n";
  if (r.plan.all_effects) {
    o << "plan: --all-effects (every effect simulated)\n";
  } else {
    std::size_t off = 0;
    for (const Decision& d : r.plan.decisions) off += !d.on;
    o << "plan: " << off << " of " << r.plan.decisions.size() << " effects skipped (stepwise scene plan says why)\n";
  }
  if (r.photons_stored) o << "caustics: " << r.photons_stored << " photons stored\n";
  if (r.refined_pixels) o << "adaptive: " << r.refined_pixels << " of " << r.rgb.size() << " pixels refined\n";
  if (r.budget_pixels) o << "budget: " << r.budget_pixels << " pixels spent their ray budget (" << c.budget_stops << " rays not cast)\n";
  return o.str();
}

}  // namespace sw::tracer
