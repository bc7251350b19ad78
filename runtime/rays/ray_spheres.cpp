// ray-sphere-{geometric,quadratic,stable} in the catalog (ray_spec.hpp).
#include "rays/ray_spec.hpp"
#include "rays/ray_sphere_geometric.hpp"
#include "rays/ray_sphere_quadratic.hpp"
#include "rays/ray_sphere_stable.hpp"

namespace sw::rays {

SW_REGISTER(SphereSpec<ray::RaySphereGeometric>);
SW_REGISTER(SphereSpec<ray::RaySphereQuadratic>);
SW_REGISTER(SphereSpec<ray::RaySphereStable>);

}  // namespace sw::rays
