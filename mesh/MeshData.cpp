// GmshMesh as plain data: lookups and chains (no gmsh here; reading is in GmshMesh.cpp, loaded
// through MeshReader).
#include <algorithm>
#include <set>

#include "GmshMesh.hpp"
#include "MeshError.hpp"

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

}  // namespace chute::mesh
