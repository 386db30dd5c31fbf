#include "GmshMesh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "GmshSession.hpp"

namespace chute::mesh {

std::vector<std::size_t> MeshGroup::nodes() const {
  std::vector<std::size_t> out;
  std::set<std::size_t> seen;
  for (const auto& e : elements)
    for (std::size_t n : e)
      if (seen.insert(n).second) out.push_back(n);
  return out;
}

int GmshMesh::indexOf(std::size_t tag) const {
  auto it = index_.find(tag);
  return it == index_.end() ? -1 : it->second;
}

const MeshGroup* GmshMesh::group(const std::string& name, int dim) const {
  const MeshGroup* found = nullptr;
  for (const auto& g : groups)
    if (g.name == name && (!found || g.dim == dim)) found = &g;
  return found;
}

std::string GmshMesh::groupList() const {
  std::string s;
  for (const auto& g : groups)
    s += (s.empty() ? "" : ", ") + g.name + " (" + std::to_string(g.dim) + "-D)";
  return s.empty() ? "none" : s;
}

void GmshMesh::buildIndex() {
  index_.clear();
  for (size_t i = 0; i < nodeTags.size(); ++i) index_[nodeTags[i]] = static_cast<int>(i);
}

std::vector<std::size_t> orderedChain(const MeshGroup& g, std::size_t first) {
  std::map<std::size_t, std::vector<std::size_t>> next;
  for (const auto& e : g.elements) {
    if (e.size() != 2) throw MeshError("group '" + g.name + "' is not made of 2-node lines");
    next[e[0]].push_back(e[1]);
    next[e[1]].push_back(e[0]);
  }
  std::vector<std::size_t> ends;
  for (const auto& [n, nb] : next) {
    if (nb.size() > 2)
      throw MeshError("group '" + g.name + "' branches at node " + std::to_string(n) +
                      " (a chain is needed)");
    if (nb.size() == 1) ends.push_back(n);
  }
  if (ends.size() != 2)
    throw MeshError("group '" + g.name + "' is not one open chain of lines (" +
                    std::to_string(ends.size()) + " ends)");
  std::size_t cur = std::find(ends.begin(), ends.end(), first) != ends.end() ? first : ends[0];
  std::vector<std::size_t> chain{cur};
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::size_t prev = none;
  for (size_t k = 0; k < g.elements.size(); ++k) {
    const auto& nb = next[cur];
    const std::size_t nxt = nb[0] != prev ? nb[0] : (nb.size() > 1 ? nb[1] : none);
    if (nxt == none) break;
    prev = cur;
    cur = nxt;
    chain.push_back(cur);
  }
  if (chain.size() != g.elements.size() + 1 ||
      std::set<std::size_t>(chain.begin(), chain.end()).size() != chain.size())
    throw MeshError("group '" + g.name + "' is not one connected chain of lines");
  return chain;
}

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

GmshMesh readMesh(const std::string& file) {
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
