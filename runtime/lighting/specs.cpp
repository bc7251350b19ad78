// The lighting family's registration: the reflection models one light at a time (models.cpp), and
// the full local model with light types and attenuation, and Gouraud against Phong shading
// (shade.cpp). Semantics: docs/lighting/semantics.md.
#include "catalog.hpp"

namespace sw {

void register_lighting_models(std::vector<Algorithm>& out);  // models.cpp
void register_lighting_shade(std::vector<Algorithm>& out);   // shade.cpp

void register_lighting(std::vector<Algorithm>& out) {
  register_lighting_models(out);
  register_lighting_shade(out);
}

}  // namespace sw
