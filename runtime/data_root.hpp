// Where stepwise's data lives: lessons/, scenes/ and out/meshes/, laid out as in the source tree
// (scene and lesson files name each other and the meshes by relative paths).
#pragma once
#include <filesystem>

namespace sw {

// $STEPWISE_DATA when set; else, for an installed binary, <its directory>/../share/stepwise when
// that holds lessons/manifest.txt (`cmake --install` and the .deb put it there, so the install
// can move); else the source tree the binary was built from.
std::filesystem::path data_root();

}  // namespace sw
