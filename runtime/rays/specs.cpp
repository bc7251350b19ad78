// The ray family's registration: the intersection tests, then the camera and inverse mapping.
#include "rays/specs.hpp"

namespace sw {

void register_rays(std::vector<Algorithm>& out) {
  register_ray_intersections(out);
  register_ray_mappings(out);
}

}  // namespace sw
