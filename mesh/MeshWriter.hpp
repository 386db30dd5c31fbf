#pragma once
// Writes a mesh held as plain data (GmshMesh) to a .msh 4.1 file through the gmsh API: elements
// that belong to the same physical groups become one discrete entity, so a mesh assembled from
// pieces (ClusterGenerator.hpp) reads back with the same groups and views. Call outside any
// GmshScope (it opens its own).
#include <string>

#include "GmshMesh.hpp"

namespace chute::mesh {

void writeMesh(const GmshMesh& mesh, const std::string& file);

}  // namespace chute::mesh
