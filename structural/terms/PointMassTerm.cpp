#include "terms/PointMassTerm.hpp"

namespace chute {

// ---- PointMassTerm ---------------------------------------------------------------------------
PointMassTerm::PointMassTerm(const Model& m) : m_(&m) {
  for (int n = 0; n < m.numNodes(); ++n)
    if (m.pointMass[n] != 0.0) nodes_.push_back(n);
}

void PointMassTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  for (int n : nodes_) cliques.push_back({n});
}

void PointMassTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  const bool wantJ = out.wantMatrix();
  for (int n : nodes_) {
    const double mass = m_->pointMass[n];
    Eigen::Matrix<double, 3, 1> r = Eigen::Matrix<double, 3, 1>::Zero();
    Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
    if (p.inertia) {
      r += mass * p.a.segment<3>(3 * n);
      J += p.ca * mass * Eigen::Matrix3d::Identity();
      if (m_->massDamping > 0.0) {  // C v with C = alpha M (solver.mass_damping)
        r += m_->massDamping * mass * p.v.segment<3>(3 * n);
        J += p.cv * m_->massDamping * mass * Eigen::Matrix3d::Identity();
      }
    }
    r -= p.loadFactor * mass * m_->gravity;
    ++out.work().pointMass;
    out.add<1>({n}, r, wantJ ? &J : nullptr);
  }
}

void PointMassTerm::addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double,
                              EnergyBreakdown& e) const {
  for (int n : nodes_) {
    const double mass = m_->pointMass[n];
    e.kinetic += 0.5 * mass * v.segment<3>(3 * n).squaredNorm();
    e.gravity -= mass * m_->gravity.dot(x.segment<3>(3 * n));
  }
}

}  // namespace chute
