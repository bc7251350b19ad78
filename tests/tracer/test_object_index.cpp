// The object index (tracer/trace_scene.hpp: index_objects, scene_hit's untraced path) against the
// plain loop over every object in id order, on the same TraceScene: the same closest hit (object,
// triangle, t and weights, bit for bit) and the same any-hit answer, for camera rays, for rays
// leaving a surface, and for rays through vertices and edges where objects tie. The scenes: the
// examples (a mesh, cornell-box's exact edge ties, huge and tiny scales) and generated ones on a
// half-integer grid (touching boxes, equal t on shared faces).
#include <catch2/catch.hpp>
#include <filesystem>
#include <random>
#include "rays/camera_ray.hpp"
#include "scale.hpp"
#include "scene_gen.hpp"
#include "source_paths.hpp"
#include "tracer/render.hpp"

using namespace sw;

namespace {

struct Counts {
  std::size_t rays = 0, hits = 0, ties = 0, any_blocked = 0;
};

// Casts r against the indexed scene and its unindexed copy; any difference fails.
void compare(const tracer::TraceScene<double>& indexed, const tracer::TraceObjects<double>& plain, const ray::Ray3<double>& r,
             const tracer::Leaving& from, double t_max, Counts& n) {
  NoProbe none;
  const tracer::Hit<double> a = tracer::scene_hit(indexed, r, false, 0.0, from, none);
  const tracer::Hit<double> b = tracer::scene_hit(plain, r, false, 0.0, from, none);
  ++n.rays;
  INFO("ray o " << r.o.x << " " << r.o.y << " " << r.o.z << " d " << r.d.x << " " << r.d.y << " " << r.d.z);
  REQUIRE(a.hit == b.hit);
  if (b.hit) {
    ++n.hits;
    REQUIRE(a.object == b.object);
    REQUIRE(a.prim == b.prim);
    REQUIRE(a.t == b.t);
    REQUIRE(a.b == b.b);
    // Another object at exactly the same t: the tie the lower id wins.
    for (std::size_t k = 0; k < plain.objects.size(); ++k) {
      if (static_cast<int>(k) == b.object) continue;
      if (static_cast<int>(k) == from.object) continue;
      const tracer::Hit<double> h = tracer::object_hit(plain, static_cast<int>(k), r, spatial::BvhQuery<double>{}, none);
      if (h.hit && h.t == b.t) {
        ++n.ties;
        break;
      }
    }
  }
  const bool any_a = tracer::scene_hit(indexed, r, true, t_max, from, none).hit;
  const bool any_b = tracer::scene_hit(plain, r, true, t_max, from, none).hit;
  REQUIRE(any_a == any_b);
  n.any_blocked += any_b;
}

// Camera rays through every pixel centre and, from each first hit, a ray to a random point of the
// scene's box (leaving that surface), with shadow queries to a finite and an infinite t_max.
Counts check_scene(const tracer::Scene& s, int w, int h, std::uint32_t seed) {
  const tracer::TraceScene<double> ts = tracer::trace_scene(s, w, h);
  REQUIRE((!ts.index.bvh.nodes.empty() || !ts.index.unbounded.empty()));
  tracer::TraceObjects<double> plain;
  plain.objects = ts.objects, plain.meshes = ts.meshes;  // no index: the loop in id order
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  NoProbe none;
  Counts n;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const ray::CameraRay<double> cr = ray::camera_ray_at(ts.camera, i, j, 0.0, 0.0, none);
      if (!cr.valid) continue;  // fisheye: outside the image circle
      const ray::Ray3<double> r = cr.ray;
      compare(ts, plain, r, tracer::Leaving{}, 1.0, n);
      const tracer::Hit<double> first = tracer::scene_hit(plain, r, false, 0.0, tracer::Leaving{}, none);
      if (!first.hit) continue;
      const Vec3<double> p = r.o + first.t * r.d;
      const Vec3<double> d{u(rng), u(rng), u(rng)};
      if (d.x == 0 && d.y == 0 && d.z == 0) continue;
      const tracer::Leaving from{first.object, first.prim};
      compare(ts, plain, ray::Ray3<double>{p, d}, from, 1.0, n);
      compare(ts, plain, ray::Ray3<double>{p, d}, from, INFINITY, n);
    }
  return n;
}

}  // namespace

TEST_CASE("object index: the same hits as the loop over every object, on the example scenes", "[tracer][index]") {
  Counts all;
  for (const char* name : {"cornell-box", "bunny", "huge-scale", "tiny-scale", "mirror-room", "spot-lit", "glass-spheres"}) {
    INFO(name);
    const tracer::Scene s = tracer::read_scene_file((sw::testing::kScenes / (std::string(name) + ".json")).string());
    // cornell-box at its own 256 x 256: its window camera sends rays exactly through the room's edges.
    const bool full = std::string(name) == "cornell-box";
    const Counts n = check_scene(s, full ? 256 : sw::testing::cases(64), full ? 256 : sw::testing::cases(48), 1);
    all.rays += n.rays, all.hits += n.hits, all.ties += n.ties, all.any_blocked += n.any_blocked;
  }
  // The comparison saw hits, blocked shadow rays and exact ties (cornell-box's edges).
  CHECK(all.hits > all.rays / 3);
  CHECK(all.any_blocked > 0);
  CHECK(all.ties > 0);
}

TEST_CASE("object index: the same hits on generated scenes with touching objects and equal t", "[tracer][index]") {
  Counts all;
  const std::uint32_t scenes = sw::testing::cases(120u);
  for (std::uint32_t seed = 0; seed < scenes; ++seed) {
    INFO("seed " << seed);
    tracer::SceneOptions opt;
    const tracer::Scene s = tracer::parse_scene(sw::testing::random_scene(seed, 24, 18), opt);
    const Counts n = check_scene(s, 24, 18, seed);
    all.rays += n.rays, all.hits += n.hits, all.ties += n.ties, all.any_blocked += n.any_blocked;
  }
  CHECK(all.hits > all.rays / 8);  // half the scenes are sparse: most of their rays miss
  CHECK(all.any_blocked > 0);
}
