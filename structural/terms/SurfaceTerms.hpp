#pragma once
// Terms of the canopy side (docs/formulation.md sections 5-6):
//  - MembraneTerm: internal force, inertia and gravity of every membrane element, with the
//    tension-field model where its set asks for it; keeps each element's last wrinkling state;
//  - PressureTerm: follower pressure on membrane sets, with its non-symmetric load stiffness;
//  - DragTerm: drag on line sets (cables, sliding groups) relative to a wind, with position and
//    velocity tangents.
#include <vector>

#include "assembly/Term.hpp"
#include "model/Model.hpp"
#include "model/SlidingGroupState.hpp"

namespace chute {

class MembraneTerm final : public Term {
 public:
  explicit MembraneTerm(const Model& m);
  const char* name() const override { return "membranes"; }
  bool loadDependent() const override { return m_->hasGravity(); }  // gravity only
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  void addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t,
                 EnergyBreakdown& e) const override;
  // Wrinkling state and principal stresses / strains of each element at the last assembly.
  struct ElementState {
    kernels::WrinkleState state = kernels::WrinkleState::Taut;
    Eigen::Vector2d principalStress = Eigen::Vector2d::Zero();
    Eigen::Vector2d principalStrain = Eigen::Vector2d::Zero();
  };
  // A function of the current strain, recomputed at every assembly (not history); kept so that
  // output after a coupling checkpoint is restored shows the restored state.
  const std::vector<ElementState>& elementStates() const { return states_; }
  bool hasHistory() const override { return true; }
  void save(History& h) const override;
  void load(HistoryReader& h) override;
  // Elements around a node, for stress probes.
  std::vector<int> elementsAt(int node) const;

 private:
  template <int N>
  void assembleElement(int e, const kernels::MembraneReference<N>& ref, const EvalPoint& p,
                       SystemAssembler& out);
  const Model* m_;
  std::vector<int> slot_;  // per element: index into refs3_ or refs4_
  std::vector<kernels::MembraneReference<3>> refs3_;
  std::vector<kernels::MembraneReference<4>> refs4_;
  std::vector<ElementState> states_;
};

class PressureTerm final : public Term {
 public:
  explicit PressureTerm(const Model& m) : m_(&m) {}
  const char* name() const override { return "pressure"; }
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  void addEnergy(const Eigen::VectorXd&, const Eigen::VectorXd&, double,
                 EnergyBreakdown&) const override {}
  bool symmetricJacobian() const override { return false; }

 private:
  const Model* m_;
};

class DragTerm final : public Term {
 public:
  // groups: the sliding-group states in model order (drag on active elements acts on both parts).
  DragTerm(const Model& m, std::vector<const SlidingGroupState*> groups)
      : m_(&m), groups_(std::move(groups)) {}
  const char* name() const override { return "drag"; }
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  void addEnergy(const Eigen::VectorXd&, const Eigen::VectorXd&, double,
                 EnergyBreakdown&) const override {}
  bool symmetricJacobian() const override { return false; }

 private:
  void addSegment(int a, int b, const kernels::Vec3& wind, double c, const EvalPoint& p,
                  SystemAssembler& out) const;
  const Model* m_;
  std::vector<const SlidingGroupState*> groups_;
};

}  // namespace chute
