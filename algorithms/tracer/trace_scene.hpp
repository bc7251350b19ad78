// The ray tracer's scene in one number type, and a ray's closest hit or any hit among its objects:
// every object is tested in id order with the rays family's test for its kind (spheres: the stable
// test; planes; boxes: the slab test; triangles: the watertight test; meshes: their BVH through
// bvh-traverse), each as a nested listing. Ties keep the lower object id. A shadow ray asks for
// any hit with t < t_max. Untraced, a scene with an index (index_objects) is searched through a
// BVH over its objects, with the same tests and the same answer. Semantics: docs/tracer/renderer.md.
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

// The untraced renderer's index over the objects (index_objects): a BVH over the boxes of the
// bounded objects, each padded so that rounding in the object's own test cannot put a hit outside
// it; planes are unbounded and tested one by one. Empty: scene_hit tests every object in order.
template <class Num> struct ObjectIndex {
  spatial::Bvh<Num> bvh;                 // its "triangle" i is object bounded[i]
  std::vector<std::int32_t> bounded;     // in id order
  std::vector<std::int32_t> unbounded;  // the planes (and any empty mesh), in id order
};

template <class Num> struct TraceObjects {
  std::vector<Prim<Num>> objects;
  std::vector<MeshData<Num>> meshes;
  ObjectIndex<Num> index;  // optional: only the untraced path reads it
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

// Builds s.index over s.objects (their meshes' BVHs built). Each bounded object's padded box goes
// to bvh-build as the flat "triangle" (lo, hi, lo), whose vertex box is the box itself. The pad,
// 10^-6 of the box's largest coordinate or extent, is far beyond the rounding of any object test.
template <class Num> void index_objects(TraceObjects<Num>& s) {
  ObjectIndex<Num> ix;
  std::vector<Triangle3<Num>> boxes;
  for (std::size_t k = 0; k < s.objects.size(); ++k) {  // bounded by the object count
    const Prim<Num>& o = s.objects[k];
    spatial::Box<Num, 3> b;
    const bool no_box =
        o.shape == Shape::plane || (o.shape == Shape::mesh && s.meshes[static_cast<std::size_t>(o.mesh)].bvh.nodes.empty());
    if (no_box) {
      ix.unbounded.push_back(static_cast<std::int32_t>(k));
      continue;
    }
    switch (o.shape) {
      case Shape::plane: break;
      case Shape::sphere: {
        const Num r = o.radius < Num(0) ? Num(-o.radius) : o.radius;
        b = {Vec3<Num>{o.a.x - r, o.a.y - r, o.a.z - r}, Vec3<Num>{o.a.x + r, o.a.y + r, o.a.z + r}};
        break;
      }
      case Shape::box: b = spatial::Box<Num, 3>::at(o.a), b.grow(o.b); break;
      case Shape::triangle: b = spatial::Box<Num, 3>::at(o.v[0]), b.grow(o.v[1]), b.grow(o.v[2]); break;
      case Shape::mesh: b = s.meshes[static_cast<std::size_t>(o.mesh)].bvh.nodes[0].box; break;
    }
    Num size(0);
    for (int a = 0; a < 3; ++a)
      for (const Num& c : {b.lo[a], b.hi[a], Num(b.hi[a] - b.lo[a])})
        if (const Num m = c < Num(0) ? Num(-c) : c; size < m) size = m;
    const Num pad = Num(1e-6) * size + Num(1e-300);
    for (int a = 0; a < 3; ++a) b.lo[a] = b.lo[a] - pad, b.hi[a] = b.hi[a] + pad;
    boxes.push_back({b.lo, b.hi, b.lo});
    ix.bounded.push_back(static_cast<std::int32_t>(k));
  }
  if (!boxes.empty()) {
    NoProbe none;
    ix.bvh = spatial::bvh_build<Num>(boxes, none);
  }
  s.index = std::move(ix);
}

namespace scene_detail {
// scene_hit through s.index, untraced: the same object tests, and the same answer as the loop in id
// order. Closest: the least (t, id) over the objects hit; a node is pruned only when its entry t is
// beyond the best t, and its padded boxes hold every hit of theirs. Any: some hit with t < t_max.
template <NumberType Num> Hit<Num> indexed_hit(const TraceObjects<Num>& s, const ray::Ray3<Num>& r, bool any, const Num& t_max,
                                               const Leaving& leaving) {
  NoProbe none;
  Hit<Num> best;
  // True when the search may stop: an any-hit query found its hit.
  auto test = [&](std::int32_t k) {
    const bool mine = k == leaving.object;
    const Shape shape = s.objects[static_cast<std::size_t>(k)].shape;
    if (mine && (shape == Shape::plane || shape == Shape::triangle)) return false;
    const spatial::BvhQuery<Num> q{any, t_max, mine && shape == Shape::mesh ? leaving.prim : -1};
    const Hit<Num> h = object_hit(s, k, r, q, none);
    if (!h.hit) return false;
    if (any) {
      if (!(h.t < t_max)) return false;
      best = h;
      return true;
    }
    if (!best.hit || h.t < best.t || (!(best.t < h.t) && k < best.object)) best = h;
    return false;
  };
  for (const std::int32_t k : s.index.unbounded)
    if (test(k)) return best;
  const spatial::Bvh<Num>& bvh = s.index.bvh;
  if (bvh.nodes.empty()) return best;
  auto box = [&](std::int32_t n) { return ray::ray_box<Num>(r, bvh.nodes[n].box.lo, bvh.nodes[n].box.hi, none); };
  spatial::bvh_detail::Stack<Num> stack;
  if (const auto h = box(0); h.hit) stack.push_back({0, h.t_near});
  while (!stack.empty()) {  // bounded: every node is pushed at most once
    const spatial::bvh_detail::Entry<Num> e = stack.back();
    stack.pop_back();
    if (any ? !(e.t < t_max) : best.hit && best.t < e.t) continue;
    const spatial::BvhNode<Num>& nd = bvh.nodes[e.node];
    if (nd.left < 0) {
      for (std::int32_t j = nd.first; j < nd.first + nd.count; ++j)
        if (test(s.index.bounded[bvh.order[j]])) return best;
      continue;
    }
    const auto hl = box(nd.left), hr = box(nd.right);
    const bool right_first = hl.hit && hr.hit && hr.t_near < hl.t_near;
    if (hl.hit && !right_first) {
      if (hr.hit) stack.push_back({nd.right, hr.t_near});
      stack.push_back({nd.left, hl.t_near});
    } else {
      if (hl.hit) stack.push_back({nd.left, hl.t_near});
      if (hr.hit) stack.push_back({nd.right, hr.t_near});
    }
  }
  return best;
}
}  // namespace scene_detail

// The closest hit (any = false), or the first hit found with t < t_max (any = true).
template <NumberType Num, StepProbe Probe = NoProbe> Hit<Num> scene_hit(const TraceObjects<Num>& s, const ray::Ray3<Num>& r,
                                                                        bool any, const Num& t_max, const Leaving& leaving,
                                                                        Probe& probe) {
  using L = SceneHit;
  if constexpr (!Probe::on) {
    if (!s.index.bvh.nodes.empty() || !s.index.unbounded.empty()) return scene_detail::indexed_hit(s, r, any, t_max, leaving);
  }
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
