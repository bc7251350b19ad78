// `stepwise scene check|plan|render` (scene_command.hpp). The scene and every option are read and
// validated in full before anything is printed or written, so bad input prints only the error line
// and leaves no image.
#include "scene_command.hpp"
#include <unistd.h>
#include <chrono>
#include <filesystem>
#include <cstdio>
#include <sstream>
#include <iostream>
#include <regex>
#include "budget.hpp"
#include "png.hpp"
#include "output.hpp"
#include "tracer/plan.hpp"
#include "pipeline/raster_shade.hpp"
#include "pipeline/raster_truth.hpp"
#include "shadows/scene_shadows.hpp"
#include "tracer/pov_export.hpp"
#include "tracer/render.hpp"
#include "tracer/scene.hpp"

namespace sw::cli {

void add_scene_commands(CLI::App& app, SceneCommands& c) {
  c.group = app.add_subcommand("scene", "Ray-tracer scenes: check, plan, render (docs/tracer/)");
  c.group->require_subcommand(1);
  c.check = c.group->add_subcommand("check", "Validate a scene file and print a summary (docs/tracer/scene-format.md)");
  c.plan = c.group->add_subcommand("plan", "Print the effect plan: each effect on or off, and why (docs/tracer/planner.md)");
  c.render = c.group->add_subcommand("render", "Render a scene to a PNG with the Whitted tracer (docs/tracer/renderer.md)");
  c.export_pov = c.group->add_subcommand("export-pov", "Write the scene as POV-Ray 3.7 SDL: the image, object ids or a shadow mask (docs/tracer/povray.md)");
  c.raster = c.group->add_subcommand("raster", "Draw a scene by rasterization: clipping, the z-buffer, local lighting (docs/pipeline/semantics.md#scene-raster)");
  for (CLI::App* sub : {c.check, c.plan, c.render, c.export_pov, c.raster}) sub->add_option("scene", c.file, "Scene file (JSON)")->required();
  c.check->add_flag("--json", c.json, "Print the summary as one JSON object");
  c.plan->add_flag("--json", c.json, "Print the plan as one JSON object");
  c.render->add_option("--out", c.out, "The PNG to write")->required();
  c.render->add_option("--size", c.size, "WxH instead of the scene's resolution (each 1..8192)");
  c.render->add_option("--spp", c.spp, "Samples per pixel, a square 1..256, on a grid (jittered if the scene jitters)");
  c.render->add_flag("--adaptive", c.adaptive, "Adaptive supersampling by neighbour contrast");
  c.render->add_flag("--all-effects", c.all_effects, "Simulate every effect (the planner's reference)");
  c.render->add_option("--threads", c.threads, "Threads (0: every core); the image does not depend on it")->check(CLI::Range(0u, 256u));
  c.render->add_flag("--quiet", c.quiet, "No progress bar and no summary");
  c.render->add_option("--max-rays", c.max_rays, "Refuse a render that implies more rays (default " + std::to_string(tracer::kDefaultMaxRays) + ")")
      ->check(CLI::Validator(budget_count_error, "COUNT"));
  c.render->add_option("--offset", c.offset, "Secondary ray origins: robust (default), none or epsilon (the naive ones, for the acne lesson)")
      ->check(CLI::IsMember({"robust", "none", "epsilon"}));
  c.export_pov->add_option("--out", c.out, "The .pov file to write")->required();
  c.export_pov->add_option("--mode", c.mode, "image (materials mapped), ids (a flat colour per object) or shadow (one light's mask)")
      ->check(CLI::IsMember({"image", "ids", "shadow"}));
  c.export_pov->add_option("--light", c.light, "shadow mode: the light's index (0-based)");
  c.export_pov->add_option("--size", c.size, "WxH the camera is set up for, instead of the scene's resolution");
  c.raster->add_option("--out", c.out, "The PNG to write")->required();
  c.raster->add_option("--size", c.size, "WxH instead of the scene's resolution (each 1..8192)");
  c.raster->add_option("--numeric", c.numeric, "The number type it draws in: float, double (default), filtered or exact")
      ->check(CLI::IsMember({"float", "double", "filtered", "exact"}));
  c.raster->add_option("--shading", c.shading, "phong (per fragment, default) or gouraud (per vertex)")->check(CLI::IsMember({"phong", "gouraud"}));
  c.raster->add_option("--stacks", c.stacks, "A sphere's bands of latitude (2 stacks slices of longitude), 2..256; default 12");
  c.raster->add_option("--depth", c.depth_out, "Also write the depth buffer as a grey PNG (near black, far white)");
  c.raster->add_flag("--identity", c.identity, "Compare every pixel with the exact ray cast (scene-hit), drawn in float, double, filtered and exact");
  c.raster->add_option("--max-work", c.max_work, "Refuse exact or filtered work (and --identity) that implies more units (default " +
                                                     std::to_string(pipespec::kDefaultMaxWork) + "; docs/cli.md)")
      ->check(CLI::Validator(budget_count_error, "COUNT"));
  c.raster->add_option("--shadows", c.shadows,
                       "none (default), map, volume or projective: a shadow map, stencil volumes or planar shadows per light whose shadows the planner cannot rule out")
      ->check(CLI::IsMember({"none", "map", "volume", "projective"}));
  c.raster->add_option("--receiver", c.receiver, "With --shadows projective: the receiving object's index (default: the first plane or triangle)");
  c.raster->add_option("--volume", c.volume, "With --shadows volume: zfail (default; counts behind the surface, with caps) or zpass (in front; wrong with the eye in a volume)")
      ->check(CLI::IsMember({"zfail", "zpass"}));
  c.raster->add_option("--map-size", c.map_size, "A shadow map's texels a side, per view (default 512; 1..2048)");
  c.raster->add_option("--map-bits", c.map_bits, "A shadow map's depth bits: 16, 24 (default) or 0 (depth in the number type)");
  c.raster->add_option("--map-bias", c.map_bias, "A constant subtracted from each point's depth in the light's window (default 1/65536)");
  c.raster->add_option("--map-slope", c.map_slope, "Times the point's own depth slope, subtracted too (default 2; glPolygonOffset's factor)");
  c.raster->add_option("--map-pcf", c.map_pcf, "Percentage-closer filtering over k x k texels, k odd (default 1: none)");
  c.raster->add_flag("--all-effects", c.all_effects, "A shadow pass for every light, not only those the planner keeps");
  c.raster->add_flag("--quiet", c.quiet, "No summary");
}

namespace {

// --size WxH into w, h (left as they are when the option is not given).
void parse_size(const std::optional<std::string>& given, std::int64_t& w, std::int64_t& h) {
  if (!given) return;
  const std::string& size = *given;
  std::smatch m;
  if (!std::regex_match(size, m, std::regex("([0-9]{1,5})x([0-9]{1,5})"))) throw InputError("--size: expected WxH, e.g. 320x240, got '" + size.substr(0, 40) + "'");
  w = std::stoll(m[1]), h = std::stoll(m[2]);
  if (w < 1 || h < 1 || w > tracer::kMaxResolution || h > tracer::kMaxResolution) throw InputError("--size: each side must be in [1, 8192], got " + size);
}

// The whole SDL is built before the file is opened; OutputFile leaves no partial file.
int export_pov(const SceneCommands& c) {
  const tracer::Scene s = tracer::read_scene_file(c.file);
  tracer::PovOptions o;
  o.mode = c.mode == "ids" ? tracer::PovMode::ids : c.mode == "shadow" ? tracer::PovMode::shadow : tracer::PovMode::image;
  if (c.light < 0) throw InputError("--light: a light's index, 0 or more, got " + std::to_string(c.light));
  o.light = static_cast<std::size_t>(c.light);
  parse_size(c.size, o.width, o.height);
  const tracer::PovScene pov = tracer::export_pov(s, o);
  OutputFile out(c.out);
  out.stream() << pov.text;
  out.commit();
  for (const std::string& a : pov.approximations) std::cout << "approximated: " << a << '\n';
  return 0;
}

int render(const SceneCommands& c) {
  const tracer::Scene s = tracer::read_scene_file(c.file);
  tracer::RenderOptions o;
  parse_size(c.size, o.width, o.height);
  if (c.spp) {
    const std::int64_t spp = *c.spp;
    const auto n = static_cast<std::int64_t>(std::llround(std::sqrt(double(std::max<std::int64_t>(spp, 0)))));
    if (spp < 1 || spp > 256 || n * n != spp) throw InputError("--spp: must be a square in [1, 256] (1, 4, 9, ..., 256), got " + std::to_string(spp));
    if (c.adaptive) throw InputError("--spp and --adaptive exclude each other");
    if (n * n > s.rays_per_pixel) throw InputError("--spp: " + std::to_string(spp) + " primary rays exceed the scene's rays_per_pixel " + std::to_string(s.rays_per_pixel));
    o.spp = spp;
  }
  o.adaptive = c.adaptive, o.all_effects = c.all_effects, o.threads = c.threads;
  o.max_rays = c.max_rays;
  o.offset = c.offset == "none" ? tracer::Offset::none : c.offset == "epsilon" ? tracer::Offset::epsilon : tracer::Offset::robust;
  const bool bar = !c.quiet && isatty(STDERR_FILENO);
  if (bar)
    o.progress = [](double f) {
      const int filled = static_cast<int>(f * 40);
      std::fprintf(stderr, "\r[%s%s] %3d%%", std::string(static_cast<std::size_t>(filled), '#').c_str(), std::string(static_cast<std::size_t>(40 - filled), ' ').c_str(),
                   static_cast<int>(f * 100));
      std::fflush(stderr);
    };
  const tracer::RenderResult r = tracer::render(s, o);
  if (bar) std::fprintf(stderr, "\n");
  const std::vector<std::uint8_t> rgb = tracer::to_rgb8(r);
  write_png(c.out, rgb.data(), static_cast<int>(r.width), static_cast<int>(r.height), 3);
  if (!c.quiet) std::cout << tracer::render_summary(r);
  return 0;
}

// The shadow map options of `scene raster` (--map-*), validated.
shadowspec::MapOptions map_options(const SceneCommands& c) {
  const Json map{{"size", c.map_size}, {"depth_bits", c.map_bits}, {"pcf", c.map_pcf}, {"bias", c.map_bias}, {"slope", c.map_slope}};
  try {
    return shadowspec::parse_map_options(map, "map", shadowspec::kMaxMapSize);
  } catch (const InputError& e) {
    throw InputError("--" + std::string(e.what()).replace(0, 4, "map-"));  // "map.pcf: ..." -> "--map-pcf: ..."
  }
}

// A line per light of `scene raster --shadows map|volume`: its pass's outcome, or why it had none.
void report_shadows(const shadowspec::SceneShadows& sh, std::int64_t map_size, std::ostream& report) {
  for (const shadowspec::LightShadows& l : sh.lights) {
    report << "light " << l.light << ": ";
    if (!l.pass) {
      report << "no shadow pass (" << l.skipped << ")\n";
      continue;
    }
    if (sh.method == shadowspec::ShadowMethod::projective) {
      const shadowspec::ProjectivePixels& p = l.projective;
      std::int64_t shadowed = 0;
      for (int v : p.shadowed) shadowed += v == 1;
      report << "projective onto object " << l.projective_in->receiver << " (GL_LESS, glPolygonOffset(-1, -1), stencil): " << p.occluders << " occluder triangles, "
             << p.fragments << " fragments, " << p.ties << " depth ties; " << shadowed << " pixels darkened; on the receiver's points facing the light: missing "
             << p.missing << ", spurious " << p.spurious << " (the receiver takes no shadow of itself, and nothing else does)\n";
      continue;
    }
    if (sh.method != shadowspec::ShadowMethod::map) {
      const shadowspec::VolumePixels& v = l.volume;
      const bool zfail = sh.method == shadowspec::ShadowMethod::volume_zfail;
      std::int64_t shadowed = 0, reached = 0;
      for (std::size_t k = 0; k < v.lit.size(); ++k) shadowed += v.lit[k] == 0, reached += v.visible[k] == 1;
      report << (zfail ? "z-fail" : "z-pass") << " stencil volumes: " << v.casters << " casters, " << v.silhouette << " silhouette edges, " << v.faces
             << " faces, " << v.fragments << " fragments; " << l.in->points.size() << " points seen, " << shadowed << " in shadow by the count, " << reached
             << " reached exactly, " << v.away << " facing away; of those facing it, wrong " << (zfail ? v.wrong_fail : v.wrong_pass) << " by "
             << (zfail ? "z-fail" : "z-pass") << " (" << (zfail ? v.wrong_pass : v.wrong_fail) << " by " << (zfail ? "z-pass" : "z-fail") << ")\n";
      continue;
    }
    const shadowspec::MapPixels& m = l.map;
    std::int64_t shadowed = 0, reached = 0;
    for (std::size_t k = 0; k < m.lit.size(); ++k) shadowed += m.lit[k] == 0, reached += m.visible[k] == 1;
    const auto& v = l.in->views;
    report << v.views.size() << (v.cube ? " cube faces" : v.views[0].orthographic ? " orthographic view" : " view") << " of " << map_size << "^2; "
           << l.in->points.size() << " points seen, " << shadowed << " in shadow by the map, " << reached << " reached exactly, " << m.away
           << " facing away; of those facing it, on the map: acne " << m.acne << ", peter-panning " << m.peter_panning << "; off the map (called lit) "
           << m.outside << ", " << m.outside_shadowed << " of them shadowed exactly\n";
  }
}

// `scene raster`: the image in the chosen mode; with --identity, each mode's pixels against the
// exact ray cast, timed. Everything is drawn and judged before a file is written.
int raster(const SceneCommands& c) {
  if (c.volume && c.shadows != "volume") throw InputError("--volume: only with --shadows volume (got --shadows " + c.shadows + ")");
  if (c.receiver && c.shadows != "projective") throw InputError("--receiver: only with --shadows projective (got --shadows " + c.shadows + ")");
  pipespec::RasterOptions o;
  parse_size(c.size, o.width, o.height);
  o.stacks = c.stacks;
  auto scene = std::make_shared<const tracer::Scene>(tracer::read_scene_file(c.file));
  const std::int64_t w = o.width ? o.width : scene->camera.width, h = o.height ? o.height : scene->camera.height;
  if (w * h > tracer::kMaxPixels) throw InputError("--size: " + std::to_string(w) + "x" + std::to_string(h) + " is more than 2^24 pixels");
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const std::shared_ptr<const pipespec::RasterScene> rs = pipespec::raster_scene(std::move(scene), o);
  const double prepared = std::chrono::duration<double>(clock::now() - t0).count();
  if (c.shadows == "projective")  // the receiver checked for every light before any work
    for (std::size_t i = 0; i < rs->scene->lights.size(); ++i) try {
        (void)shadowspec::receiver_plane(*rs, i, c.receiver.value_or(-1));
      } catch (const InputError& e) {
        throw InputError("--" + std::string(e.what()) + " (light " + std::to_string(i) + ")");
      }
  const Numeric mode = parse_numeric(c.numeric).value();  // checked by the option
  auto timed = [&](Numeric n, bool* fb) {
    const auto t = clock::now();
    pipespec::RasterPixels px = pipespec::draw(*rs, n, fb);
    return std::pair{std::move(px), std::chrono::duration<double>(clock::now() - t).count()};
  };
  // The budget, before any exact work: the units the exact modes and the ray casts imply, with
  // double's fragments standing for the exact ones.
  if (c.identity || mode == Numeric::exact || mode == Numeric::filtered) {
    const std::uint64_t fragments = std::uint64_t(pipespec::draw(*rs, Numeric::f64).fragments);
    // A shadow pass per light: at most six views, each its triangles and its texels' fragments.
    const bool rounded = mode == Numeric::f32 || mode == Numeric::f64;
    std::uint64_t shadow_work = c.shadows == "map" && !rounded
                             ? rs->scene->lights.size() * 6 * (pipespec::kWorkPerTriangle * rs->tris.size() + std::uint64_t(c.map_size * c.map_size))
                             : 0;
    // Stencil volumes: per light the eye pass again, and the volumes' fragments (double's counts).
    if (c.shadows == "volume" && !rounded) shadow_work = rs->scene->lights.size() * (pipespec::kWorkPerTriangle * 3 * rs->tris.size() + 4 * fragments);
    const std::uint64_t work = pipespec::kWorkPerTriangle * rs->tris.size() + pipespec::kWorkPerFragment * fragments +
                               (c.identity ? pipespec::kWorkPerRay * std::uint64_t(rs->width * rs->height) : 0) + shadow_work;
    if (work > c.max_work)
      throw InputError("this scene implies about " + std::to_string(work) + " units of exact work (" + std::to_string(rs->tris.size()) +
                       " triangles x 50, " + std::to_string(fragments) + " fragments" + (c.identity ? ", a ray a pixel x 3" : "") +
                       (shadow_work ? ", shadow passes " + std::to_string(shadow_work) : "") +
                       "), more than the budget of " + std::to_string(c.max_work) + " (--max-work raises it)");
  }
  bool fell_back = false;
  const auto [px, seconds] = timed(mode, &fell_back);
  std::ostringstream report;
  report.precision(3);
  report << "scene raster: " << rs->width << "x" << rs->height << " in " << c.numeric << (fell_back ? " (intervals fell back to exact)" : "") << ", "
         << rs->tris.size() << " triangles (" << px.culled << " outside the view volume, " << px.cut << " cut by its planes), " << px.drawn
         << " window triangles, " << px.fragments << " fragments; " << seconds << " s (scene prepared in " << prepared << " s)\n"
         << "near plane at eye depth " << rs->camera.near.get_d() << " (half the nearest surface in view), far plane at infinity; "
         << pipespec::shading_name(c.shading == "gouraud" ? pipespec::Shading::gouraud : pipespec::Shading::phong)
         << " shading; shadows: " << (c.shadows == "map" ? "shadow maps" : c.shadows == "volume" ? "stencil volumes" : c.shadows == "projective" ? "projective (planar)" : "none") << "; not drawn: mirror and glass rays (a rasterizer lights locally)\n";
  if (c.identity) {
    const auto t = clock::now();
    const pipespec::RasterTruth truth = pipespec::raster_truth(*rs, 0);
    report << "identity against the exact ray cast through each pixel centre (scene-hit, " << truth.px.size() << " pixels, "
           << truth.exact_rays << " decided in rationals; " << std::chrono::duration<double>(clock::now() - t).count() << " s):\n"
           << "  mode      seconds  differ  ties  wrong  inside  holes  objects differ  objects wrong\n";
    for (Numeric n : {Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact}) {
      const auto [p, s] = n == mode ? std::pair{px, seconds} : timed(n, nullptr);
      const pipespec::Identity id = pipespec::identity(truth, p);
      char line[160];
      std::snprintf(line, sizeof line, "  %-8s %8.3f %7lld %5lld %6lld %7lld %6lld %15lld %14lld\n", std::string(numeric_name(n)).c_str(), s,
                    (long long)id.differ, (long long)id.ties, (long long)id.wrong, (long long)id.wrong_inside, (long long)id.holes, (long long)id.objects_differ,
                    (long long)id.objects_wrong);
      report << line;
    }
    report << "  differ: another primitive than scene-hit's closest hit; ties: of those, exact edge ties GL's rule gives to another triangle; "
              "wrong: another primitive than GL's rule gives; inside: of those, where the closest hit lies inside a triangle (no tie); holes: of "
              "those, where the raster shows nothing (a crack)\n";
  }
  std::vector<std::uint32_t> blocked(px.objects.size(), 0);
  if (c.shadows != "none") {
    const shadowspec::ShadowMethod method = c.shadows == "map"          ? shadowspec::ShadowMethod::map
                                            : c.shadows == "projective" ? shadowspec::ShadowMethod::projective
                                            : c.volume.value_or("zfail") == "zfail" ? shadowspec::ShadowMethod::volume_zfail
                                                                                    : shadowspec::ShadowMethod::volume_zpass;
    const shadowspec::SceneShadows sh = shadowspec::scene_shadows(rs, method, map_options(c), mode, c.all_effects, c.receiver.value_or(-1));
    report_shadows(sh, c.map_size, report);
    blocked = sh.blocked;
  }
  const std::vector<std::uint8_t> rgb = tracer::to_rgb8(
      pipespec::shade_pixels(*rs, px, c.shading == "gouraud" ? pipespec::Shading::gouraud : pipespec::Shading::phong, c.shadows == "none" ? nullptr : &blocked));
  write_png(c.out, rgb.data(), static_cast<int>(px.width), static_cast<int>(px.height), 3);
  if (!c.depth_out.empty()) {
    const std::vector<std::uint8_t> grey = pipespec::depth_grey(px);
    try {
      write_png(c.depth_out, grey.data(), static_cast<int>(px.width), static_cast<int>(px.height), 1);
    } catch (const InputError&) {
      std::filesystem::remove(c.out);  // both files or neither
      throw;
    }
  }
  if (!c.quiet) std::cout << report.str();
  return 0;
}

}  // namespace

int run_scene_commands(const SceneCommands& c) {
  if (*c.check) {
    const tracer::Scene s = tracer::read_scene_file(c.file);
    if (c.json) std::cout << tracer::scene_summary(s).dump() << '\n';
    else std::cout << tracer::scene_summary_text(s);
    return 0;
  }
  if (*c.plan) {
    const tracer::Plan p = tracer::plan_scene(tracer::read_scene_file(c.file));
    if (c.json) std::cout << tracer::plan_json(p).dump() << '\n';
    else std::cout << tracer::plan_text(p);
    return 0;
  }
  if (*c.render) return render(c);
  if (*c.export_pov) return export_pov(c);
  if (*c.raster) return raster(c);
  return 2;
}

}  // namespace sw::cli
