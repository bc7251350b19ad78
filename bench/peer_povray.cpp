// Our Whitted tracer against POV-Ray 3.7 (docs/tracer/povray.md) on the example scenes, three seeded
// ones and an oblique view of cornell-box: per pixel centre, the object id of the first hit and each
// light's shadow mask, every difference classified by the exact oracle (tracer/pov_compare.hpp); the
// PSNR of our render (1 sample a pixel) against POV-Ray's image where the materials map; and the
// times, ours on one thread against POV-Ray's +WT1 (wall time of the process, and POV's own trace time).
// And the rasterizer's stencil shadow volumes (`scene raster --shadows volume`, z-fail in double,
// spheres of 64 stacks) against the same POV-Ray masks, classified by the same exact oracle (on
// the true spheres: tessellation's differences count as ours wrong).
// Plain main, Markdown tables. Usage: peer_povray [scenes dir = SW_SOURCE_DIR/scenes] [work dir = /tmp/peer_povray]
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include "pipeline/raster_scene.hpp"
#include "png.hpp"
#include "shadows/shadow_volume_input.hpp"
#include "tracer/passes.hpp"
#include "tracer/pov_compare.hpp"
#include "tracer/pov_export.hpp"
#include "tracer/render.hpp"

using namespace sw;
namespace fs = std::filesystem;

namespace {

void write_text(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// POV-Ray's own "Trace Time: ... (x seconds)" from its log, or -1.
double pov_trace_seconds(const fs::path& log) {
  std::ifstream in(log);
  std::stringstream all;
  all << in.rdbuf();
  std::smatch m;
  const std::string text = all.str();
  if (std::regex_search(text, m, std::regex("Trace Time:[^(]*\\(([0-9.]+) seconds\\)"))) return std::stod(m[1]);
  return -1;
}

// A seeded scene: a floor and 12 spheres, boxes and triangles, lambert and phong, two point lights.
Json generated(std::uint32_t seed) {
  std::mt19937 rng(seed);
  auto u = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  Json objects = Json::array({{{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "floor"}}});
  for (int k = 0; k < 12; ++k) {
    const double x = u(-4, 4), z = u(-4, 2), r = u(0.3, 0.9);
    const int kind = k % 3;
    if (kind == 0) objects.push_back({{"type", "sphere"}, {"center", {x, r + u(0, 1), z}}, {"radius", r}, {"material", "shiny"}});
    else if (kind == 1)
      objects.push_back({{"type", "box"}, {"min", {x - r, 0, z - r}}, {"max", {x + r, u(0.5, 2), z + r}}, {"material", "matte"}});
    else
      objects.push_back({{"type", "triangle"},
                         {"vertices", {{x - r, u(0, 1), z}, {x + r, u(0, 1), z + u(-0.5, 0.5)}, {x, u(1, 2.5), z - u(0, 0.5)}}},
                         {"material", "matte"}});
  }
  return {{"camera",
           {{"eye", {u(-1, 1), u(3, 5), 9}},
            {"vpn", {0, 0.35, 1}},
            {"vup", {0, 1, 0}},
            {"d", 1},
            {"fov", 50},
            {"resolution", {320, 240}}}},
          {"materials",
           {{"floor", {{"diffuse", {0.6, 0.6, 0.6}}}},
            {"matte", {{"diffuse", {0.7, 0.4, 0.3}}}},
            {"shiny",
             {{"diffuse", {0.3, 0.4, 0.7}}, {"specular", {0.5, 0.5, 0.5}}, {"specular_model", "phong"}, {"shininess", 40}}}}},
          {"lights",
           {{{"type", "point"}, {"position", {u(-4, 4), 6, u(0, 5)}}},
            {{"type", "point"}, {"position", {u(-4, 4), 5, u(0, 5)}}, {"colour", {0.4, 0.4, 0.4}}}}},
          {"objects", objects}};
}

struct Row {
  std::string name;
  tracer::IdCounts ids;
  tracer::ShadowCounts shadows, volumes;
  std::string psnr = "-", ours = "-", pov = "-", note;
};

// The stencil volumes' mask of light l (z-fail, double) against POV-Ray's, where both see one object.
void add_volume_counts(const tracer::Scene& s, std::size_t l, const std::vector<int>& pov_ids, const std::vector<double>& cosine,
                       const std::vector<char>& pov_lit, tracer::ShadowCounts& sum) {
  const std::int64_t w = s.camera.width, h = s.camera.height;
  std::shared_ptr<const pipespec::RasterScene> rs;
  try {
    rs = pipespec::raster_scene(std::make_shared<const tracer::Scene>(s), {w, h, 64});
  } catch (const InputError&) {
    return;  // a camera the rasterizer cannot take
  }
  NoProbe none;
  const auto img = shadow::shadow_volume<double>(pipespec::camera_in<double>(rs->camera), pipespec::triangles_in<double>(rs->tris),
                                                 shadowspec::mesh_in<double>(shadowspec::volume_mesh(*rs)),
                                                 shadowspec::v4_in<double>(shadowspec::homogeneous_light(*rs, l)), true, none);
  const pipespec::RasterPixels px = pipespec::draw(*rs, Numeric::f64);
  std::vector<char> lit(px.objects.size(), 0);
  for (std::int64_t j = 0; j < h; ++j)
    for (std::int64_t i = 0; i < w; ++i) lit[std::size_t(j * w + i)] = img.zfail[std::size_t((h - 1 - j) * w + i)] == 0;
  std::vector<int> ids(px.objects.begin(), px.objects.end());
  const tracer::ShadowCounts c = tracer::compare_shadows(s, w, h, l, ids, pov_ids, lit, cosine, pov_lit);
  sum.compared += c.compared, sum.differ += c.differ, sum.grazing += c.grazing, sum.silhouette += c.silhouette;
  sum.ours_right += c.ours_right, sum.pov_right += c.pov_right, sum.undecided += c.undecided, sum.unexplained += c.unexplained;
}

Row compare(const std::string& name, const tracer::Scene& s, const fs::path& work) {
  Row row;
  row.name = name;
  const std::int64_t w = s.camera.width, h = s.camera.height;
  const fs::path base = work / name;
  tracer::PovOptions po;
  po.mode = tracer::PovMode::ids;
  write_text(base.string() + "-ids.pov", tracer::export_pov(s, po).text);
  tracer::run_povray(base.string() + "-ids.pov", base.string() + "-ids.png", w, h);
  const tracer::TraceScene<double> ts = tracer::trace_scene(s, w, h);
  const std::vector<int> ours_ids = tracer::object_id_pass(ts), pov_ids = tracer::read_pov_ids(base.string() + "-ids.png");
  row.ids = tracer::compare_ids(s, w, h, ours_ids, pov_ids);
  if (std::getenv("PEER_POVRAY_VERBOSE")) {  // the first differing pixels, with the exact answer
    int shown = 0;

    for (std::size_t p = 0; p < ours_ids.size() && shown < 12; ++p)
      if (ours_ids[p] != pov_ids[p]) {
        const std::int64_t i = std::int64_t(p) % w, j = std::int64_t(p) / w;
        std::string e;
        for (const int k : tracer::exact_first_hits(s, w, h, i, j)) e += " " + std::to_string(k);
        std::printf("%s (%lld, %lld): ours %d, POV %d, exact {%s }\n", name.c_str(), (long long)i, (long long)j, ours_ids[p],
                    pov_ids[p], e.c_str());
        ++shown;
      }
  }
  for (std::size_t l = 0; l < s.lights.size(); ++l) {
    po.mode = tracer::PovMode::shadow, po.light = l;
    const std::string stem = base.string() + "-shadow" + std::to_string(l);
    write_text(stem + ".pov", tracer::export_pov(s, po).text);
    tracer::run_povray(stem + ".pov", stem + ".png", w, h);
    const tracer::ShadowPass ours = tracer::shadow_pass(ts, l);
    const tracer::ShadowCounts c =
        tracer::compare_shadows(s, w, h, l, ours_ids, pov_ids, ours.lit, ours.cosine, tracer::read_pov_lit(stem + ".png"));
    row.shadows.compared += c.compared, row.shadows.differ += c.differ, row.shadows.grazing += c.grazing,
        row.shadows.silhouette += c.silhouette;
    row.shadows.ours_right += c.ours_right, row.shadows.pov_right += c.pov_right, row.shadows.undecided += c.undecided;
    row.shadows.unexplained += c.unexplained;
    add_volume_counts(s, l, pov_ids, ours.cosine, tracer::read_pov_lit(stem + ".png"), row.volumes);
  }
  po.mode = tracer::PovMode::image;
  tracer::PovScene img;
  try {
    img = tracer::export_pov(s, po);
  } catch (const InputError& e) {
    row.note = std::string("image refused: ") + e.what();
    return row;
  }
  if (!img.approximations.empty())
    row.note = std::to_string(img.approximations.size()) + " approximated: " + img.approximations.front();
  write_text(base.string() + ".pov", img.text);
  const double pov_wall = tracer::run_povray(base.string() + ".pov", base.string() + ".png", w, h);
  tracer::RenderOptions ro;
  ro.spp = 1, ro.threads = 1;
  tracer::Scene one = s;  // one ray through each pixel centre, as POV-Ray without antialiasing
  one.sampling = tracer::Sampling{};
  one.photons.count = 0;  // the export maps no photons: POV-Ray's image has no caustics, so neither has ours
  const tracer::RenderResult r = tracer::render(one, ro);
  const std::vector<std::uint8_t> ours = tracer::to_rgb8(r);
  write_png(base.string() + "-ours.png", ours.data(), static_cast<int>(w), static_cast<int>(h), 3);
  char b[64];
  std::snprintf(b, sizeof b, "%.1f", tracer::psnr(ours, read_png_rgb(base.string() + ".png").rgb));
  row.psnr = b;
  std::snprintf(b, sizeof b, "%.3f", r.seconds);
  row.ours = b;
  std::snprintf(b, sizeof b, "%.3f (%.3f)", pov_wall, pov_trace_seconds(base.string() + ".png.log"));
  row.pov = b;
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path(SW_SCENES_DIR);
  const fs::path work = argc > 2 ? fs::path(argv[2]) : fs::path("/tmp/peer_povray");
  fs::create_directories(work);
  std::vector<Row> rows;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  auto run = [&](const std::string& name, auto&& load) {
    try {
      rows.push_back(compare(name, load(), work));
    } catch (const InputError& e) {
      std::printf("%s: not compared: %s\n", name.c_str(), e.what());
    }
  };
  for (const fs::path& f : files) run(f.stem().string(), [&] { return tracer::read_scene_file(f.string()); });
  for (std::uint32_t seed = 1; seed <= 3; ++seed)
    run("generated-" + std::to_string(seed), [&] { return tracer::parse_scene(generated(seed), tracer::SceneOptions{}); });
  // An oblique view: cornell-box with an off-centre, non-square window and a tilted view-plane normal.
  if (fs::exists(dir / "cornell-box.json"))
    run("cornell-oblique", [&] {
      Json j = Json::parse(std::ifstream(dir / "cornell-box.json"));
      j["camera"]["window"] = {-0.3, 0.6, -0.5, 0.2}, j["camera"]["resolution"] = {320, 180}, j["camera"]["vpn"] = {0.2, 0.1, 1};
      return tracer::parse_scene(j, tracer::SceneOptions{});
    });
  std::printf(
      "\n| scene | pixels | ids differ | ours right | POV right | tie | both wrong | silhouette | POV wrong inside | unexplained "
      "| shadow px | shadow differ | grazing | mask edge | ours right | POV right | undecided | unexplained "
      "| PSNR dB | ours 1 thread s | POV +WT1 s (trace) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    const auto& i = r.ids;
    const auto& s = r.shadows;
    std::printf(
        "| %s | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %s | %s | "
        "%s |\n",
        r.name.c_str(), i.pixels, i.differ, i.ours_right, i.pov_right, i.both_right, i.both_wrong, i.silhouette,
        i.pov_wrong_inside, i.unexplained, s.compared, s.differ, s.grazing, s.silhouette, s.ours_right, s.pov_right, s.undecided,
        s.unexplained, r.psnr.c_str(), r.ours.c_str(), r.pov.c_str());
  }
  std::printf(
      "\nscene raster --shadows volume (z-fail, double, 64 stacks) against the same POV-Ray masks, where both see one object\n"
      "| scene | shadow px | differ | grazing | mask edge | ours right | POV right | undecided | unexplained |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    const auto& s = r.volumes;
    if (s.compared == 0) continue;
    std::printf("| %s | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu |\n", r.name.c_str(), s.compared, s.differ, s.grazing, s.silhouette, s.ours_right,
                s.pov_right, s.undecided, s.unexplained);
  }
  std::printf("\n");
  for (const Row& r : rows)
    if (!r.note.empty()) std::printf("- %s: %s\n", r.name.c_str(), r.note.c_str());
  return 0;
}
