#pragma once
// Internal force, inertia and gravity of every two-node cable / truss element (docs/formulation.md
// F1-F5), with the slack / taut switch located in time (RG4).
#include "assembly/Term.hpp"
#include "model/Model.hpp"

namespace chute {

class CableTerm final : public Term, public EventSource {
 public:
  explicit CableTerm(const Model& m) : m_(&m) {}
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

 private:
  const Model* m_;
};

}  // namespace chute
