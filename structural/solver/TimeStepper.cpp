#include "solver/TimeStepper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "solver/CentralDifference.hpp"

namespace chute {

TimeStepper::TimeStepper(StructuralSystem& sys, GeneralizedAlpha& integrator, double dtNominal,
                         double dtMin)
    : sys_(&sys), integrator_(&integrator), control_(dtNominal, dtMin) {}

StructuralState TimeStepper::start() {
  StructuralState s = integrator_->initialState();
  s.control = control_.initial();
  if (explicit_)
    explicit_->computeAcceleration(s);
  else
    integrator_->computeInitialAcceleration(s);
  accelerationAfterCut(s);
  sys_->commit(CommitPoint{s.x, s.t, 0.0, s.t});
  return s;
}

TimeStepper::Saved TimeStepper::save(const StructuralState& s) const {
  Saved out;
  out.snapshot = sys_->saveState(s);
  out.counters = counters_;
  // Fell back to LU (from CHOLMOD or the symmetric part's LDL^T): a restart stays on LU.
  const LinearSolver& ls = integrator_->linearSolver();
  out.linearSolverLU =
      ls.kind() == LinearSolver::Kind::Umfpack && ls.preferred() != LinearSolver::Kind::Umfpack;
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
  if (saved.linearSolverLU) integrator_->linearSolver().useLU();
  return s;
}

void TimeStepper::accelerationAfterCut(StructuralState& s) {
  if (!sys_->model().hasCutAt(s.t)) return;
  StructuralState after = s;
  after.t = std::nextafter(s.t, std::numeric_limits<double>::infinity());
  for (int d = 0; d < after.a.size(); ++d)
    if (sys_->dofs().eqOfDof(d) >= 0) after.a[d] = 0.0;
  if (explicit_)
    explicit_->computeAcceleration(after);
  else
    integrator_->computeInitialAcceleration(after);
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
    if (explicit_) {
      // The stable step from the current positions, every kStableStepEvery steps of the run
      // (a restart keeps the count) and after a cut (EX5); no sliver absorption (it would
      // exceed it).
      if (counters_.steps % CentralDifference::kStableStepEvery == 0 || m.hasCutAt(s.t))
        s.control.dt = explicit_->chooseStep(s.control.dt, control_.nominal(), s.x, s.t);
      const double h = std::min(s.control.dt, stop - s.t);
      const bool reachesStop = h == stop - s.t;
      const NewtonReport rep = explicit_->step(s, h);
      if (!rep.converged) {
        std::ostringstream why;
        why.precision(9);
        why << "unstable explicit step at t = " << s.t << " (" << rep.failure << ")";
        result.outcome = Outcome::BelowMinimum;
        result.reason = why.str();
        return result;
      }
      if (reachesStop) s.t = stop;
      ++counters_.steps;
      accelerationAfterCut(s);
      if (!afterStep(s, 0)) {
        result.outcome = Outcome::Stopped;
        return result;
      }
      continue;
    }
    const double h = control_.propose(s.control, s.t, stop);
    const bool reachesStop = control_.reachesStop();
    // The state the step starts from: a failed try goes back to exactly this.
    const SystemSnapshot before = sys_->saveState(s);
    const NewtonReport rep = integrator_->step(s, h);
    counters_.newtonIterations += rep.iterations;
    if (!rep.converged) s = sys_->loadState(before);
    const auto verdict = control_.judge(s.control, rep, h);
    if (verdict == StepController::Verdict::EventRetry) {
      ++counters_.eventRetries;  // retried to end where the event happens
      continue;
    }
    if (verdict != StepController::Verdict::Accepted) {
      ++counters_.rejectedSteps;
      if (verdict == StepController::Verdict::BelowMinimum) {
        std::ostringstream why;
        why.precision(9);
        why << "step rejected at t = " << s.t;
        why.precision(3);
        why << " with dt = " << h << " (" << rep.failure
            << "); dt would fall below dt_min = " << control_.minimum();
        result.outcome = Outcome::BelowMinimum;
        result.reason = why.str();
        return result;
      }
      continue;
    }
    if (reachesStop) s.t = stop;  // no round-off drift of output times
    ++counters_.steps;
    accelerationAfterCut(s);
    counters_.maxNewtonInStep = std::max(counters_.maxNewtonInStep, rep.iterations);
    if (!afterStep(s, rep.iterations)) {
      result.outcome = Outcome::Stopped;
      return result;
    }
  }
  return result;
}

}  // namespace chute
