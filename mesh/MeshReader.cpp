// readMesh(): in-process when gmsh is linked in, else through the gmsh plugin (GmshPlugin.hpp).
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "GmshMesh.hpp"
#include "GmshPlugin.hpp"
#include "MeshError.hpp"

namespace chute::mesh {

namespace {
MeshReaderFn& inProcessReader() {
  static MeshReaderFn reader = nullptr;
  return reader;
}

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

void setInProcessMeshReader(MeshReaderFn reader) {
  inProcessReader() = reader;
}

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
  if (const MeshReaderFn reader = inProcessReader()) return reader(file);
  const GmshPluginApi& plugin = gmshPlugin();
  GmshMesh mesh;
  std::string error;
  if (!plugin.readMesh(file.c_str(), &mesh, &error)) throw MeshError(error);
  return mesh;
}

}  // namespace chute::mesh
