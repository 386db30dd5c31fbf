#include "terms/FaceDragTerm.hpp"

#include <algorithm>
#include <type_traits>

#include "kernels/FaceDrag.hpp"

namespace chute {

using kernels::Vec3;

void FaceDragTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  for (const auto& e : m_->membranes)
    if (std::any_of(m_->faceDrags.begin(), m_->faceDrags.end(),
                    [&](const FaceDragLoadDef& d) { return d.set == e.set; }))
      cliques.emplace_back(e.nodes.begin(), e.nodes.begin() + e.numNodes);
}

namespace {
// Residual only (the explicit path): the one residual every node of the face gets (FD1).
template <int N>
void addNodeResiduals(const MembraneElement& e, const FaceDragLoadDef& load, double coef,
                      const EvalPoint& p, SystemAssembler& out) {
  std::array<Vec3, N> x, v;
  std::array<int, N> ids;
  for (int i = 0; i < N; ++i) {
    ids[i] = e.nodes[i];
    x[i] = p.x.segment<3>(3 * ids[i]);
    v[i] = p.v.segment<3>(3 * ids[i]);
  }
  out.addToEachNode<N>(
      ids, kernels::faceDragNodeResidual<N>(x, v, load.wind, coef, load.steadySubtracted));
}
}  // namespace

// Per face, 0.72 of an explicit membrane triangle (Term::assemblyCost); none for the faces the
// membrane term takes (P2).
double FaceDragTerm::assemblyCost() const {
  return 0.72 * faces_.left();
}

void FaceDragTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  if (!p.inertia) return;  // drag needs motion: nothing in statics
  const bool wantJ = out.wantMatrix();
  // The faces the membranes' pass takes are left out of the explicit step's evaluation (P2).
  const auto& faces = faces_.of(p, out);
  for (size_t li = 0; li < faces.size(); ++li) {
    const FaceDragLoadDef& load = m_->faceDrags[li];
    const double coef = load.coefficient * p.loadFactor;  // an applied load, like the others
    for (const auto& f : faces[li]) {
      const auto& e = m_->membranes[f.element];
      ++out.work().faceDrag;
      if (!wantJ) {
        if (e.numNodes == 3)
          addNodeResiduals<3>(e, load, coef, p, out);
        else
          addNodeResiduals<4>(e, load, coef, p, out);
        continue;
      }
      auto one = [&](auto nodesTag) {
        constexpr int N = decltype(nodesTag)::value;
        std::array<Vec3, N> x, v;
        std::array<int, N> ids;
        for (int i = 0; i < N; ++i) {
          ids[i] = e.nodes[i];
          x[i] = p.x.segment<3>(3 * ids[i]);
          v[i] = p.v.segment<3>(3 * ids[i]);
        }
        const auto d = kernels::faceDrag<N>(x, v, load.wind, coef, load.steadySubtracted, true);
        const Eigen::Matrix<double, 3 * N, 3 * N> J = p.cx * d.dPosition + p.cv * d.dVelocity;
        out.add<N>(ids, d.residual, &J);
      };
      if (e.numNodes == 3)
        one(std::integral_constant<int, 3>{});
      else
        one(std::integral_constant<int, 4>{});
    }
  }
}

}  // namespace chute
