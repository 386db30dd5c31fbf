#include "io/Plugin.hpp"

#include <dlfcn.h>

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

void* pluginSymbol(const std::string& path, const char* symbol, const std::string& what,
                   const std::string& name, std::string& why) {
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    why = "cannot load " + what + " " + path + ": " + dlerror();
    return nullptr;
  }
  void* entry = dlsym(handle, symbol);
  if (!entry) why = path + " is not chute's " + name + " (no " + symbol + ")";
  return entry;
}

}  // namespace chute
