// The spatial family's registration: BSP and the painter's order (bsp.cpp), quadtree and octree
// (point_trees.cpp), kd-tree build, traversal and nearest neighbours (kd.cpp), BVH build and
// traversal (bvh.cpp), the brute-force ray-triangles (brute.cpp) and the 3D grid walk (grid.cpp). Semantics: docs/spatial/semantics.md.
#include "catalog.hpp"

namespace sw {

void register_spatial_bsp(std::vector<Algorithm>& out);          // bsp.cpp
void register_spatial_point_trees(std::vector<Algorithm>& out);  // point_trees.cpp
void register_spatial_kd(std::vector<Algorithm>& out);           // kd.cpp
void register_spatial_bvh(std::vector<Algorithm>& out);          // bvh.cpp
void register_spatial_grid(std::vector<Algorithm>& out);         // grid.cpp
void register_spatial_brute(std::vector<Algorithm>& out);        // brute.cpp

void register_spatial(std::vector<Algorithm>& out) {
  register_spatial_bsp(out);
  register_spatial_point_trees(out);
  register_spatial_kd(out);
  register_spatial_bvh(out);
  register_spatial_brute(out);
  register_spatial_grid(out);
}

}  // namespace sw
