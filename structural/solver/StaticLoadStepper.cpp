#include "solver/StaticLoadStepper.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace chute {

namespace {
// The static evaluation point: no velocity, no inertia, loads scaled by the factor.
class StaticProblem final : public NewtonProblem {
 public:
  StaticProblem(const Eigen::VectorXd& x, double t, double loadFactor)
      : x_(x), zero_(Eigen::VectorXd::Zero(x.size())), t_(t), loadFactor_(loadFactor) {}
  EvalPoint point() override { return EvalPoint::statics(x_, zero_, t_, loadFactor_); }
  void afterUpdate() override {}

 private:
  const Eigen::VectorXd& x_;
  Eigen::VectorXd zero_;
  double t_, loadFactor_;
};
}  // namespace

NewtonReport StaticLoadStepper::solve(StructuralState& s, int nSteps, double initialFactor) {
  NewtonReport total;
  Eigen::VectorXd x = s.x;
  double lambda = 0.0, increment = 1.0 / nSteps;
  const bool geometric = initialFactor < 1.0 && nSteps > 1;
  // The growth that takes initialFactor to 1 in nSteps; by logarithms when 1 / initialFactor
  // overflows (a subnormal factor: an infinite growth made the first increment after it
  // infinite, and halving an infinite increment never ended).
  const double inverse = 1.0 / initialFactor;
  const double growth = !geometric ? 1.0
                        : std::isfinite(inverse)
                            ? std::pow(inverse, 1.0 / (nSteps - 1))
                            : std::exp(-std::log(initialFactor) / (nSteps - 1));
  if (geometric) increment = initialFactor;
  const double tol = newton_->settings().tolDisplacement;
  bool halvedInThisStep = false;
  long increments = 0;
  while (lambda < 1.0 - 1e-12) {
    // A bound on the work (docs/limits.md): a load that equilibrium follows only in increments
    // halved near their floor (gravity 1e9 on a small case) converged step after step of 1e-8
    // of the load, for hours.
    if (++increments > kMaxIncrements) {
      char factor[32];
      std::snprintf(factor, sizeof factor, "%.6g", lambda);
      total.failure = "no equilibrium path within " + std::to_string(kMaxIncrements) +
                      " load increments (reached load factor " + factor + ")";
      keepReached(s, x, lambda);
      return total;
    }
    const double target = std::min(1.0, lambda + increment);
    StaticProblem problem(x, s.t, target);
    const Eigen::VectorXd start = x;
    // ST1 (docs/formulation.md): an increment whose Newton ran out of iterations without
    // diverging continues from its last iterate, up to kContinuations more times, before its
    // load is halved: far from equilibrium (a ring on a stiff rope) the iterates wander before
    // they enter the region of quadratic convergence, and a smaller load does not shorten that
    // when the equilibrium does not depend on the load.
    // The continuations are bounded so that a hopeless increment fails as fast as before: only
    // on the first try of a load step (not after its load was halved) and only while the
    // residual has come down (to half of where the increment started, at least once).
    NewtonReport rep;
    int inStep = 0;
    double startResidual = -1.0, leastResidual = 0.0;
    for (int attempt = 0; attempt <= kContinuations; ++attempt) {
      rep = newton_->solve(x, tol, problem, true, nullptr);
      inStep += rep.iterations;
      total.iterations += rep.iterations;
      total.residualNorms.insert(total.residualNorms.end(), rep.residualNorms.begin(),
                                 rep.residualNorms.end());
      if (rep.converged || !rep.outOfIterations || halvedInThisStep) break;
      if (rep.residualNorms.empty()) break;
      if (startResidual < 0.0) startResidual = leastResidual = rep.residualNorms.front();
      for (const double r : rep.residualNorms) leastResidual = std::min(leastResidual, r);
      if (!(leastResidual < 0.5 * startResidual)) break;
    }
    maxInStep_ = std::max(maxInStep_, inStep);
    if (!rep.converged) {
      x = start;
      sys_->revert();
      halvedInThisStep = true;
      increment *= 0.5;
      if (increment < 1e-9) {
        char factor[32];  // significant digits: the factor may be 1e-9
        std::snprintf(factor, sizeof factor, "%.6g", target);
        total.failure = "no convergence in " + std::to_string(inStep) + " iterations";
        if (!rep.outOfIterations) total.failure = rep.failure;
        total.failure += std::string(" at load factor ") + factor;
        keepReached(s, x, lambda);
        return total;
      }
      continue;
    }
    sys_->commit(CommitPoint{x, s.t, 0.0, s.t});
    ++taken_;
    halvedInThisStep = false;
    lambda = target;
    increment = geometric ? std::min(1.0, std::max(increment, lambda * (growth - 1.0))) : increment;
  }
  total.converged = true;
  keepReached(s, x, 1.0);
  return total;
}

void StaticLoadStepper::keepReached(StructuralState& s, const Eigen::VectorXd& x, double lambda) {
  s.x = x;
  s.v.setZero();
  s.a.setZero();
  reached_ = lambda;
}

NewtonReport StaticLoadStepper::solveFromStart(StructuralState& s, int nSteps,
                                               double initialFactor) {
  sys_->updateState(s.x);
  sys_->commit(CommitPoint{s.x, s.t, 0.0, s.t});
  NewtonReport rep = solve(s, nSteps, initialFactor);
  s.t = reached_;
  return rep;
}

}  // namespace chute
