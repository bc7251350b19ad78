// ray-triangle-{barycentric,mt,watertight} in the catalog (ray_spec.hpp).
#include "rays/ray_spec.hpp"
#include "rays/ray_triangle_barycentric.hpp"
#include "rays/ray_triangle_mt.hpp"
#include "rays/ray_triangle_watertight.hpp"

namespace sw::rays {

SW_REGISTER(TriangleSpec<ray::RayTriangleBarycentric>);
SW_REGISTER(TriangleSpec<ray::RayTriangleMT>);
SW_REGISTER(TriangleSpec<ray::RayTriangleWatertight>);

}  // namespace sw::rays
