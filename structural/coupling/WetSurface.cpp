#include "coupling/WetSurface.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "case/CaseText.hpp"
#include "kernels/PressureKernel.hpp"

namespace chute::coupling {

WetSurface WetSurface::fromModel(const Model& m, const std::vector<std::string>& setNames) {
  if (m.membranes.empty())
    throw std::invalid_argument("the model has no membranes: no wet surface to couple");
  WetSurface w;
  if (setNames.empty()) {
    for (size_t s = 0; s < m.membraneSets.size(); ++s) w.sets.push_back(static_cast<int>(s));
  } else {
    for (const auto& name : setNames) {
      auto it = std::find_if(m.membraneSets.begin(), m.membraneSets.end(),
                             [&](const MembraneSet& s) { return s.name == name; });
      if (it == m.membraneSets.end()) {
        std::vector<std::string> known;
        for (const auto& s : m.membraneSets) known.push_back(s.name);
        throw std::invalid_argument("no membrane set '" + name + "' for the wet surface" +
                                    caseio::nameSuggestion(name, known, "membrane sets"));
      }
      w.sets.push_back(static_cast<int>(it - m.membraneSets.begin()));
    }
  }
  auto wet = [&](int set) { return std::find(w.sets.begin(), w.sets.end(), set) != w.sets.end(); };
  std::map<int, int> vertexOf;
  for (size_t k = 0; k < m.membranes.size(); ++k)
    if (wet(m.membranes[k].set))
      for (int i = 0; i < m.membranes[k].numNodes; ++i) vertexOf[m.membranes[k].nodes[i]] = 0;
  for (auto& [n, v] : vertexOf) {
    v = static_cast<int>(w.node.size());
    w.node.push_back(n);
  }
  for (size_t k = 0; k < m.membranes.size(); ++k) {
    const auto& e = m.membranes[k];
    if (!wet(e.set)) continue;
    std::array<int, 4> f{-1, -1, -1, -1};
    for (int i = 0; i < e.numNodes; ++i) f[i] = vertexOf.at(e.nodes[i]);
    w.element.push_back(static_cast<int>(k));
    w.faceVertices.push_back(f);
    w.faceSize.push_back(e.numNodes);
  }
  return w;
}

Eigen::VectorXd WetSurface::gather(const Eigen::VectorXd& full) const {
  Eigen::VectorXd out(3 * numVertices());
  for (int v = 0; v < numVertices(); ++v) out.segment<3>(3 * v) = full.segment<3>(3 * node[v]);
  return out;
}

Eigen::VectorXd WetSurface::faceAreaVectors(const Eigen::VectorXd& x) const {
  Eigen::VectorXd out(3 * numFaces());
  for (int f = 0; f < numFaces(); ++f) {
    const auto& fv = faceVertices[f];
    auto at = [&](int i) -> Vec3 { return x.segment<3>(3 * node[fv[i]]); };
    out.segment<3>(3 * f) = faceSize[f] == 3 ? kernels::areaVector<3>({at(0), at(1), at(2)})
                                             : kernels::areaVector<4>({at(0), at(1), at(2), at(3)});
  }
  return out;
}

Eigen::VectorXd WetSurface::faceMeans(const Eigen::VectorXd& vertexValues) const {
  Eigen::VectorXd out(3 * numFaces());
  for (int f = 0; f < numFaces(); ++f) {
    Vec3 s = Vec3::Zero();
    for (int i = 0; i < faceSize[f]; ++i) s += vertexValues.segment<3>(3 * faceVertices[f][i]);
    out.segment<3>(3 * f) = s / faceSize[f];
  }
  return out;
}

}  // namespace chute::coupling
