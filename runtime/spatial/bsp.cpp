// Placeholder: filled in by the bsp work.
#include "catalog.hpp"

namespace sw {

void register_spatial_bsp(std::vector<Algorithm>&) {}

}  // namespace sw
