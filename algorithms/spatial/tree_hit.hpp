// What a ray query through a tree returns: the closest hit (least (t, id)) or none, with the
// barycentrics of the hit and the work done. bvh-traverse and kd-traverse share it.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

namespace sw::spatial {

template <class Num> struct TreeHit {
  bool hit = false;
  std::int32_t prim = -1;
  Num t{};
  std::array<Num, 3> b{};
  std::size_t nodes_visited = 0, prim_tests = 0;
};

}  // namespace sw::spatial
