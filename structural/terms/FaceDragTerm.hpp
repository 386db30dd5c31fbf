#pragma once
// Face drag on membrane sets (docs/formulation.md FD1, kernels/FaceDrag): the air's resistance
// to the fabric moving normal to itself, with position and velocity tangents. Dissipative, so no
// energy; nothing in statics (it needs motion), like the line drag.
#include <vector>

#include "assembly/Term.hpp"
#include "model/Model.hpp"
#include "terms/FaceLoadFusion.hpp"

namespace chute {

class FaceDragTerm final : public Term {
 public:
  explicit FaceDragTerm(const Model& m) : m_(&m), faces_(m, m.faceDrags) {}
  const char* name() const override { return "face_drag"; }
  bool doesExternalWork() const override { return true; }
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  void addEnergy(const Eigen::VectorXd&, const Eigen::VectorXd&, double,
                 EnergyBreakdown&) const override {}
  bool symmetricJacobian() const override { return false; }
  double assemblyCost() const override;
  bool assemblesApart() const override { return true; }
  // The faces whose drag the membrane term adds on the explicit step (P2): left out then.
  void leaveFaces(const TakenFaces& taken) { faces_.leave(taken); }

 private:
  const Model* m_;
  FacesOfLoads faces_;  // per load, all and those left on the explicit step
};

}  // namespace chute
