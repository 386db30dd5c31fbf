#pragma once
// Internal force, inertia and gravity of every two-node cable / truss element (docs/formulation.md
// F1-F5), with the slack / taut switch located in time (RG4). The explicit step's forces go
// through the cables four at a time with AVX2 (CB1), with the drag of their line sets when taken.
#include <vector>

#include "assembly/Term.hpp"
#include "kernels/CableBatch.hpp"
#include "model/Model.hpp"
#include "terms/LineDragFusion.hpp"
#include "terms/NodeMassEnergy.hpp"

namespace chute {

class CableTerm final : public Term, public EventSource {
 public:
  explicit CableTerm(const Model& m);
  const char* name() const override { return "cables"; }
  bool loadDependent() const override { return m_->hasGravity(); }  // gravity only
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  void addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t,
                 EnergyBreakdown& e) const override;
  // Slack / taut switches are located in time like a slider at a node: a step whose motion
  // takes a tension-only cable across zero strain is cut to end there, so no step straddles
  // the kink of its energy (the trapezoidal rule conserves the energy of each smooth piece).
  // Measured along the step's whole motion: Newton's later updates may take a cable across.
  double stepEventFraction(const Eigen::VectorXd& start, const Eigen::VectorXd& motion) override;
  EventSource* events() override { return this; }
  void addStiffnessBound(const Eigen::VectorXd& x, double t, const std::vector<char>& free,
                         std::vector<double>& S) const override;
  double assemblyCost() const override;
  bool assemblesApart() const override { return true; }
  // CB1: the drag of every cable whose line set has exactly one drag load, to be added in the
  // cables' pass on the explicit step's evaluations (fusedLineDrag); which cables it took, for
  // the line-drag term to leave out there (nullptr: none, as without AVX2).
  TakenCables takeLineDrag();

 private:
  // The explicit step's forces (explicitForcesOnly), four cables at a time; with the taken
  // drag where withDrag.
  void assembleLanes(const EvalPoint& p, SystemAssembler& out, bool withDrag);
  const Model* m_;
  std::vector<char> hanging_;  // per node: touched by no membrane element (EX6l)
  // CB1's lanes (with AVX2 only) and per lane slot the cable in it (-1: none), in model order.
  std::vector<kernels::CableLanes> lanes_;
  std::vector<int> laneCable_;
  std::vector<char> takenSlot_;  // per lane slot: its cable's drag taken
  bool anyCut_ = false;          // a cable's set is cut at some time
  bool dragTaken_ = false;       // takeLineDrag took at least one cable's drag
  // With a lumped mass, each node's mass from the cables whose set is not gone (addEnergy), for
  // the sets gone when it was made.
  const NodeMasses& nodeMassAt(double t) const;
  mutable NodeMasses nodeMass_;
  mutable std::vector<char> nodeMassGone_;
  mutable bool nodeMassMade_ = false;
};

}  // namespace chute
