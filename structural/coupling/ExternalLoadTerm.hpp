#pragma once
// Loads a flow solver supplies on the wet surface for the current time window (held constant
// over the window, the zeroth-order waveform of preCICE):
//  - pressure per face: follower load p n dA through the same kernel as case-file pressure
//    (kernels::pressureLoad), with its non-symmetric load stiffness;
//  - pressure per vertex: follower load interpolated over each face (kernels::pressureLoadNodal),
//    consistent tangent with the values held fixed;
//  - force per vertex: dead load within the window (no stiffness).
// The three add up. The term exists only in coupled runs.
#include <Eigen/Core>

#include "assembly/Term.hpp"
#include "coupling/WetSurface.hpp"

namespace chute::coupling {

class ExternalLoadTerm final : public Term {
 public:
  explicit ExternalLoadTerm(const WetSurface& surface);
  const char* name() const override { return "external_load"; }
  bool doesExternalWork() const override { return true; }
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  void addEnergy(const Eigen::VectorXd&, const Eigen::VectorXd&, double,
                 EnergyBreakdown&) const override {}
  bool symmetricJacobian() const override { return false; }
  // Per face, 0.42 of an explicit membrane triangle (as a case's pressure).
  double assemblyCost() const override { return 0.42 * surface_->numFaces(); }
  bool assemblesApart() const override { return true; }

  // Sizes: one per face; one per vertex; three per vertex. Throw std::invalid_argument otherwise.
  void setFacePressures(const Eigen::VectorXd& p);
  void setVertexPressures(const Eigen::VectorXd& p);
  void setVertexForces(const Eigen::VectorXd& f);
  const Eigen::VectorXd& facePressures() const { return facePressure_; }
  const Eigen::VectorXd& vertexPressures() const { return vertexPressure_; }
  const Eigen::VectorXd& vertexForces() const { return vertexForce_; }

 private:
  const WetSurface* surface_;
  Eigen::VectorXd facePressure_, vertexPressure_, vertexForce_;
  bool anyVertexPressure_ = false, anyVertexForce_ = false;
};

}  // namespace chute::coupling
