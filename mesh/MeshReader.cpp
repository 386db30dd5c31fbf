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

namespace chute::mesh {

namespace {
std::string pluginPath() {
  if (const char* p = std::getenv("CHUTE_GMSH_PLUGIN"); p && *p) return p;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto next = exe.parent_path() / "libchute_gmsh.so";
    if (std::filesystem::exists(next, ec)) return next.string();
  }
  return CHUTE_GMSH_PLUGIN_PATH;  // the build tree's
}
}  // namespace

const GmshPluginApi& gmshPlugin() {
  static std::mutex mutex;
  static const GmshPluginApi* api = nullptr;
  std::lock_guard lock(mutex);
  if (api) return *api;
  const std::string path = pluginPath();
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
