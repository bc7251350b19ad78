// The closest hit of a ray among triangles by brute force: every triangle is tested, in id order,
// with one of the rays family's tests (Moller-Trumbore, the guide's barycentric test, or the
// watertight test), as a nested listing. The baseline that bvh-traverse and kd-traverse speed up,
// and the place to see a shared edge lose a ray: two triangles that each miss by rounding.
// Ties: the lower id wins at equal t, as in the trees' traversals.
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "rays/ray_triangle_barycentric.hpp"
#include "rays/ray_triangle_mt.hpp"
#include "rays/ray_triangle_watertight.hpp"
#include "spatial/tree_hit.hpp"

namespace sw::spatial {

struct RayTriangles {
  static constexpr std::string_view id = "ray-triangles";
  static constexpr std::string_view summary =
      "Ray against every triangle (brute force) with a chosen test: closest hit, ties by id";
#define SW_LINES_RAY_TRIANGLES(X) \
  X(start, "best <- none") \
  X(test, "for each triangle i, in order: test it (mt, barycentric or watertight)") \
  X(keep, "    if it is hit and (t, i) < (t_best, i_best): best <- (t, i)") \
  X(done, "the best hit, or none")
  SW_LISTING("Ray against every triangle", SW_LINES_RAY_TRIANGLES)
#undef SW_LINES_RAY_TRIANGLES
};

// At most this many triangles are drawn as the scene (a mesh's trace stays small).
inline constexpr std::size_t kSceneTriangles = 4096;

// Which triangle test runs per triangle.
enum class TriangleTest { mt, barycentric, watertight };

template <class Test, NumberType Num, StepProbe Probe>
TreeHit<Num> ray_triangles_with(const std::vector<std::array<Vec3<Num>, 3>>& tris, const ray::Ray3<Num>& r, Probe& probe) {
  using L = RayTriangles;
  TreeHit<Num> out;
  if constexpr (Probe::on) {  // the scene stays on view while each test draws its own working
    auto& s = probe.step(L::start, StepKind::init).idx("triangles", static_cast<std::int64_t>(tris.size())).ray(r.o, r.d).keep();
    for (std::size_t k = 0; k < tris.size() && k < kSceneTriangles; ++k) s.triangle(tris[k][0], tris[k][1], tris[k][2]).keep();
  }
  for (std::size_t k = 0; k < tris.size(); ++k) {  // bounded by the triangle count
    const auto i = static_cast<std::int32_t>(k);
    keep_closest<L>(out, leaf_test<L, Test>(out, tris, r, i, probe), i, r, probe);  // in id order: an equal t keeps the lower id
  }
  if constexpr (Probe::on) record_done<L>(out, probe);
  return out;
}

template <NumberType Num, StepProbe Probe = NoProbe> TreeHit<Num> ray_triangles(const std::vector<std::array<Vec3<Num>, 3>>& tris,
                                                                                const ray::Ray3<Num>& r, TriangleTest test,
                                                                                Probe& probe) {
  switch (test) {
    case TriangleTest::mt: return ray_triangles_with<ray::RayTriangleMT>(tris, r, probe);
    case TriangleTest::barycentric: return ray_triangles_with<ray::RayTriangleBarycentric>(tris, r, probe);
    case TriangleTest::watertight: break;
  }
  return ray_triangles_with<ray::RayTriangleWatertight>(tris, r, probe);
}

}  // namespace sw::spatial
