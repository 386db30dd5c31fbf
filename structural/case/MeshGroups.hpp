#pragma once
// A case's [mesh] table: the nodes of a gmsh mesh (.msh or .geo) and its physical groups mapped
// to roles: 2-D groups -> membranes, 1-D -> cables, sliding groups, drag edges; 0-D -> point
// masses, named nodes (a single-node group names its node: sliders, supports, probes). Every
// group is also a node set of the same name. Keys are documented in docs/meshing.md.
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "GmshMesh.hpp"
#include "case/TomlTable.hpp"
#include "model/Model.hpp"

namespace chute {

struct MeshImport {
  std::string file;  // as resolved (relative to the case file)
  mesh::GmshMesh mesh;
  std::map<std::size_t, int> node;  // gmsh node tag -> model node id
  // The group `key` names, of dimension dim; fails naming file, line, key and group otherwise.
  const mesh::MeshGroup& group(TomlTable& t, const std::string& key, int dim) const;
};

// Reads [mesh] (file, initial_displacement, scale) and adds every node of the mesh to the model.
std::unique_ptr<MeshImport> importMesh(Model& m, TomlTable t, const std::string& caseFile);

// Entries with `group = "..."` instead of their structured or path form (mesh may be null: error).
void readMeshCables(Model& m, const MeshImport* mesh, TomlTable t, int index);
void readMeshSlidingGroup(Model& m, const MeshImport* mesh, TomlTable t, int index);
void readMeshMembranes(Model& m, const MeshImport* mesh, TomlTable t);
void readMeshPointMasses(Model& m, const MeshImport* mesh, TomlTable t);
// The 2-node elements of a 1-D group as node-id pairs (drag on slider edges, ...).
std::vector<std::array<int, 2>> meshEdges(const MeshImport* mesh, TomlTable& t);

// Mesh nodes that no element, slider or point mass uses (groups the case does not map) are held
// fixed, so they add no singular dofs.
void holdUnusedMeshNodes(Model& m, const MeshImport& mesh);

}  // namespace chute
