#pragma once
// Static equilibrium under the loads, applied in increments of the load factor: equal, or
// growing geometrically from an initial factor to 1 (a flat membrane under pressure stiffens
// with its deflection: w ~ p^(1/3)). A slider reaching a node is handed over within the solve (no
// step straddles it in statics); a failed increment is halved.
#include "solver/Newton.hpp"
#include "solver/StructuralState.hpp"

namespace chute {

class StaticLoadStepper {
 public:
  StaticLoadStepper(StructuralSystem& sys, Newton& newton) : sys_(&sys), newton_(&newton) {}
  NewtonReport solve(StructuralState& s, int nSteps, double initialFactor = 1.0);
  // A static run: from the model's positions (s, committed), solved in nSteps increments; the
  // solution is reported at t = 1, the full load factor.
  NewtonReport solveFromStart(StructuralState& s, int nSteps, double initialFactor);
  // The most Newton iterations one load increment took (converged or not).
  int maxIterationsInStep() const { return maxInStep_; }

 private:
  StructuralSystem* sys_;
  Newton* newton_;
  int maxInStep_ = 0;
};

}  // namespace chute
