#pragma once
// Static equilibrium under the loads, applied in increments of the load factor: equal, or
// growing geometrically from an initial factor to 1 (a flat membrane under pressure stiffens
// with its deflection: w ~ p^(1/3)). A slider reaching a node is handed over within the solve (no
// step straddles it in statics); an increment that runs out of Newton iterations continues from its
// last iterate (ST1), and one that still fails is halved.
#include "solver/Newton.hpp"
#include "solver/StructuralState.hpp"

namespace chute {

class StaticLoadStepper {
 public:
  StaticLoadStepper(StructuralSystem& sys, Newton& newton) : sys_(&sys), newton_(&newton) {}
  NewtonReport solve(StructuralState& s, int nSteps, double initialFactor = 1.0);
  // A static run: from the model's positions (s, committed), solved in nSteps increments; the
  // solution is reported at t = 1, the full load factor. One that fails leaves in s the last
  // equilibrium it reached, at t = its load factor (a diverged run's last good state: the start
  // at t = 0 if no increment converged; it was the start reported at t = 1).
  NewtonReport solveFromStart(StructuralState& s, int nSteps, double initialFactor);
  // The most Newton iterations one load increment took (converged or not).
  int maxIterationsInStep() const { return maxInStep_; }
  // The increments that converged.
  long incrementsTaken() const { return taken_; }

 private:
  // ST1: further Newton runs (newton_max_iterations each) of an increment that ran out of
  // iterations, before its load is halved. 3: 100 iterations at the default 25; the ring on a
  // stiff rope needs up to 62 from starts one rope length away (tests/cases/test_static_far_start).
  static constexpr int kContinuations = 3;
  // Load increments one solve may take, halved ones included (docs/limits.md).
  static constexpr long kMaxIncrements = 100000;

  StructuralSystem* sys_;
  Newton* newton_;
  int maxInStep_ = 0;
  double reached_ = 0.0;
  long taken_ = 0;
  // s holds the equilibrium x reached at load factor lambda (on success or failure).
  void keepReached(StructuralState& s, const Eigen::VectorXd& x, double lambda);
};

}  // namespace chute
