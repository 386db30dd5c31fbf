#include "terms/CableTerm.hpp"

#include <algorithm>

#include "kernels/CableKernel.hpp"
#include "kernels/StiffnessBound.hpp"
#include "terms/LineElementAssembly.hpp"

namespace chute {

using line_assembly::assembleCable;
using line_assembly::cableEnergy;
using line_assembly::pos;

// ---- CableTerm -------------------------------------------------------------------------------
void CableTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  for (const auto& c : m_->cables) cliques.push_back({c.a, c.b});
}

void CableTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  if (line_assembly::explicitForcesOnly(*m_, p, out)) {
    for (const auto& c : m_->cables)
      if (!m_->lineSets[c.set].cutBy(p.t))
        line_assembly::addCableExplicitForce(*m_, c.a, c.b, c.L, m_->materials[c.material], p, out);
    return;
  }
  for (const auto& c : m_->cables)
    if (!m_->lineSets[c.set].cutBy(p.t)) assembleCable(*m_, c.a, c.b, c.L, c.material, p, out);
}

void CableTerm::addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t,
                          EnergyBreakdown& e) const {
  for (const auto& c : m_->cables)
    if (!m_->lineSets[c.set].goneAt(t)) cableEnergy(*m_, c.a, c.b, c.L, c.material, x, v, e);
}

void CableTerm::addStiffnessBound(const Eigen::VectorXd& /*x*/, double t,
                                  const std::vector<char>& free, std::vector<double>& S) const {
  for (const auto& c : m_->cables) {
    if (m_->lineSets[c.set].cutBy(t)) continue;
    kernels::addLineBound(c.a, c.b, kernels::lineStiffness(m_->materials[c.material], c.L), free,
                          S);  // EX6
  }
}

// Per element, 0.7 of an explicit membrane triangle (Term::assemblyCost).
double CableTerm::assemblyCost() const {
  return 0.7 * static_cast<double>(m_->cables.size());
}

double CableTerm::stepEventFraction(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) {
  double fraction = 1.0;
  for (const auto& c : m_->cables) {
    const auto& mat = m_->materials[c.material];
    if (!mat.tensionOnly || mat.compressionStiffnessRatio == 1.0) continue;  // no kink
    fraction = std::min(fraction, kernels::slackTautCrossing(pos(x, c.b) - pos(x, c.a),
                                                             pos(dx, c.b) - pos(dx, c.a), c.L));
  }
  return fraction;
}

}  // namespace chute
