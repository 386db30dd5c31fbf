#include "MeshWriter.hpp"

#include <gmsh.h>

#include <map>
#include <set>
#include <vector>

#include "GmshSession.hpp"

namespace chute::mesh {

namespace {

int gmshType(size_t nodes) {
  switch (nodes) {
    case 1:
      return 15;  // point
    case 2:
      return 1;  // 2-node line
    case 3:
      return 2;  // 3-node triangle
    default:
      return 3;  // 4-node quadrangle
  }
}

}  // namespace

void writeMesh(const GmshMesh& m, const std::string& file) {
  GmshScope scope;
  callGmsh("writing " + file, [&] {
    gmsh::model::add("assembled");
    // Each element once, with the groups it belongs to: those groups' common entity.
    using Element = std::pair<int, std::vector<std::size_t>>;  // dim, nodes
    std::map<Element, std::set<int>> groupsOf;
    std::vector<Element> order;
    for (int g = 0; g < static_cast<int>(m.groups.size()); ++g)
      for (const auto& e : m.groups[g].elements) {
        Element key{m.groups[g].dim, e};
        auto [it, fresh] = groupsOf.try_emplace(key);
        if (fresh) order.push_back(key);
        it->second.insert(g);
      }
    std::map<std::pair<int, std::set<int>>, int> entityOf;  // (dim, groups) -> entity tag
    std::map<int, std::vector<const Element*>> elementsOf;  // entity tag -> elements
    std::map<int, int> dimOf;
    for (const auto& key : order) {
      const auto id = std::make_pair(key.first, groupsOf.at(key));
      auto it = entityOf.find(id);
      if (it == entityOf.end()) {
        const int tag = gmsh::model::addDiscreteEntity(key.first);
        it = entityOf.emplace(id, tag).first;
        dimOf[tag] = key.first;
      }
      elementsOf[it->second].push_back(&key);
    }
    // Nodes: each on the first entity of the highest dimension that uses it.
    std::set<std::size_t> placed;
    for (int dim = 2; dim >= 0; --dim)
      for (const auto& [tag, elements] : elementsOf) {
        if (dimOf[tag] != dim) continue;
        std::vector<std::size_t> tags;
        std::vector<double> xyz;
        for (const Element* e : elements)
          for (std::size_t n : e->second)
            if (placed.insert(n).second) {
              tags.push_back(n);
              const Vec3& x = m.at(n);
              xyz.insert(xyz.end(), {x.x(), x.y(), x.z()});
            }
        if (!tags.empty()) gmsh::model::mesh::addNodes(dim, tag, tags, xyz);
      }
    std::size_t next = 1;
    for (const auto& [tag, elements] : elementsOf) {
      std::map<int, std::pair<std::vector<std::size_t>, std::vector<std::size_t>>> byType;
      for (const Element* e : elements) {
        auto& [ids, nodes] = byType[gmshType(e->second.size())];
        ids.push_back(next++);
        nodes.insert(nodes.end(), e->second.begin(), e->second.end());
      }
      for (const auto& [type, data] : byType)
        gmsh::model::mesh::addElementsByType(tag, type, data.first, data.second);
    }
    for (int g = 0; g < static_cast<int>(m.groups.size()); ++g) {
      std::vector<int> entities;
      for (const auto& [id, tag] : entityOf)
        if (id.first == m.groups[g].dim && id.second.count(g)) entities.push_back(tag);
      const int p = gmsh::model::addPhysicalGroup(m.groups[g].dim, entities);
      gmsh::model::setPhysicalName(m.groups[g].dim, p, m.groups[g].name);
    }
  });
  writeCurrentMesh(file, m.views);
}

}  // namespace chute::mesh
