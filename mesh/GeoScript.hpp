#pragma once
// `chute mesh geo`: meshes a gmsh script (.geo) into a .msh. A .geo is a program -- it can run
// shell commands (System "..."), loop forever or allocate without bound -- so it is run only
// when the user asks for it by this verb, never by a case or the coupling library, and in a
// child process with a time limit and an address-space limit; its whole process group is killed
// when the time is up. The .msh appears only when the script succeeded and chute's own reader
// (MshReader.hpp) reads it back.
#include <string>

#include "GmshMesh.hpp"

namespace chute::mesh {

struct GeoScriptLimits {
  double seconds = 600.0;     // wall time of the script and the meshing
  double memoryMiB = 8192.0;  // address space of the child (RLIMIT_AS)
};

// Runs `geo` through gmsh, meshes it in the highest dimension of its entities and writes `out`
// (.msh 4.1, ASCII). Returns the mesh as read back. Throws MeshError: the script failed, timed out
// or ran out of memory (nothing written).
GmshMesh meshGeoScript(const std::string& geo, const std::string& out,
                       const GeoScriptLimits& limits);

}  // namespace chute::mesh
