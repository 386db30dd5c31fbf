#pragma once
// The energy balance of a dynamic run (docs/formulation.md, eq. EB1): the energy of the
// structure (kinetic + strain + gravity, at each step's equilibrium point) against the work done
// on it by the loads that have no energy (pressure, drag, a flow's loads: Term::doesExternalWork)
// and by the supports that move it (prescribed motion):
//
//   B(t_n) = E(t_n) - E(t_0) - W(t_0, t_n),  W += (f_loads + R) . (x_{n+1} - x_n) per step,
//
// the forces at the step's equilibrium point; or, for a scheme whose equations hold at the
// steps' ends (explicit central differences, whose balance is taken over windows of steps), the
// mean of the forces at the window's two ends (trapezoidal: second order in the window, where the
// end's force alone is first order and booked a folded canopy's quickly changing inside pressure
// 14 % short over its first 120 steps). B is what friction, damping, the cut of a set and
// the integrator's numerical dissipation took out (B <= 0) or what the integration made up
// (B > 0). The scale S is the largest kinetic + strain energy so far, plus the gross work done,
// plus the work gravity does on all the mass over the model's size (m |g| L: the floor of a
// scene at rest). A run whose B stays above tolerance x S for kPersistentSteps steps in a row,
// exceeds S once, or ends above tolerance x S, has made energy up: it is unstable, whatever its
// Newton did. (A start far from equilibrium may gain a few per cent of its small energy for a few
// steps while the numerical damping takes its stiff modes out, measured 6 steps on
// cases/airbag.toml; a blow-up gains on every step.) The monitor knows no integrator: any
// integrator that gives an equilibrium point per step (solver/EquilibriumPoint.hpp) plugs in.
//
// EB2: a closed run (no load without an energy, no moving support) has nothing that may add
// energy, and no transient from loads or supports to allow for: there the bound is
// kClosedFraction x tolerance x S (0.005 S at the default), on kPersistentSteps steps in a row or
// at the end. A cable pendulum at 120 steps per period, rho_inf = 1, goes slack, gains 7 % of its
// energy for 20 steps (B up to 0.011 S) and then snatches at 18 times the exact force; its energy
// falls again afterwards, so only a bound on the way catches it. The good runs and stressed
// shipped cases of bench/results/energy_monitor.md stay below 3e-4 S. The growth is counted
// from the largest balance (>= 0) of the first 2 kPersistentSteps steps: a start off
// equilibrium may gain a few per cent while its stiff modes are damped out (the membrane of
// tests/cases/test_pay_only.cpp released from a prestrain: 0.046 S in its first 10 steps), which
// is EB1's to judge.
#include <limits>
#include <string>

#include "solver/EquilibriumPoint.hpp"
#include "solver/StructuralState.hpp"
#include "solver/StructuralSystem.hpp"

namespace chute {

class EnergyMonitor {
 public:
  static constexpr int kPersistentSteps = 10;
  static constexpr double kClosedFraction = 0.1;  // EB2

  // tolerance: the largest B allowed, relative to the scale (solver.energy_tolerance; <= 0: the
  // balance is kept but never stops a run).
  // trapezoidal: the work of a window from the forces at both its ends (above).
  EnergyMonitor(StructuralSystem& sys, double tolerance, bool trapezoidal = false);

  // The state the balance starts from (a start, or the state a restart continues from).
  void start(const StructuralState& s, const EquilibriumPoint& eq);
  // Whether a window's work can take the loads its last step applied (an explicit run with
  // loads and no moving support): the run then asks the step ending a window to keep them
  // (StructuralSystem::captureStepLoads) rather than evaluating them again here, where they cost
  // a tenth of the generated C-9's run (a sixth on two threads).
  bool takesStepLoads() const { return trapezoidal_ && loads_ && !supportsMove_; }
  // After an accepted step from `before` to `s` with equilibrium point eq; returns false when
  // the balance is violated (reason()).
  bool afterStep(const StructuralState& before, const StructuralState& s,
                 const EquilibriumPoint& eq, double dt);

  // At the end of a run: false when B is above tolerance x S there (the answer holds energy the
  // integration made up, however briefly it has been above). A run of fewer than
  // 2 kPersistentSteps steps is not judged at its end: it may end inside a start's transient
  // (cases/airbag.toml cut to 5 steps ends at B = 0.15 S, and 2 steps later B < 0).
  bool finish();

  double energy() const { return energy_; }                      // E(t_n)
  double work() const { return work_; }                          // W(t_0, t_n)
  double balance() const { return energy_ - energy0_ - work_; }  // B(t_n)
  double scale() const { return fullScale(); }                   // S
  double largestBalance() const { return largest_; }             // max B so far
  // Whether the last afterStep found B within its bounds (EB1, EB2): a state to trust, where a
  // run stopped as unstable may be cut back to.
  bool withinBounds() const { return stepsOver_ == 0 && stepsGrowing_ == 0; }
  const std::string& reason() const { return reason_; }

 private:
  StructuralSystem* sys_;
  double tolerance_;
  double energy0_ = 0.0, energy_ = 0.0, work_ = 0.0, grossWork_ = 0.0, scale_ = 0.0;
  double largest_ = -std::numeric_limits<double>::infinity();
  std::string reason_;
  double fullScale() const { return scale_ + grossWork_ + gravityFloor_; }
  bool supportsMove_ = false;  // any constrained dof with prescribed motion
  bool loads_ = false;         // any term doing external work
  bool trapezoidal_ = false;
  Eigen::VectorXd lastForce_;  // trapezoidal: f_loads + R at the last balance (over all dofs)
  Eigen::VectorXd forceAt(const EvalPoint& p) const;  // f_loads + R over all dofs
  bool closed() const { return !supportsMove_ && !loads_; }
  double startBalance_ = 0.0;  // EB2: the largest B (>= 0) of the first 2 kPersistentSteps steps
  bool closedViolated(double b) const {
    return closed() && steps_ > 2 * kPersistentSteps &&
           b - startBalance_ > kClosedFraction * tolerance_ * fullScale();
  }
  double gravityFloor_ = 0.0;  // m |g| L
  int stepsOver_ = 0;          // consecutive steps with B > tolerance x S
  int stepsGrowing_ = 0;       // EB2: consecutive steps of a closed run above its bound
  long steps_ = 0;             // steps since start()
};

}  // namespace chute
