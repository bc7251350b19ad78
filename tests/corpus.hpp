// The hard-case corpora of tests/cases/<family>/ as inputs, for tests that iterate the catalog.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>
#include "input.hpp"

namespace sw::testing {

// The inputs of a family's corpus files (tests/cases/<family>/*.jsonl, "input" members; files
// named bad* hold inputs that must be refused and are left out); with an algorithm, only its lines.
inline std::vector<Json> corpus(std::string_view family, std::string_view algorithm = {}) {
  std::vector<Json> out;
  const auto dir = std::filesystem::path(SW_SOURCE_DIR) / "tests" / "cases" / std::string(family);
  if (!std::filesystem::exists(dir)) return out;
  for (const auto& f : std::filesystem::directory_iterator(dir)) {
    if (f.path().extension() != ".jsonl" || f.path().filename().string().rfind("bad", 0) == 0) continue;
    std::ifstream in(f.path());
    std::string line;
    while (std::getline(in, line))
      if (!line.empty() && line[0] == '{') {
        const Json j = Json::parse(line);
        if (algorithm.empty() || j.value("algorithm", "") == algorithm) out.push_back(j.at("input"));
      }
  }
  return out;
}

}  // namespace sw::testing
