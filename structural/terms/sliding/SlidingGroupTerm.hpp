#pragma once
// One sliding group: its active three-node elements (docs/formulation.md F6-F11, with friction
// docs/friction.md) and its inactive elements as cables; runs the active-element search (F12) in
// updateState() and the node hand-overs (RG2-RG3) at converged steps.
#include "assembly/Term.hpp"
#include "kernels/CableBatch.hpp"
#include "kernels/Regularisations.hpp"
#include "model/Model.hpp"
#include "terms/sliding/SlidingGroupState.hpp"

namespace chute {

class SlidingGroupTerm final : public Term, public EventSource {
 public:
  SlidingGroupTerm(const Model& m, int group, SliderSearch search);
  const char* name() const override { return "sliding_group"; }
  bool loadDependent() const override { return m_->hasGravity(); }  // gravity only
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  int updateState(const Eigen::VectorXd& x) override { return state_.search(x, search_); }
  long searchesPerUpdate() const override { return static_cast<long>(state_.def().sliders.size()); }
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  // CB1: the drag of the inactive elements, when the group's line set has exactly one drag load,
  // to be added in the group's pass on the explicit step's evaluations (fusedLineDrag), their
  // elastic forces four at a time; whether it took it (never without AVX2).
  bool takeLineDrag();
  void addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t,
                 EnergyBreakdown& e) const override;
  // Configuration-dependent mass and gravity make the consistent Jacobian non-symmetric.
  bool symmetricJacobian() const override;
  // Node crossings are located in time: an update that would carry a slider through an end node
  // cuts the step to end where they meet (passageFraction); at the end of that step the slider is
  // placed on the node and handed over to the neighbouring element (onConverged).
  double passageFraction(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) override {
    return condensed_ ? 1.0 : state_.passageFraction(x, dx);
  }
  bool onConverged(Eigen::VectorXd& x) override {
    return !condensed_ &&
           state_.arriveAtNodes(*m_, x, kernels::kArrivalFraction, kernels::kSeparationFraction);
  }
  bool drivesKinks() const override { return state_.hasDriven(); }
  int crossDriven(const Eigen::VectorXd& from, Eigen::VectorXd& to) override {
    return state_.crossDriven(*m_, from, to, kernels::kSeparationFraction);
  }
  bool crossNow(Eigen::VectorXd& x) override {
    return !condensed_ && state_.arriveAtNodes(*m_, x, kernels::kArrivalFraction,
                                               kernels::kSeparationFraction, true);
  }
  double displacementFloor() const override { return floor_; }
  // EX3, F12b: explicit steps hand sliders over where the motion passed a node (notePassages) or
  // left a slider within kExplicitArrivalFraction of one (the node placed a hair ahead of it, as
  // at an implicit arrival, RG2).
  bool watchesExplicitMotion() const override { return !condensed_; }
  void noteExplicitMotion(const Eigen::VectorXd& x, const Eigen::VectorXd& motion) override {
    state_.notePassages(x, motion);
  }
  void afterExplicitMotion(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& /*motion*/,
                           Eigen::VectorXd& xEnd) override {
    state_.arriveAtNodes(*m_, xEnd, kernels::kExplicitArrivalFraction, kernels::kSeparationFraction,
                         true);
  }
  EventSource* events() override { return this; }
  // EM12 under energy-momentum steps: the chain condensed where it can be.
  void prepareFor(const IntegrationTraits& traits) override {
    condenseChain(traits.discreteGradients);
  }
  // F10: the lumped mass follows the slider's split.
  bool massMovesWithPositions() const override { return true; }
  void addStiffnessBound(const Eigen::VectorXd& x, double t, const std::vector<char>& free,
                         std::vector<double>& S) const override;
  bool stiffnessBoundOfPositions() const override { return false; }  // reads the sliders' places
  // Per element 0.9 of an explicit membrane triangle, and 8 more for each element a slider
  // splits (Term::assemblyCost).
  double assemblyCost() const override {
    return 0.9 * state_.def().numElements() +
           8.0 * static_cast<double>(state_.def().sliders.size());
  }
  // Not moved to the second thread, though it reads only the model and its own state: the C-9's
  // parts balance without it, and a scene made of sliding groups alone would be split group by
  // group for no measured gain.
  // Sliders with friction: the converged split at x is found (docs/friction.md) and committed.
  bool hasHistory() const override { return true; }
  void commit(const CommitPoint& c) override;
  // Its own state from c and the model only (the lines through one grommet commit side by side).
  bool commitsApart() const override { return true; }
  void revert() override { state_.revert(); }
  void save(History& h) const override;
  void load(HistoryReader& h) override;
  // EM12: a chain of more than one element without mass or friction whose inner nodes nothing
  // else touches (no other element, point mass, drag or support) is, for the energy-momentum
  // integrator, one uniform-strain polyline through its sliders (a massless frictionless line
  // has one tension); its inner nodes are placed along it at their material coordinates, and
  // sliders change elements without hand-over events.
  bool condensable() const { return condensable_; }
  void condenseChain(bool on) { condensed_ = on && condensable_; }
  bool condensed() const { return condensed_; }
  const SlidingGroupState& state() const { return state_; }
  SlidingGroupState& state() { return state_; }

  // Forces and strains of the two parts of active element `element` at x (equal for a
  // frictionless slider), with the committed split for a slider with friction (output).
  struct ActiveParts {
    double N1, strain1, N2, strain2;
  };
  ActiveParts activeParts(int element, const Eigen::VectorXd& x) const;

 private:
  // The explicit step's inactive elements four at a time (CB1), with the taken drag when
  // withDrag, in chain order (the active ones are assembled after them).
  void assembleInactiveLanes(const EvalPoint& p, SystemAssembler& out, bool withDrag);
  const DragLoadDef* drag_ = nullptr;  // the taken drag load (takeLineDrag)
  bool lanes_ = false;                 // AVX2: the inactive elements in lanes
  // The lanes of the inactive elements, made again only when an element's activity or reference
  // length changed (a hand-over): the elements in them and their lengths, and whether the drag
  // in them is the taken one.
  std::vector<kernels::CableLanes> inactiveLanes_;
  std::vector<int> laneElements_;
  std::vector<double> laneLengths_;
  int laneDrag_ = -1;
  // EvalPoint::inertiaOnly: M(x) a alone (EX2's lumped mass), reading the state and writing only
  // to out.
  void assembleInertia(const EvalPoint& p, SystemAssembler& out) const;
  const Model* m_;
  SlidingGroupState state_;
  SliderSearch search_;
  // Of the last commit: the time the step's forces were evaluated at (a lock's time is compared
  // with it) and the positions (friction: FR15).
  double committedT_ = 0.0;
  Eigen::VectorXd committedX_;
  double floor_ = 0.0;  // round-off floor of the last assembly (FR16)
  bool condensable_ = false, condensed_ = false;
  // EM12: the path (end, sliders in order along the chain at x, end) and its reference length.
  std::vector<int> chainPath(const Eigen::VectorXd& x) const;
  double chainLength() const;
  void assembleCondensed(const EvalPoint& p, SystemAssembler& out);
  void placeSlidersOnChain(const Eigen::VectorXd& x);  // active elements from the path at x
};

}  // namespace chute
