#pragma once
// Explicit central-difference time integration (docs/formulation.md section 7b, EX1-EX8): lumped
// mass, no Jacobian and no linear solve, one residual-only evaluation of every term per step, a
// step bounded by the elements' wave speeds (StableStep) and recomputed from the current
// positions every kStableStepEvery steps. The TimeStepper drives it as it drives the implicit
// schemes (stops, events, output, signals, checkpoints); the state it steps is (x_n, v_n, a_n),
// so a snapshot of it is a restart bit for bit. An unstable (non-finite) step ends the run; it is
// not retried.
#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "assembly/SystemAssembler.hpp"
#include "solver/Newton.hpp"
#include "solver/StableStep.hpp"
#include "solver/TimeIntegrator.hpp"

namespace chute {

struct ExplicitSettings {
  double safety = 0.9;            // fraction of the estimated stable step taken (EX5)
  double targetStep = 0.0;        // > 0: mass scaling to this stable step (EX8)
  double stiffnessDamping = 0.0;  // beta of Rayleigh damping C = beta K (EX7); 0: off
  // > 0: the target is safety x this quantile of the free nodes' own stable steps at the start
  // (EX8): the nodes below it, that fraction of them, get mass.
  double massScalingQuantile = 0.0;
  // From this many dofs the step's passes over all dofs (EX1's prediction and update, EX7's
  // shifted positions) run in halves on the assembly's two threads, the same values: a hand-over
  // to the second thread costs about what a half pass over a few thousand dofs saves (the C-9
  // slider case, 2,448 equations: 0.99x alone, 0.95x with its bound alongside;
  // docs/performance.md).
  int halvesFromDofs = 2000;
};

// Free dofs without mass: central differences cannot move them (M^-1). Names the nodes.
class MasslessNodesError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class CentralDifference final : public TimeIntegrator {
 public:
  // Mass scaling (targetStep > 0) is computed here, from the model's start positions; a free
  // node without mass is refused here (MasslessNodesError), before the run starts. maxStep: the
  // case's dt, the longest step taken.
  CentralDifference(StructuralSystem& sys, ExplicitSettings settings, double maxStep);

  IntegratorKind kind() const override { return IntegratorKind::CentralDifference; }
  StepControl initialControl() const override { return StepControl{maxStep_, 0.0, 0}; }
  // a = M^-1 (f_ext - f_int) at (s.x, s.v, s.t), lumped mass (EX2). Throws MasslessNodesError.
  void computeAcceleration(StructuralState& s) override;
  // The stable step from the current positions every kStableStepEvery steps of the run (a
  // restart keeps the count) and after a cut (EX5), cut to land on the stop; no sliver
  // absorption (it would exceed the stable step). Fails only on a non-finite state.
  StepResult step(StructuralState& s, double stop, StepCounters& counters) override;
  bool takesNominalStep() const override { return false; }
  // EB1: the balance over windows of this many steps (and at every probe row and the last step).
  static constexpr long kBalanceStride = 10;
  long balanceStride() const override { return kBalanceStride; }
  bool equationsAtStepEnds() const override { return true; }
  const StableStepRecord* stableSteps() const override { return &record_; }
  // The step chooseStep would settle on from s (0.9 x safety x the damped stable step, at most
  // the case's dt), without recording it.
  std::optional<StepEstimate> estimateStep(const StructuralState& s) override;

  // The step to take from positions x at time t, given the last step taken (the nominal step at
  // the start): safety x the stable step (with damping), with hysteresis (EX5).
  // At most maxStep (the case's dt).
  //
  // Estimated every kStableStepEvery steps (EX5): the estimate is ~10 % of the cost of a step,
  // and the step taken is at most safety x the estimate when it is made. Over k steps of
  // dt <= h / c an element's altitude h shrinks by at most k dt |v_rel| <= k (|v_rel| / c) h,
  // with c the element's wave speed (fabric and lines of the C-9: sqrt(E / rho) = 2680 ft/s):
  // relative node speeds below 0.025 c (67 ft/s there, ~7x the C-9's wind) keep the estimate
  // within 10 % of its value, which the default safety 0.9 covers.
  static constexpr long kStableStepEvery = 4;
  double chooseStep(double lastStep, const Eigen::VectorXd& x, double t);

  // Advances s by dt (EX1-EX3) and commits the terms' histories. Fails (converged = false, the
  // terms reverted, s unchanged) only on a non-finite state: the run stops as unstable.
  NewtonReport advance(StructuralState& s, double dt);

  const ExplicitSettings& settings() const { return settings_; }
  // Mass added by mass scaling, per part (line set, membrane set, or "point masses").
  const std::vector<std::pair<std::string, double>>& addedMass() const { return record_.addedMass; }
  double totalAddedMass() const { return record_.totalAddedMass; }

 private:
  // Lumped (row-sum) mass per equation at x, t (EX2): the terms' inertia r(a = 1) - r(a = 0).
  // With check, refuses massless free nodes (MasslessNodesError) when it evaluates a new mass.
  const Eigen::VectorXd& lumpedMass(const Eigen::VectorXd& x, double t, bool check = true);
  Eigen::VectorXd massOf(const std::vector<Term*>& terms, const Eigen::VectorXd& x, double t);
  int cutSets(double t) const;  // line sets cut by time t
  // The least of each node's free equations' masses (0: none), into a buffer kept from call to
  // call (the step estimate asks every kStableStepEvery steps).
  const std::vector<double>& nodalMass(const Eigen::VectorXd& massEq);
  std::vector<double> nodalMass_;
  void refuseMassless(const Eigen::VectorXd& massEq) const;

  StructuralSystem* sys_;
  ExplicitSettings settings_;
  double maxStep_;
  SystemAssembler massAssembler_;
  std::vector<Term*> fixedMassTerms_, movingMassTerms_;
  // The moving mass's own assembler, and the equations of its terms' nodes (their couplings'),
  // the only ones it clears and reads (SystemAssembler::beginOn).
  SystemAssembler movingMassAssembler_;
  std::vector<int> movingMassEqs_;
  // The terms whose mass changes at commit (Term::massChangesAtCommit), each with where its nodes'
  // masses go: a node whose three dofs carry no other varying mass, its first equation (each of
  // the three set to the base plus its mass); any other free equation with its node's index, set
  // so, or, shared with a moving mass or another committed one, summed with them first
  // (sharedMassEqs_, varyingMass_) and the base added last: the old assembly's sums, bit for bit.
  struct CommittedMass {
    struct Equation {
      int eq, node;
      bool shared;
    };
    Term* term;
    std::vector<std::pair<int, int>> setNodes;  // (first equation, node index)
    std::vector<Equation> equations;
    bool basePositive = false;  // the base mass positive on every equation of setNodes
  };
  std::vector<CommittedMass> committedMass_;
  std::vector<int> committedMassEqs_;  // every equation those terms' masses reach
  // The equations with more than one varying mass, each with whether a moving mass is one.
  std::vector<std::pair<int, bool>> sharedMassEqs_;
  Eigen::VectorXd varyingMass_;  // their varying masses' sums, by equation
  // fixedMass_ + addedEq_, formed when either changes, and whether it is positive on every
  // equation outside movingMassEqs_.
  Eigen::VectorXd massBase_;
  bool massBaseStale_ = true, basePositive_ = false;
  bool movingPositive_ = true;     // every moving-mass equation's mass positive at the cached x
  bool committedPositive_ = true;  // every equation a committed mass reaches positive
  Eigen::VectorXd fixedMass_;      // of the terms whose mass does not move, at fixedMassCuts_
  int fixedMassCuts_ = -1;         // number of cut line sets fixedMass_ was computed with
  Eigen::VectorXd x0_;             // the start positions
  Eigen::VectorXd addedEq_;        // mass scaling, per equation
  // From the stiffness bounds S and nodal masses at the start: StableStepRecord::nodalSteps
  // (returns the free nodes' own steps, sorted), and EX8's added mass for settings_.targetStep.
  std::vector<double> recordNodalSteps(const std::vector<double>& S,
                                       const std::vector<double>& mass);
  void scaleMass(const std::vector<double>& S, const std::vector<double>& mass);
  static double quantile(const std::vector<double>& sorted, double q);
  std::vector<char> freeNode_;
  StableStepRecord record_;
  // The last lumped mass and where it was evaluated (the active elements are those at x): the
  // positions at movingMassDofs_, all the moving mass depends on (a copy of every position at
  // every step was a pass over all dofs of the step's own work).
  Eigen::VectorXd cachedMass_, cachedX_;
  double cachedT_ = 0.0;
  bool cacheValid_ = false;
  std::vector<int> movingMassDofs_;  // every dof of the nodes the moving mass's terms couple
  bool wholeKey_ = false;            // ... or, where those are most, every position
  // Kept from step to step rather than allocated at each: zero and unit vectors over all dofs
  // (the step's zero acceleration, the sliding mass's M(x) 1) and the state being built.
  Eigen::VectorXd zeroDofs_, onesDofs_;
  StructuralState next_;
  Eigen::VectorXd vHalf_, vStar_, xEval_;  // advance's v_{n+1/2}, v*, x + beta v*
  // The bound of the terms whose stiffness bound is a function of the positions and time
  // (StructuralSystem::positionStiffnessBound) at a step's end positions, made alongside its
  // assembly when the next step estimates its step: the same function at the same (x, t), so the
  // same bits, off the step's serial part on two threads. chooseStep adds the bounds of the terms
  // that read their state (sliding groups, contact) at that (x, t).
  bool boundAheadWanted_ = false;
  std::vector<double> boundAhead_;
  std::vector<double> boundParts_[2];  // the two parts' (StructuralSystem::hasTwoParts)
  bool boundInParts_ = false;
  Eigen::VectorXd boundAheadX_;
  double boundAheadT_ = -1.0;
};

}  // namespace chute
