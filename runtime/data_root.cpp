#include "data_root.hpp"
#include <cstdlib>
#include <system_error>

namespace sw {

std::filesystem::path data_root() {
  if (const char* env = std::getenv("STEPWISE_DATA"); env && *env) return env;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path installed = (exe.parent_path() / ".." / "share" / "stepwise").lexically_normal();
    if (std::filesystem::is_regular_file(installed / "lessons" / "manifest.txt", ec)) return installed;
  }
#ifdef SW_SOURCE_ROOT
  return SW_SOURCE_ROOT;
#else
  return ".";
#endif
}

}  // namespace sw
