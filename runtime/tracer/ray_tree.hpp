// The ray tree of a recorded pixel history (the catalog's `whitted`): every ray the pixel cast,
// read back from the steps of the Whitted listing (the top level and its recursive calls), with
// what each added to the pixel. The pixel's colour is the sum over the rays that meet a surface
// or the background of weight x local colour, where weight is the product of the kr, kt and
// Fresnel factors along the path.
//
// It reads what the algorithm declares for views, never a variable's name: the listing's lines
// (Whitted::closest, ::reflect, ...: a renamed line does not compile), the steps' kinds (a ray's
// closest step is a hit or a miss, a shadow step a hit when blocked), their geometry (the mirror
// and transmitted rays carry their weight factor as their value; a ray's segment ends at its hit;
// a shadow ray runs to its light) and the colour each step records (a colour variable, whatever
// its name; the caustic step's last one).
#pragma once
#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "lighting/lights.hpp"

namespace sw::tracer {

struct RayNode {
  enum class Kind : std::uint8_t { primary, mirror, transmitted, shadow };
  Kind kind = Kind::primary;
  int depth = 1;                   // primary 1; a shadow ray has its surface's depth
  int parent = -1;                 // index into the tree; -1 for the primary
  std::size_t step = 0;            // closest (or shadow) step
  std::size_t end = 0;             // the step it returned on (a shadow ray: its step)
  double weight = 0;               // the path's weight (a shadow ray: its surface's)
  bool hit = false;                // met an object (a shadow ray: blocked)
  std::array<double, 3> at{};      // where it met the object (a shadow ray: its origin)
  std::int64_t light = -1;         // a shadow ray's light
  std::array<double, 3> local{};   // the colour found here: shading (and caustics), or the background
  std::array<double, 3> colour{};  // what this ray returned (local plus its children's share)
  std::array<double, 3> added{};   // weight x local: its share of the pixel (0 for shadow rays)
  bool returned = false;           // its final colour was recorded
};

std::string_view kind_name(RayNode::Kind k);

// Rays in the order they were cast; `lights` are the scene's (a shadow ray is matched to the one
// it runs to). An empty tree for another algorithm's trace.
std::vector<RayNode> ray_tree(const TraceView& t, std::span<const lighting::Light<Rational>> lights);

// The sum of the rays' shares (the pixel's colour, up to rounding).
std::array<double, 3> ray_tree_sum(const std::vector<RayNode>& tree);

}  // namespace sw::tracer
