#pragma once
// What the implicit schemes share (generalized-alpha / Bossak, energy-momentum): Newton on the
// assembled residual with the consistent tangent, the consistent initial acceleration, and the
// step control (StepController): steps of the case's dt, landed on stops, retried to end where an
// event happens, halved on a failed solve and grown back. Each scheme gives its one try of a step
// of a given length (tryStep).
#include "solver/Newton.hpp"
#include "solver/StepController.hpp"
#include "solver/TimeIntegrator.hpp"

namespace chute {

class ImplicitIntegrator : public TimeIntegrator {
 public:
  ImplicitIntegrator(StructuralSystem& sys, NewtonSettings newton, double dtNominal, double dtMin);

  StepControl initialControl() const override { return control_.initial(); }
  // Consistent acceleration M a = f_ext - f_int at s (massless dofs get a = 0).
  void computeAcceleration(StructuralState& s) override;
  StepResult step(StructuralState& s, double stop, StepCounters& counters) override;
  LinearSolver* linearSolver() override { return &newton_.linearSolver(); }

  Newton& newton() { return newton_; }

  // One try of a step of length dt from s, without step control: on success s is the step's end
  // and the terms' histories are committed; on failure s is left as it was and the terms' trial
  // changes are reverted.
  virtual NewtonReport tryStep(StructuralState& s, double dt) = 0;

 protected:
  StructuralSystem* sys_;
  Newton newton_;
  StepController control_;
};

}  // namespace chute
