#pragma once
// The source tree's data folders, as the tests read them (SW_SOURCE_DIR comes from CMake).
#include <filesystem>

namespace sw::testing {

inline const std::filesystem::path kSourceDir = SW_SOURCE_DIR;
inline const std::filesystem::path kLessons = kSourceDir / "lessons";
inline const std::filesystem::path kScenes = kSourceDir / "scenes";

}  // namespace sw::testing
