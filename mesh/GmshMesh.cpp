#include "GmshMesh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "GmshSession.hpp"

namespace chute::mesh {

namespace {

int nodesOfType(int type) {
  switch (type) {
    case 15:
      return 1;  // point
    case 1:
      return 2;  // 2-node line
    case 2:
      return 3;  // 3-node triangle
    case 3:
      return 4;  // 4-node quadrangle
    default:
      return -1;
  }
}

}  // namespace

GmshMesh currentMesh() {
  GmshMesh mesh;
  std::vector<std::size_t> tags;
  std::vector<double> xyz, param;
  gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, false, false);
  std::unordered_map<std::size_t, size_t> where;
  for (size_t i = 0; i < tags.size(); ++i) where[tags[i]] = i;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  for (const auto& [dim, tag] : groups) {
    MeshGroup g;
    g.dim = dim;
    g.tag = tag;
    gmsh::model::getPhysicalName(dim, tag, g.name);
    if (g.name.empty()) g.name = "physical_" + std::to_string(dim) + "d_" + std::to_string(tag);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (int ent : entities) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elTags, elNodes;
      gmsh::model::mesh::getElements(types, elTags, elNodes, dim, ent);
      for (size_t t = 0; t < types.size(); ++t) {
        const int n = nodesOfType(types[t]);
        if (n < 0) {
          std::string typeName;
          int d, order, nn, np;
          std::vector<double> lc;
          gmsh::model::mesh::getElementProperties(types[t], typeName, d, order, nn, lc, np);
          throw MeshError("physical group '" + g.name + "' has elements of type '" + typeName +
                          "': only first-order points, lines, triangles and quadrangles are "
                          "supported");
        }
        for (size_t e = 0; e < elTags[t].size(); ++e)
          g.elements.emplace_back(elNodes[t].begin() + e * n, elNodes[t].begin() + (e + 1) * n);
      }
    }
    mesh.groups.push_back(std::move(g));
  }
  // The nodes the groups use (what a .msh keeps), ascending by tag.
  std::set<std::size_t> used;
  for (const auto& g : mesh.groups)
    for (const auto& e : g.elements) used.insert(e.begin(), e.end());
  for (std::size_t t : used) {
    const size_t i = where.at(t);
    mesh.nodeTags.push_back(t);
    mesh.coords.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  }
  mesh.buildIndex();

  std::vector<int> views;
  gmsh::view::getTags(views);
  for (int v : views) {
    std::string name;
    gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(v)) + "].Name", name);
    std::string type;
    std::vector<std::size_t> vt;
    std::vector<std::vector<double>> data;
    double time;
    int numComp;
    gmsh::view::getModelData(v, 0, type, vt, data, time, numComp);
    if (type != "NodeData" || numComp != 3) continue;
    auto& out = mesh.views[name];
    for (size_t i = 0; i < vt.size(); ++i) out[vt[i]] = Vec3(data[i][0], data[i][1], data[i][2]);
  }
  return mesh;
}

GmshMesh readMeshWithGmsh(const std::string& file) {
  if (!std::filesystem::exists(file)) throw MeshError(file + ": no such mesh file");
  GmshScope scope;
  return callGmsh(file, [&] {
    gmsh::open(file);
    if (std::filesystem::path(file).extension() == ".geo")
      gmsh::model::mesh::generate(gmsh::model::getDimension());
    GmshMesh m = currentMesh();
    if (m.nodeTags.empty()) throw MeshError(file + ": the mesh has no nodes");
    return m;
  });
}

void writeCurrentMesh(const std::string& file, const std::map<std::string, NodeVectors>& views) {
  callGmsh("writing " + file, [&] {
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.Binary", 0);
    gmsh::write(file);
    gmsh::option::setNumber("PostProcessing.SaveMesh", 0);  // the views only, after the mesh
    gmsh::option::setNumber("PostProcessing.SaveInterpolationMatrices", 0);
    std::string model;
    gmsh::model::getCurrent(model);
    for (const auto& [name, values] : views) {
      const int v = gmsh::view::add(name);
      std::vector<std::size_t> tags;
      std::vector<std::vector<double>> data;
      for (const auto& [tag, u] : values) {
        tags.push_back(tag);
        data.push_back({u.x(), u.y(), u.z()});
      }
      gmsh::view::addModelData(v, 0, model, "NodeData", tags, data, 0.0, 3);
      gmsh::view::write(v, file, true);
      gmsh::view::remove(v);
    }
  });
}

}  // namespace chute::mesh
