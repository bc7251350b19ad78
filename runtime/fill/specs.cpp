// The fill and clip family's registration: the fills (fills.cpp) and the clippers (clip.cpp).
// Semantics: docs/fill/semantics.md.
#include "catalog.hpp"

namespace sw {

void register_fills(std::vector<Algorithm>& out);  // fills.cpp
void register_clip(std::vector<Algorithm>& out);   // clip.cpp

void register_fill(std::vector<Algorithm>& out) {
  register_fills(out);
  register_clip(out);
}

}  // namespace sw
