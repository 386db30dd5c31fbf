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

FaceDragTerm::FaceDragTerm(const Model& m) : m_(&m), faces_(m.faceDrags.size()) {
  for (size_t li = 0; li < m.faceDrags.size(); ++li) {
    int inSet = 0;
    for (size_t k = 0; k < m.membranes.size(); ++k)
      if (m.membranes[k].set == m.faceDrags[li].set)
        faces_[li].push_back({static_cast<int>(k), inSet++});
  }
  left_ = faces_;
}

void FaceDragTerm::leaveFaces(TakenFaces taken) {
  taken_ = std::move(taken);
  for (size_t li = 0; li < faces_.size(); ++li) {
    left_[li].clear();
    for (const Face& f : faces_[li])
      if (!(taken_ && (*taken_)[f.element])) left_[li].push_back(f);
  }
}

// Per face, 0.72 of an explicit membrane triangle (Term::assemblyCost); none for the faces the
// membrane term takes (P2).
double FaceDragTerm::assemblyCost() const {
  double faces = 0.0;
  for (const auto& l : left_) faces += static_cast<double>(l.size());
  return 0.72 * faces;
}

void FaceDragTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  if (!p.inertia) return;  // drag needs motion: nothing in statics
  const bool wantJ = out.wantMatrix();
  // The faces the membranes' pass takes are left out of the explicit step's evaluation (P2).
  const auto& faces = taken_ && fusedFaceLoads(p, out) ? left_ : faces_;
  for (size_t li = 0; li < faces.size(); ++li) {
    const FaceDragLoadDef& load = m_->faceDrags[li];
    const double coef = load.coefficient * p.loadFactor;  // an applied load, like the others
    for (const Face& f : faces[li]) {
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
