// The ray tracer's scene in one number type, and a ray's closest hit or any hit among its objects:
// every object is tested in id order with the rays family's test for its kind (spheres: the stable
// test; planes; boxes: the slab test; triangles: the watertight test; meshes: their BVH through
// bvh-traverse), each as a nested listing. Ties keep the lower object id. A shadow ray asks for
// any hit with t < t_max. Semantics: docs/tracer/renderer.md.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "rays/ray_box.hpp"
#include "rays/ray_plane.hpp"
#include "rays/ray_sphere_stable.hpp"
#include "rays/ray_triangle_watertight.hpp"
#include "spatial/bvh_traverse.hpp"

namespace sw::tracer {

enum class Shape : std::uint8_t { sphere, plane, box, triangle, mesh };

template <class Num> using Triangle3 = std::array<Vec3<Num>, 3>;

template <class Num> struct MeshData {
  std::vector<Triangle3<Num>> tris;  // in world coordinates
  spatial::Bvh<Num> bvh;
};

template <class Num> struct Prim {
  Shape shape = Shape::sphere;
  int material = 0;
  Vec3<Num> a, b;      // sphere: a = centre; plane: a = point, b = normal (front side); box: a = min, b = max
  Num radius{};        // sphere
  Triangle3<Num> v{};  // triangle (counter-clockwise seen from the front)
  int mesh = -1;       // mesh: index into TraceScene::meshes
};

template <class Num> struct Hit {
  bool hit = false;
  int object = -1;  // index into TraceScene::objects
  int prim = -1;    // a mesh's triangle
  Num t{};
  std::array<Num, 3> b{};  // triangles: barycentric weights of v0, v1, v2
};

struct SceneHit {
  static constexpr std::string_view id = "scene-hit";
  static constexpr std::string_view summary =
      "A ray against every object of a scene in id order: closest hit (ties by id), or any hit before t_max";
#define SW_TRACER_SCENE_HIT(X) \
  X(start, "best <- none") \
  X(test, "for each object k, in order: its kind's test (sphere, plane, box, triangle; a mesh through bvh-traverse)") \
  X(flat, "    but skip the flat surface the ray leaves: a ray cannot meet its own plane again") \
  X(keep, "    if it is hit and t < t_best: best <- (t, k)       -- in id order: equal t keeps the lower id") \
  X(any, "    shadow ray: if it is hit with t < t_max: occluded; stop") \
  X(done, "the best hit, or none")
  SW_LISTING("Closest hit in a scene", SW_TRACER_SCENE_HIT)
#undef SW_TRACER_SCENE_HIT
};

// The surface a secondary ray leaves, when it is flat (a plane, a triangle, a mesh's triangle): the
// ray cannot meet that plane again, so it is not tested (the exact argument that rounding in a test
// cannot overturn). Curved and closed surfaces are tested: a ray may cross them to the far side.
struct Leaving {
  int object = -1;
  std::int32_t prim = -1;
};

template <class Num> struct TraceObjects {
  std::vector<Prim<Num>> objects;
  std::vector<MeshData<Num>> meshes;
};

// One object's test: hit and t (> 0), with the triangle and its weights for meshes. The callee's
// listing is entered when the probe records.
template <NumberType Num, StepProbe Probe>
Hit<Num> object_hit(const TraceObjects<Num>& s, int k, const ray::Ray3<Num>& r, const spatial::BvhQuery<Num>& q, Probe& probe) {
  const Prim<Num>& o = s.objects[static_cast<std::size_t>(k)];
  Hit<Num> h;
  auto run = [&]<class Algo>(std::type_identity<Algo>, auto&& test) {
    const auto call = nested<Algo>(probe);
    test();
  };
  switch (o.shape) {
    case Shape::sphere:
      run(std::type_identity<ray::RaySphereStable>{}, [&] {
        const auto x = ray::ray_sphere_stable<Num>(r, o.a, o.radius, probe);
        h.hit = x.hit, h.t = x.t;
      });
      break;
    case Shape::plane:
      run(std::type_identity<ray::RayPlane>{}, [&] {
        const auto x = ray::ray_plane<Num>(r, o.a, o.b, probe);
        h.hit = x.hit, h.t = x.t;
      });
      break;
    case Shape::box:
      run(std::type_identity<ray::RayBox>{}, [&] {
        const auto x = ray::ray_box<Num>(r, o.a, o.b, probe);
        h.hit = x.hit, h.t = x.t;
      });
      break;
    case Shape::triangle:
      run(std::type_identity<ray::RayTriangleWatertight>{}, [&] {
        const auto x = ray::ray_triangle_watertight<Num>(r, o.v, probe);
        h.hit = x.hit, h.t = x.t, h.b = x.b;
      });
      break;
    case Shape::mesh:
      run(std::type_identity<spatial::BvhTraverse>{}, [&] {
        const MeshData<Num>& m = s.meshes[static_cast<std::size_t>(o.mesh)];
        const auto x = spatial::bvh_query<Num>(m.bvh, m.tris, r, q, probe);
        h.hit = x.hit, h.t = x.t, h.b = x.b, h.prim = x.prim;
      });
      break;
  }
  h.object = k;
  return h;
}

// The closest hit (any = false), or the first hit found with t < t_max (any = true).
template <NumberType Num, StepProbe Probe = NoProbe> Hit<Num> scene_hit(const TraceObjects<Num>& s, const ray::Ray3<Num>& r,
                                                                        bool any, const Num& t_max, const Leaving& leaving,
                                                                        Probe& probe) {
  using L = SceneHit;
  Hit<Num> best;
  if constexpr (Probe::on)
    probe.step(L::start, StepKind::init).ray(r.o, r.d).keep().idx("objects", std::int64_t(s.objects.size()));
  for (std::size_t k = 0; k < s.objects.size(); ++k) {  // bounded by the object count
    const bool mine = static_cast<int>(k) == leaving.object;
    const Shape shape = s.objects[k].shape;
    if (mine && (shape == Shape::plane || shape == Shape::triangle)) {
      if constexpr (Probe::on) probe.step(L::flat, StepKind::decide).idx("k", std::int64_t(k));
      continue;
    }
    if constexpr (Probe::on) probe.step(L::test, StepKind::visit).idx("k", std::int64_t(k));
    const spatial::BvhQuery<Num> q{any, t_max, mine && shape == Shape::mesh ? leaving.prim : -1};
    const Hit<Num> h = object_hit(s, static_cast<int>(k), r, q, probe);
    if (!h.hit) continue;
    if (any) {
      if (h.t < t_max) {
        if constexpr (Probe::on)
          probe.step(L::any, StepKind::hit)
              .idx("k", std::int64_t(k))
              .num("t", h.t)
              .point(Vec3<Num>(r.o + h.t * r.d))
              .label("occluder");
        return h;
      }
    } else if (!best.hit || h.t < best.t) {
      best = h;
      if constexpr (Probe::on)
        probe.step(L::keep, StepKind::hit)
            .idx("k", std::int64_t(k))
            .num("t", h.t)
            .point(Vec3<Num>(r.o + h.t * r.d))
            .label("best");
    }
  }
  if (any) best = {};
  if constexpr (Probe::on) {
    auto& st = probe.step(L::done, best.hit ? StepKind::hit : StepKind::miss).idx("hit", best.hit);
    if (best.hit) st.idx("k", best.object).num("t", best.t);
  }
  return best;
}

}  // namespace sw::tracer
