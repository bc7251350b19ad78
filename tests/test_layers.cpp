// The visualizer's folders are its libraries (visualizer/CMakeLists.txt, docs/visualizer.md), and
// their includes point one way: lessons/ (sw_lessons) has no ImGui or GL and nothing of panels/
// or headless/; panels/ nothing of headless/; and no visualizer file includes a runtime/tracer
// header: the tracer's views come through declared Spec hooks (docs/hooks.md).
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Every #include line of the files under visualizer/<dir> ("" for all of visualizer/).
std::vector<std::pair<std::string, std::string>> includes(const std::string& dir) {
  std::vector<std::pair<std::string, std::string>> out;
  const fs::path root = fs::path(SW_SOURCE_DIR) / "visualizer" / dir;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    const std::string ext = e.path().extension().string();
    if (ext != ".cpp" && ext != ".hpp") continue;
    std::ifstream f(e.path());
    for (std::string line; std::getline(f, line);)
      if (line.rfind("#include", 0) == 0) out.emplace_back(fs::relative(e.path(), fs::path(SW_SOURCE_DIR)).string(), line);
  }
  return out;
}

bool has(const std::string& line, const char* what) { return line.find(what) != std::string::npos; }

}  // namespace

TEST_CASE("layers: the visualizer's includes point one way, and none reaches into the tracer", "[layout]") {
  const auto all = includes("");
  REQUIRE(all.size() > 100);
  for (const auto& [file, line] : all) {
    INFO(file << ": " << line);
    CHECK_FALSE(has(line, "\"tracer/"));
  }
  const auto lessons = includes("lessons");
  REQUIRE(lessons.size() > 20);
  for (const auto& [file, line] : lessons) {
    INFO(file << ": " << line);
    CHECK_FALSE(has(line, "\"panels/"));
    CHECK_FALSE(has(line, "\"headless/"));
    CHECK_FALSE(has(line, "imgui"));
    CHECK_FALSE(has(line, "GL/"));
    CHECK_FALSE(has(line, "GLFW"));
  }
  for (const auto& [file, line] : includes("panels")) {
    INFO(file << ": " << line);
    CHECK_FALSE(has(line, "\"headless/"));
    CHECK_FALSE(has(line, "GL/"));
  }
}
