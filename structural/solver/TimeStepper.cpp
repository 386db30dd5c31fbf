#include "solver/TimeStepper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace chute {

TimeStepper::TimeStepper(StructuralSystem& sys, TimeIntegrator& integrator, double dtNominal)
    : sys_(&sys), integrator_(&integrator), dtNominal_(dtNominal) {}

StructuralState TimeStepper::start() {
  StructuralState s = sys_->initialState();
  s.control = integrator_->initialControl();
  integrator_->computeAcceleration(s);
  accelerationAfterCut(s);
  sys_->commit(CommitPoint{s.x, s.t, 0.0, s.t});
  return s;
}

TimeStepper::Saved TimeStepper::save(const StructuralState& s) const {
  Saved out;
  out.snapshot = sys_->saveState(s);
  out.counters = counters_;
  // Fell back to LU (from CHOLMOD or the symmetric part's LDL^T): a restart stays on LU.
  if (const LinearSolver* ls = integrator_->linearSolver())
    out.linearSolverLU =
        ls->kind() == LinearSolver::Kind::Umfpack && ls->preferred() != LinearSolver::Kind::Umfpack;
  return out;
}

StructuralState TimeStepper::resume(const Saved& saved) {
  StructuralState s = sys_->loadState(saved.snapshot);
  // The bound a case's own coordinates have (docs/limits.md): a finite but absurd value (a
  // velocity of 1e308) overflows in the first step, after the output has been touched.
  constexpr double kMaxState = 1e100;
  if (s.x.cwiseAbs().maxCoeff() > kMaxState || s.v.cwiseAbs().maxCoeff() > kMaxState ||
      s.a.cwiseAbs().maxCoeff() > kMaxState)
    throw HistoryError("state beyond +-1e100");
  counters_ = saved.counters;
  if (saved.linearSolverLU)
    if (LinearSolver* ls = integrator_->linearSolver()) ls->useLU();
  return s;
}

void TimeStepper::accelerationAfterCut(StructuralState& s) {
  if (!sys_->model().hasCutAt(s.t)) return;
  StructuralState after = s;
  after.t = std::nextafter(s.t, std::numeric_limits<double>::infinity());
  for (int d = 0; d < after.a.size(); ++d)
    if (sys_->dofs().eqOfDof(d) >= 0) after.a[d] = 0.0;
  integrator_->computeAcceleration(after);
  s.a = after.a;
}

TimeStepper::Result TimeStepper::advanceTo(
    StructuralState& s, double tStop, const std::function<double(double)>& nextStop,
    const std::function<bool(const StructuralState&, int)>& afterStep) {
  Result result;
  const Model& m = sys_->model();
  while (!reached(s.t, tStop)) {
    // The next stop: the target, the caller's next stop, the next cable cut.
    const double stop = std::min({tStop, nextStop(s.t), m.nextCutAfter(s.t)});
    const StepResult step = integrator_->step(s, stop, counters_);
    if (!step.accepted) {
      result.outcome = Outcome::BelowMinimum;
      result.reason = step.failure;
      return result;
    }
    if (step.reachesStop) s.t = stop;  // no round-off drift of output times
    ++counters_.steps;
    accelerationAfterCut(s);
    counters_.maxNewtonInStep = std::max(counters_.maxNewtonInStep, step.newtonIterations);
    if (!afterStep(s, step.newtonIterations)) {
      result.outcome = Outcome::Stopped;
      return result;
    }
  }
  return result;
}

}  // namespace chute
