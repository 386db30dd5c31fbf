#pragma once
// The gmsh plugin (libchute_gmsh.so): everything that calls gmsh, behind a table of functions
// that the `chute` command loads with dlopen when
// the user runs `chute mesh` (meshes are read without gmsh: MshReader.hpp). Loading gmsh costs ~0.2
// s (about 90 libraries); a run that reads no mesh never pays it.
#include <string>

#include "GmshMesh.hpp"

namespace chute::mesh {

constexpr int kGmshPluginVersion = 2;

struct GmshPluginApi {
  int version = kGmshPluginVersion;
  // `chute mesh ...` (argv[0] = "chute", argv[1] = "mesh"); returns the exit status.
  int (*meshCommand)(int argc, char** argv) = nullptr;
};

// The loaded plugin: $CHUTE_GMSH_PLUGIN, else libchute_gmsh.so next to the executable, else the
// build tree's. Throws MeshError naming the path if it cannot be loaded.
const GmshPluginApi& gmshPlugin();

}  // namespace chute::mesh

// The plugin's one exported symbol.
extern "C" const chute::mesh::GmshPluginApi* chute_gmsh_plugin();
