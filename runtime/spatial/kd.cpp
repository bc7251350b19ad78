// Placeholder: filled in by the kd work.
#include "catalog.hpp"

namespace sw {

void register_spatial_kd(std::vector<Algorithm>&) {}

}  // namespace sw
