#include "terms/PressureTerm.hpp"

#include <algorithm>
#include <type_traits>

#include "kernels/PressureKernel.hpp"
#include "terms/MembraneElementAssembly.hpp"

namespace chute {

using kernels::Vec3;
using membrane_assembly::gatherNodes;
using membrane_assembly::nodeIds;

// ---- PressureTerm --------------------------------------------------------------------------
void PressureTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  // Only the loaded sets' elements (the membrane term already couples all of them).
  for (const auto& e : m_->membranes)
    if (std::any_of(m_->pressures.begin(), m_->pressures.end(),
                    [&](const PressureLoadDef& l) { return l.set == e.set; }))
      cliques.emplace_back(e.nodes.begin(), e.nodes.begin() + e.numNodes);
}

namespace {
// Residual only (the explicit path), a triangle under a uniform pressure: the one force on each
// of its nodes (P1).
void addTriangleResidual(const MembraneElement& e, double pressure, const EvalPoint& p,
                         SystemAssembler& out) {
  const Vec3 f = kernels::trianglePressureForce(gatherNodes<3>(p.x, e), pressure);
  Eigen::Matrix<double, 9, 1> r;
  r << -f, -f, -f;
  out.add<3>(nodeIds<3>(e), r, nullptr);
}
}  // namespace

// Per face, 0.42 of an explicit membrane triangle (Term::assemblyCost); none for the faces the
// membrane term takes (P2).
double PressureTerm::assemblyCost() const {
  return 0.42 * faces_.left();
}

void PressureTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  const bool wantJ = out.wantMatrix();
  // The faces the membranes' pass takes are left out of the explicit step's evaluation (P2).
  const auto& faces = faces_.of(p, out);
  for (size_t li = 0; li < faces.size(); ++li) {
    const PressureLoadDef& load = m_->pressures[li];
    const double p0 = p.loadFactor * load.at(p.t);
    if (p0 == 0.0) continue;
    for (const auto& f : faces[li]) {
      const auto& e = m_->membranes[f.element];
      const double pr = load.elementFactor.empty() ? p0 : p0 * load.elementFactor[f.inSet];
      ++out.work().pressure;
      if (!wantJ && e.numNodes == 3) {
        addTriangleResidual(e, pr, p, out);
        continue;
      }
      auto one = [&](auto nodesTag) {
        constexpr int N = decltype(nodesTag)::value;
        const auto pl = kernels::pressureLoad<N>(gatherNodes<N>(p.x, e), pr, wantJ);
        const Eigen::Matrix<double, 3 * N, 1> r = -pl.force;
        if (!wantJ) {
          out.add<N>(nodeIds<N>(e), r, nullptr);
          return;
        }
        const Eigen::Matrix<double, 3 * N, 3 * N> J = -p.cx * pl.dForce;
        out.add<N>(nodeIds<N>(e), r, &J);
      };
      if (e.numNodes == 3)
        one(std::integral_constant<int, 3>{});
      else
        one(std::integral_constant<int, 4>{});
    }
  }
}

}  // namespace chute
