// Placeholder: filled in by the bvh work.
#include "catalog.hpp"

namespace sw {

void register_spatial_bvh(std::vector<Algorithm>&) {}

}  // namespace sw
