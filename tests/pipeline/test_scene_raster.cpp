// scene-raster: the visibility identity (at every pixel centre the exact z-buffer names the
// primitive the exact ray cast meets, except exact edge ties, which GL's rule gives to a neighbour),
// on the example scenes and on seeded scenes built to be hard (shared edges through pixel centres,
// triangles behind and around the eye, planes to the horizon); the clipper against a brute-force
// intersection of half-planes; and the tessellation rule.
#include <catch2/catch.hpp>
#include "refusals.hpp"
#include <filesystem>
#include <map>
#include <random>
#include <sstream>
#include "catalog.hpp"
#include "data_root.hpp"
#include "pipeline/raster_truth.hpp"
#include "tracer/history.hpp"
#include "pipeline_test_support.hpp"
#include "raster_test_support.hpp"
#include "cli_harness.hpp"
#include "run.hpp"

using namespace sw;
using namespace sw::pipespec;

namespace {

std::shared_ptr<const RasterScene> scene_of(const Json& scene, std::int64_t w, std::int64_t h, int stacks = 8) {
  std::string name;
  return raster_scene(tracer::scene_input(scene, &name), RasterOptions{w, h, stacks});
}

// The example scenes a rasterizer can take (perspective), by file name.
std::vector<std::string> example_scenes() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(data_root() / "scenes"))
    if (e.path().extension() == ".json") {
      const std::string f = "scenes/" + e.path().filename().string();
      std::string name;
      if (tracer::scene_input(Json(f), &name)->camera.projection == ray::Projection::perspective) out.push_back(f);
    }
  std::sort(out.begin(), out.end());
  return out;
}

// A seeded scene on a grid of 1/8: a camera looking at the origin from a few units away, a floor
// plane, quads of two triangles sharing a diagonal, boxes, spheres, a triangle around the eye
// (cut by the near plane and the sides) and one through the eye (seen edge-on).
Json hard_scene(std::mt19937_64& rng) {
  auto g = [&](int lo, int hi) { return testing::ratio(lo + int(rng() % unsigned(hi - lo + 1)), 8); };
  auto s = [](const Rational& q) { return q.get_str(); };
  auto pt = [&](int lo, int hi) { return Json{s(g(lo, hi)), s(g(lo, hi)), s(g(lo, hi))}; };
  // Half the scenes look straight down -z at quads centred on the view axis: pixel centres then lie
  // exactly on their diagonals, edges and corners.
  const bool aligned = rng() % 2 == 0;
  Json objects = Json::array();
  objects.push_back({{"type", "plane"}, {"point", {0, s(g(-16, -4)), 0}}, {"normal", {s(g(-2, 2)), 8, s(g(-2, 2))}}, {"material", "m"}});
  for (int q = 0; q < 2; ++q) {  // a quad on an axis plane: its diagonal often passes through pixel centres
    // Aligned: in front of the rest, between the eye (z = 6) and the scene, so nothing hides the diagonal.
    const Rational z = aligned ? g(20, 32) : g(-16, 0), half = aligned ? g(4, 8) : g(4, 24);
    const Rational x0 = aligned ? Rational(-half) : g(-24, 0), y0 = aligned ? Rational(-half) : g(-24, 0), x1 = aligned ? half : x0 + g(8, 24),
                   y1 = aligned ? half : y0 + g(8, 24);
    const Json a{s(x0), s(y0), s(z)}, b{s(x1), s(y0), s(z)}, c{s(x1), s(y1), s(z)}, d{s(x0), s(y1), s(z)};
    // The second quad draws first the triangle GL's rule does not give the diagonal to (its edge
    // there runs up the screen: a right edge), so there the ray cast's lower id and GL disagree.
    const Json lower{{"type", "triangle"}, {"vertices", {a, b, c}}, {"material", "m"}}, upper{{"type", "triangle"}, {"vertices", {a, c, d}}, {"material", "m"}};
    objects.push_back(q == 0 ? lower : upper);
    objects.push_back(q == 0 ? upper : lower);
  }
  const Rational bx = g(-16, 8), by = g(-16, 8), bz = g(-16, 8);
  objects.push_back({{"type", "box"}, {"min", {s(bx), s(by), s(bz)}}, {"max", {s(bx + g(4, 16)), s(by + g(4, 16)), s(bz + g(4, 16))}}, {"material", "m"}});
  objects.push_back({{"type", "sphere"}, {"center", pt(-16, 16)}, {"radius", s(g(4, 12))}, {"material", "m"}});
  const Json eye{0, 0, 6};
  // Beside the eye: a triangle from behind it to far ahead, on the left; one whose plane holds it.
  objects.push_back({{"type", "triangle"}, {"vertices", {{-9, -9, 9}, {-2, -9, -9}, {"-5/2", 9, -9}}}, {"material", "m"}});
  objects.push_back({{"type", "triangle"}, {"vertices", {{0, 0, 7}, {2, 0, -3}, {-1, 0, -5}}}, {"material", "m"}});
  objects.push_back({{"type", "triangle"}, {"vertices", {{-1, -1, 9}, {1, -1, 9}, {0, 1, 9}}}, {"material", "m"}});  // behind the eye
  for (int k = 0; k < 3; ++k) objects.push_back({{"type", "triangle"}, {"vertices", {pt(-24, 24), pt(-24, 24), pt(-24, 24)}}, {"material", "m"}});
  objects.push_back({{"type", "mesh"}, {"file", "out/meshes/nefertiti.off"}, {"scale", s(g(4, 8))}, {"translate", {s(g(-28, -16)), s(g(-8, 8)), s(g(-24, -8))}}, {"material", "m"}});
  return {{"camera", {{"eye", eye}, {"vpn", aligned ? Json{0, 0, 1} : Json{s(g(-2, 2)), s(g(-2, 2)), 1}}, {"vup", {0, 1, 0}}, {"d", 1}, {"window", {"-1/2", "1/2", "-3/8", "3/8"}}, {"resolution", {32, 24}}}},
          {"materials", {{"m", Json::object()}}},
          {"lights", Json::array()},
          {"objects", objects}};
}

}  // namespace

TEST_CASE("scene-raster: the exact z-buffer sees what the exact ray cast sees, on the example scenes", "[pipeline][raster][identity]") {
  std::int64_t pixels = 0, ties = 0, exact_rays = 0;
  for (const std::string& f : example_scenes()) {
    INFO(f);
    std::string name;
    const auto scene = tracer::scene_input(Json(f), &name);
    // The bunny's 75,412 triangles take 19 s in rationals here; bench/scene_raster_identity.sh
    // draws it at full size, and the seeded scenes below hold a mesh.
    if (scene->mesh_triangles > 10000) continue;
    const tracer::Camera& cam = scene->camera;
    const auto s = scene_of(Json(f), 64, std::max<std::int64_t>(1, 64 * cam.height / cam.width));  // the scene's aspect
    const RasterTruth truth = raster_truth(*s, 0);
    const Identity id = identity(truth, draw(*s, Numeric::exact));
    CHECK(id.wrong == 0);
    CHECK(id.objects_wrong == 0);
    pixels += id.pixels, ties += id.ties, exact_rays += truth.exact_rays;
    // Every tie is an edge tie: the ray's closest hit lies on a triangle's boundary there.
    std::int64_t boundary = 0;
    for (const PixelTruth& p : truth.px) boundary += p.boundary && (p.object != p.ray_object || p.prim != p.ray_prim);
    CHECK(boundary == id.ties);
  }
  CHECK(pixels >= 6 * 64 * 40);
  CHECK(ties > 0);  // the cornell box's walls meet on pixel centres
  CHECK(exact_rays > 0);
}

TEST_CASE("scene-raster: the identity on seeded hard scenes, and what float and double get wrong", "[pipeline][raster][identity]") {
  std::mt19937_64 rng(20261201);
  std::int64_t ties = 0, cut = 0, culled = 0, boundary = 0;
  std::map<Numeric, std::int64_t> wrong, inside;
  for (int k = 0; k < 16; ++k) {
    const Json scene = hard_scene(rng);
    INFO(scene.dump());
    const auto s = scene_of(scene, 32, 24, 4);
    const RasterTruth truth = raster_truth(*s, 0);
    const RasterPixels exact = draw(*s, Numeric::exact);
    const Identity id = identity(truth, exact);
    REQUIRE(id.wrong == 0);
    CHECK(id.objects_wrong == 0);
    ties += id.ties, cut += exact.cut, culled += exact.culled;
    for (const PixelTruth& p : truth.px) boundary += p.boundary;
    for (Numeric n : {Numeric::f32, Numeric::f64}) {
      const Identity r = identity(truth, draw(*s, n));
      wrong[n] += r.wrong, inside[n] += r.wrong_inside;
    }
    // Filtered mode draws the exact picture, whether its intervals decide or it falls back.
    CHECK(identity(truth, draw(*s, Numeric::filtered)).wrong == 0);
  }
  CHECK(cut >= 16);     // the triangle beside the eye is cut in every scene
  CHECK(culled >= 16);  // the triangle behind the eye is gone
  CHECK(boundary > 0);
  CHECK(ties >= 10);
  WARN("seeded scenes: " << ties << " exact edge ties; float wrong on " << wrong[Numeric::f32] << " pixels (" << inside[Numeric::f32]
                          << " off the ties), double on " << wrong[Numeric::f64] << " (" << inside[Numeric::f64] << ")");
}

TEST_CASE("scene-raster: a floor near 10^6 reaches its horizon in float too", "[pipeline][raster][identity]") {
  // The floor's wedges run from a point near 10^6 to points at infinity. With directions of length
  // about 1, float's cut between the two lost the floor over a tenth of the picture (7,725 holes at
  // 320 x 240); directions scaled to the point's size keep it whole.
  const auto s = scene_of(Json("scenes/huge-scale.json"), 64, 48);
  const RasterTruth truth = raster_truth(*s, 0);
  for (Numeric n : {Numeric::f32, Numeric::f64, Numeric::exact}) {
    INFO(numeric_name(n));
    const Identity id = identity(truth, draw(*s, n));
    CHECK(id.wrong == 0);
    CHECK(id.holes == 0);
  }
}

using testing::raster::V4;

TEST_CASE("clip-volume keeps exactly the triangle's part inside the view volume, with its edges' origins", "[pipeline][raster][clip]") {
  std::mt19937_64 rng(7);
  int kept = 0, empty = 0, infinite = 0;
  auto coord = [&] { return testing::ratio(int(rng() % 401) - 200, 64); };
  for (int n = 0; n < 3000; ++n) {
    std::array<V4, 3> c;
    for (auto& v : c) v = {coord(), coord(), coord(), n % 5 == 0 && &v == &c[2] ? Rational(0) : testing::ratio(int(rng() % 300) - 100, 64)};
    NoProbe none;
    const pipe::ClippedPolygon<Rational> K = pipe::clip_volume<Rational>(c, none);
    const std::vector<V4> want = testing::raster::brute_clip(c);
    INFO("case " << n);
    REQUIRE(std::size_t(K.k) == want.size());
    for (int k = 0; k < K.k; ++k) {
      const V4& v = K.v[k].c;
      CHECK(v.w > 0);
      CHECK(std::any_of(want.begin(), want.end(), [&](const V4& o) { return testing::raster::same(o, v); }));
      // An edge said to lie on the triangle's edge e: both its ends are blends of e's two corners.
      const int e = K.v[k].edge;
      if (e < 0) continue;
      const V4& a = c[e];
      const V4& b = c[(e + 1) % 3];
      for (const V4& p : {v, K.v[(k + 1) % K.k].c}) {
        // p = a + s (b - a) for one s: the 2x2 minors of (p - a, b - a) vanish.
        const std::array<Rational, 4> u{p.x - a.x, p.y - a.y, p.z - a.z, p.w - a.w}, d{b.x - a.x, b.y - a.y, b.z - a.z, b.w - a.w};
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j) CHECK(u[i] * d[j] - u[j] * d[i] == 0);
      }
    }
    kept += K.k > 0, empty += K.k == 0, infinite += c[2].w == 0 && K.k > 0;
  }
  CHECK(kept > 300);
  CHECK(empty > 300);
  CHECK(infinite > 20);
}

TEST_CASE("scene-raster: a sphere's tessellation is the documented closed mesh on the sphere", "[pipeline][raster][tessellation]") {
  for (int S : {2, 3, 8, 12}) {
    const Json scene{{"camera", {{"eye", {0, 0, 10}}, {"vpn", {0, 0, 1}}, {"vup", {0, 1, 0}}, {"d", 1}, {"fov", 40}, {"resolution", {8, 8}}}},
                     {"materials", {{"m", Json::object()}}},
                     {"lights", Json::array()},
                     {"objects", {{{"type", "sphere"}, {"center", {"1/3", 2, -1}}, {"radius", "5/2"}, {"material", "m"}}}}};
    const auto s = scene_of(scene, 8, 8, S);
    INFO("stacks " << S);
    REQUIRE(s->tris.size() == std::size_t(4 * S * (S - 1)));
    const Vec3<double> c{1.0 / 3, 2, -1};
    std::map<std::array<double, 6>, int> edges;  // directed edges: each appears once, its reverse once
    for (std::size_t t = 0; t < s->tris.size(); ++t) {
      std::array<Vec3<double>, 3> x;
      for (int k = 0; k < 3; ++k) x[k] = {s->tris[t].x[k].x.get_d(), s->tris[t].x[k].y.get_d(), s->tris[t].x[k].z.get_d()};
      for (const auto& p : x) CHECK(std::abs(std::sqrt(dot(Vec3<double>(p - c), Vec3<double>(p - c))) - 2.5) < 1e-14);
      CHECK(dot(cross(Vec3<double>(x[1] - x[0]), Vec3<double>(x[2] - x[0])), Vec3<double>(x[0] + x[1] + x[2] - 3.0 * c)) > 0);  // outward
      for (int k = 0; k < 3; ++k) ++edges[{x[k].x, x[k].y, x[k].z, x[(k + 1) % 3].x, x[(k + 1) % 3].y, x[(k + 1) % 3].z}];
    }
    for (const auto& [e, n] : edges) {
      CHECK(n == 1);
      CHECK(edges.count({e[3], e[4], e[5], e[0], e[1], e[2]}) == 1);
    }
  }
}

TEST_CASE("scene-raster: bad input is one line naming the problem", "[pipeline][raster][input]") {
  const Algorithm& alg = find_algorithm("scene-raster");
  auto refused = [&](const std::string& text, const std::string& needle) { testing::expect_refused(alg, text, needle); };
  refused(R"({"scene":"scenes/tiny-scale.json","size":[8,8]})", "perspective only");
  refused(R"({"scene":"scenes/glass-spheres.json","size":[0,8]})", "input.size[0]");
  refused(R"({"scene":"scenes/glass-spheres.json","size":[513,8]})", "input.size[0]");
  refused(R"({"scene":"scenes/glass-spheres.json","size":[8,8],"stacks":1})", "input.stacks");
  refused(R"({"scene":"scenes/no-such-scene.json"})", "cannot read scene file");
  refused(R"({"size":[8,8]})", "scene");
}

TEST_CASE("scene raster on the command line: the image, the depth buffer and the identity, and no file from bad input", "[pipeline][raster][cli]") {
  const auto dir = testing::scratch("scene-raster");
  const std::string png = (dir / "r.png").string(), depth = (dir / "d.png").string();
  const std::string scene = (data_root() / "scenes/cornell-box.json").string();
  const testing::Ran ok = testing::run_stepwise("scene raster " + testing::sh_quote(scene) + " --size 48x48 --identity --numeric exact --out " +
                                                testing::sh_quote(png) + " --depth " + testing::sh_quote(depth));
  INFO(ok.err);
  REQUIRE(ok.status == 0);
  CHECK(std::filesystem::file_size(png) > 100);
  CHECK(std::filesystem::file_size(depth) > 100);
  CHECK(ok.out.find("48x48 in exact") != std::string::npos);
  // The identity's table: one row per mode; exact's wrong count is 0.
  const auto row = ok.out.find("\n  exact ");
  REQUIRE(row != std::string::npos);
  std::istringstream cells(ok.out.substr(row + 8));
  double seconds = 0;
  long differ = -1, ties = -1, wrong = -1, inside = -1, holes = -1;
  cells >> seconds >> differ >> ties >> wrong >> inside >> holes;
  CHECK(wrong == 0);
  CHECK(inside == 0);
  CHECK(holes == 0);
  CHECK(differ == ties);
  CHECK(ties > 0);  // the box's walls meet on pixel centres at 48 x 48
  for (const std::string bad : {" --size 0x4", " --stacks 1", " --numeric int", " --shading flat"}) {
    std::filesystem::remove(png);
    const testing::Ran r = testing::run_stepwise("scene raster " + testing::sh_quote(scene) + bad + " --out " + testing::sh_quote(png));
    INFO(bad << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(!std::filesystem::exists(png));
  }
  const testing::Ran fisheye =
      testing::run_stepwise("scene raster " + testing::sh_quote((data_root() / "scenes/tiny-scale.json").string()) + " --out " + testing::sh_quote(png));
  CHECK(fisheye.status == 2);
  CHECK(fisheye.err.find("perspective only") != std::string::npos);
  CHECK(!std::filesystem::exists(png));
}
