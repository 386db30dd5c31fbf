#include "solver/ImplicitIntegrator.hpp"

#include <Eigen/UmfPackSupport>
#include <sstream>

namespace chute {

ImplicitIntegrator::ImplicitIntegrator(StructuralSystem& sys, NewtonSettings newton,
                                       double dtNominal, double dtMin)
    : sys_(&sys), newton_(sys, newton), control_(dtNominal, dtMin) {}

void ImplicitIntegrator::computeAcceleration(StructuralState& s) {
  if (sys_->numEquations() == 0) return;
  sys_->updateState(s.x);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(s.x.size());
  const EvalPoint pt = EvalPoint::massMatrix(s.x, s.v, zero, s.t);
  sys_->assemble(pt, true);  // residual f_int - f_ext, matrix M
  SparseMatrix M = sys_->matrix();
  Eigen::VectorXd rhs = -sys_->residual();
  // Massless dofs have no inertia row: pin their initial acceleration to zero.
  for (int e = 0; e < M.cols(); ++e) {
    bool empty = true;
    for (SparseMatrix::InnerIterator it(M, e); it; ++it)
      if (it.value() != 0.0) empty = false;
    if (empty) {
      M.coeffRef(e, e) = 1.0;
      rhs[e] = 0.0;
    }
  }
  Eigen::UmfPackLU<SparseMatrix> lu;
  lu.compute(M);
  Eigen::VectorXd a0 = lu.solve(rhs);
  if (lu.info() == Eigen::Success && a0.allFinite()) sys_->addToDofs(a0, s.a);
}

StepResult ImplicitIntegrator::step(StructuralState& s, double stop, StepCounters& n) {
  StepResult result;
  for (;;) {
    const double h = control_.propose(s.control, s.t, stop);
    const bool reachesStop = control_.reachesStop();
    // The state the step starts from: a failed try goes back to exactly this.
    const SystemSnapshot before = sys_->saveState(s);
    const NewtonReport rep = tryStep(s, h);
    n.newtonIterations += rep.iterations;
    if (!rep.converged) s = sys_->loadState(before);
    const auto verdict = control_.judge(s.control, rep, h);
    if (verdict == StepController::Verdict::EventRetry) {
      ++n.eventRetries;  // retried to end where the event happens
      continue;
    }
    if (verdict == StepController::Verdict::Accepted) {
      result.reachesStop = reachesStop;
      result.newtonIterations = rep.iterations;
      return result;
    }
    ++n.rejectedSteps;
    if (verdict == StepController::Verdict::BelowMinimum) {
      std::ostringstream why;
      why.precision(9);
      why << "step rejected at t = " << s.t;
      why.precision(3);
      why << " with dt = " << h << " (" << rep.failure
          << "); dt would fall below dt_min = " << control_.minimum();
      result.accepted = false;
      result.failure = why.str();
      return result;
    }
  }
}

}  // namespace chute
