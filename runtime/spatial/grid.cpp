// Placeholder: filled in by the grid work.
#include "catalog.hpp"

namespace sw {

void register_spatial_grid(std::vector<Algorithm>&) {}

}  // namespace sw
