#include "terms/contact/ContactMesh.hpp"

#include <algorithm>
#include <set>

#include "terms/sliding/SlidingGroupState.hpp"

namespace chute::contact {

namespace {
bool contains(const std::vector<int>& v, int k) {
  return std::find(v.begin(), v.end(), k) != v.end();
}
}  // namespace

ContactMesh::ContactMesh(const Model& m, const ContactDef& def) {
  std::set<std::array<int, 2>> edges;
  std::set<int> points, nodes;
  auto addEdge = [&](int a, int b) { edges.insert({std::min(a, b), std::max(a, b)}); };
  for (const auto& e : m.membranes) {
    if (!contains(def.membraneSets, e.set)) continue;
    const auto& n = e.nodes;
    // A quadrilateral is two triangles sharing its diagonal 0-2 (the contact surface is then
    // the two triangles; a warped quad's own surface lies between them).
    triangles_.push_back({n[0], n[1], n[2]});
    if (e.numNodes == 4) {
      triangles_.push_back({n[0], n[2], n[3]});
      addEdge(n[0], n[2]);
    }
    for (int i = 0; i < e.numNodes; ++i) {
      addEdge(n[i], n[(i + 1) % e.numNodes]);
      points.insert(n[i]);
    }
  }
  for (const auto& c : m.cables) {
    if (!contains(def.lineSets, c.set)) continue;
    lines_.push_back({c.a, c.b, -1, -1});
    points.insert(c.a), points.insert(c.b);
  }
  for (size_t g = 0; g < m.groups.size(); ++g) {
    const auto& grp = m.groups[g];
    if (!contains(def.lineSets, grp.set)) continue;
    for (int k = 0; k + 1 < static_cast<int>(grp.chain.size()); ++k) {
      lines_.push_back({grp.chain[k], grp.chain[k + 1], static_cast<int>(g), k});
      points.insert(grp.chain[k]), points.insert(grp.chain[k + 1]);
    }
    for (int s : grp.sliders) points.insert(s), nodes.insert(s);
  }
  lineOfElement_.resize(m.groups.size());
  for (size_t g = 0; g < m.groups.size(); ++g)
    lineOfElement_[g].assign(m.groups[g].numElements(), -1);
  for (size_t i = 0; i < lines_.size(); ++i)
    if (lines_[i].group >= 0)
      lineOfElement_[lines_[i].group][lines_[i].element] = static_cast<int>(i);
  edges_.assign(edges.begin(), edges.end());
  points_.assign(points.begin(), points.end());
  nodes.insert(points.begin(), points.end());
  nodes_.assign(nodes.begin(), nodes.end());
  free_.assign(m.numNodes(), 0);
  for (int n = 0; n < m.numNodes(); ++n) {
    const auto& f = m.constraint[n].fixed;
    free_[n] = !(f[0] && f[1] && f[2]);
  }
}

void ContactMesh::slidersOn(const std::vector<const SlidingGroupState*>& groups,
                            std::vector<int>& sliders) const {
  sliders.assign(lines_.size(), -1);
  for (size_t g = 0; g < groups.size() && g < lineOfElement_.size(); ++g) {
    const SlidingGroupState& st = *groups[g];
    const auto& nodes = st.def().sliders;
    // From the last slider to the first: the first on an element is the one left there.
    for (int k = static_cast<int>(nodes.size()) - 1; k >= 0; --k) {
      const int e = st.activeElement(k);
      if (e >= 0 && e < static_cast<int>(lineOfElement_[g].size()) && lineOfElement_[g][e] >= 0)
        sliders[lineOfElement_[g][e]] = nodes[k];
    }
  }
}

}  // namespace chute::contact
