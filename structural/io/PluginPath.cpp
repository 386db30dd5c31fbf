#include "io/PluginPath.hpp"

#include <cstdlib>
#include <filesystem>

namespace chute {

std::string pluginPath(const char* environmentVariable, const char* fileName,
                       const char* buildTreePath) {
  if (const char* p = std::getenv(environmentVariable); p && *p) return p;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto next = exe.parent_path() / fileName;
    if (std::filesystem::exists(next, ec)) return next.string();
  }
  return buildTreePath;
}

}  // namespace chute
