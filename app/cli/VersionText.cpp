#include "app/cli/VersionText.hpp"

#include <SuiteSparse_config.h>
#include <fmt/core.h>
#include <gmsh.h>
#include <vtkVersionMacros.h>

#include <CLI/Version.hpp>
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <toml.hpp>

namespace chute::cli {

namespace {
std::string compiler() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("gcc ") + __VERSION__;
#else
  return "unknown compiler";
#endif
}
}  // namespace

std::string versionText() {
  std::string s = fmt::format("chute {} ({} build, {}, C++{})\n", CHUTE_VERSION, CHUTE_BUILD_TYPE,
                              compiler(), __cplusplus / 100 % 100);
  s += fmt::format("  Eigen         {}.{}.{}\n", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION,
                   EIGEN_MINOR_VERSION);
  s += fmt::format("  SuiteSparse   {}.{}.{} (CHOLMOD, UMFPACK)\n", SUITESPARSE_MAIN_VERSION,
                   SUITESPARSE_SUB_VERSION, SUITESPARSE_SUBSUB_VERSION);
  s += fmt::format("  VTK           {}\n", VTK_VERSION);
  s += fmt::format("  gmsh          {} (API of gmsh.h; `chute mesh` loads libchute_gmsh.so)\n",
                   GMSH_API_VERSION);
  s += fmt::format("  toml11        {}.{}.{}\n", TOML11_VERSION_MAJOR, TOML11_VERSION_MINOR,
                   TOML11_VERSION_PATCH);
  s += fmt::format("  fmt           {}.{}.{}\n", FMT_VERSION / 10000, FMT_VERSION / 100 % 100,
                   FMT_VERSION % 100);
  s += fmt::format("  nlohmann-json {}.{}.{}\n", NLOHMANN_JSON_VERSION_MAJOR,
                   NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH);
  s += fmt::format("  CLI11         {}", CLI11_VERSION);
  return s;
}

}  // namespace chute::cli
