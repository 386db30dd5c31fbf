// `chute --version`: chute's version and build, and the versions of the libraries it was built
// against, each read here from the same headers' macros (an independent reading: the test does
// not call chute's own formatting).
#include <SuiteSparse_config.h>
#include <fmt/core.h>
#include <gmsh.h>
#include <gtest/gtest.h>
#include <vtkVersionMacros.h>

#include <CLI/Version.hpp>
#include <Eigen/Core>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <toml.hpp>
#include <vector>

namespace {
std::string output(const std::string& cmd, int& status) {
  std::string text;
  std::FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return text;
  char buf[256];
  while (std::fgets(buf, sizeof buf, p)) text += buf;
  status = ::pclose(p);
  return text;
}
std::string v3(int a, int b, int c) {
  return std::to_string(a) + "." + std::to_string(b) + "." + std::to_string(c);
}
}  // namespace

TEST(Version, NamesChuteItsBuildAndEveryLibraryWithItsHeaderVersion) {
  int status = -1;
  const std::string text = output(std::string(CHUTE_BINARY) + " --version", status);
  std::printf("%s\n", text.c_str());
  EXPECT_EQ(status, 0);
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"chute", "0."},
      {"Eigen", v3(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
      {"SuiteSparse",
       v3(SUITESPARSE_MAIN_VERSION, SUITESPARSE_SUB_VERSION, SUITESPARSE_SUBSUB_VERSION)},
      {"VTK", VTK_VERSION},
      {"gmsh", GMSH_API_VERSION},
      {"toml11", v3(TOML11_VERSION_MAJOR, TOML11_VERSION_MINOR, TOML11_VERSION_PATCH)},
      {"fmt", v3(FMT_VERSION / 10000, FMT_VERSION / 100 % 100, FMT_VERSION % 100)},
      {"nlohmann-json",
       v3(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH)},
      {"CLI11", CLI11_VERSION}};
  for (const auto& [name, version] : expected) {
    // A line naming the library and then its version.
    const auto at = text.find(name + " ");
    ASSERT_NE(at, std::string::npos) << name;
    const std::string line = text.substr(at, text.find('\n', at) - at);
    EXPECT_NE(line.find(version), std::string::npos) << line << " (expected " << version << ")";
  }
  EXPECT_NE(text.find(CHUTE_BUILD_TYPE_NAME " build"), std::string::npos);
  EXPECT_NE(text.find("gcc"), std::string::npos);
}
