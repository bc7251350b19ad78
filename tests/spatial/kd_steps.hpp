// What the kd-tree step replays share: the node items' values and small exact coordinates (the
// walk over a recording is step_values.hpp's for_each_step).
#pragma once
#include <catch2/catch.hpp>
#include <functional>
#include <random>
#include "kd_support.hpp"
#include "step_values.hpp"

namespace sw::testing::kd {

template <int D> std::vector<Q> flat_values(const VecN<Q, D>& a) {
  std::vector<Q> out;
  for (int k = 0; k < D; ++k) out.push_back(a[k]);
  return out;
}
template <int D> std::vector<Q> node_values(std::int64_t id, std::int64_t parent, const Box<Q, D>& c) {
  std::vector<Q> v{Q(id), Q(parent)};
  for (const Q& x : flat_values<D>(c.lo)) v.push_back(x);
  for (const Q& x : flat_values<D>(c.hi)) v.push_back(x);
  return v;
}

// A small exact coordinate: a multiple of 1/2 in [lo/2, hi/2].
inline Q qc(std::mt19937_64& rng, int lo, int hi) { return Q(std::uniform_int_distribution<int>(lo, hi)(rng)) / 2; }

}  // namespace sw::testing::kd
