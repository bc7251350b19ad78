// What a ray query through a tree returns: the closest hit (least (t, id)) or none, with the
// barycentrics of the hit and the work done; and the leaf test the walks share (bvh-traverse,
// kd-traverse, and the brute-force ray-triangles).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>
#include "core/probe.hpp"
#include "rays/ray_triangle_watertight.hpp"

namespace sw::spatial {

template <class Num> struct TreeHit {
  bool hit = false;
  std::int32_t prim = -1;
  Num t{};
  std::array<Num, 3> b{};
  std::size_t nodes_visited = 0, prim_tests = 0;
};

// Triangle i of a leaf, on the walk's listing L: the `test` step, then Test (watertight unless
// told) in its own nested listing. Counts the test in best.prim_tests and returns its hit.
template <class L, class Test = ray::RayTriangleWatertight, NumberType Num, StepProbe Probe>
ray::TriangleHit<Num> leaf_test(TreeHit<Num>& best, const std::vector<std::array<Vec3<Num>, 3>>& tris, const ray::Ray3<Num>& r,
                                std::int32_t i, Probe& probe) {
  if constexpr (Probe::on) probe.step(L::test, StepKind::visit).idx("prim", i);
  ++best.prim_tests;
  const auto call = nested<Test>(probe);
  return Test{}(r, tris[static_cast<std::size_t>(i)], probe);
}

// Hit h of triangle i becomes the best, with a step on L's line `line` (keep, or an any-hit walk's stop).
template <class L, NumberType Num, StepProbe Probe> void take_hit(TreeHit<Num>& best, const ray::TriangleHit<Num>& h,
                                                                  std::int32_t i, const ray::Ray3<Num>& r, typename L::Line line,
                                                                  Probe& probe) {
  best.hit = true, best.prim = i, best.t = h.t, best.b = h.b;
  if constexpr (Probe::on)
    probe.step(line, StepKind::hit).idx("prim", i).num("t", h.t).point(Vec3<Num>(r.o + h.t * r.d)).label("best");
}

// The closest-hit rule: h of triangle i becomes the best when it is hit and (t, i) < (t_best, i_best),
// so that ties go to the lower id whatever the order the leaves are visited in (L's `keep` step).
template <class L, NumberType Num, StepProbe Probe>
void keep_closest(TreeHit<Num>& best, const ray::TriangleHit<Num>& h, std::int32_t i, const ray::Ray3<Num>& r, Probe& probe) {
  if (h.hit && (!best.hit || h.t < best.t || (h.t == best.t && i < best.prim))) take_hit<L>(best, h, i, r, L::keep, probe);
}

// The walk's last step, on L's `done` line: the best hit, or none.
template <class L, NumberType Num, StepProbe Probe> void record_done(const TreeHit<Num>& best, Probe& probe) {
  auto& s = probe.step(L::done, best.hit ? StepKind::hit : StepKind::miss).idx("hit", best.hit);
  if (best.hit) s.idx("prim", best.prim).num("t", best.t);
}

}  // namespace sw::spatial
