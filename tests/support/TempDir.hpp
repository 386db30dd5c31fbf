#pragma once
// An empty scratch path under the system's temporary directory, one per test and name.
#include <filesystem>
#include <string>

namespace chute::testing {

// temp/<prefix><name>, removed if present; created when `create` (else left for the code under
// test to create, as `chute run --out` does).
inline std::filesystem::path freshTempDir(const std::string& prefix, const std::string& name,
                                          bool create = false) {
  const auto d = std::filesystem::temp_directory_path() / (prefix + name);
  std::filesystem::remove_all(d);
  if (create) std::filesystem::create_directories(d);
  return d;
}

}  // namespace chute::testing
