#include "solver/Newton.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace chute {

double NewtonSettings::toleranceFor(double h) const {
  double tol = tolDisplacement;
  if (nominalStep > 0.0 && h < nominalStep) {
    const double ratio = h / nominalStep;
    tol = std::max(tol * ratio * ratio, 100.0 * 2.22e-16 * lengthScale);
  }
  return tol;
}

Newton::Newton(StructuralSystem& sys, NewtonSettings settings)
    : sys_(&sys), settings_(settings), linear_(sys.symmetric(), sys.timings()) {
  if (settings_.symmetricPartSolver && !sys.symmetric()) linear_.useSymmetricPart();
}

NewtonReport Newton::solve(Eigen::VectorXd& x, double tol, NewtonProblem& problem,
                           bool crossInPlace, const Eigen::VectorXd* stepStart) {
  NewtonReport rep;
  const int neq = sys_->numEquations();
  const bool driven = !crossInPlace && sys_->drivesKinks();
  Eigen::VectorXd dxEq(neq), dx(x.size()), before, motion;
  int lastChanges = 0;
  double previousUpdate = 0.0;
  // A factorisation serves one step only: a restarted run then solves exactly as the run it
  // continues. (Carried across steps it saved 9 % more factorisations on the C-9.)
  bool factorHeld = false;
  // RG10: in the first iteration (the linearised step) tension-only parts on the kink take their
  // taut tangent, so a line at zero strain is pulled straight at once instead of one part per
  // iteration; the later iterations are exact Newton. That Jacobian is stiffer than the
  // residual's derivative there: a first update that looks converged is confirmed by one
  // iteration with the exact tangent (exact).
  bool exact = false;
  for (int it = 0; it < settings_.maxIterations; ++it) {
    lastChanges = sys_->updateState(x);
    rep.stateChanges += lastChanges;
    EvalPoint pt = problem.point();
    pt.kinkTangent = it == 0 && !exact;
    // Modified Newton: the step's factorisation serves while nothing discrete changed; its
    // update is then judged by its contraction below.
    bool stale = settings_.reuseTangent && factorHeld && lastChanges == 0;
    const long kinks = sys_->workCounters().kinkTangents;
    sys_->assemble(pt, !stale);
    bool kinkTangent = sys_->workCounters().kinkTangents != kinks;
    const Eigen::VectorXd& R = sys_->residual();
    const double rn = R.norm();
    rep.residualNorms.push_back(rn);
    if (!std::isfinite(rn)) {
      rep.failure = "non-finite residual";
      return rep;
    }
    for (int attempt = 0; attempt < 2; ++attempt) {
      if (!stale) {
        factorHeld = false;
        if (!linear_.factorize(sys_->matrix())) {
          rep.failure = "singular tangent";
          return rep;
        }
        factorHeld = settings_.reuseTangent;
      }
      if (!linear_.solve(-R, dxEq)) {
        if (stale) {
          stale = false;
          sys_->assemble(pt, true);
          kinkTangent = sys_->workCounters().kinkTangents != kinks;
          continue;
        }
        rep.failure = "linear solve failed";
        return rep;
      }
      if (!stale) break;
      // A stale tangent's update must contract; if not, factorise afresh here and redo it.
      const double un = dxEq.lpNorm<Eigen::Infinity>();
      if (std::isfinite(un) && un <= settings_.reuseContraction * previousUpdate) break;
      stale = false;
      sys_->assemble(pt, true);
      kinkTangent = sys_->workCounters().kinkTangents != kinks;
    }
    previousUpdate = dxEq.lpNorm<Eigen::Infinity>();
    dx.setZero();
    sys_->addToDofs(dxEq, dx);
    const double un = dx.lpNorm<Eigen::Infinity>();
    rep.updateNorms.push_back(un);
    rep.iterations = it + 1;
    if (!std::isfinite(un)) {
      rep.failure = "non-finite update";
      return rep;
    }
    const double passage = sys_->passageFraction(x, dx);
    if (settings_.verbose)
      std::fprintf(stderr, "    newton %2d  |R| = %.3e  |dx| = %.3e  changes %d%s\n", it, rn, un,
                   lastChanges, passage < 1.0 ? "  passes an event" : "");
    if (passage < 1.0 && (crossInPlace || !settings_.sliderEvents)) {
      x += passage * dx;  // to where slider and node meet, then across
      sys_->crossNow(x);
      problem.afterUpdate();
      continue;
    }
    // Slack / taut switches: along the whole motion from the step's start to this trial end
    // (the fraction of the step where it passes one, positions being linear in time to first
    // order).
    double stepEvent = 1.0;
    if (stepStart && settings_.slackTautEvents) {
      motion = x + dx - *stepStart;
      stepEvent = sys_->stepEventFraction(*stepStart, motion);
    }
    if (passage < 1.0 || stepEvent < 1.0) {
      // The first update is the linearised step: its passage fraction estimates the event time.
      rep.failure = "an event (a slider at a node, a cable slack / taut) within the step";
      const double sliders = passage < 1.0 ? (it == 0 ? passage : 0.5) : 1.0;
      rep.eventFraction = std::max(std::min(sliders, stepEvent), 1e-12);
      return rep;
    }
    if (driven) before = x;
    x += dx;
    problem.afterUpdate();
    // A driven slider carried past a node by this update is handed over there.
    const bool crossed = driven && sys_->crossDriven(before, x) > 0;
    if (crossed) problem.afterUpdate();
    // Not below what round-off lets the assembled forces resolve (a stiff short part, FR16).
    if (lastChanges == 0 && !crossed && un <= std::max(tol, sys_->displacementFloor())) {
      if (kinkTangent && !exact) {
        exact = true;  // confirm with the exact tangent (RG10)
        continue;
      }
      if (sys_->onConverged(x)) problem.afterUpdate();  // moved negligibly onto an event
      rep.converged = true;
      return rep;
    }
  }
  rep.failure = "no convergence in " + std::to_string(settings_.maxIterations) + " iterations";
  rep.outOfIterations = true;
  return rep;
}

}  // namespace chute
