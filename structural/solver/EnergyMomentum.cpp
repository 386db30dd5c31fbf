#include "solver/EnergyMomentum.hpp"

#include <cmath>

namespace chute {

namespace {
// The unknowns x_{n+1}; velocities from EM1, the evaluation point at the midpoint (EM2).
class EnergyMomentumProblem final : public NewtonProblem {
 public:
  EnergyMomentumProblem(const StructuralSystem& sys, const StructuralState& old, StructuralState& n,
                        double dt, double chi)
      : sys_(sys), old_(old), n_(n), dt_(dt), chi_(chi) {}

  // Constrained dofs follow their prescribed motion (fixed: where they started).
  void prescribe() { sys_.prescribeMotion(n_); }
  void afterUpdate() override {
    // EM1: v_{n+1} = 2 (x_{n+1} - x_n) / dt - v_n; a = (v_{n+1} - v_n) / dt, the step's mean
    // acceleration (the inertia force of EM2).
    n_.v = (2.0 / dt_) * (n_.x - old_.x) - old_.v;
    n_.a = (n_.v - old_.v) / dt_;
    prescribe();
  }
  EvalPoint point() override {
    x_ = 0.5 * (old_.x + n_.x);
    v_ = 0.5 * (old_.v + n_.v);
    a_ = (n_.v - old_.v) / dt_;
    // d x_mid / d x_{n+1} = 1/2, d v_mid / d x_{n+1} = 1/dt, d a / d x_{n+1} = 2/dt^2.
    return EvalPoint::energyMomentumStep(x_, v_, a_, forceTime(),
                                         {0.5, 1.0 / dt_, 2.0 / (dt_ * dt_)}, dt_, old_.x, chi_);
  }
  double forceTime() const { return old_.t + 0.5 * dt_; }

 private:
  const StructuralSystem& sys_;
  const StructuralState& old_;
  StructuralState& n_;
  double dt_, chi_;
  Eigen::VectorXd x_, v_, a_;
};
}  // namespace

EnergyMomentum::EnergyMomentum(StructuralSystem& sys, NewtonSettings newton, double dtNominal,
                               double dtMin, double chi, int order)
    : ImplicitIntegrator(sys, newton, dtNominal, dtMin), chi_(chi), order_(order) {
  // The discrete gradient's tangent is not symmetric (EM5): LU from the start.
  newton_.linearSolver().useLU();
  // EM12: the terms that can condense themselves for discrete gradients do (Term::prepareFor).
  sys.prepareFor(IntegrationTraits{false, true});
}

NewtonReport EnergyMomentum::tryStep(StructuralState& s, double dt) {
  if (order_ != 4) return midpointStep(s, dt);
  // EM14: Yoshida's triple jump, steps g1 dt, g2 dt, g1 dt with 2 g1 + g2 = 1 and
  // 2 g1^3 + g2^3 = 0, g1 = 1 / (2 - 2^(1/3)): the composition of a symmetric second-order
  // method is fourth-order and symmetric, and keeps what every step keeps (energy, momenta).
  // A failed part fails the step (the step control restores its start and halves it).
  const double g1 = 1.0 / (2.0 - std::cbrt(2.0)), g2 = 1.0 - 2.0 * g1;
  NewtonReport total;
  total.converged = true;
  const double t0 = s.t;
  for (const double g : {g1, g2, g1}) {
    const NewtonReport part = midpointStep(s, g * dt);
    total.iterations += part.iterations;
    total.stateChanges += part.stateChanges;
    total.residualNorms.insert(total.residualNorms.end(), part.residualNorms.begin(),
                               part.residualNorms.end());
    total.updateNorms.insert(total.updateNorms.end(), part.updateNorms.begin(),
                             part.updateNorms.end());
    if (!part.converged) {
      total.converged = false;
      total.failure = part.failure;
      total.outOfIterations = part.outOfIterations;
      return total;
    }
  }
  s.t = t0 + dt;  // the parts' times add up to dt only to round-off
  return total;
}

NewtonReport EnergyMomentum::midpointStep(StructuralState& s, double dt) {
  StructuralSystem& sys = *sys_;
  Newton& newton = newton_;
  const double chi = chi_;
  const StructuralState old = s;
  StructuralState n = s;
  // Predictor: positions stay where they are (as for generalized-alpha, GeneralizedAlpha.cpp).
  n.x = old.x;
  n.t = old.t + dt;
  EnergyMomentumProblem problem(sys, old, n, dt, chi);
  problem.prescribe();
  problem.afterUpdate();
  if (sys.drivesKinks() && sys.crossDriven(old.x, n.x) > 0) problem.afterUpdate();
  NewtonReport rep = newton.solve(n.x, newton.settings().toleranceFor(dt), problem, false, &old.x);
  if (rep.converged) {
    sys.commit(CommitPoint{n.x, n.t, dt, problem.forceTime()});
    s = n;
  } else {
    sys.revert();
  }
  return rep;
}

}  // namespace chute
