// Placeholder: filled in by the point_trees work.
#include "catalog.hpp"

namespace sw {

void register_spatial_point_trees(std::vector<Algorithm>&) {}

}  // namespace sw
