#pragma once
// A gmsh mesh as plain data: nodes by tag, and the elements of every physical group (first-order
// points, lines, triangles, quadrangles) as lists of node tags, plus any 3-component NodeData
// views (e.g. "initial_displacement"). Cases read it with MshReader; writing goes through the
// gmsh API (GmshScope).
#include <cstddef>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "model/Model.hpp"

namespace chute::mesh {

struct MeshGroup {
  std::string name;
  int dim = 0;  // 0 points, 1 curves, 2 surfaces
  int tag = 0;
  std::vector<std::vector<std::size_t>> elements;  // node tags; 1, 2, 3 or 4 per element
  std::vector<std::size_t> nodes() const;          // every node once, in order of appearance
};

using NodeVectors = std::map<std::size_t, Vec3>;  // node tag -> vector

struct GmshMesh {
  std::vector<std::size_t> nodeTags;  // ascending
  std::vector<Vec3> coords;           // coords[i] belongs to nodeTags[i]
  std::vector<MeshGroup> groups;
  std::map<std::string, NodeVectors> views;  // 3-component NodeData views by name (step 0)

  int indexOf(std::size_t tag) const;  // -1 if absent
  const Vec3& at(std::size_t tag) const { return coords[indexOf(tag)]; }
  // The group of that name, preferring dimension dim when several share the name; nullptr if none.
  const MeshGroup* group(const std::string& name, int dim = -1) const;
  std::string groupList() const;  // "canopy (2-D), lines (1-D), ..." for error messages
  void buildIndex();

 private:
  std::unordered_map<std::size_t, int> index_;
};

// The nodes of a 1-D group that forms one open chain, from one end to the other (starting at
// `first` when given and an end). Throws MeshError if the elements do not form a simple chain.
std::vector<std::size_t> orderedChain(const MeshGroup& g, std::size_t first = 0);

// Reads a mesh file for a case: a .msh (2.2 or 4.1) through chute's own reader (MshReader.hpp),
// never through gmsh. Anything else -- a .geo script (gmsh scripts can run commands), a .unv,
// ... -- is refused: a .geo is meshed only by `chute mesh geo`. Throws MeshError naming the file.
struct MshLimits;
GmshMesh readMesh(const std::string& file);
GmshMesh readMesh(const std::string& file, const MshLimits& limits);

// Reads a .msh or meshes a .geo through the gmsh API (chute_mesh only): `chute mesh geo`, and the
// tests that compare chute's reader with gmsh's.
GmshMesh readMeshWithGmsh(const std::string& file);

// The mesh of gmsh's current model (inside a GmshScope).
GmshMesh currentMesh();

// Writes gmsh's current model to a .msh 4.1 file and appends the views (NodeData, 3 components).
void writeCurrentMesh(const std::string& file, const std::map<std::string, NodeVectors>& views);

}  // namespace chute::mesh
