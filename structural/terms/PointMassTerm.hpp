#pragma once
// Lumped point masses: their inertia and weight.
#include <vector>

#include "assembly/Term.hpp"
#include "model/Model.hpp"

namespace chute {

class PointMassTerm final : public Term {
 public:
  explicit PointMassTerm(const Model& m);
  const char* name() const override { return "point_masses"; }
  bool loadDependent() const override { return m_->hasGravity(); }  // gravity only
  // Its node's own 3x3 block: a point mass on a node no element uses has no other entry.
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  void addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t,
                 EnergyBreakdown& e) const override;

 private:
  const Model* m_;
  std::vector<int> nodes_;  // the nodes with a point mass (not every node of a canopy mesh)
};

}  // namespace chute
