#pragma once
// chute's plugins (the gmsh plugin, the render plugin): shared libraries loaded with dlopen on
// first use, each exporting one function that returns its table of functions, whose first
// member is its version.
#include <string>

namespace chute {

// Where a plugin is looked for: the path the environment variable names, else the file next to
// the running executable, else the build tree's (where a test or a script runs an executable
// from elsewhere).
std::string pluginPath(const char* environmentVariable, const char* fileName,
                       const char* buildTreePath);

// The plugin file at `path` opened (never unloaded) and its exported `symbol`; nullptr on failure,
// with `why` one line naming the path. `what`: what the plugin brings ("gmsh support"), `name`:
// what it is ("gmsh plugin").
void* pluginSymbol(const std::string& path, const char* symbol, const std::string& what,
                   const std::string& name, std::string& why);

// The plugin's table (Api, whose `version` must be `version`), from pluginSymbol's entry.
template <class Api>
const Api* loadPlugin(const std::string& path, const char* symbol, int version,
                      const std::string& what, const std::string& name, std::string& why) {
  void* entry = pluginSymbol(path, symbol, what, name, why);
  if (!entry) return nullptr;
  const Api* api = reinterpret_cast<const Api* (*)()>(entry)();
  if (api && api->version == version) return api;
  why = path + ": " + name + " of another version of chute (rebuild)";
  return nullptr;
}

}  // namespace chute
