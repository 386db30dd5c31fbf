#include "solver/GeneralizedAlpha.hpp"

#include <cmath>

namespace chute {

GeneralizedAlphaParams GeneralizedAlphaParams::fromRhoInf(double rho, AlphaScheme scheme) {
  // Second-order accurate, unconditionally stable for linear problems, high-frequency spectral
  // radius rho_inf (Chung & Hulbert 1993, eqs. 25-27 with their alpha_m, alpha_f signs).
  GeneralizedAlphaParams p;
  if (scheme == AlphaScheme::ChungHulbert) {
    p.alphaM = (2.0 * rho - 1.0) / (rho + 1.0);
    p.alphaF = rho / (rho + 1.0);
  } else {
    p.alphaM = (rho - 1.0) / (rho + 1.0);
    p.alphaF = 0.0;
  }
  p.gamma = 0.5 - p.alphaM + p.alphaF;
  p.beta = 0.25 * (1.0 - p.alphaM + p.alphaF) * (1.0 - p.alphaM + p.alphaF);
  return p;
}

GeneralizedAlpha::GeneralizedAlpha(StructuralSystem& sys, double rhoInf, AlphaScheme scheme,
                                   NewtonSettings newton, double dtNominal, double dtMin)
    : ImplicitIntegrator(sys, newton, dtNominal, dtMin),
      p_(GeneralizedAlphaParams::fromRhoInf(rhoInf, scheme)),
      scheme_(scheme) {
  sys.prepareFor(IntegrationTraits{});
  eq_.atEnd = p_.alphaF == 0.0;
}

namespace {
// One step's unknowns and their evaluation point: Newmark's update of velocity and acceleration
// from the trial positions, prescribed dofs on their path, and the alpha-blended point where the
// forces are evaluated.
class StepProblem final : public NewtonProblem {
 public:
  StepProblem(const StructuralSystem& sys, const GeneralizedAlphaParams& p,
              const StructuralState& old, StructuralState& n, double dt)
      : sys_(sys), p_(p), old_(old), n_(n), dt_(dt) {}

  // Constrained dofs follow their prescribed motion (fixed: where they started).
  void prescribe() { sys_.prescribeMotion(n_); }
  void afterUpdate() override {
    const double dt = dt_;
    n_.a = (n_.x - old_.x - dt * old_.v - dt * dt * (0.5 - p_.beta) * old_.a) / (p_.beta * dt * dt);
    n_.v = old_.v + dt * ((1.0 - p_.gamma) * old_.a + p_.gamma * n_.a);
    prescribe();
  }
  EvalPoint point() override {
    x_ = (1.0 - p_.alphaF) * n_.x + p_.alphaF * old_.x;
    v_ = (1.0 - p_.alphaF) * n_.v + p_.alphaF * old_.v;
    a_ = (1.0 - p_.alphaM) * n_.a + p_.alphaM * old_.a;
    return EvalPoint::implicitStep(x_, v_, a_, forceTime(),
                                   {1.0 - p_.alphaF, (1.0 - p_.alphaF) * p_.gamma / (p_.beta * dt_),
                                    (1.0 - p_.alphaM) / (p_.beta * dt_ * dt_)},
                                   dt_);
  }
  double forceTime() const { return old_.t + (1.0 - p_.alphaF) * dt_; }

 private:
  const StructuralSystem& sys_;
  const GeneralizedAlphaParams& p_;
  const StructuralState& old_;
  StructuralState& n_;
  double dt_;
  Eigen::VectorXd x_, v_, a_;
};
}  // namespace

NewtonReport GeneralizedAlpha::tryStep(StructuralState& s, double dt) {
  const StructuralState old = s;
  StructuralState n = s;
  // Predictor: positions stay where they are (the first Newton update is then a consistent
  // linearised step from the last converged state). Predicting positions from Newmark's
  // velocity would move a heavy slider while the massless rope nodes around it, whose Newmark
  // velocities carry no information, stay behind: a stiff rope then starts a step with a large
  // spurious stretch.
  n.x = old.x;
  n.t = old.t + dt;
  StepProblem problem(*sys_, p_, old, n, dt);
  problem.prescribe();
  problem.afterUpdate();
  // The prescribed motion's jump may carry a driven slider past nodes: it starts Newton in the
  // element it has reached.
  if (sys_->drivesKinks() && sys_->crossDriven(old.x, n.x) > 0) problem.afterUpdate();
  NewtonReport rep =
      newton_.solve(n.x, newton_.settings().toleranceFor(dt), problem, false, &old.x);
  if (rep.converged) {
    sys_->commit(CommitPoint{n.x, n.t, dt, problem.forceTime()});
    if (!eq_.atEnd) {  // the alpha-point of the converged step (eq. TI5)
      eq_.x = (1.0 - p_.alphaF) * n.x + p_.alphaF * old.x;
      eq_.v = (1.0 - p_.alphaF) * n.v + p_.alphaF * old.v;
      eq_.a = (1.0 - p_.alphaM) * n.a + p_.alphaM * old.a;
      eq_.t = problem.forceTime();
      eq_.tEnd = n.t;
    }
    s = n;
  } else {
    sys_->revert();
  }
  return rep;
}

}  // namespace chute
