// readMesh() for cases: .msh files through chute's own reader, nothing else; and the loader of the
// gmsh plugin (GmshPlugin.hpp) that `chute mesh` runs in.
#include <filesystem>
#include <mutex>

#include "GmshMesh.hpp"
#include "GmshPlugin.hpp"
#include "MeshError.hpp"
#include "MshReader.hpp"
#include "io/Plugin.hpp"

namespace chute::mesh {

const GmshPluginApi& gmshPlugin() {
  static std::mutex mutex;
  static const GmshPluginApi* api = nullptr;
  std::lock_guard lock(mutex);
  if (api) return *api;
  const std::string path =
      pluginPath("CHUTE_GMSH_PLUGIN", "libchute_gmsh.so", CHUTE_GMSH_PLUGIN_PATH);
  // Never unloaded: gmsh finalises itself at exit.
  std::string why;
  api = loadPlugin<GmshPluginApi>(path, "chute_gmsh_plugin", kGmshPluginVersion, "gmsh support",
                                  "gmsh plugin", why);
  if (!api) throw MeshError(why);
  return *api;
}

GmshMesh readMesh(const std::string& file) {
  return readMesh(file, MshLimits{});
}

GmshMesh readMesh(const std::string& file, const MshLimits& limits) {
  const std::string ext = std::filesystem::path(file).extension().string();
  if (ext == ".geo")
    throw MeshError(file +
                    ": a gmsh script is not read by a case (it can run commands): mesh it "
                    "with `chute mesh geo " +
                    file + " --out MESH.msh` and name the .msh");
  if (ext != ".msh")
    throw MeshError(file + ": not a .msh file: chute reads gmsh .msh meshes (formats 2.2 and 4.1)");
  return readMsh(file, limits);
}

}  // namespace chute::mesh
