// readMesh() for cases: .msh files through chute's own reader, nothing else; and the loader of the
// gmsh plugin (GmshPlugin.hpp) that `chute mesh` runs in.
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "GmshMesh.hpp"
#include "GmshPlugin.hpp"
#include "MeshError.hpp"
#include "MshReader.hpp"
#include "io/PluginPath.hpp"

namespace chute::mesh {

const GmshPluginApi& gmshPlugin() {
  static std::mutex mutex;
  static const GmshPluginApi* api = nullptr;
  std::lock_guard lock(mutex);
  if (api) return *api;
  const std::string path =
      pluginPath("CHUTE_GMSH_PLUGIN", "libchute_gmsh.so", CHUTE_GMSH_PLUGIN_PATH);
  // Never unloaded: gmsh finalises itself at exit.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw MeshError("cannot load gmsh support " + path + ": " + dlerror());
  using Entry = const GmshPluginApi* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, "chute_gmsh_plugin"));
  if (!entry) throw MeshError(path + " is not chute's gmsh plugin (no chute_gmsh_plugin)");
  const GmshPluginApi* loaded = entry();
  if (!loaded || loaded->version != kGmshPluginVersion)
    throw MeshError(path + ": gmsh plugin of another version of chute (rebuild)");
  api = loaded;
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
